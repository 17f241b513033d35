//! SearchL's stops: after the hit the robot brakes on its path, `\PStop` and `\SStop`
//! each over its own stop time, and the program goes on when it stands still.
//!
//! Timing model: a MoveL at v50 with the IRB 120's 10 m/s² ramp speeds up for 0.005 s
//! over 0.125 mm, then cruises at 50 mm/s. Stop times (the manual's typical stop
//! distances at 50 mm/s, the middle of each range, braked at a constant rate): `\SStop`
//! 6 mm → 2 · 6 / 50 = 0.24 s, `\PStop` 20 mm → 0.8 s.

use std::fs;
use std::path::Path;
use std::process::Command;

#[test]
fn pstop_and_sstop_brake_their_own_distance_after_the_hit() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("search").join("stops");
    let _ = fs::remove_dir_all(&dir);
    let root = dir.join("sys");
    fs::create_dir_all(root.join("RAPID/TASK1/PROGMOD")).expect("task folder");
    fs::create_dir_all(root.join("SYSPAR")).expect("syspar");
    // Each probe rises 0.5 s into its search: the TCP is 0.125 + 50 · 0.495 = 24.875 mm
    // along, at x = 324.875. \PStop: 50 · 0.8 / 2 = 20 mm more, x = 344.875, standing at
    // 0.5 + 0.8 = 1.3 s. \SStop: 50 · 0.24 / 2 = 6 mm more, x = 330.875, at 0.74 s.
    let module = "MODULE S
  CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  VAR robtarget hit;
  VAR clock c;
  PROC main()
    MoveJ p0, v1000, fine, tool0;
    ClkStart c;
    SetDO doFirst, 1;
    SearchL \\PStop, diFirst, hit, Offs(p0, 100, 0, 0), v50, tool0;
    Report \"PStop\";
    MoveJ p0, v1000, fine, tool0;
    ClkReset c;
    ClkStart c;
    SetDO doSecond, 1;
    SearchL \\SStop, diSecond, hit, Offs(p0, 100, 0, 0), v50, tool0;
    Report \"SStop\";
  ENDPROC
  PROC Report(string kind)
    VAR pos at;
    at := CPos();
    TPWrite kind + \": hit x \" + NumToStr(hit.trans.x, 1) + \", stands at x \" + NumToStr(at.x, 1) + \" after \" + NumToStr(ClkRead(c), 2);
  ENDPROC
ENDMODULE
";
    fs::write(root.join("RAPID/TASK1/PROGMOD/Main.mod"), module).expect("module");
    let sys = "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n      -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask\n";
    fs::write(root.join("SYSPAR/SYS.cfg"), sys).expect("SYS.cfg");
    let signals: String = [("doFirst", "DO"), ("doSecond", "DO"), ("diFirst", "DI"), ("diSecond", "DI")]
        .iter()
        .map(|(name, kind)| format!("\n      -Name \"{name}\" -SignalType \"{kind}\"\n"))
        .collect();
    fs::write(root.join("SYSPAR/EIO.cfg"), format!("EIO:CFG_1.0:6:0::\n#\nEIO_SIGNAL:\n{signals}")).expect("EIO");
    let stimulus = "when doFirst = 1 after 0.5 s set diFirst 1\nwhen doSecond = 1 after 0.5 s set diSecond 1\n";
    fs::write(dir.join("probe.stim"), stimulus).expect("stimulus");
    let out = Command::new(env!("CARGO_BIN_EXE_rapid"))
        .current_dir(&dir)
        .args(["run", "--quiet", "--stimulus", "probe.stim", "sys"])
        .output()
        .expect("run rapid");
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(
        String::from_utf8_lossy(&out.stdout),
        "PStop: hit x 324.9, stands at x 344.9 after 1.30\nSStop: hit x 324.9, stands at x 330.9 after 0.74\n"
    );
}
