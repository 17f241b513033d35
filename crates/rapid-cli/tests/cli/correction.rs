//! Path correction on the simulated robot: CorrWrite from a trap while a `\Corr` move
//! runs shifts the rest of the path, seen by CRobT in a later trap and in `--trace`.
//!
//! The timing model the expectations use (as in `triggers.rs`): a 100 mm MoveL at
//! v100 with the model's 10 m/s² ramps accelerates for 0.01 s over 0.5 mm, so the TCP
//! is d mm (0.5 ≤ d ≤ 99.5) along at 0.01 + (d - 0.5) / 100 s after the move starts;
//! it stands at the point at 1.01 s. The move starts when it is given, right after
//! the timers are set: a timer of 0.3 s fires with the TCP 0.5 + 29 = 29.5 mm along.
//!
//! The path coordinate system (corr.rs): x along the path, z the tool's z axis, y =
//! z × x. The tool points down (orient [0,0,1,0]: tool z = -z of the world), so on a
//! path along +x the path's y is the world's -y, on a path along -x the world's +y,
//! and the path's z is the world's -z either way.

use std::fs;
use std::process::Output;

use crate::fixture::{rapid_in, scratch_in, text, Scratch};

/// A fresh, empty scratch folder for one test.
fn scratch(name: &str) -> Scratch {
    scratch_in("correction", name)
}

const P0: &str = "CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];";

/// Runs module `S` made of `decls`, a main of a MoveJ to p0 then `body`, and `traps`,
/// with a 4 ms trace. Returns the run and the trace's rows as (time, x, y, z).
fn run(name: &str, decls: &str, body: &str, traps: &str) -> (Output, Vec<[f64; 4]>) {
    let dir = scratch(name);
    let module = format!(
        "MODULE S\n  {P0}\n{decls}\n  PROC main()\n    MoveJ p0, v1000, fine, tool0;\n{body}\n  ENDPROC\n{traps}\nENDMODULE\n"
    );
    fs::write(dir.join("s.mod"), module).expect("module");
    let out = rapid_in(&dir, &["run", "--quiet", "--trace", "t.csv", "s.mod"]);
    let trace = fs::read_to_string(dir.join("t.csv")).unwrap_or_default();
    let rows = trace
        .lines()
        .skip(1)
        .filter_map(|line| {
            let f: Vec<f64> = line.split(',').take(10).map(|v| v.parse().unwrap_or(f64::NAN)).collect();
            (f.len() == 10).then(|| [f[0], f[7], f[8], f[9]])
        })
        .collect();
    (out, rows)
}

/// The rows of the first move along +x from p0 to x = 400 (after the MoveJ): from
/// the last row standing at p0 to the first at x = 400.
fn first_pass(rows: &[[f64; 4]]) -> &[[f64; 4]] {
    let at_p0 = |r: &[f64; 4]| (r[1] - 300.0).abs() < 1e-3 && (r[3] - 400.0).abs() < 1e-3;
    let start = rows.iter().rposition(|r| at_p0(r) && rows.iter().any(|l| l[0] > r[0] && l[1] > 300.1));
    let start = start.unwrap_or_else(|| panic!("the robot never left p0: {rows:?}"));
    let len = rows[start..].iter().position(|r| r[1] > 399.99).unwrap_or(rows.len() - start - 1);
    &rows[start..=start + len]
}

const TIMERS: &str = "  VAR corrdescr c;\n  VAR intnum i1;\n  VAR intnum i2;";

/// Traps: `write` at 0.3 s, `look` (CRobT) at 0.6 s.
const TRAPS: &str = "  TRAP write\n    CorrWrite c, [0, 5, 0];\n  ENDTRAP\n  \
                     TRAP look\n    VAR robtarget p;\n    p := CRobT();\n    \
                     TPWrite \"at 0.6 \" \\Pos:=p.trans;\n  ENDTRAP";

#[test]
fn a_correction_written_in_a_trap_shifts_the_rest_of_the_path() {
    // At 0.3 s the trap writes 5 mm along the path's y: the world's -y on this path.
    // At 0.6 s the TCP is 0.5 + 59 = 59.5 mm along (x = 359.5) and 5 mm aside; the
    // stop point is [400, -5, 400]; CorrRead returns what was written.
    let body = "    CorrCon c;\n    CONNECT i1 WITH write;\n    CONNECT i2 WITH look;\n    \
                ITimer \\Single, 0.3, i1;\n    ITimer \\Single, 0.6, i2;\n    \
                MoveL Offs(p0, 100, 0, 0), v100, fine, tool0 \\Corr;\n    \
                TPWrite \"end \" \\Pos:=CPos();\n    TPWrite \"total \" \\Pos:=CorrRead();";
    let (out, rows) = run("trap", TIMERS, body, TRAPS);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "at 0.6 [359.5,-5,400]\nend [400,-5,400]\ntotal [0,5,0]\n");
    // The trace: y = 0 until the TCP is 29.5 mm along (x = 329.5), -5 from there on;
    // a 4 ms row is 0.4 mm of path, so the first shifted row is within 0.4 mm after.
    let pass = first_pass(&rows);
    let shifted = pass.iter().position(|r| r[2] < -4.999).unwrap_or_else(|| panic!("never shifted: {pass:?}"));
    let x = pass[shifted][1];
    assert!((329.5..=329.9 + 1e-6).contains(&x), "first shifted row at x = {x}: {pass:?}");
    assert!(pass[..shifted].iter().all(|r| r[2].abs() < 1e-6), "{pass:?}");
    assert!(pass[shifted..].iter().all(|r| (r[2] + 5.0).abs() < 1e-6 && (r[3] - 400.0).abs() < 1e-6), "{pass:?}");
}

