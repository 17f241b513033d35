//! Conveyor tracking (§1.8 传送带跟踪: WaitWObj, DropWObj) with a conveyor of the
//! manifest: CNV1 runs along the world x axis from (250, 0, 300), its speed the analog
//! input c1Speed (the stimulus sets 100 mm/s at 0 s), an object at its sync switch on
//! each rising edge of c1Sync. The start window is 200 mm, the maximum distance 400 mm.
//!
//! Timing model (the IRB 120): a MoveL of L mm at v mm/s with the 10 m/s² TCP ramp takes
//! L/v + v/10000 s when L ≥ v²/10000 (else 2·√(L/10000)), and a stop point 0.05 s more.
//! While the robot tracks, its path is planned in the object's frame and shifted by the
//! object's travel since the first tracked move started.

use std::fs;
use std::path::Path;
use std::process::Output;

use crate::fixture::{rapid, scratch_in, stderr, stdout, Scratch};

const MANIFEST: &str = r#"[system]
io = "eio.cfg"

[[task]]
name = "T_ROB1"
modules = ["main.mod"]

[[conveyor]]
name = "CNV1"
sync = "c1Sync"
speed = "c1Speed"
base = [250, 0, 300]
start_window = 200
max_dist = 400
"#;

const EIO: &str = "EIO:CFG_1.0:6:0::\n#\nEIO_SIGNAL:\n\n      -Name \"c1Sync\" -SignalType \"DI\"\n\n      \
                   -Name \"c1Speed\" -SignalType \"AI\"\n";

