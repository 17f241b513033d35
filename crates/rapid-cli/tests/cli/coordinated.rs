//! A robot working in the work object of another task's unit (MultiMove): T_ROB1's
//! robot works on turntable STN1, which task T_STN1 moves (a positioner's motion task,
//! moving no robot of its own: `robot = false`). The table's frame stands at
//! (300, 0, 0) and turns about the world z axis (eax_a of T_STN1, ±180°, 180 °/s,
//! reaching full speed in 0.15 s); the work object's object frame is 200 mm above it
//! (a coordinated work object's user frame is the unit's, whatever its `uframe` says).
//! The object point (100, 0, 100) is (400, 0, 300) in the world with the table at 0°,
//! and (300, 100, 300) with it at 90° (a turn of +90° about z takes x to y).
//!
//! Semi-coordinated (the tasks synchronize with WaitSyncTask): the robot works in the
//! object where the table stands. Synchronized (SyncMoveOn): the robot follows it.
//! Expected values are worked by hand in the comments.

use std::fs;
use std::path::Path;

use crate::fixture::{rapid, scratch_in, Scratch};

/// T_ROB1 and the positioner's task T_STN1, then [`TABLE`].
const TASKS: &str = r#"
[[task]]
name = "T_ROB1"
modules = ["rob.mod"]

[[task]]
name = "T_STN1"
type = "NORMAL"
motion = true
robot = false
modules = ["stn.mod"]
"#;

/// The turntable STN1 of task T_STN1.
const TABLE: &str = r#"
[[unit]]
name = "STN1"
task = "T_STN1"
base = [300, 0, 0]
[[unit.axis]]
logical = 7
type = "rotating"
min = -180
max = 180
speed = 180
"#;

/// The declarations both tasks share: the task list and the sync points.
const COMMON: &str = "  PERS tasks all{2} := [[\"T_ROB1\"],[\"T_STN1\"]];\n  VAR syncident turn;\n  \
                      VAR syncident turned;\n  VAR syncident on;\n  VAR syncident off;\n  VAR clock c;\n";

/// The robot's declarations: the table's work object and points in it.
const ROB_DECLS: &str =
    "  PERS wobjdata wobj_stn := [FALSE, FALSE, \"STN1\", [[0,0,0],[1,0,0,0]], [[0,0,200],[1,0,0,0]]];\n  \
                         CONST robtarget p := [[100,0,100],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\n  \
                         CONST robtarget p_low := [[100,0,50],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\n  \
                         VAR robtarget r;\n";

/// Prints where the TCP is in the world and in the table's work object.
const SHOW: &str = "    TPWrite \"world \" \\Pos:=CPos(\\Tool:=tool0 \\WObj:=wobj0);\n    \
                    r := CRobT(\\Tool:=tool0 \\WObj:=wobj_stn);\n    TPWrite \"object \" \\Pos:=r.trans;\n";

/// The table to 90°.
const TURN: &str = "MoveExtJ [[0,0,0,0,0,0],[90,9E9,9E9,9E9,9E9,9E9]]";

/// A fresh, empty scratch folder for one test.
fn scratch(name: &str) -> Scratch {
    scratch_in("coordinated", name)
}

/// A fresh project folder: the manifest and the two tasks' modules, whose `main`
/// bodies are given.
fn project(name: &str, rob: &str, stn: &str) -> Scratch {
    let dir = scratch(name);
    fs::write(dir.join("rapid.toml"), format!("{TASKS}{TABLE}")).expect("manifest");
    let module = |name: &str, decls: &str, body: &str| {
        format!("MODULE {name}\n{COMMON}{decls}  PROC main()\n{body}  ENDPROC\nENDMODULE\n")
    };
    fs::write(dir.join("rob.mod"), module("rob", ROB_DECLS, rob)).expect("module");
    fs::write(dir.join("stn.mod"), module("stn", "", stn)).expect("module");
    dir
}

fn run(dir: &Path) -> (String, String, Option<i32>) {
    let out = rapid(&["run", "--quiet", dir.to_str().expect("path")]);
    (
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
        out.status.code(),
    )
}

#[test]
fn a_robot_works_on_another_tasks_table_where_it_stands() {
    // The robot goes to p with the table at 0°, stands, and lets T_STN1 turn it (the
    // first sync point); after the turn (the second) it goes to p again: p is now where
    // the turned table has it.
    let rob = format!(
        "    MoveJ p, v1000, fine, tool0 \\WObj:=wobj_stn;\n{SHOW}    WaitSyncTask turn, all;\n    \
         WaitSyncTask turned, all;\n    MoveJ p, v1000, fine, tool0 \\WObj:=wobj_stn;\n{SHOW}"
    );
    let stn = format!("    WaitSyncTask turn, all;\n    {TURN}, v1000, fine;\n    WaitSyncTask turned, all;\n");
    let (stdout, stderr, code) = run(&project("semi", &rob, &stn));
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(stdout, "world [400,0,300]\nobject [100,0,100]\nworld [300,100,300]\nobject [100,0,100]\n");
}