#[test]
fn corrdiscon_takes_the_generators_correction_off_the_path() {
    // 5 mm written at 0.3 s (x = 329.5), the generator disconnected at 0.6 s
    // (x = 359.5): the path is 5 mm aside in between and back on its line after.
    let traps = "  TRAP write\n    CorrWrite c, [0, 5, 0];\n  ENDTRAP\n  TRAP look\n    CorrDiscon c;\n  ENDTRAP";
    let body = "    CorrCon c;\n    CONNECT i1 WITH write;\n    CONNECT i2 WITH look;\n    \
                ITimer \\Single, 0.3, i1;\n    ITimer \\Single, 0.6, i2;\n    \
                MoveL Offs(p0, 100, 0, 0), v100, fine, tool0 \\Corr;\n    \
                TPWrite \"end \" \\Pos:=CPos();\n    TPWrite \"total \" \\Pos:=CorrRead();";
    let (out, rows) = run("discon", TIMERS, body, traps);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "end [400,0,400]\ntotal [0,0,0]\n");
    let pass = first_pass(&rows);
    for r in pass {
        let aside = if r[1] > 330.0 && r[1] < 359.4 {
            -5.0
        } else if r[1] < 329.4 || r[1] > 360.0 {
            0.0
        } else {
            continue;
        };
        assert!((r[2] - aside).abs() < 1e-6, "y = {} at x = {}: {pass:?}", r[2], r[1]);
    }
}

#[test]
fn the_next_move_without_corr_fades_the_correction_out() {
    // A correction of 5 along the path's y written before a move along +x: the move
    // ends at [400, -5, 400]. The next move (back to p0, no \Corr) starts there and
    // ends on its programmed point; the offset fades with time, and the move's
    // profile is symmetric, so half way (x = 350) y is -2.5. A second generator's
    // 2 mm along path z is in force too: -2 of the world's z, fading the same way.
    let decls = "  VAR corrdescr c;\n  VAR corrdescr d;";
    let body = "    CorrCon c;\n    CorrCon d;\n    CorrWrite c, [0, 5, 0];\n    CorrWrite d, [0, 0, 2];\n    \
                MoveL Offs(p0, 100, 0, 0), v100, fine, tool0 \\Corr;\n    \
                TPWrite \"there \" \\Pos:=CPos();\n    MoveL p0, v100, fine, tool0;\n    \
                TPWrite \"back \" \\Pos:=CPos();";
    let (out, rows) = run("fade", decls, body, "");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "there [400,-5,398]\nback [300,0,400]\n");
    let back: Vec<_> = rows.iter().skip_while(|r| r[1] < 399.99).filter(|r| r[1] < 399.9).collect();
    let mid = back.iter().min_by(|a, b| (a[1] - 350.0).abs().total_cmp(&(b[1] - 350.0).abs())).expect("rows back");
    // 4 ms from the middle is 0.4 mm of path and 0.02 mm of fade.
    assert!((mid[2] + 2.5).abs() < 0.03 && (mid[3] - 399.0).abs() < 0.02, "{mid:?}");
    let ys: Vec<f64> = back.iter().map(|r| r[2]).collect();
    assert!(ys.windows(2).all(|w| w[1] >= w[0] - 1e-9), "y rises steadily back to 0: {ys:?}");
}

#[test]
fn a_correction_out_of_reach_written_while_moving_stops_execution() {
    // 2000 mm along path z (down) at 0.3 s: z = -1600, out of the IRB 120's reach.
    let traps = "  TRAP write\n    CorrWrite c, [0, 0, 2000];\n  ENDTRAP\n  TRAP look\n  ENDTRAP";
    let body = "    CorrCon c;\n    CONNECT i1 WITH write;\n    ITimer \\Single, 0.3, i1;\n    \
                MoveL Offs(p0, 100, 0, 0), v100, fine, tool0 \\Corr;\n    TPWrite \"not reached\";";
    let (out, rows) = run("reach", TIMERS, body, traps);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    assert!(text(&out.stderr).contains("50050 Position outside reach"), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "");
    assert!(rows.iter().flatten().all(|v| v.is_finite()), "{rows:?}");
}

#[test]
fn a_stopmove_pause_keeps_the_robot_on_its_corrected_path() {
    // A constant 5 mm along the path's y (the world's -y) from before the move: the
    // robot stops in a trap at 0.3 s, stands 0.5 s and goes on. Standing, going on and
    // at the end it is 5 mm aside; every row of the move on the work plane (z = 400,
    // x past p0) has y = -5.
    let traps = "  TRAP halt\n    VAR pos here;\n    StopMove;\n    WaitTime 0.5;\n    here := CPos();\n    \
                 TPWrite \"paused y \" \\Num:=here.y;\n    StartMove;\n  ENDTRAP";
    let body =
        "    CorrCon c;\n    CorrWrite c, [0, 5, 0];\n    CONNECT i1 WITH halt;\n    ITimer \\Single, 0.3, i1;\n    \
                MoveL Offs(p0, 100, 0, 0), v100, fine, tool0 \\Corr;\n    \
                TPWrite \"end \" \\Pos:=CPos();\n    WaitTime 1;\n    TPWrite \"later \" \\Pos:=CPos();";
    let (out, rows) = run("pause", TIMERS, body, traps);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "paused y -5\nend [400,-5,400]\nlater [400,-5,400]\n");
    let plane: Vec<_> = rows.iter().filter(|r| r[1] > 300.01 && (r[3] - 400.0).abs() < 1e-6).collect();
    assert!(plane.len() > 300, "{rows:?}");
    assert!(plane.iter().all(|r| (r[2] + 5.0).abs() < 1e-6), "{plane:?}");
}
