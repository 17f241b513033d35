//! The IRB 14000 YuMi as a system runs it (issue 20 item 6): two 7-axis arms, ROB_R and
//! ROB_L, of MOC.cfg types `ROB_R_14000_05_05` / `ROB_L_14000_05_05` (a public backup's
//! spelling). Axis 7 is a jointtarget's `extax.eax_a`, the arm angle a robtarget's.
//! The fixture is `tests/systems/yumi`. Expected values by hand: each arm starts at its
//! calibration position (the backup's MOC.cfg `-cal_position`: axes 2, 3, 5 at −130°,
//! 30°, 40°; axis 7 at −135° on ROB_R, 135° on ROB_L); a MoveAbsJ's seven values are read
//! back as given; a MoveL to Offs(p, 20, 10, −15) ends √(20² + 10² + 15²) = 26.93 mm
//! from p, with p's arm angle; a MoveL that only adds 10° to the arm angle leaves the TCP
//! where it is and turns axis 7; axis 7 at 170° is outside its ±168.5° range: 50028 for
//! joint 7, as for any axis out of range.

use std::path::PathBuf;

use crate::fixture::{copy_dir, rapid_in, repo_root, scratch_in, text};

#[test]
fn a_two_arm_yumi_moves_its_seven_axes_and_keeps_the_arm_angle() {
    let dir = scratch_in("yumi", "system");
    let fixture: PathBuf = repo_root().join("tests/systems/yumi");
    copy_dir(&fixture, &dir);
    let checked = rapid_in(&dir, &["check", "."]);
    assert_eq!(checked.status.code(), Some(0), "{}", text(&checked.stdout));
    let out = rapid_in(&dir, &["run", "--quiet", "."]);
    assert_eq!(
        text(&out.stdout),
        "L start [0,-130,30,0,40,0] 135\n\
         R start [0,-130,30,0,40,0] -135\n\
         L axes [10,-120,20,15,35,-10] 100\n\
         moved TRUE\n\
         angle kept TRUE\n\
         elbow turned TRUE\n\
         axis 7 moved TRUE\n"
    );
    assert_eq!(out.status.code(), Some(1));
    let stderr = text(&out.stderr);
    assert!(stderr.contains("50028 Joint 7 out of range"), "{stderr}");
    assert!(stderr.contains("MainModule.mod:27:5"), "{stderr}");
}