#[test]
fn the_table_does_not_turn_while_the_robot_works_on_it_unsynchronized() {
    // The robot's move to p takes well over 0.2 s; T_STN1 turns the table at 0.2 s
    // without waiting for it: execution stops in T_STN1, at its MoveExtJ (line 10).
    let rob = "    MoveJ p, v1000, fine, tool0 \\WObj:=wobj_stn;\n";
    let stn = format!("    WaitTime 0.2;\n    {TURN}, v1000, fine;\n");
    let (_, stderr, code) = run(&project("semi_unit_moves", rob, &stn));
    assert_eq!(code, Some(1), "{stderr}");
    assert!(
        stderr.contains("unit STN1 would move while the robot of task T_ROB1 moves in a work object it carries")
            && stderr.contains("stn.mod:10"),
        "{stderr}"
    );
}

#[test]
fn the_robot_does_not_work_on_a_turning_table_unsynchronized() {
    // The table turns from 0 s to 0.65 s; the robot's move in its work object at 0.2 s
    // stops execution in T_ROB1 (line 14).
    let rob = "    WaitTime 0.2;\n    MoveJ p, v1000, fine, tool0 \\WObj:=wobj_stn;\n";
    let stn = format!("    {TURN}, v1000, fine;\n");
    let (_, stderr, code) = run(&project("semi_robot_moves", rob, &stn));
    assert_eq!(code, Some(1), "{stderr}");
    assert!(
        stderr.contains("the work object's unit STN1 (task T_STN1) moves") && stderr.contains("rob.mod:14"),
        "{stderr}"
    );
}

