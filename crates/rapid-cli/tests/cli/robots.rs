//! The robot as a user finds it (issue 20 item 6, and the robots of item 3): a move to
//! where the robot is goes nowhere, whatever the tool and at the wrist singularity; the
//! start pose from `--start-joints` or a manifest's `start_joints`; a MOC.cfg robot type
//! we have no model of stops the run before it starts, never replaced by another robot;
//! robots named `ROB_L`/`ROB_R` and every mechanical unit of MOC.cfg are `mecunit` data.
//! Expected values are worked out by hand from the IRB 120's link lengths (motion.md
//! §2.2: a2 = −70, c1 + c2 = 560, c3 = 302, c4 = 72 mm) and the confdata rules (§3.7).

use crate::fixture::{rapid_in, scratch_in, text, write_files as write, Scratch};

fn scratch(name: &str) -> Scratch {
    scratch_in("robots", name)
}

/// Reads where the robot is with a tool turned −90° about its z axis, moves there with
/// MoveJ and MoveL, and says whether every axis stayed within 0.01° of where it was.
const BACK_TO_CROBT: &str = "MODULE M
  PERS tooldata t := [TRUE,[[0,0,100],[0.707107,0,0,-0.707107]],[1,[0,0,1],[1,0,0,0],0,0,0]];
  PERS wobjdata w := [FALSE,TRUE,\"\",[[100,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
  PROC main()
    VAR robtarget p;
    VAR jointtarget a;
    VAR jointtarget b;
    a := CJointT();
    p := CRobT(\\Tool:=t \\WObj:=w);
    TPWrite \"conf \" + ValToStr(p.robconf);
    MoveJ CRobT(\\Tool:=t \\WObj:=w), v100, fine, t \\WObj:=w;
    MoveL CRobT(\\Tool:=t \\WObj:=w), v100, fine, t \\WObj:=w;
    b := CJointT();
    TPWrite \"still \" \\Bool:=Abs(b.robax.rax_1 - a.robax.rax_1) < 0.01 AND Abs(b.robax.rax_2 - a.robax.rax_2) < 0.01
      AND Abs(b.robax.rax_3 - a.robax.rax_3) < 0.01 AND Abs(b.robax.rax_4 - a.robax.rax_4) < 0.01
      AND Abs(b.robax.rax_5 - a.robax.rax_5) < 0.01 AND Abs(b.robax.rax_6 - a.robax.rax_6) < 0.01;
  ENDPROC
ENDMODULE
";

#[test]
fn a_move_to_crobt_goes_nowhere_at_the_wrist_singularity() {
    // Axis 5 at 0 is the wrist singularity. The IRB 1200 (c1 = 399.1 mm) failed with
    // 50080 before: CRobT's pose, stored in single precision, is a little off the
    // singularity and axes 4 and 6 came from rounding noise.
    // Calibration position: cf1 = cf4 = cf6 = 0; the wrist centre in front of axis 1 and
    // of the lower arm, axis 5 not negative: cfx 0.
    // [30, 10, 20, 45, 0, −100]: cf1 = ⌊30/90⌋ = 0, cf4 = ⌊45/90⌋ = 0, cf6 = ⌊−100/90⌋ = −2;
    // cfx 0 as before (axes 2 and 3 lean the arm forward only a little).
    let dir = scratch("crobt");
    write(&dir, &[("back.mod", BACK_TO_CROBT)]);
    for robot in ["IRB 120-3/0.58", "IRB 1200-5/0.9", "IRB 4600-40/2.55"] {
        let out = rapid_in(&dir, &["run", "--quiet", "--robot", robot, "back.mod"]);
        assert_eq!(out.status.code(), Some(0), "{robot}: {}", text(&out.stderr));
        assert_eq!(text(&out.stdout), "conf [0,0,0,0]\nstill TRUE\n", "{robot}");
        let args = ["run", "--quiet", "--robot", robot, "--start-joints", "30,10,20,45,0,-100", "back.mod"];
        let out = rapid_in(&dir, &args);
        assert_eq!(out.status.code(), Some(0), "{robot}: {}", text(&out.stderr));
        assert_eq!(text(&out.stdout), "conf [0,0,-2,0]\nstill TRUE\n", "{robot}");
    }
}

/// Writes the axis values and where tool0 is in wobj0.
const WHERE: &str = "MODULE M
  PROC main()
    VAR jointtarget j;
    VAR robtarget p;
    j := CJointT();
    p := CRobT(\\Tool:=tool0 \\WObj:=wobj0);
    TPWrite \"axes \" + ValToStr(j.robax);
    TPWrite \"at \" + NumToStr(p.trans.x, 2) + \" \" + NumToStr(p.trans.y, 2) + \" \" + NumToStr(p.trans.z, 2);
  ENDPROC
ENDMODULE
";

#[test]
fn the_start_pose_comes_from_the_flag_else_the_manifest_else_calibration() {
    // IRB 120, axis 5 at 30°: the wrist centre stays at (302, 0, 630), the flange 72 mm
    // along the tilted tool axis: (302 + 72·cos 30°, 0, 630 − 72·sin 30°) =
    // (364.35, 0, 594). At calibration: (302 + 72, 0, 630) = (374, 0, 630).
    let dir = scratch("start");
    let manifest =
        "[system]\nstart_joints = [0, 0, 0, 0, 30, 0]\n\n[[task]]\nname = \"T_ROB1\"\nmodules = [\"m.mod\"]\n";
    write(&dir, &[("m.mod", WHERE), ("cell/rapid.toml", manifest), ("cell/m.mod", WHERE)]);
    let out = rapid_in(&dir, &["run", "--quiet", "m.mod"]);
    assert_eq!(text(&out.stdout), "axes [0,0,0,0,0,0]\nat 374.00 0.00 630.00\n", "{}", text(&out.stderr));
    let out = rapid_in(&dir, &["run", "--quiet", "cell"]);
    assert_eq!(text(&out.stdout), "axes [0,0,0,0,30,0]\nat 364.35 0.00 594.00\n", "{}", text(&out.stderr));
    // The flag stands above the manifest: axis 1 at 90° turns (374, 0, 630) onto y.
    let out = rapid_in(&dir, &["run", "--quiet", "--start-joints", "90,0,0,0,0,0", "cell"]);
    assert_eq!(text(&out.stdout), "axes [90,0,0,0,0,0]\nat 0.00 374.00 630.00\n", "{}", text(&out.stderr));

    // Outside the IRB 120's axis 5 range (±120°): refused before anything runs.
    let out = rapid_in(&dir, &["run", "--start-joints", "0,0,0,0,130,0", "m.mod"]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(text(&out.stdout), "");
    assert!(text(&out.stderr).contains("axis 5 of the robot at 130°"), "{}", text(&out.stderr));
    // Five values are no start pose.
    let out = rapid_in(&dir, &["run", "--start-joints", "0,0,0,0,30", "m.mod"]);
    assert_eq!(out.status.code(), Some(2));
    // Nor in the manifest: a finding at the value.
    let bad = manifest.replace("[0, 0, 0, 0, 30, 0]", "[0, 0, 30]");
    write(&dir, &[("cell/rapid.toml", &bad)]);
    let out = rapid_in(&dir, &["check", "cell"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(text(&out.stdout).contains("`start_joints` is six axis values"), "{}", text(&out.stdout));
    assert!(text(&out.stdout).contains("cell/rapid.toml:2:16"), "{}", text(&out.stdout));
}

#[test]
fn a_robot_type_we_have_no_model_of_stops_the_run_naming_it_and_the_override() {
    // A SCARA's backup: no IRB 120 is moved in its place. `check` has nothing against the
    // program (the type is no error of the backup's); `run` refuses before the program
    // starts, naming the type and --robot; with --robot the run goes on.
    let dir = scratch("unknown_type");
    let moc = "MOC:CFG_1.0:6:0::\n#\nROBOT:\n\n      -name \"ROB_1\" -use_robot_type \"ROB1_910SC_0.55_3\"\n";
    write(&dir, &[("cell/SYSPAR/MOC.cfg", moc), ("cell/RAPID/TASK1/PROGMOD/MainModule.mod", WHERE)]);
    let checked = rapid_in(&dir, &["check", "cell"]);
    assert_eq!(checked.status.code(), Some(0), "{}", text(&checked.stdout));
    // Exit status 2, as for an unknown `--robot`: the tool cannot run this system.
    let out = rapid_in(&dir, &["run", "cell"]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(text(&out.stdout), "");
    let stderr = text(&out.stderr);
    for part in ["robot type `ROB1_910SC_0.55_3`", "SCARA", "not supported yet", "--robot"] {
        assert!(stderr.contains(part), "`{part}` in {stderr}");
    }
    let out = rapid_in(&dir, &["run", "--quiet", "--robot", "IRB120", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "axes [0,0,0,0,0,0]\nat 374.00 0.00 630.00\n");
}

#[test]
fn robots_named_rob_l_and_rob_r_run_and_every_unit_is_mecunit_data() {
    // A two-arm system's naming (ROB_L, ROB_R), on two IRB 120 arms; MOC.cfg has also a
    // unit of mechanics we do not read (M7DM1). Each name is predefined mecunit data:
    // `check` finds nothing undefined. ROB_L is MOC.cfg's first robot, ROB_R its second;
    // each task's RobName is its robot's name. ROB_R stands 1 m along y.
    let dir = scratch("rob_l_r");
    let sys = "SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n      \
               -Name \"T_ROB_L\" -Type \"NORMAL\" -UseMechanicalUnitGroup \"rob_l\" -MotionTask\n\n      \
               -Name \"T_ROB_R\" -Type \"NORMAL\" -UseMechanicalUnitGroup \"rob_r\" -MotionTask\n#\n\
               MECHANICAL_UNIT_GROUP:\n\n      -Name \"rob_l\" -Robot \"ROB_L\" -MechanicalUnit_1 \"ROB_L\"\n\n      \
               -Name \"rob_r\" -Robot \"ROB_R\" -MechanicalUnit_1 \"ROB_R\"\n";
    let moc = "MOC:CFG_1.0:6:0::\n#\nMECHANICAL_UNIT:\n\n      -name \"M7DM1\" -use_single_0 \"M7DM1\"\n#\n\
               ROBOT:\n\n      -name \"ROB_L\" -use_robot_type \"ROB1_120_0.58_3\"\n\n      \
               -name \"ROB_R\" -use_robot_type \"ROB1_120_0.58_3\" -base_frame_pos_y 1\n";
    let program = |own: &str, wait: &str| {
        format!(
            "MODULE Main\n  PROC main()\n    VAR robtarget p;\n    WaitTime {wait};\n    \
             p := CRobT(\\Tool:=tool0 \\WObj:=wobj0);\n    \
             TPWrite RobName() + \" \" + NumToStr(p.trans.y, 1) \\Bool:=IsMechUnitActive({own});\n  ENDPROC\n  \
             PROC unused()\n    ActUnit M7DM1;\n    DeactUnit M7DM1;\n  ENDPROC\nENDMODULE\n"
        )
    };
    let (left, right) = (program("ROB_L", "0"), program("ROB_R", "0.1"));
    write(
        &dir,
        &[
            ("sys/SYSPAR/SYS.cfg", sys),
            ("sys/SYSPAR/MOC.cfg", moc),
            ("sys/RAPID/TASK1/PROGMOD/Main.mod", &left),
            ("sys/RAPID/TASK2/PROGMOD/Main.mod", &right),
        ],
    );
    let checked = rapid_in(&dir, &["check", "sys"]);
    assert_eq!(checked.status.code(), Some(0), "{}", text(&checked.stdout));
    let out = rapid_in(&dir, &["run", "--quiet", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "ROB_L 0.0TRUE\nROB_R 1000.0TRUE\n");
}

#[test]
fn a_palletizer_backup_moves_its_four_axes_with_the_flange_level() {
    // MOC.cfg's IRB 460 (ROB1_460_2.4_110). Hand-worked from its links (d1 = 745,
    // a1 = 260, l2 = 945, l3 = 1025, a4 = 225, d5 = 251.5; see rapid-motion's
    // palletizers.rs): at zero the flange is at (1510, 0, 1438.5), pointing down
    // ([0, 0, 1, 0]); a 300 mm gripper along tool0's z puts the TCP 300 mm lower, at
    // (1510, 0, 1138.5). At (30, 20, 30, 0, 0, −60): r = 260 + 945·sin 20° + 1025·cos 30°
    // + 225 = 260 + 323.205 + 887.676 + 225 = 1695.881, x = r·cos 30° = 1468.676,
    // y = r·sin 30° = 847.941, z = 745 + 945·cos 20° − 1025·sin 30° − 251.5 − 300 =
    // 745 + 888.011 − 512.5 − 551.5 = 569.011; cf6 = ⌊−60/90⌋ = −1. Tilting the gripper
    // is out of a palletizer's reach (50050). GetNextMechUnit counts four axes.
    let dir = scratch("palletizer");
    let moc = "MOC:CFG_1.0:6:0::\n#\nROBOT:\n\n      -name \"ROB_1\" -use_robot_type \"ROB1_460_2.4_110\"\n";
    let program = "MODULE MainModule
  PERS tooldata grip := [TRUE,[[0,0,300],[1,0,0,0]],[50,[0,0,150],[1,0,0,0],0,0,0]];
  PROC main()
    VAR robtarget p;
    VAR num n := 0;
    VAR string name;
    VAR num axes;
    p := CRobT(\\Tool:=grip \\WObj:=wobj0);
    TPWrite \"at \" + NumToStr(p.trans.x, 2) + \" \" + NumToStr(p.trans.y, 2) + \" \" + NumToStr(p.trans.z, 2)
      + \" \" + ValToStr(p.rot);
    MoveL Offs(p, 0, 0, -500), v1000, z50, grip;
    MoveAbsJ [[30,20,30,0,0,-60],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, grip;
    p := CRobT(\\Tool:=grip \\WObj:=wobj0);
    TPWrite \"at \" + NumToStr(p.trans.x, 2) + \" \" + NumToStr(p.trans.y, 2) + \" \" + NumToStr(p.trans.z, 2)
      + \" \" + ValToStr(p.robconf);
    MoveJ p, v1000, fine, grip;
    IF GetNextMechUnit(n, name \\NoOfAxes:=axes) TPWrite name + \" axes \" \\Num:=axes;
    MoveL RelTool(p, 0, 0, 0 \\Rx:=5), v100, fine, grip;
  ENDPROC
ENDMODULE
";
    write(&dir, &[("cell/SYSPAR/MOC.cfg", moc), ("cell/RAPID/TASK1/PROGMOD/MainModule.mod", program)]);
    let out = rapid_in(&dir, &["run", "cell"]);
    assert_eq!(
        text(&out.stdout),
        "at 1510.00 0.00 1138.50 [0,0,1,0]\nat 1468.68 847.94 569.01 [0,0,-1,0]\nROB_1 axes 4\n",
        "{}",
        text(&out.stderr)
    );
    assert_eq!(out.status.code(), Some(1));
    let stderr = text(&out.stderr);
    assert!(stderr.contains("50050") && stderr.contains("MainModule.mod:18:"), "{stderr}");
    assert!(stderr.contains("ROB_1 IRB 460-110/2.4"), "{stderr}");
}
