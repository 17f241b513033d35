//! Robots numbered by the tasks' mechanical unit groups, not by the tasks' order: a real
//! RobotWare 6 backup may list T_ROB2 before T_ROB1 in SYS.cfg's CAB_TASKS, each task's
//! `-UseMechanicalUnitGroup` naming a `MECHANICAL_UNIT_GROUP` whose `-Robot` is its
//! robot. Expected positions are worked out by hand from MOC.cfg's base frames.

use std::fs;
use std::path::{Path, PathBuf};

use crate::fixture::{rapid_in, scratch_in, text, Scratch};

/// A fresh, empty scratch folder for one test.
fn scratch(name: &str) -> Scratch {
    scratch_in("robot_numbers", name)
}

/// SYS.cfg's two motion tasks, T_ROB2 listed first (lines 5 and 7), and the groups
/// RobotWare 6 writes in SYS.cfg (rob1 on line 11, rob2 on line 13).
fn sys_cfg(rob1_robot: &str, rob2_robot: &str) -> String {
    let indent = "      ";
    format!(
        "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n\
         {indent}-Name \"T_ROB2\" -Type \"NORMAL\" -UseMechanicalUnitGroup \"rob2\" -MotionTask\n\n\
         {indent}-Name \"T_ROB1\" -Type \"NORMAL\" -UseMechanicalUnitGroup \"rob1\" -MotionTask\n\
         #\nMECHANICAL_UNIT_GROUP:\n\n\
         {indent}-Name \"rob1\" -Robot \"{rob1_robot}\" -MechanicalUnit_1 \"{rob1_robot}\"\n\n\
         {indent}-Name \"rob2\" -Robot \"{rob2_robot}\" -MechanicalUnit_1 \"{rob2_robot}\"\n"
    )
}

/// MOC.cfg's two IRB 120 robots: ROB_1 on the world's origin; ROB_2 at (2000, 500, 0)
/// mm, turned 180° about z (quaternion [0, 0, 0, 1]), facing ROB_1.
const MOC: &str = "MOC:CFG_1.0:6:0::\n#\nROBOT:\n\n      \
                   -name \"ROB_1\" -use_robot_type \"ROB1_120_0.58_3\"\n\n      \
                   -name \"ROB_2\" -use_robot_type \"ROB1_120_0.58_3\" -base_frame_pos_x 2 -base_frame_pos_y 0.5\\\n      \
                   -base_frame_orient_u0 0 -base_frame_orient_u3 1\n";

/// Writes backup `sys` in `dir`: T_ROB2 in RAPID/TASK1, T_ROB1 in RAPID/TASK2, with
/// SYS.cfg and MOC.cfg as given.
fn backup(dir: &Path, sys: &str, rob2: &str, rob1: &str) -> PathBuf {
    let root = dir.join("sys");
    for (n, module) in [(1, rob2), (2, rob1)] {
        let folder = root.join(format!("RAPID/TASK{n}/PROGMOD"));
        fs::create_dir_all(&folder).expect("task folder");
        fs::write(folder.join("Main.mod"), module).expect("module");
    }
    fs::create_dir_all(root.join("SYSPAR")).expect("syspar");
    fs::write(root.join("SYSPAR/SYS.cfg"), sys).expect("SYS.cfg");
    fs::write(root.join("SYSPAR/MOC.cfg"), MOC).expect("MOC.cfg");
    root
}

/// A task's program: it names its robot and its motion planner, moves axis 5 to 30° and back to the
/// calibration position, then writes where tool0 is in the world (CRobT in wobj0). The
/// second task waits a little so that the lines come in order.
fn program(task: &str, wait: f64) -> String {
    format!(
        "MODULE Main\n  VAR robtarget p;\n  PROC main()\n    WaitTime {wait};\n    \
         TPWrite \"{task} \" + RobName() + \" \" + GetMecUnitName(ROB_ID) + \" planner \" \\Num:=MotionPlannerNo();\n    \
         MoveAbsJ [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;\n    \
         MoveAbsJ [[0,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;\n    \
         p := CRobT(\\Tool:=tool0 \\WObj:=wobj0);\n    \
         TPWrite \"{task} world \" + NumToStr(p.trans.x, 1) + \" \" + NumToStr(p.trans.y, 1) + \" \" \
         + NumToStr(p.trans.z, 1);\n  ENDPROC\nENDMODULE\n"
    )
}