#[test]
fn a_robot_follows_another_tasks_table_in_synchronized_movement() {
    // After SyncMoveOn the robot goes 50 mm down in the object (at v100 alone 0.5 + 0.01
    // s) while the table turns 90° (alone 90/180 + 0.15 = 0.65 s): both take 0.65 s, +
    // 0.05 s settle at the fine point. At the end the robot is at p_low of the turned
    // table: (100, 0, 250) above the table's origin turned to (0, 100, 250), so
    // (300, 100, 250) in the world.
    // After SyncMoveOff the robot stands where it is while T_STN1 turns the table back
    // (semi-coordinated again): it no longer follows the table.
    let rob = format!(
        "    MoveJ p, v1000, fine, tool0 \\WObj:=wobj_stn;\n    SyncMoveOn on, all;\n    ClkStart c;\n    \
         MoveL p_low \\ID:=10, v100, fine, tool0 \\WObj:=wobj_stn;\n    ClkStop c;\n    SyncMoveOff off;\n    \
         TPWrite \"t \" \\Num:=ClkRead(c);\n{SHOW}    WaitSyncTask turned, all;\n    \
         TPWrite \"world \" \\Pos:=CPos(\\Tool:=tool0 \\WObj:=wobj0);\n"
    );
    let stn = format!(
        "    SyncMoveOn on, all;\n    {TURN} \\ID:=10, v1000, fine;\n    SyncMoveOff off;\n    \
         MoveExtJ [[0,0,0,0,0,0],[0,9E9,9E9,9E9,9E9,9E9]], v1000, fine;\n    WaitSyncTask turned, all;\n"
    );
    let dir = project("synchronized", &rob, &stn);
    let trace = dir.join("trace.csv");
    let out = rapid(&[
        "run",
        "--quiet",
        "--sample",
        "1",
        "--trace",
        trace.to_str().expect("path"),
        dir.to_str().expect("path"),
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert_eq!(
        String::from_utf8_lossy(&out.stdout),
        "t 0.7\nworld [300,100,250]\nobject [100,0,50]\nworld [300,100,250]\n"
    );
    // Every row of the synchronized move: the TCP is on the object's line x = 100,
    // y = 0 (the trace's work-object columns follow the turning table), 100 ≥ z ≥ 50, and
    // in the world on the table at that height, 100 mm from its axis.
    let text = fs::read_to_string(&trace).expect("trace");
    let rows: Vec<Vec<f64>> = text
        .lines()
        .filter(|l| l.ends_with("rob.mod:16"))
        .map(|l| l.split(',').take(17).map(|f| f.parse().expect("number")).collect())
        .collect();
    assert!(rows.len() > 600, "{} rows", rows.len());
    for row in &rows {
        let (x, y, z, wx, wy, wz) = (row[7], row[8], row[9], row[14], row[15], row[16]);
        assert!((wx - 100.0).abs() < 0.01 && wy.abs() < 0.01 && (49.99..=100.01).contains(&wz), "{row:?}");
        assert!(((x - 300.0).hypot(y) - 100.0).abs() < 0.01 && (z - (wz + 200.0)).abs() < 0.01, "{row:?}");
    }
    // Half way (0.325 s in; rows every 1 ms, the first within 1 ms of the start) both
    // profiles are half done, by symmetry: the table at 45°, the robot 75 mm up in the
    // object: (100, 0, 275) above the table turned 45°, (370.71, 70.71, 275) in the
    // world. A millisecond moves the table 0.18°, 0.31 mm at 100 mm.
    let mid = rows.iter().find(|r| r[0] >= rows[0][0] + 0.325 - 1e-9).expect("mid row");
    assert!((mid[7] - 370.71).abs() < 0.5 && (mid[8] - 70.71).abs() < 0.5, "{mid:?}");
    assert!((mid[9] - 275.0).abs() < 0.2, "{mid:?}");
    // T_STN1's own trace (trace.T_STN1.csv) has the table's axis only: at that row's
    // time it is at 45° (within the 0.18° a millisecond turns it).
    let table = fs::read_to_string(dir.join("trace.T_STN1.csv")).expect("the positioner's trace");
    assert_eq!(table.lines().next(), Some("time,eax_a,line"));
    let time = format!("{:.3},", mid[0]);
    let row = table.lines().find(|l| l.starts_with(&time)).expect("the table's row at that time");
    let angle: f64 = row.split(',').nth(1).expect("eax_a").parse().expect("number");
    assert!((angle - 45.0).abs() < 0.2, "{row}");
}

#[test]
fn a_positioners_task_moves_its_axes_and_no_robot() {
    // T_STN1 comes first in the manifest and moves no robot: T_ROB1's robot is ROB_1.
    // TaskRunRob is FALSE there, TaskRunMec TRUE; MoveAbsJ moves the table (90° in
    // 0.65 s + 0.05 s settle) and not the robot axes it names; CJointT reads no robot
    // axes (9E9, as axes the system lacks); a MoveL stops execution.
    let dir = scratch("positioner_task");
    let manifest = format!(
        "[[task]]\nname = \"T_STN1\"\nrobot = false\nmodules = [\"stn.mod\"]\n\n\
         [[task]]\nname = \"T_ROB1\"\ntype = \"NORMAL\"\nmotion = true\nmodules = [\"rob.mod\"]\n{TABLE}"
    );
    fs::write(dir.join("rapid.toml"), manifest).expect("manifest");
    let show = "    TPWrite GetTaskName() + \" \" + RobName() + \" \" + ValToStr(TaskRunRob()) + \" \" + ValToStr(TaskRunMec());\n";
    let stn = format!(
        "MODULE stn\n  VAR clock c;\n  VAR jointtarget jt;\n  PROC main()\n{show}    ClkStart c;\n    \
         MoveAbsJ [[10,20,30,0,0,0],[90,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;\n    jt := CJointT();\n    \
         TPWrite \"stn \" \\Num:=ClkRead(c);\n    TPWrite \"table \" \\Num:=jt.extax.eax_a;\n    \
         TPWrite \"robax \" \\Bool:=jt.robax.rax_1 = 9E9;\n    \
         MoveL [[400,0,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, fine, tool0;\n  ENDPROC\nENDMODULE\n"
    );
    fs::write(dir.join("stn.mod"), stn).expect("module");
    let rob = format!("MODULE rob\n  PROC main()\n{show}  ENDPROC\nENDMODULE\n");
    fs::write(dir.join("rob.mod"), rob).expect("module");
    let (stdout, stderr, code) = run(&dir);
    assert_eq!(code, Some(1), "{stderr}");
    let mut lines: Vec<&str> = stdout.lines().collect();
    lines.sort_unstable();
    assert_eq!(lines, ["T_ROB1 ROB_1 TRUE TRUE", "T_STN1  FALSE TRUE", "robax TRUE", "stn 0.7", "table 90"]);
    assert!(stderr.contains("task T_STN1 moves no robot") && stderr.contains("stn.mod:12"), "{stderr}");
}

#[test]
fn wait_sync_task_in_pos_lets_the_table_turn_after_a_fly_by_point() {
    // The robot's last move on the table ends at a fly-by point. WaitSyncTask \InPos
    // first waits for the robot to stand there (the fly-by point becomes a stop point,
    // without a fine point's settle: 50 mm at v100, 0.5 + 0.01 s), so the table may turn
    // after the meeting; the robot stands where it was in the world, (400, 0, 250), which
    // on the turned table is (0, -100, 50). Without \InPos the robot is still given its
    // fly-by move when the tasks meet, and the table's turn stops execution.
    for (in_pos, ok) in [("\\InPos, ", true), ("", false)] {
        let rob = format!(
            "    MoveJ p, v1000, fine, tool0 \\WObj:=wobj_stn;\n    ClkStart c;\n    \
             MoveL p_low, v100, z10, tool0 \\WObj:=wobj_stn;\n    WaitSyncTask {in_pos}turn, all;\n    \
             TPWrite \"met \" \\Num:=ClkRead(c);\n    WaitSyncTask turned, all;\n{SHOW}    \
             r := CRobT(\\Tool:=tool0);\n    TPWrite \"active \" \\Pos:=r.trans;\n"
        );
        let stn = format!("    WaitSyncTask turn, all;\n    {TURN}, v1000, fine;\n    WaitSyncTask turned, all;\n");
        let (stdout, stderr, code) = run(&project(&format!("in_pos_{ok}"), &rob, &stn));
        if ok {
            assert_eq!(code, Some(0), "{stderr}");
            // CRobT without \\WObj reads in the active work object, where the table has it.
            assert_eq!(stdout, "met 0.51\nworld [400,0,250]\nobject [0,-100,50]\nactive [0,-100,50]\n");
        } else {
            assert_eq!(code, Some(1), "{stderr}");
            assert!(stderr.contains("unit STN1 would move while the robot of task T_ROB1 moves"), "{stderr}");
        }
    }
}

#[test]
fn a_table_stopped_by_stop_move_is_seen_standing() {
    // T_STN1 turns the table 90° and stops its path from 0.3 s to 0.8 s (StopMove,
    // StartMove). At 0.5 s the table stands, so CalcJointT \UseCurWObjPos in T_ROB1
    // computes; at 1.0 s it turns again (the rest of the turn, 0.35 s, from 0.8 s):
    // ERR_WOBJ_MOVING.
    let rob = "    WaitTime 0.5;\n    Check;\n    WaitTime 0.5;\n    Check;\n  ENDPROC\n  PROC Check()\n    \
               VAR jointtarget jt;\n    jt := CalcJointT(\\UseCurWObjPos, p, tool0 \\WObj:=wobj_stn);\n    \
               TPWrite \"standing\";\n  ERROR\n    IF ERRNO = ERR_WOBJ_MOVING THEN\n      TPWrite \"moving\";\n      \
               RETURN;\n    ENDIF\n";
    let stn = format!(
        "    VAR intnum stop;\n    CONNECT stop WITH Hold;\n    ITimer \\Single, 0.3, stop;\n    {TURN}, v1000, fine;\n  \
         ENDPROC\n  TRAP Hold\n    StopMove;\n    WaitTime 0.5;\n    StartMove;\n  ENDTRAP\n  PROC Unused()\n"
    );
    let (stdout, stderr, code) = run(&project("paused_table", rob, &stn));
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(stdout, "standing\nmoving\n");
}

#[test]
fn another_tasks_unit_is_named_with_its_task() {
    // ActUnit, DeactUnit, IsMechUnitActive … on T_STN1's unit from T_ROB1 are not
    // supported yet: the message says whose unit it is (it was "not in the system").
    let rob = "    TPWrite \"active \" \\Bool:=IsMechUnitActive(STN1);\n";
    let (_, stderr, code) = run(&project("other_tasks_unit", rob, "    WaitTime 0.1;\n"));
    assert_eq!(code, Some(1), "{stderr}");
    assert!(
        stderr.contains("STN1 is a mechanical unit of task T_STN1: using it from another task is not supported yet"),
        "{stderr}"
    );
}

#[test]
fn two_robots_follow_one_table_in_synchronized_movement() {
    // Two robots work on opposite sides of the table while it turns 30° (SyncMoveOn of
    // all three tasks). T_ROB2 stands at (600, 0, 0) turned 180°. Each goes 30 mm down
    // in the object: T_ROB1 to (100, 0, 70) on the table, (100, 0, 270) above its origin,
    // turned 30°: (386.603, 50, 270); T_ROB2 to (-100, 0, 70): (213.397, -50, 270).
    let dir = scratch("two_robots");
    let manifest = format!(
        "[[task]]\nname = \"T_ROB1\"\nmodules = [\"rob1.mod\"]\n\n[[task]]\nname = \"T_ROB2\"\ntype = \"NORMAL\"\n\
         motion = true\nbase = [600, 0, 0]\norientation = [0, 0, 0, 1]\nmodules = [\"rob2.mod\"]\n\n[[task]]\n\
         name = \"T_STN1\"\ntype = \"NORMAL\"\nmotion = true\nrobot = false\nmodules = [\"stn.mod\"]\n{TABLE}"
    );
    fs::write(dir.join("rapid.toml"), manifest).expect("manifest");
    let list =
        "  PERS tasks all{3} := [[\"T_ROB1\"],[\"T_ROB2\"],[\"T_STN1\"]];\n  VAR syncident on;\n  VAR syncident off;\n";
    for (n, x) in [(1, 100), (2, -100)] {
        let module = format!(
            "MODULE rob{n}\n{list}  PERS wobjdata wobj_stn := [FALSE, FALSE, \"STN1\", [[0,0,0],[1,0,0,0]], \
             [[0,0,200],[1,0,0,0]]];\n  CONST robtarget p := [[{x},0,100],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\n  \
             PROC main()\n    ConfL \\Off;\n    ConfJ \\Off;\n    MoveJ p, v1000, fine, tool0 \\WObj:=wobj_stn;\n    \
             SyncMoveOn on, all;\n    MoveL Offs(p,0,0,-30) \\ID:=10, v100, fine, tool0 \\WObj:=wobj_stn;\n    \
             SyncMoveOff off;\n    TPWrite GetTaskName() + \" \" \\Pos:=CPos(\\Tool:=tool0 \\WObj:=wobj0);\n  ENDPROC\nENDMODULE\n"
        );
        fs::write(dir.join(format!("rob{n}.mod")), module).expect("module");
    }
    let stn = format!(
        "MODULE stn\n{list}  PROC main()\n    SyncMoveOn on, all;\n    \
         MoveExtJ [[0,0,0,0,0,0],[30,9E9,9E9,9E9,9E9,9E9]] \\ID:=10, v1000, fine;\n    SyncMoveOff off;\n  ENDPROC\nENDMODULE\n"
    );
    fs::write(dir.join("stn.mod"), stn).expect("module");
    let (stdout, stderr, code) = run(&dir);
    assert_eq!(code, Some(0), "{stderr}");
    let mut lines: Vec<&str> = stdout.lines().collect();
    lines.sort_unstable();
    assert_eq!(lines, ["T_ROB1 [386.603,50,270]", "T_ROB2 [213.397,-50,270]"]);
}

#[test]
fn a_positioners_task_has_no_tcp_to_read() {
    // CRobT in T_STN1 (no robot) stops execution; CPos as well (its line 9 and 10 in two
    // runs); from T_ROB1, CJointT of T_STN1 reads its table and no robot axes.
    for (call, line) in [("VAR robtarget r;\n    r := CRobT(\\Tool:=tool0);", 10), ("TPWrite \"\" \\Pos:=CPos();", 9)] {
        let stn = format!("    {call}\n");
        let rob = "    VAR jointtarget jt;\n    jt := CJointT(\\TaskName:=\"T_STN1\");\n    \
                   TPWrite \"other \" \\Bool:=jt.robax.rax_1 = 9E9 AND jt.extax.eax_a = 0;\n";
        let (stdout, stderr, code) = run(&project(&format!("no_tcp_{line}"), rob, &stn));
        assert_eq!(code, Some(1), "{stderr}");
        assert!(stderr.contains("the task moves no robot (a positioner's task): there is no TCP to read"), "{stderr}");
        assert!(stderr.contains(&format!("stn.mod:{line}")), "{stderr}");
        assert_eq!(stdout, "other TRUE\n");
    }
}

#[test]
fn a_positioners_unit_is_listed_with_its_own_task_and_motion_planner() {
    // In T_STN1 (task 2) GetNextMechUnit lists ROB_1 (T_ROB1's, task 1, planner 1), then
    // T_STN1's own unit STN1: task 2, and the planner after the one robot's, 2.
    let stn = "    VAR num n := 0;\n    VAR string name;\n    VAR num task_no;\n    VAR num planner;\n    \
               WHILE GetNextMechUnit(n, name \\MecTaskNo:=task_no \\MotPlanNo:=planner) DO\n      \
               TPWrite name + \" \" + NumToStr(task_no, 0) + \" \" + NumToStr(planner, 0);\n    ENDWHILE\n";
    let dir = project("positioner_unit_numbers", "", stn);
    let (stdout, stderr, code) = run(&dir);
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(stdout, "ROB_1 1 1\nSTN1 2 2\n");
}