/// The robot stands at home (tool0 pointing down) before the first object comes.
const HEAD: &str = "MODULE main
  PERS wobjdata wobj_cnv1 := [FALSE, FALSE, \"CNV1\", [[0,0,0],[1,0,0,0]], [[0,0,0],[1,0,0,0]]];
  CONST robtarget home := [[300,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget above := [[0,0,100],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock c;
  VAR robtarget p;
  VAR pos w;
  VAR bool late;
  PROC main()
    ClkStart c;
    ConfL \\Off;
    MoveJ home, v1000, fine, tool0;
";

/// A project with `body` after HEAD and the stimulus `objects` (after the speed line).
fn project(name: &str, body: &str, objects: &str) -> Scratch {
    let dir = scratch(name);
    fs::write(dir.join("rapid.toml"), MANIFEST).expect("manifest");
    fs::write(dir.join("eio.cfg"), EIO).expect("EIO");
    fs::write(dir.join("main.mod"), format!("{HEAD}{body}  ENDPROC\nENDMODULE\n")).expect("module");
    fs::write(dir.join("cnv.stim"), format!("at 0 set c1Speed 100\n{objects}")).expect("stimulus");
    dir
}

fn run(dir: &Path, extra: &[&str]) -> Output {
    let stim = dir.join("cnv.stim");
    let mut args = vec!["run", "--quiet", "--stimulus", stim.to_str().expect("path")];
    args.extend_from_slice(extra);
    args.push(dir.to_str().expect("path"));
    rapid(&args)
}

/// A fresh, empty scratch folder for one test.
fn scratch(name: &str) -> Scratch {
    scratch_in("conveyor", name)
}

/// One object at the sync switch at 0.5 s.
const ONE_OBJECT: &str = "at 0.5 set c1Sync 1\nat 0.6 set c1Sync 0\n";

#[test]
fn the_robot_follows_the_object_it_connected_to() {
    // Connected at 0.5 s (the object at the switch). The move above it is planned with
    // the object where it is then (x 250): 50 mm at v500, 0.15 s + 0.05 s settle, so the
    // robot stands above it at 0.7 s, where the object has travelled 20 mm: x 270. After
    // 0.5 s more it has travelled 70 mm and the robot with it: x 320, still 100 mm above
    // the object. Leaving for home (fixed work object) from x 320: 20 mm at v1000, a
    // triangle 2·√(20/10000) = 0.0894 s + 0.05 s: home at 1.339 s.
    let body = "    WaitWObj wobj_cnv1;
    TPWrite \"connected \" \\Num:=ClkRead(c);
    MoveL above, v500, fine, tool0 \\WObj:=wobj_cnv1;
    TPWrite \"above \" \\Num:=ClkRead(c);
    w := CPos(\\Tool:=tool0 \\WObj:=wobj0);
    TPWrite \"world \" \\Pos:=w;
    WaitTime 0.5;
    p := CRobT(\\Tool:=tool0 \\WObj:=wobj_cnv1);
    TPWrite \"rel \" \\Pos:=p.trans;
    p := CRobT();
    TPWrite \"active \" \\Pos:=p.trans;
    w := CPos(\\Tool:=tool0 \\WObj:=wobj0);
    TPWrite \"world \" \\Pos:=w;
    MoveL home, v1000, fine, tool0 \\WObj:=wobj0;
    TPWrite \"home \" \\Num:=ClkRead(c);
    DropWObj wobj_cnv1;
";
    let dir = project("follow", body, ONE_OBJECT);
    let trace = dir.join("trace.csv");
    let out = run(&dir, &["--trace", trace.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert_eq!(
        stdout(&out),
        "connected 0.5\nabove 0.7\nworld [270,0,400]\nrel [0,0,100]\nactive [0,0,100]\nworld [320,0,400]\nhome 1.339\n"
    );
    // 0.1 s into the tracked move: 12.5 mm of ramp and 0.05 s at 500 mm/s towards x 250
    // (x 262.5 in the frozen frame), shifted by the object's 10 mm: x 272.5.
    let text = fs::read_to_string(&trace).expect("trace");
    let row = text.lines().find(|l| l.starts_with("0.600,")).expect("a row at 0.6 s");
    let x: f64 = row.split(',').nth(7).and_then(|f| f.parse().ok()).expect("x");
    assert!((x - 272.5).abs() < 0.01, "x {x} in {row}");
}

#[test]
fn rel_dist_waits_until_the_object_is_that_far() {
    // 50 mm past the switch at 100 mm/s: 0.5 s after the edge.
    let body = "    WaitWObj wobj_cnv1 \\RelDist:=50;\n    TPWrite \"connected \" \\Num:=ClkRead(c);\n";
    let out = run(&project("rel_dist", body, ONE_OBJECT), &[]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert_eq!(stdout(&out), "connected 1\n");
}

#[test]
fn objects_past_the_start_window_are_skipped() {
    // The first object leaves the 200 mm window at 2.5 s; waiting from 3 s, the robot
    // connects to the second one, at the switch at 3.5 s.
    let body = "    WaitTime 3 - ClkRead(c);\n    WaitWObj wobj_cnv1;\n    TPWrite \"connected \" \\Num:=ClkRead(c);\n";
    let objects = "at 0.5 set c1Sync 1\nat 0.6 set c1Sync 0\nat 3.5 set c1Sync 1\nat 3.6 set c1Sync 0\n";
    let out = run(&project("window", body, objects), &[]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert_eq!(stdout(&out), "connected 3.5\n");
}

#[test]
fn max_time_and_time_flag() {
    let body = "    WaitWObj wobj_cnv1 \\MaxTime:=1 \\TimeFlag:=late;\n    TPWrite \"late \" \\Bool:=late;\n    \
                TPWrite \"at \" \\Num:=ClkRead(c);\n    WaitWObj wobj_cnv1 \\MaxTime:=1;\n";
    let out = run(&project("max_time", body, ""), &[]);
    // The first wait starts when home is reached (before 0.5 s) and ends 1 s later; the
    // second ends with ERR_WAIT_MAXTIME.
    assert_eq!(out.status.code(), Some(1));
    let text = stdout(&out);
    assert!(text.starts_with("late TRUE\nat 1."), "{text}");
    assert!(stderr(&out).contains("ERR_WAIT_MAXTIME"), "{}", stderr(&out));
}

#[test]
fn waiting_again_while_connected_is_err_cnv_connect() {
    let body = "    WaitWObj wobj_cnv1;\n    WaitWObj wobj_cnv1 \\RelDist:=10;\n    \
                TPWrite \"rel \" \\Num:=ClkRead(c);\n    WaitWObj wobj_cnv1;\n";
    let out = run(&project("connected_twice", body, ONE_OBJECT), &[]);
    // \RelDist on the connected object: 10 mm at 100 mm/s after 0.5 s.
    assert_eq!(stdout(&out), "rel 0.6\n");
    assert_eq!(out.status.code(), Some(1));
    assert!(stderr(&out).contains("ERR_CNV_CONNECT"), "{}", stderr(&out));
}

#[test]
fn dropping_while_the_robot_tracks_stops_the_motion() {
    let body =
        "    WaitWObj wobj_cnv1;\n    MoveL above, v500, fine, tool0 \\WObj:=wobj_cnv1;\n    DropWObj wobj_cnv1;\n";
    let out = run(&project("drop_tracking", body, ONE_OBJECT), &[]);
    assert_eq!(out.status.code(), Some(1));
    assert!(stderr(&out).contains("DropWObj while the robot still moves in the conveyor's work object"));
}

#[test]
fn a_move_on_an_object_past_the_maximum_distance_stops() {
    // At 5 s the object is 450 mm from the switch, beyond 400 mm.
    let body = "    WaitWObj wobj_cnv1;\n    WaitTime 5 - ClkRead(c);\n    MoveL above, v500, fine, tool0 \\WObj:=wobj_cnv1;\n";
    let out = run(&project("max_dist", body, ONE_OBJECT), &[]);
    assert_eq!(out.status.code(), Some(1));
    assert!(stderr(&out).contains("beyond the maximum distance 400 mm"), "{}", stderr(&out));
}

#[test]
fn a_move_in_the_conveyor_work_object_before_wait_wobj_is_refused() {
    let body = "    MoveL above, v500, fine, tool0 \\WObj:=wobj_cnv1;\n";
    let out = run(&project("not_connected", body, ONE_OBJECT), &[]);
    assert_eq!(out.status.code(), Some(1));
    assert!(stderr(&out).contains("ERR_CNV_NOT_ACT"), "{}", stderr(&out));
}

#[test]
fn a_follow_time_stop_point_follows_the_object_that_long() {
    // As in the first test, but the point above the object is a follow-time stop point
    // of 0.3 s (stoppointdata type 3, progsynch TRUE, follow time 0.3): the robot
    // reaches it at 0.65 s and follows the object until 0.95 s, when the object has
    // travelled 45 mm: x 295.
    let body = "    WaitWObj wobj_cnv1;
    MoveL above, v500, fine \\Inpos:=follow, tool0 \\WObj:=wobj_cnv1;
    TPWrite \"above \" \\Num:=ClkRead(c);
    w := CPos(\\Tool:=tool0 \\WObj:=wobj0);
    TPWrite \"world \" \\Pos:=w;
";
    let dir = project("follow_time", body, ONE_OBJECT);
    let module = fs::read_to_string(dir.join("main.mod")).expect("module").replace(
        "  VAR clock c;\n",
        "  VAR clock c;\n  CONST stoppointdata follow := [3, TRUE, [0, 0, 0, 0], 0, 0.3, \"\", 0, 0];\n",
    );
    fs::write(dir.join("main.mod"), module).expect("module");
    let out = run(&dir, &[]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert_eq!(stdout(&out), "above 0.95\nworld [295,0,400]\n");
}

#[test]
fn world_zones_see_the_robot_where_it_follows_the_object() {
    // The zone is world x 265 … 275 (y ±50, z 350 … 450). The move above the object ends
    // at x 270 in the world (the object has travelled 20 mm): inside. Planned with the
    // object frozen at x 250, it would have passed the zone and ended outside it.
    let body = "    WZBoxDef \\Inside, box, [265,-50,350], [275,50,450];
    WZDOSet \\Temp, zone \\Inside, box, doZone, 1;
    WaitWObj wobj_cnv1;
    MoveL above, v500, fine, tool0 \\WObj:=wobj_cnv1;
    TPWrite \"in the zone \" \\Num:=DOutput(doZone);
";
    let dir = project("zone", body, ONE_OBJECT);
    let module = fs::read_to_string(dir.join("main.mod"))
        .expect("module")
        .replace("  VAR clock c;\n", "  VAR clock c;\n  VAR wztemporary zone;\n  VAR shapedata box;\n");
    fs::write(dir.join("main.mod"), module).expect("module");
    let eio = format!("{EIO}\n      -Name \"doZone\" -SignalType \"DO\"\n");
    fs::write(dir.join("eio.cfg"), eio).expect("EIO");
    let out = run(&dir, &[]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert_eq!(stdout(&out), "in the zone 1\n");
}

#[test]
fn conveyor_configuration_is_checked() {
    // Manifest findings (rapid check): bad numbers, a base of two numbers, a task that
    // is no motion task.
    let dir = project("bad_config", "", "");
    let manifest = MANIFEST
        .replace("start_window = 200", "start_window = -1\ntask = \"T_NONE\"")
        .replace("base = [250, 0, 300]", "base = [250, 0]\norientation = [1, 1, 0, 0]");
    fs::write(dir.join("rapid.toml"), manifest).expect("manifest");
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_rapid"))
        .args(["check", dir.to_str().unwrap()])
        .output()
        .unwrap();
    let all = format!("{}{}", stdout(&out), stderr(&out));
    assert!(!out.status.success());
    for message in [
        "start_window -1 is not a positive number",
        "base takes 3 numbers",
        "the orientation is not a unit quaternion",
        "`T_NONE` is no motion task",
    ] {
        assert!(all.contains(message), "missing `{message}` in:\n{all}");
    }
    // A speed input that is no analog input of the I/O configuration stops the run.
    let dir = project("bad_signal", "", "");
    fs::write(dir.join("rapid.toml"), MANIFEST.replace("speed = \"c1Speed\"", "speed = \"c1Sync\"")).expect("manifest");
    let out = run(&dir, &[]);
    assert_eq!(out.status.code(), Some(1));
    assert!(stderr(&out).contains("conveyor CNV1: `c1Sync` is no AI signal"), "{}", stderr(&out));
}

#[test]
fn the_conveyor_is_a_mechanical_unit_that_must_be_active() {
    // CNV1 is listed after the robot, active; deactivated, WaitWObj cannot track it
    // (ERR_CNV_NOT_ACT, taken by the handler, which activates it and retries).
    let body = "    VAR num n := 0;\n    VAR string name;\n    VAR bool tcp;\n    VAR num axes;\n";
    let body = format!(
        "{body}    WHILE GetNextMechUnit(n, name \\TCPRob:=tcp \\NoOfAxes:=axes) DO\n      \
         TPWrite name + \" \" + ValToStr(tcp) + \" \" + ValToStr(axes);\n    ENDWHILE\n    \
         DeactUnit CNV1;\n    TPWrite \"active \" \\Bool:=IsMechUnitActive(CNV1);\n    WaitWObj wobj_cnv1;\n    \
         TPWrite \"connected \" \\Num:=ClkRead(c);\n  ERROR\n    TPWrite \"error \" \\Num:=ERRNO;\n    \
         ActUnit CNV1;\n    RETRY;\n"
    );
    // Declarations cannot follow statements: move them into the module.
    let dir = project("unit", "", ONE_OBJECT);
    let module = fs::read_to_string(dir.join("main.mod")).expect("module");
    let (decls, statements) = body.split_at(body.find("    WHILE").expect("statements"));
    let module = module
        .replace("  VAR clock c;\n", &format!("  VAR clock c;\n{}", decls.replace("    VAR", "  VAR")))
        .replace("  ENDPROC\n", &format!("{statements}  ENDPROC\n"));
    fs::write(dir.join("main.mod"), module).expect("module");
    let out = run(&dir, &[]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert_eq!(stdout(&out), "ROB_1 TRUE 6\nCNV1 FALSE 1\nactive FALSE\nerror 1152\nconnected 0.5\n");
}

/// The most any axis moves between two rows of a trace (rows of time and axes 1–6).
fn largest_axis_step(rows: &[Vec<f64>]) -> f64 {
    rows.windows(2).map(|w| (1..7).map(|j| (w[1][j] - w[0][j]).abs()).fold(0.0, f64::max)).fold(0.0, f64::max)
}

/// Down from home to `via` (fixed work object, zone `zone`), then above the object.
fn approach(zone: &str) -> String {
    format!(
        "    WaitWObj wobj_cnv1;
    MoveL [[300,0,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v500, {zone}, tool0;
    MoveL above, v500, fine, tool0 \\WObj:=wobj_cnv1;
    TPWrite \"above \" \\Num:=ClkRead(c);
    p := CRobT(\\Tool:=tool0 \\WObj:=wobj_cnv1);
    TPWrite \"rel \" \\Pos:=p.trans;
    w := CPos(\\Tool:=tool0 \\WObj:=wobj0);
    TPWrite \"world x \" \\Num:=Round(w.x);
"
    )
}

#[test]
fn a_fly_by_point_before_the_first_tracked_move_is_a_corner_not_a_stop() {
    // §2.2.3: a change from uncoordinated to coordinated motion gets a corner path
    // (joint-interpolated), not a stop. Connected at 0.5 s; 100 mm down at v500 to a
    // point in the fixed work object, then above the object.
    //
    // With a fine point there: 0.2 + 0.05 s ramp + 0.05 s settle, standing at 0.8 s
    // with the object at x 280; above it (x 280, z 400) is √(20² + 100²) = 101.98 mm:
    // 0.204 + 0.05 + 0.05 s, above the object at 1.10396 s (ClkRead counts whole
    // milliseconds: 1.103), where it has travelled to x 310.4.
    let fine = run(&project("approach_fine", &approach("fine"), ONE_OBJECT), &[]);
    assert_eq!(fine.status.code(), Some(0), "{}", stderr(&fine));
    assert_eq!(stdout(&fine), "above 1.103\nrel [0,0,100]\nworld x 310\n");
    // With z20 the robot does not stop: at least the settle (0.05 s) and the stop's
    // braking and starting again (500/10000 s) are saved, less what the 90° corner
    // may cost. It ends above the object all the same, wherever that is by then:
    // x 250 + 100 mm/s · (t - 0.5).
    let dir = project("approach_fly_by", &approach("z20"), ONE_OBJECT);
    let trace = dir.join("trace.csv");
    let out = run(&dir, &["--trace", trace.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let text = stdout(&out);
    let lines: Vec<&str> = text.lines().collect();
    let t: f64 = lines[0].trim_start_matches("above ").parse().expect("a time");
    assert!(t < 1.104 - 0.05, "{text}");
    assert_eq!(lines[1], "rel [0,0,100]");
    assert_eq!(lines[2], format!("world x {}", (250.0 + 100.0 * (t - 0.5)).round()));
    // No jump where the following fades in: every 4 ms the axes move little.
    let text = fs::read_to_string(&trace).expect("trace");
    let rows: Vec<Vec<f64>> =
        text.lines().skip(1).map(|l| l.split(',').take(7).map(|f| f.parse().expect("number")).collect()).collect();
    // The point in the fixed work object (line 14) is in wobj0 all the way, its corner
    // too: the trace's work-object columns are its world ones.
    let fixed: Vec<Vec<f64>> = text
        .lines()
        .filter(|l| l.ends_with("main.mod:14"))
        .map(|l| l.split(',').take(17).map(|f| f.parse().expect("number")).collect())
        .collect();
    assert!(fixed.len() > 50, "{} rows", fixed.len());
    for row in &fixed {
        assert!((7..10).all(|k| (row[k] - row[k + 7]).abs() < 1e-3), "{row:?}");
    }
    let step = largest_axis_step(&rows);
    assert!(step < 2.0, "an axis moved {step}° in one sample");
}

/// Above the object, up 50 mm with it (zone `zone`), then home in the fixed work object.
fn leave(zone: &str) -> String {
    format!(
        "    WaitWObj wobj_cnv1;
    MoveL above, v500, fine, tool0 \\WObj:=wobj_cnv1;
    MoveL Offs(above, 0, 0, 50), v500, {zone}, tool0 \\WObj:=wobj_cnv1;
    MoveL home, v500, fine, tool0;
    TPWrite \"home \" \\Num:=ClkRead(c);
    w := CPos(\\Tool:=tool0 \\WObj:=wobj0);
    TPWrite \"world \" \\Pos:=w;
    DropWObj wobj_cnv1;
"
    )
}

#[test]
fn the_last_tracked_move_blends_into_a_fixed_one_without_a_stop() {
    // §2.2.3: a change from coordinated to uncoordinated motion gets a corner path, not
    // a stop. With `fine` on the last tracked move the robot stops on the moving object
    // (settling 0.05 s) before it goes home; with z20 it does not, so it is home sooner,
    // and home all the same.
    let fine = run(&project("leave_fine", &leave("fine"), ONE_OBJECT), &[]);
    assert_eq!(fine.status.code(), Some(0), "{}", stderr(&fine));
    let dir = project("leave_fly_by", &leave("z20"), ONE_OBJECT);
    let trace = dir.join("trace.csv");
    let out = run(&dir, &["--trace", trace.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let time = |text: &str| -> f64 {
        text.lines().next().and_then(|l| l.strip_prefix("home ")).and_then(|t| t.parse().ok()).expect("a time")
    };
    let (t_fine, t_fly) = (time(&stdout(&fine)), time(&stdout(&out)));
    assert!(t_fly < t_fine - 0.05, "fine {t_fine} s, fly-by {t_fly} s");
    assert!(stdout(&out).ends_with("world [300,0,400]\n"), "{}", stdout(&out));
    // Up 50 mm with the object (line 15): until its corner begins 20 mm before the
    // point (z 130 in the object) the TCP goes straight up in the object's frame, at
    // x 0 and y 0 there.
    let text = fs::read_to_string(&trace).expect("trace");
    let rows: Vec<Vec<f64>> =
        text.lines().skip(1).map(|l| l.split(',').take(17).map(|f| f.parse().expect("number")).collect()).collect();
    let up: Vec<&Vec<f64>> = text
        .lines()
        .skip(1)
        .zip(&rows)
        .filter(|(l, _)| l.ends_with("main.mod:15"))
        .map(|(_, r)| r)
        .take_while(|r| r[16] < 129.9)
        .collect();
    assert!(up.len() > 10, "{} rows", up.len());
    let off = up.iter().find(|r| r[14].abs() > 0.01 || r[15].abs() > 0.01);
    assert!(off.is_none(), "{off:?}");
    // And no jump anywhere.
    let step = largest_axis_step(&rows);
    assert!(step < 2.0, "an axis moved {step}° in one sample");
}