#[test]
fn each_task_moves_the_robot_its_group_names() {
    // T_ROB2 is the first motion task, but its group names ROB_2: RobName and
    // GetMecUnitName(ROB_ID) answer ROB_2 there, and its motion planner is ROB_2's, 2;
    // ROB_1 and planner 1 in T_ROB1. At the calibration
    // position the IRB 120's tool0 is at (374, 0, 630) in its base frame (wrist centre
    // 302 mm out and 630 mm up, the flange 72 mm beyond it along x). ROB_1's base is the
    // world: (374.0, 0.0, 630.0). ROB_2's base turns x to -x and y to -y and stands at
    // (2000, 500, 0): (2000 - 374, 500 - 0, 630) = (1626.0, 500.0, 630.0).
    let dir = scratch("by_groups");
    let list = "    VAR num n := 0;\n    VAR string name;\n    VAR num task_no;\n    \
                WHILE GetNextMechUnit(n, name \\MecTaskNo:=task_no) DO\n      \
                TPWrite \"unit \" + name + \" task \" + NumToStr(task_no, 0);\n    ENDWHILE\n";
    let rob1 = program("T_ROB1", 0.1).replace("  PROC main()\n", &format!("  PROC main()\n{list}"));
    let root = backup(&dir, &sys_cfg("ROB_1", "ROB_2"), &program("T_ROB2", 0.0), &rob1);
    let trace = dir.join("t.json");
    let report = dir.join("r.html");
    let args = ["run", "--trace", trace.to_str().expect("path"), "--report", report.to_str().expect("path")];
    let out = rapid_in(&dir, &[&args[..], &[root.to_str().expect("path")]].concat());
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    // The units by number: ROB_1 is moved by task 2 (T_ROB1), ROB_2 by task 1.
    let lines: Vec<String> = text(&out.stdout).lines().map(str::to_owned).collect();
    assert_eq!(
        lines,
        [
            "T_ROB2 ROB_2 ROB_2 planner 2",
            "unit ROB_1 task 2",
            "unit ROB_2 task 1",
            "T_ROB1 ROB_1 ROB_1 planner 1",
            "T_ROB2 world 1626.0 500.0 630.0",
            "T_ROB1 world 374.0 0.0 630.0",
        ]
    );
    // The cycle time names each task's robot.
    let stderr = text(&out.stderr);
    let cycle = |task: &str| stderr.lines().find(|l| l.starts_with(&format!("cycle time {task}:"))).map(str::to_owned);
    assert!(cycle("T_ROB2").is_some_and(|l| l.ends_with("(2 moves, ROB_2 IRB 120-3/0.58)")), "{stderr}");
    assert!(cycle("T_ROB1").is_some_and(|l| l.ends_with("(2 moves, ROB_1 IRB 120-3/0.58)")), "{stderr}");

    // The first motion task's trace (T_ROB2's) is ROB_2's, ending where that robot
    // stands; T_ROB1's, beside it, ROB_1's.
    let read = |path: PathBuf| -> serde_json::Value {
        let text = fs::read_to_string(&path).unwrap_or_else(|_| panic!("no trace {}", path.display()));
        serde_json::from_str(&text).expect("valid JSON")
    };
    for (path, unit, at) in
        [(trace, "ROB_2", [1626.0, 500.0, 630.0]), (dir.join("t.T_ROB1.json"), "ROB_1", [374.0, 0.0, 630.0])]
    {
        let json = read(path);
        assert_eq!(json["mech_unit"], unit);
        let last = json["rows"].as_array().and_then(|rows| rows.last()).and_then(|r| r.as_array()).expect("rows");
        // Columns 7, 8, 9 are the TCP's x, y, z in the world.
        let xyz: Vec<f64> = last[7..10].iter().map(|v| v.as_f64().expect("a number")).collect();
        assert!(xyz.iter().zip(at).all(|(v, w)| (v - w).abs() < 0.01), "{unit}: {xyz:?}");
    }
    // The report is T_ROB2's robot's.
    let page = fs::read_to_string(&report).expect("the report");
    assert!(page.contains("<dt>Task</dt><dd>T_ROB2</dd>"), "the report's task");
    assert!(page.contains("<dt>Robot</dt><dd>ROB_2 (IRB 120-3/0.58)</dd>"), "the report's robot");
}

#[test]
fn a_backup_of_one_task_moves_the_robot_its_group_names() {
    // One task, T_ROB2, whose group names ROB_2: it is no MultiMove system, but its robot
    // is ROB_2 and stands where MOC.cfg puts ROB_2: (1626.0, 500.0, 630.0), worked out in
    // `each_task_moves_the_robot_its_group_names`.
    let dir = scratch("one_task");
    let sys = sys_cfg("ROB_1", "ROB_2")
        .replace("\n      -Name \"T_ROB1\" -Type \"NORMAL\" -UseMechanicalUnitGroup \"rob1\" -MotionTask\n", "");
    let root = backup(&dir, &sys, &program("T_ROB2", 0.0), "MODULE Unused\nENDMODULE\n");
    let out = rapid_in(&dir, &["run", root.to_str().expect("path")]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "T_ROB2 ROB_2 ROB_2 planner 2\nT_ROB2 world 1626.0 500.0 630.0\n");
    // The cycle time is the task's, by its name.
    let stderr = text(&out.stderr);
    assert!(stderr.contains("cycle time T_ROB2: ") && stderr.contains("(2 moves, ROB_2 IRB 120-3/0.58)"), "{stderr}");
}

