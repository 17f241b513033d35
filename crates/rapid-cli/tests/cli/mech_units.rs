//! Mechanical units in a system of several tasks (§1.8, §1.20): each motion task has
//! its own TCP robot ROB_n (n its place among the motion tasks), and every task sees
//! all of them through GetNextMechUnit. Expectations from the configuration order:
//! T_ROB1 (motion, task 1), T_PLC (no robot, task 2), T_ROB2 (motion, task 3).

use std::fs;

use crate::fixture::{rapid_in, scratch_in, system_of, text, Scratch};

/// A fresh, empty scratch folder for one test.
fn scratch(name: &str) -> Scratch {
    scratch_in("mech_units", name)
}

/// Lists the units as one line each: name, task number, planner number.
const LIST: &str = "    VAR num n := 0;\n    VAR string name;\n    VAR num task_no;\n    VAR num planner;\n    \
                    WHILE GetNextMechUnit(n, name \\MecTaskNo:=task_no \\MotPlanNo:=planner) DO\n      \
                    TPWrite ArgName(n) + \" \" + name + \" task \" + NumToStr(task_no, 0) + \" planner \" + NumToStr(planner, 0);\n    \
                    ENDWHILE\n";

#[test]
fn every_motion_task_has_its_robot_and_every_task_sees_them_all() {
    let dir = scratch("three_tasks");
    let rob1 =
        format!("MODULE R1\n  PROC main()\n{LIST}    TPWrite \"T_ROB1 is \" + RobName();\n  ENDPROC\nENDMODULE\n");
    // T_PLC waits so that the tasks print one after another.
    let plc = "MODULE P\n  PROC main()\n    WaitTime 0.1;\n    TPWrite \"T_PLC is \" + RobName();\n    \
               TPWrite \"ROB_1 seen from T_PLC \" \\Bool:=IsMechUnitActive(ROB_1);\n  ENDPROC\nENDMODULE\n";
    let rob2 = "MODULE R2\n  PROC main()\n    WaitTime 0.2;\n    TPWrite \"T_ROB2 is \" + RobName();\n    \
                TPWrite \"its own \" \\Bool:=IsMechUnitActive(ROB_ID);\n  ENDPROC\nENDMODULE\n";
    system_of(
        &dir,
        &[
            ("T_ROB1", "-Type \"NORMAL\" -MotionTask", &rob1),
            ("T_PLC", "-Type \"NORMAL\"", plc),
            ("T_ROB2", "-Type \"NORMAL\" -MotionTask", rob2),
        ],
    );
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    // ROB_1 belongs to T_ROB1 (task 1, planner 1), ROB_2 to T_ROB2 (task 3, planner 2);
    // T_PLC controls no robot: RobName is "".
    assert_eq!(
        text(&out.stdout),
        "n ROB_1 task 1 planner 1\nn ROB_2 task 3 planner 2\nT_ROB1 is ROB_1\nT_PLC is \n\
         ROB_1 seen from T_PLC TRUE\nT_ROB2 is ROB_2\nits own TRUE\n"
    );
}

#[test]
fn a_task_without_a_robot_must_name_the_unit() {
    let dir = scratch("no_robot");
    // ReadMotor without \MecUnit in a task without a robot: ERR_ARGVALERR, handled.
    let plc = "MODULE P\n  PROC main()\n    TPWrite \"motor \" \\Num:=ReadMotor(1);\n  ERROR\n    \
               IF ERRNO = ERR_ARGVALERR TPWrite \"no robot here\";\n    RETURN;\n  ENDPROC\nENDMODULE\n";
    let rob = "MODULE R\n  PROC main()\n  ENDPROC\nENDMODULE\n";
    system_of(&dir, &[("T_ROB1", "-Type \"NORMAL\" -MotionTask", rob), ("T_PLC", "-Type \"NORMAL\"", plc)]);
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "no robot here\n");
}

#[test]
fn another_task_reads_the_robot_where_its_base_frame_stands() {
    // MOC.cfg sets ROB_1's base frame 2 m along x: at its calibration position tool0 is
    // at x = 2000 + 374 in the world (wobj0). T_CTRL, no motion task, reads T_ROB1's
    // robot through its unit group and with \TaskName: the same 2374 (it read 374,
    // the base frame left out).
    let dir = scratch("other_task_base");
    let probe = "MODULE Probe\n  PROC main()\n    VAR robtarget p;\n    p := CRobT(\\Tool:=tool0 \\WObj:=wobj0);\n    \
                 TPWrite \"own \" \\Num:=p.trans.x;\n  ENDPROC\nENDMODULE\n";
    let ctrl = "MODULE Ctrl\n  PROC main()\n    VAR robtarget p;\n    WaitTime 0.1;\n    \
                p := CRobT(\\Tool:=tool0 \\WObj:=wobj0);\n    TPWrite \"group \" \\Num:=p.trans.x;\n    \
                p := CRobT(\\TaskName:=\"T_ROB1\" \\Tool:=tool0 \\WObj:=wobj0);\n    TPWrite \"named \" \\Num:=p.trans.x;\n  \
                ENDPROC\nENDMODULE\n";
    let root = system_of(
        &dir,
        &[
            ("T_ROB1", "-Type \"NORMAL\" -UseMechanicalUnitGroup \"rob1\" -MotionTask", probe),
            ("T_CTRL", "-Type \"NORMAL\" -UseMechanicalUnitGroup \"rob1\"", ctrl),
        ],
    );
    let moc = "MOC:CFG_1.0:6:0::\n#\nROBOT:\n\n      -name \"ROB_1\" -use_robot_type \"ROB1_120_0.58_3\" -base_frame_pos_x 2\n";
    fs::write(root.join("SYSPAR/MOC.cfg"), moc).expect("MOC.cfg");
    let out = rapid_in(&dir, &["run", "--quiet", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "own 2374\ngroup 2374\nnamed 2374\n");
}