#[test]
fn the_robot_flag_names_a_yumi_arm() {
    // `--robot "IRB 14000"` moves the right arm: it starts with axis 7 at −135°.
    let dir = scratch_in("yumi", "flag");
    let program = "MODULE M\n  PROC main()\n    VAR jointtarget j;\n    j := CJointT();\n    \
                   TPWrite ValToStr(j.robax) + \" \" + ValToStr(j.extax.eax_a);\n  ENDPROC\nENDMODULE\n";
    crate::fixture::write_files(&dir, &[("m.mod", program)]);
    let out = rapid_in(&dir, &["run", "--quiet", "--robot", "IRB 14000", "m.mod"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "[0,-130,30,0,40,0] -135\n");
}

/// `CRobT(\TaskName:="T_ROB_L")` from the right arm's task reads the left arm as the
/// left arm's own CRobT does: the same TCP and eax_a the arm angle, not axis 7. The left
/// arm stands with axis 7 at 100°, which is not its arm angle there (the fixture's test
/// above: a MoveL that turns the arm angle by 10° moves axis 7 away from 100).
#[test]
fn another_tasks_crobt_of_an_arm_reads_its_arm_angle() {
    let dir = scratch_in("yumi", "foreign");
    copy_dir(&repo_root().join("tests/systems/yumi"), &dir);
    let shared = "  PERS tasks both{2} := [[\"T_ROB_R\"],[\"T_ROB_L\"]];\n  VAR syncident stood;\n  \
                  PERS robtarget own := [[0,0,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\n";
    let left = format!(
        "MODULE MainModule\n{shared}  PROC main()\n    \
         MoveAbsJ [[10,-120,20,15,35,-10],[100,9E9,9E9,9E9,9E9,9E9]], v200, fine, tool0;\n    \
         own := CRobT(\\Tool:=tool0 \\WObj:=wobj0);\n    WaitSyncTask stood, both;\n  ENDPROC\nENDMODULE\n"
    );
    let right = format!(
        "MODULE MainModule\n{shared}  PROC main()\n    VAR robtarget read;\n    \
         WaitSyncTask stood, both;\n    read := CRobT(\\TaskName:=\"T_ROB_L\" \\Tool:=tool0 \\WObj:=wobj0);\n    \
         TPWrite \"same place \" \\Bool:=Distance(read.trans, own.trans) < 0.01;\n    \
         TPWrite \"same arm angle \" \\Bool:=Abs(read.extax.eax_a - own.extax.eax_a) < 0.01;\n    \
         TPWrite \"not axis 7 \" \\Bool:=Abs(read.extax.eax_a - 100) > 1;\n  ENDPROC\nENDMODULE\n"
    );
    crate::fixture::write_files(
        &dir,
        &[("RAPID/TASK1/PROGMOD/MainModule.mod", &right), ("RAPID/TASK2/PROGMOD/MainModule.mod", &left)],
    );
    let out = rapid_in(&dir, &["run", "--quiet", "."]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "same place TRUE\nsame arm angle TRUE\nnot axis 7 TRUE\n");
}

/// `--robot "IRB 14000"` on the two-arm system moves each task's own arm: the task of
/// ROB_L gets the left arm (axis 7 starting at 135°), the task of ROB_R the right one
/// (−135°), so the fixture runs exactly as with MOC.cfg's types.
#[test]
fn the_robot_flag_gives_each_task_of_a_yumi_its_own_arm() {
    let dir = scratch_in("yumi", "flag_system");
    copy_dir(&repo_root().join("tests/systems/yumi"), &dir);
    let out = rapid_in(&dir, &["run", "--quiet", "--robot", "IRB 14000", "."]);
    assert_eq!(
        text(&out.stdout),
        "L start [0,-130,30,0,40,0] 135\n\
         R start [0,-130,30,0,40,0] -135\n\
         L axes [10,-120,20,15,35,-10] 100\n\
         moved TRUE\n\
         angle kept TRUE\n\
         elbow turned TRUE\n\
         axis 7 moved TRUE\n",
        "{}",
        text(&out.stderr)
    );
    assert_eq!(out.status.code(), Some(1));
    assert!(text(&out.stderr).contains("50028 Joint 7 out of range"), "{}", text(&out.stderr));
}

/// A run that moves a YuMi arm says that the arm angle is our own reading (ABB's
/// definition is not public), so nobody takes our axis 7 for a real YuMi's; a run of
/// another robot says nothing of it.
#[test]
fn a_run_moving_a_yumi_arm_notes_whose_arm_angle_it_is() {
    let dir = scratch_in("yumi", "note");
    let program = |eax_a: &str| {
        format!(
            "MODULE M\n  PROC main()\n    MoveAbsJ [[0,-100,30,0,40,0],[{eax_a},9E9,9E9,9E9,9E9,9E9]], v100, fine, \
             tool0;\n  ENDPROC\nENDMODULE\n"
        )
    };
    let (yumi_program, other_program) = (program("-135"), program("9E9"));
    crate::fixture::write_files(&dir, &[("yumi.mod", yumi_program.as_str()), ("other.mod", other_program.as_str())]);
    let note = "the arm angle (robtarget eax_a) follows our own reading";
    let yumi = rapid_in(&dir, &["run", "--robot", "IRB 14000", "yumi.mod"]);
    assert_eq!(yumi.status.code(), Some(0), "{}", text(&yumi.stderr));
    assert!(text(&yumi.stderr).contains(note), "{}", text(&yumi.stderr));
    let other = rapid_in(&dir, &["run", "other.mod"]);
    assert_eq!(other.status.code(), Some(0), "{}", text(&other.stderr));
    assert!(!text(&other.stderr).contains(note), "{}", text(&other.stderr));
}

/// A manifest's `[system] robot = "IRB 14000"` on a two-arm system of its own: the
/// task named for the left arm moves the left arm (axis 7 at its calibration's 135°),
/// the one named for the right arm the right arm (−135°), as MOC.cfg's arm names
/// choose them in a backup.
#[test]
fn a_manifests_yumi_gives_each_task_the_arm_its_name_says() {
    let dir = scratch_in("yumi", "manifest");
    let toml = "[system]\nrobot = \"IRB 14000\"\n\n\
                [[task]]\nname = \"T_ROB_L\"\nmodules = [\"left.mod\"]\nmotion = true\n\n\
                [[task]]\nname = \"T_ROB_R\"\ntype = \"NORMAL\"\nmodules = [\"right.mod\"]\nmotion = true\n";
    let arm = |side: &str, wait: &str| {
        format!(
            "MODULE {side}Arm\n  PROC main()\n    VAR jointtarget j;\n    WaitTime {wait};\n    j := CJointT();\n    \
             TPWrite \"{side} \" \\Num:=j.extax.eax_a;\n  ENDPROC\nENDMODULE\n"
        )
    };
    std::fs::write(dir.join("rapid.toml"), toml).expect("manifest");
    std::fs::write(dir.join("left.mod"), arm("L", "0")).expect("left");
    std::fs::write(dir.join("right.mod"), arm("R", "0.1")).expect("right");
    let out = rapid_in(&dir, &["run", "--quiet", "rapid.toml"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "L 135\nR -135\n");
}