#[test]
fn robots_numbered_by_groups_move_synchronized_in_their_own_base_frames() {
    // Both tasks meet at SyncMoveOn and move 100 mm along the world's y axis with
    // \ID:=10 (from axis 5 at 30°, away from the wrist's singularity). There tool0 is at
    // (302 + 72 cos 30°, 0, 630 - 72 sin 30°) = (364.354, 0, 594) in the base frame:
    // ROB_1 at (364.4, 0.0, 594.0) in the world, ROB_2 at (2000 - 364.354, 500, 594) =
    // (1635.6, 500.0, 594.0). After the move each is 100 mm further along y. Moved in a
    // work object that ROB_2 holds (`ufmec` "ROB_2"), T_ROB1 is refused, naming ROB_2.
    let dir = scratch("synchronized");
    let body = |task: &str, wait: f64| {
        format!(
            "MODULE Main\n  VAR syncident s_on;\n  VAR syncident s_off;\n  \
             PERS tasks all{{2}} := [[\"T_ROB1\"],[\"T_ROB2\"]];\n  VAR robtarget p;\n  \
             PERS wobjdata held := [FALSE, FALSE, \"ROB_2\", [[0,0,0],[1,0,0,0]], [[0,0,0],[1,0,0,0]]];\n  \
             PROC main()\n    ConfL \\Off;\n    \
             MoveAbsJ [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;\n    \
             p := CRobT(\\Tool:=tool0 \\WObj:=wobj0);\n    SyncMoveOn s_on, all;\n    \
             MoveL Offs(p, 0, 100, 0) \\ID:=10, v100, fine, tool0;\n    SyncMoveOff s_off;\n    \
             WaitTime {wait};\n    p := CRobT(\\Tool:=tool0 \\WObj:=wobj0);\n    \
             TPWrite \"{task} world \" + NumToStr(p.trans.x, 1) + \" \" + NumToStr(p.trans.y, 1) + \" \" \
             + NumToStr(p.trans.z, 1);\n  ENDPROC\nENDMODULE\n"
        )
    };
    let held = "    MoveL Offs(p, 0, 0, 10), v100, fine, tool0 \\WObj:=held;\n  ENDPROC";
    let rob1 = body("T_ROB1", 0.1).replacen("  ENDPROC", held, 1);
    let root = backup(&dir, &sys_cfg("ROB_1", "ROB_2"), &body("T_ROB2", 0.0), &rob1);
    let out = rapid_in(&dir, &["run", "--quiet", root.to_str().expect("path")]);
    assert_eq!(text(&out.stdout), "T_ROB2 world 1635.6 600.0 594.0\nT_ROB1 world 364.4 100.0 594.0\n");
    assert_eq!(out.status.code(), Some(1));
    assert!(text(&out.stderr).contains("a work object moved by the robot ROB_2"), "{}", text(&out.stderr));
}

#[test]
fn two_tasks_moving_one_robot_or_a_robot_moc_cfg_lacks_are_refused_at_load() {
    // Both groups name ROB_2: the second task to move it (T_ROB1, line 7 of SYS.cfg) is
    // refused, by `check` and by `run` alike, before anything runs.
    let dir = scratch("refused");
    let module = program("T", 0.0);
    backup(&dir, &sys_cfg("ROB_2", "ROB_2"), &module, &module);
    let checked = rapid_in(&dir, &["check", "sys"]);
    assert_eq!(checked.status.code(), Some(1));
    let stdout = text(&checked.stdout);
    assert!(
        stdout.contains(
            "error[E0701]: task T_ROB1 moves robot ROB_2 (mechanical unit group `rob1`), which task T_ROB2 moves \
             already: a robot is moved by one task\n --> sys/SYSPAR/SYS.cfg:7:1"
        ),
        "{stdout}"
    );
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(text(&out.stdout), "");
    assert!(text(&out.stderr).contains("sys/SYSPAR/SYS.cfg:7:"), "{}", text(&out.stderr));

    // MOC.cfg has no ROB_3: the group rob2 (line 13) naming it is refused.
    let dir = scratch("unknown_robot");
    backup(&dir, &sys_cfg("ROB_1", "ROB_3"), &module, &module);
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(text(&out.stdout), "");
    let stderr = text(&out.stderr);
    assert!(
        stderr.contains(
            "mechanical unit group `rob2` (of task T_ROB2) names robot `ROB_3`, which MOC.cfg does not have \
             (its robots: ROB_1, ROB_2)\n  --> sys/SYSPAR/SYS.cfg:13:"
        ),
        "{stderr}"
    );
}
