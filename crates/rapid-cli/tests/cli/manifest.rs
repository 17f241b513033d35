//! `rapid.toml` project manifests (docs/manifest.md): a manifest describes a system as
//! a backup does, so one task runs as a single program and several run as a system.
//! Every problem of a manifest is reported at its line and the system is not run.
//! Expected outputs are worked out by hand from the programs and the multitasking rules.

use std::fs;
use std::path::Path;

use crate::fixture::{rapid_in, scratch_in, text, write_files as write, Scratch};

/// A fresh, empty scratch folder for one test.
fn scratch(name: &str) -> Scratch {
    scratch_in("manifest", name)
}

/// Asserts that `report` has the finding `message` at `place` (`file:line:column`).
fn finding_at(report: &str, message: &str, place: &str) {
    let lines: Vec<&str> = report.lines().collect();
    let Some(at) = lines.iter().position(|l| l.starts_with("error[E0701]: ") && l.contains(message)) else {
        panic!("no finding `{message}` in:\n{report}");
    };
    let next = lines.get(at + 1).copied().unwrap_or("");
    assert!(next.trim_start().starts_with(&format!("--> {place}")), "`{message}` is not at {place}:\n{report}");
}

#[test]
fn a_one_task_manifest_runs_with_its_home() {
    let dir = scratch("one_task");
    write(
        &dir,
        &[
            ("proj/rapid.toml", "[[task]]\nname = \"T_ROB1\"\nmodules = [\"src\"]\n"),
            (
                "proj/src/Main.mod",
                "MODULE Main\n  PROC main()\n    VAR iodev f;\n    Open \"HOME:/note.txt\", f \\Write;\n    \
                 Write f, \"hello\";\n    Close f;\n    TPWrite \"written\";\n  ENDPROC\nENDMODULE\n",
            ),
        ],
    );
    let out = rapid_in(&dir, &["run", "proj"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "written\n");
    // HOME: is the HOME folder beside the manifest.
    assert_eq!(fs::read_to_string(dir.join("proj/HOME/note.txt")).expect("HOME file"), "hello\n");

    // `home` moves it; the manifest file itself is a PATH too.
    let toml = "[system]\nhome = \"data/HOME\"\n\n[[task]]\nname = \"T_ROB1\"\nmodules = [\"src/*.mod\"]\n";
    write(&dir, &[("proj/rapid.toml", toml)]);
    let out = rapid_in(&dir, &["run", "proj/rapid.toml"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(fs::read_to_string(dir.join("proj/data/HOME/note.txt")).expect("home file"), "hello\n");
}

/// Three tasks sharing the persistent `counter` and meeting twice. T_ROB1 sets it to
/// 10 before the first meeting; after it, T_A reads 10 and adds 1 at once, while T_B
/// first waits 0.5 s, so reads 11 and makes it 12; after the second meeting T_ROB1
/// reads 12. T_B has no `type`: SEMISTATIC, started with the system.
#[test]
fn a_three_task_manifest_shares_persistents_and_syncs() {
    let dir = scratch("three_tasks");
    let shared = "  PERS num counter := 0;\n  PERS tasks all{3} := [[\"T_ROB1\"], [\"T_A\"], [\"T_B\"]];\n  \
                  VAR syncident s1;\n  VAR syncident s2;\n";
    let rob = format!(
        "MODULE Rob\n{shared}  PROC main()\n    counter := 10;\n    WaitSyncTask s1, all;\n    \
         WaitSyncTask s2, all;\n    TPWrite \"rob: counter \" \\Num:=counter;\n  ENDPROC\nENDMODULE\n"
    );
    let a = format!(
        "MODULE TaskA\n{shared}  PROC a_main()\n    WaitSyncTask s1, all;\n    \
         TPWrite \"a: counter \" \\Num:=counter;\n    counter := counter + 1;\n    WaitSyncTask s2, all;\n  \
         ENDPROC\nENDMODULE\n"
    );
    let b = format!(
        "MODULE TaskB\n{shared}  PROC b_main()\n    WaitSyncTask s1, all;\n    WaitTime 0.5;\n    \
         TPWrite \"b: counter \" \\Num:=counter;\n    counter := counter + 1;\n    WaitSyncTask s2, all;\n  \
         ENDPROC\nENDMODULE\n"
    );
    let toml = "[system]\nname = \"three\"\n\n\
                [[task]]\nname = \"T_ROB1\"\nmodules = [\"rob/Rob.mod\"]\n\n\
                [[task]]\nname = \"T_A\"\ntype = \"NORMAL\"\nentry = \"a_main\"\nmodules = [\"a/*.mod\"]\n\n\
                [[task]]\nname = \"T_B\"\nentry = \"b_main\"\nmodules = [\"b\"]\n";
    write(&dir, &[("rapid.toml", toml), ("rob/Rob.mod", &rob), ("a/TaskA.mod", &a), ("b/TaskB.mod", &b)]);
    let out = rapid_in(&dir, &["run", "."]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "a: counter 10\nb: counter 11\nrob: counter 12\n");
}

#[test]
fn check_reports_the_module_errors_of_every_task() {
    let dir = scratch("check_tasks");
    let toml = "[[task]]\nname = \"T_ROB1\"\nmodules = [\"one/One.mod\"]\n\n\
                [[task]]\nname = \"T_TWO\"\nmodules = [\"two/Two.mod\"]\n";
    let one = "MODULE One\n  PROC main()\n    unknownOne := 1;\n  ENDPROC\nENDMODULE\n";
    let two = "MODULE Two\n  PROC main()\n    TPWrite \"x\";\n    unknownTwo := 2;\n  ENDPROC\nENDMODULE\n";
    write(&dir, &[("rapid.toml", toml), ("one/One.mod", one), ("two/Two.mod", two)]);
    let out = rapid_in(&dir, &["check", "rapid.toml"]);
    assert_eq!(out.status.code(), Some(1));
    let report = text(&out.stdout);
    assert!(report.contains("one/One.mod:3:5"), "{report}");
    assert!(report.contains("two/Two.mod:4:5"), "{report}");
    assert!(report.contains("unknownOne") && report.contains("unknownTwo"), "{report}");
}

/// One manifest with every kind of problem the reader finds together.
#[test]
fn manifest_problems_are_reported_at_their_lines() {
    let dir = scratch("problems");
    let toml = "\
[system]
robot = \"\"
io = \"missing.cfg\"
home = \"home\"

[[task]]
name = \"T_ROB1\"
type = \"FAST\"
modules = [\"src/Main.mod\", \"src/Gone.mod\", \"lib/*.sys\", \"src/notes.txt\"]
foreground = \"T_NOBODY\"
trust_level = \"Maybe\"
rmq = { type = \"Internal\", max_msg_size = 5000 }

[[task]]
name = \"t_rob1\"
modules = [\"empty\"]
";
    let main = "MODULE Main\n  PROC main()\n  ENDPROC\nENDMODULE\n";
    write(&dir, &[("rapid.toml", toml), ("src/Main.mod", main), ("src/notes.txt", "notes"), ("empty/x.txt", "")]);
    fs::create_dir_all(dir.join("lib")).expect("lib");
    let out = rapid_in(&dir, &["check", "rapid.toml"]);
    assert_eq!(out.status.code(), Some(1));
    let report = text(&out.stdout);
    finding_at(&report, "`robot` is empty", "rapid.toml:2:9");
    finding_at(&report, "the HOME: folder `home` must be named HOME", "rapid.toml:4:8");
    finding_at(&report, "no I/O configuration file `missing.cfg`", "rapid.toml:3:6");
    finding_at(&report, "task `T_ROB1`: unknown type `FAST` (NORMAL, STATIC or SEMISTATIC)", "rapid.toml:8:8");
    finding_at(&report, "no module file `src/Gone.mod`", "rapid.toml:9:28");
    finding_at(&report, "`lib/*.sys` matches no file", "rapid.toml:9:44");
    finding_at(&report, "`src/notes.txt` is not a RAPID module file", "rapid.toml:9:57");
    finding_at(&report, "task `T_ROB1` runs in the background of `T_NOBODY`, which is not a task", "rapid.toml:10:14");
    finding_at(&report, "unknown trust_level `Maybe`", "rapid.toml:11:15");
    finding_at(&report, "rmq max_msg_size 5000 is not a number from 1 to 3000", "rapid.toml:12:43");
    finding_at(&report, "task `t_rob1` is configured twice", "rapid.toml:15:8");
    finding_at(&report, "folder `empty` holds no RAPID module files", "rapid.toml:16:12");
    assert!(report.contains("found 12 errors"), "{report}");

    // The controller refuses to start.
    let out = rapid_in(&dir, &["run", "rapid.toml"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(text(&out.stdout).is_empty());
    let report = text(&out.stderr);
    finding_at(&report, "task `t_rob1` is configured twice", "rapid.toml:15:8");
    assert!(report.ends_with("the system has errors; it was not run\n"), "{report}");
}

#[test]
fn structural_problems_stop_the_reader_at_their_line() {
    let dir = scratch("structure");
    let module = "MODULE Main\n  PROC main()\n  ENDPROC\nENDMODULE\n";
    let cases = [
        ("[system]\nname = \"x\"\nspeed = 5\n", "unknown field `speed`", "rapid.toml:3:1"),
        (
            "[[task]]\nname = \"T_ROB1\"\nmodules = [\"Main.mod\"]\nmotion = \"yes\"\n",
            "invalid type",
            "rapid.toml:4:10",
        ),
        ("[[task]\nname = \"T_ROB1\"\n", "unclosed array table", "rapid.toml:1:8"),
        ("[system]\nname = \"x\"\n", "the manifest configures no task", "rapid.toml:1:1"),
    ];
    for (toml, message, place) in cases {
        write(&dir, &[("rapid.toml", toml), ("Main.mod", module)]);
        let out = rapid_in(&dir, &["check", "."]);
        assert_eq!(out.status.code(), Some(1), "{toml}");
        finding_at(&text(&out.stdout).replace("./rapid.toml", "rapid.toml"), message, place);
    }
}

#[test]
fn more_than_twenty_tasks_are_refused_at_the_twenty_first() {
    let dir = scratch("too_many");
    let mut toml = String::new();
    for n in 1..=21 {
        toml.push_str(&format!("[[task]]\nname = \"T{n}\"\nmodules = [\"Main.mod\"]\n\n"));
    }
    write(&dir, &[("rapid.toml", &toml), ("Main.mod", "MODULE Main\n  PROC main()\n  ENDPROC\nENDMODULE\n")]);
    let out = rapid_in(&dir, &["check", "rapid.toml"]);
    assert_eq!(out.status.code(), Some(1));
    // Four lines per task: the 21st starts at line 81.
    finding_at(&text(&out.stdout), "at most 20 tasks; 1 more are configured", "rapid.toml:81:1");
}

#[test]
fn a_manifest_with_an_io_file_takes_a_stimulus() {
    let dir = scratch("io");
    let toml = "[system]\nio = \"cell.cfg\"\n\n[[task]]\nname = \"T_ROB1\"\nmodules = [\"Main.mod\"]\n";
    let eio = "EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n\n      -Name \"diStart\" -SignalType \"DI\"\n\n      \
               -Name \"doLamp\" -SignalType \"DO\"\n";
    let module = "MODULE Main\n  PROC main()\n    WaitDI diStart, 1;\n    SetDO doLamp, 1;\n    \
                  TPWrite \"started\";\n  ENDPROC\nENDMODULE\n";
    write(
        &dir,
        &[("rapid.toml", toml), ("cell.cfg", eio), ("Main.mod", module), ("go.stim", "at 1.5 s set diStart 1\n")],
    );
    let out = rapid_in(&dir, &["run", "--stimulus", "go.stim", "--io-log", "io.csv", "rapid.toml"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "started\n");
    let log = fs::read_to_string(dir.join("io.csv")).expect("io log");
    assert!(log.contains("1.5,diStart,0,1,"), "{log}");
    assert!(log.contains("1.5,doLamp,0,1,Order"), "{log}");

    // A bad line of the I/O file is reported in that file; the system is not run.
    let bad = format!("{eio}\n      -Name \"aiOdd\" -SignalType \"XI\"\n");
    write(&dir, &[("cell.cfg", &bad)]);
    let out = rapid_in(&dir, &["run", "--stimulus", "go.stim", "rapid.toml"]);
    assert_eq!(out.status.code(), Some(1));
    let report = text(&out.stderr);
    assert!(report.contains("--> cell.cfg:9:33"), "{report}");
    assert!(report.ends_with("the system has errors; it was not run\n"), "{report}");
}

fn copy_dir(from: &Path, to: &Path) {
    fs::create_dir_all(to).expect("folder");
    for entry in fs::read_dir(from).expect("read folder") {
        let entry = entry.expect("entry");
        let target = to.join(entry.file_name());
        if entry.path().is_dir() {
            copy_dir(&entry.path(), &target);
        } else {
            fs::copy(entry.path(), &target).expect("copy");
        }
    }
}

/// examples/press_cell_project is examples/press_cell written as a manifest: both
/// give the same run, line for line, and the same signal log.
#[test]
fn the_press_cell_project_runs_like_the_backup() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let dir = scratch("press_cell");
    copy_dir(&root.join("examples/press_cell"), &dir.join("backup"));
    copy_dir(&root.join("examples/press_cell_project"), &dir.join("project"));
    fs::copy(root.join("examples/press_cell.stimulus"), dir.join("cell.stim")).expect("stimulus");
    let backup = rapid_in(&dir, &["run", "--stimulus", "cell.stim", "--io-log", "backup.csv", "backup"]);
    let project = rapid_in(&dir, &["run", "--stimulus", "cell.stim", "--io-log", "project.csv", "project"]);
    assert_eq!(backup.status.code(), Some(0), "{}", text(&backup.stderr));
    assert_eq!(project.status.code(), Some(0), "{}", text(&project.stderr));
    assert_eq!(text(&project.stdout), text(&backup.stdout));
    assert!(text(&project.stdout).ends_with("press: 3 parts pressed\n"));
    let read = |name: &str| fs::read_to_string(dir.join(name)).expect("io log");
    assert_eq!(read("project.csv"), read("backup.csv"));
    let check = rapid_in(&dir, &["check", "project"]);
    assert_eq!(check.status.code(), Some(0), "{}", text(&check.stdout));
}

#[test]
fn shared_modules_of_a_manifest_are_one_module_for_every_task() {
    let dir = scratch("shared_modules");
    // lib/shared.sys is installed shared: `counter` is one variable both tasks change,
    // `mine` (TASK VAR) one per task. T_ROB1 bumps at 0, T_B at 0.1; both print at 0.2+.
    let shared = "MODULE shared(SYSMODULE)\n  VAR num counter := 0;\n  TASK VAR num mine := 0;\n  PROC bump()\n    \
                  counter := counter + 1;\n    mine := mine + 1;\n  ENDPROC\nENDMODULE\n";
    let rob =
        "MODULE R\n  PROC main()\n    bump;\n    WaitTime 0.2;\n    TPWrite \"rob counter \" \\Num:=counter;\n    \
               TPWrite \"rob mine \" \\Num:=mine;\n  ENDPROC\nENDMODULE\n";
    let b = "MODULE B\n  PROC main()\n    WaitTime 0.1;\n    bump;\n    WaitTime 0.2;\n    \
             TPWrite \"b counter \" \\Num:=counter;\n    TPWrite \"b mine \" \\Num:=mine;\n  ENDPROC\nENDMODULE\n";
    let toml = "[system]\nshared = [\"lib/shared.sys\"]\n\n[[task]]\nname = \"T_ROB1\"\nmodules = [\"rob\"]\n\n\
                [[task]]\nname = \"T_B\"\ntype = \"NORMAL\"\nmodules = [\"b\"]\n";
    write(
        &dir,
        &[("proj/rapid.toml", toml), ("proj/lib/shared.sys", shared), ("proj/rob/R.mod", rob), ("proj/b/B.mod", b)],
    );
    let out = rapid_in(&dir, &["run", "proj"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "rob counter 2\nrob mine 1\nb counter 2\nb mine 1\n");
    // `rapid check` sees the shared module in every task.
    let out = rapid_in(&dir, &["check", "proj"]);
    assert_eq!(out.status.code(), Some(0), "{}{}", text(&out.stdout), text(&out.stderr));

    // A shared module that does not exist is a finding at its place in the manifest.
    let toml = toml.replace("lib/shared.sys", "lib/gone.sys");
    write(&dir, &[("proj/rapid.toml", &toml)]);
    let out = rapid_in(&dir, &["run", "proj"]);
    assert_eq!(out.status.code(), Some(1));
    finding_at(&text(&out.stderr), "no module file", "proj/rapid.toml:2:11");
}

#[test]
fn a_motion_tasks_base_places_its_robot_in_the_world() {
    // The robot stands 500 mm up, turned 90° about z (its x axis the world's y): the
    // world target [0, 300, 900] pointing down in its base frame is [300, 0, 400] there,
    // reached at [0, 0.5818, 28.9565, 0, 60.4616, 0] (tests/hand/, as the backup test).
    // A base on a task that moves no robot is a finding.
    let dir = scratch("robot_base");
    let manifest = "[[task]]\nname = \"T_ROB1\"\nmodules = [\"main.mod\"]\nbase = [0, 0, 500]\n\
                    orientation = [0.70710678, 0, 0, 0.70710678]\n";
    let program = "MODULE main
  VAR jointtarget jt;
  PROC main()
    MoveJ [[0,300,900],[0,-0.70710678,0.70710678,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;
    jt := CJointT();
    TPWrite \"axes \" + NumToStr(jt.robax.rax_2, 3) + \" \" + NumToStr(jt.robax.rax_3, 3);
  ENDPROC
ENDMODULE
";
    write(&dir, &[("cell/rapid.toml", manifest), ("cell/main.mod", program)]);
    let out = rapid_in(&dir, &["run", "--quiet", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "axes 0.582 28.957\n");
    let bad = format!("{manifest}\n[[task]]\nname = \"T_PLC\"\nmodules = [\"main.mod\"]\nbase = [0, 0, 1]\n");
    write(&dir, &[("bad/rapid.toml", &bad), ("bad/main.mod", program)]);
    let out = rapid_in(&dir, &["check", "bad"]);
    let report = format!("{}{}", text(&out.stdout), text(&out.stderr));
    finding_at(&report, "task `T_PLC`: base and orientation place a motion task's robot", "bad/rapid.toml:10:8");
}

#[test]
fn a_tasks_robot_is_a_known_model_or_none_and_only_a_motion_tasks() {
    // `robot = false` makes a positioner's task (tests/coordinated.rs); a model must be
    // one we know, and a task that is no motion task has no robot to name.
    let dir = scratch("task_robot");
    let manifest = "[[task]]\nname = \"T_ROB1\"\nmodules = [\"main.mod\"]\nrobot = \"IRB 9999\"\n\n\
                    [[task]]\nname = \"T_PLC\"\nmodules = [\"main.mod\"]\nrobot = false\n\n\
                    [[task]]\nname = \"T_ROB2\"\nmotion = true\nmodules = [\"main.mod\"]\nrobot = 5\n";
    let program = "MODULE main\n  PROC main()\n  ENDPROC\nENDMODULE\n";
    write(&dir, &[("bad/rapid.toml", manifest), ("bad/main.mod", program)]);
    let out = rapid_in(&dir, &["check", "bad"]);
    let report = format!("{}{}", text(&out.stdout), text(&out.stderr));
    finding_at(&report, "task `T_ROB1`: unknown robot model `IRB 9999` (known: IRB 120-3/0.58", "bad/rapid.toml:4:9");
    finding_at(&report, "task `T_PLC`: robot is a motion task's (motion = true)", "bad/rapid.toml:9:9");
    finding_at(&report, "task `T_ROB2`: robot is a robot model's name, or false", "bad/rapid.toml:15:9");
}

#[test]
fn each_motion_task_moves_the_robot_model_it_names() {
    // T_ROB2 names its own model: at the calibration position (all axes 0) its TCP is
    // the IRB 2600-12/1.65's (a1 + c3 + c4, 0, c1 + c2 - a2) = (1030, 0, 1260); T_ROB1
    // keeps the system's IRB 120 at (374, 0, 630).
    let dir = scratch("task_models");
    let manifest = "[[task]]\nname = \"T_ROB1\"\nmodules = [\"main.mod\"]\n\n\
                    [[task]]\nname = \"T_ROB2\"\ntype = \"NORMAL\"\nmotion = true\nrobot = \"IRB 2600-12/1.65\"\n\
                    modules = [\"main.mod\"]\n";
    let program =
        "MODULE main\n  PROC main()\n    TPWrite GetTaskName() + \" \" + RobName() \\Pos:=CPos(\\Tool:=tool0);\n  \
                   ENDPROC\nENDMODULE\n";
    write(&dir, &[("cell/rapid.toml", manifest), ("cell/main.mod", program)]);
    let out = rapid_in(&dir, &["run", "--quiet", "cell"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let mut lines: Vec<String> = text(&out.stdout).lines().map(str::to_owned).collect();
    lines.sort();
    assert_eq!(lines, ["T_ROB1 ROB_1[374,0,630]", "T_ROB2 ROB_2[1030,0,1260]"]);
}

#[test]
fn a_task_using_a_motion_tasks_unit_group_reads_its_robot() {
    // T_ROB1 moves axis 1 to 10°, axis 5 to 40°. T_MON is no motion task; with
    // `mechanical_unit_group = "rob1"` (SYS.cfg's -UseMechanicalUnitGroup; rob1 is the
    // first motion task's) its CJointT, CRobT and CPos read T_ROB1's robot, as a
    // ROS-style state server does; so does T_OFF without a group, the system having one
    // motion task (`a_task_without_a_unit_group_reads_the_only_robot`). tool0
    // there: the wrist centre (302, 0, 630) at zero, the flange 72 mm on along the tool's
    // z axis, tilted 40° down by axis 5: x = 302 + 72·cos 40° = 357.155, z = 630 −
    // 72·sin 40° = 583.719; axis 1 turns it 10°: (351.729, 62.019, 583.719).
    let dir = scratch("unit_group");
    let rob = "MODULE Rob\n  PERS bool moved := FALSE;\n  PROC main()\n    \
               MoveAbsJ [[10,0,0,0,40,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;\n    moved := TRUE;\n    \
               WaitTime 1;\n  ENDPROC\nENDMODULE\n";
    let mon = |who: &str| {
        format!(
            "MODULE Mon\n  PERS bool moved := FALSE;\n  PROC mon_main()\n    VAR jointtarget jt;\n    \
             VAR robtarget rt;\n    WaitUntil moved;\n    jt := CJointT();\n    \
             TPWrite \"{who} axis 1 \" \\Num:=jt.robax.rax_1;\n    \
             IF \"{who}\" = \"mon\" THEN\n      TPWrite \"mon at \" \\Pos:=CPos(\\Tool:=tool0);\n      \
             rt := CRobT(\\Tool:=tool0);\n      TPWrite \"mon robtarget at \" \\Pos:=rt.trans;\n    ENDIF\n  \
             ENDPROC\nENDMODULE\n"
        )
    };
    let (on, off) = (mon("mon"), mon("off").replace("Mon", "Off"));
    let toml = "[[task]]\nname = \"T_ROB1\"\nmodules = [\"Rob.mod\"]\n\n\
                [[task]]\nname = \"T_MON\"\ntype = \"NORMAL\"\nentry = \"mon_main\"\nmechanical_unit_group = \"rob1\"\n\
                modules = [\"mon/Mon.mod\"]\n\n\
                [[task]]\nname = \"T_OFF\"\ntype = \"NORMAL\"\nentry = \"mon_main\"\nmodules = [\"off/Off.mod\"]\n";
    write(&dir, &[("rapid.toml", toml), ("Rob.mod", rob), ("mon/Mon.mod", &on), ("off/Off.mod", &off)]);
    let out = rapid_in(&dir, &["run", "--quiet", "."]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let mut lines: Vec<String> = text(&out.stdout).lines().map(str::to_owned).collect();
    lines.sort();
    assert_eq!(
        lines,
        [
            "mon at [351.729,62.0193,583.719]",
            "mon axis 1 10",
            "mon robtarget at [351.729,62.0193,583.719]",
            "off axis 1 10"
        ]
    );
}

#[test]
fn a_persistent_declared_without_a_value_takes_the_value_another_task_gives() {
    // §1.2.2: a persistent may omit its initial value and then takes the value it has
    // (the other declarations'). T_LOG comes first and declares ip and port without
    // values; T_ROB1 gives them: both tasks see "127.0.0.1" and 5003, whatever the order.
    let dir = scratch("pers_no_value");
    let rob = "MODULE Rob\n  PERS string ip := \"127.0.0.1\";\n  PERS num port := 5003;\n  PROC main()\n    \
               WaitTime 0.1;\n    TPWrite \"rob \" + ip + \" \" \\Num:=port;\n  ENDPROC\nENDMODULE\n";
    let log = "MODULE Log\n  PERS string ip;\n  PERS num port;\n  PROC log_main()\n    \
               TPWrite \"log \" + ip + \" \" \\Num:=port;\n  ENDPROC\nENDMODULE\n";
    let toml = "[[task]]\nname = \"T_LOG\"\ntype = \"NORMAL\"\nentry = \"log_main\"\nmotion = false\nmodules = [\"Log.mod\"]\n\n\
                [[task]]\nname = \"T_ROB1\"\ntype = \"NORMAL\"\nmotion = true\nmodules = [\"Rob.mod\"]\n";
    write(&dir, &[("rapid.toml", toml), ("Rob.mod", rob), ("Log.mod", log)]);
    let out = rapid_in(&dir, &["run", "--quiet", "."]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "log 127.0.0.1 5003\nrob 127.0.0.1 5003\n");
}

#[test]
fn tasks_in_each_others_background_are_refused() {
    // T_A waits for T_B to be idle and T_B for T_A: neither could ever run.
    let dir = scratch("foreground_cycle");
    let module = "MODULE M\n  PROC main()\n    TPWrite \"ran\";\n  ENDPROC\nENDMODULE\n";
    let toml = "[[task]]\nname = \"T_A\"\ntype = \"NORMAL\"\nforeground = \"T_B\"\nmodules = [\"a/M.mod\"]\n\n\
                [[task]]\nname = \"T_B\"\ntype = \"NORMAL\"\nforeground = \"T_A\"\nmodules = [\"b/M.mod\"]\n";
    write(&dir, &[("rapid.toml", toml), ("a/M.mod", module), ("b/M.mod", module)]);
    let out = rapid_in(&dir, &["run", "rapid.toml"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stdout));
    let report = text(&out.stderr);
    finding_at(
        &report,
        "task `T_A` runs in the background of `T_B`, which runs (through its foreground tasks) in the background of `T_A`",
        "rapid.toml:4:14",
    );
}

#[test]
fn max_time_bounds_a_system_whose_task_never_waits() {
    // T_BUSY loops without ever waiting; the clock moves by the nominal instruction time
    // as it computes, so --max-time 0.5 ends the run (it never ended before).
    let dir = scratch("max_time_busy");
    let busy = "MODULE Busy\n  PROC main()\n    VAR num n := 0;\n    WHILE TRUE DO\n      n := n + 1;\n    \
                ENDWHILE\n  ENDPROC\nENDMODULE\n";
    let other =
        "MODULE Other\n  PROC other_main()\n    WaitTime 0.1;\n    TPWrite \"other waited\";\n  ENDPROC\nENDMODULE\n";
    let toml = "[[task]]\nname = \"T_BUSY\"\ntype = \"NORMAL\"\nmodules = [\"Busy.mod\"]\n\n\
                [[task]]\nname = \"T_OTHER\"\ntype = \"NORMAL\"\nentry = \"other_main\"\nmodules = [\"o/Other.mod\"]\n";
    write(&dir, &[("rapid.toml", toml), ("Busy.mod", busy), ("o/Other.mod", other)]);
    // --max-steps only keeps a broken bound from hanging the test.
    let out = rapid_in(&dir, &["run", "--quiet", "--max-time", "0.5", "--max-steps", "5000000", "rapid.toml"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stdout));
    assert_eq!(text(&out.stdout), "other waited\n");
    assert!(text(&out.stderr).contains("stopped at 0.5 s of controller time (--max-time)"), "{}", text(&out.stderr));
}

#[test]
fn each_normal_task_of_a_system_runs_its_cycles() {
    let dir = scratch("cycles_system");
    // `--cycles 3`: every NORMAL task starts main again when it ends (continuous mode,
    // data kept). T_A's cycles take 0.3 s, T_B's 0.5 s (the second ended by ExitCycle,
    // which ends a cycle like the end of main); T_C's EXIT in its second cycle, at
    // 0.4 s, ends T_C for good (a restart is not allowed). Prints: T_A at 0, 0.3, 0.6;
    // T_B at 0, 0.5, 1.0; T_C at 0 and 0.2.
    let cycle = |task: &str, wait: &str, end: &str| {
        format!(
            "MODULE M\n  VAR num n := 0;\n  PROC main()\n    n := n + 1;\n    TPWrite \"{task} \" \\Num:=n;\n    \
             WaitTime {wait};\n    IF n = 2 {end};\n  ENDPROC\nENDMODULE\n"
        )
    };
    let (a, b, c) = (cycle("a", "0.3", "n := n"), cycle("b", "0.5", "ExitCycle"), cycle("c", "0.2", "EXIT"));
    let toml = "[[task]]\nname = \"T_A\"\ntype = \"NORMAL\"\nmodules = [\"a/M.mod\"]\n\n\
                [[task]]\nname = \"T_B\"\ntype = \"NORMAL\"\nmodules = [\"b/M.mod\"]\n\n\
                [[task]]\nname = \"T_C\"\ntype = \"NORMAL\"\nmodules = [\"c/M.mod\"]\n";
    write(&dir, &[("rapid.toml", toml), ("a/M.mod", &a), ("b/M.mod", &b), ("c/M.mod", &c)]);
    let out = rapid_in(&dir, &["run", "--quiet", "--cycles", "3", "rapid.toml"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "a 1\nb 1\nc 1\nc 2\na 2\nb 2\na 3\nb 3\n");
}

#[test]
fn exit_cycle_in_cycle_mode_ends_the_run_and_says_how_to_run_on() {
    let dir = scratch("exit_cycle_note");
    // T_A ends its cycle with ExitCycle at 0.5 s; in cycle mode that ends its run, and
    // with it the system's (T_B is static: it runs while a NORMAL task does).
    let a = "MODULE M\n  PROC main()\n    WaitTime 0.5;\n    TPWrite \"a\";\n    ExitCycle;\n  ENDPROC\nENDMODULE\n";
    let b = "MODULE N\n  PROC main()\n    WaitTime 0.2;\n    TPWrite \"b\";\n  ENDPROC\nENDMODULE\n";
    let toml = "[[task]]\nname = \"T_A\"\ntype = \"NORMAL\"\nmodules = [\"a/M.mod\"]\n\n\
                [[task]]\nname = \"T_B\"\ntype = \"STATIC\"\nmodules = [\"b/N.mod\"]\n";
    write(&dir, &[("rapid.toml", toml), ("a/M.mod", a), ("b/N.mod", b)]);
    let out = rapid_in(&dir, &["run", "--quiet", "rapid.toml"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "b\nb\na\n");
    let stderr = text(&out.stderr);
    assert!(stderr.contains("note: ExitCycle ended the cycle of T_A; in cycle mode"), "{stderr}");
    assert!(stderr.contains("`--cycles 0` runs continuously"), "{stderr}");
}

#[test]
fn another_tasks_robot_is_read_with_its_own_model() {
    let dir = scratch("other_model");
    // T_ROB2's robot is an IRB 2400-10/1.55 at its calibration position: tool0 at
    // x = a1 + c3 + c4 = 100 + 755 + 85 = 940, z = c1 + c2 - a2 = 615 + 705 + 135 = 1455
    // (its OPW lengths). T_ROB1, an IRB 120, reads it so (not 374/630, its own robot's).
    let rob1 = "MODULE R1\n  PROC main()\n    VAR robtarget p;\n    WaitTime 0.1;\n    \
                p := CRobT(\\TaskName:=\"T_ROB2\" \\Tool:=tool0 \\WObj:=wobj0);\n    \
                TPWrite \"x \" \\Num:=p.trans.x;\n    TPWrite \"z \" \\Num:=p.trans.z;\n  ENDPROC\nENDMODULE\n";
    let rob2 = "MODULE R2\n  PROC main()\n    WaitTime 0.2;\n  ENDPROC\nENDMODULE\n";
    let toml = "[[task]]\nname = \"T_ROB1\"\ntype = \"NORMAL\"\nmotion = true\nmodules = [\"r1/R1.mod\"]\n\n\
                [[task]]\nname = \"T_ROB2\"\ntype = \"NORMAL\"\nmotion = true\nrobot = \"IRB 2400-10/1.55\"\n\
                modules = [\"r2/R2.mod\"]\n";
    write(&dir, &[("rapid.toml", toml), ("r1/R1.mod", rob1), ("r2/R2.mod", rob2)]);
    let out = rapid_in(&dir, &["run", "--quiet", "rapid.toml"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "x 940\nz 1455\n");
}

#[test]
fn a_task_without_a_unit_group_reads_the_only_robot() {
    let dir = scratch("only_robot");
    // One motion task (no MultiMove): MON, no motion task and no unit group, reads its
    // robot as open_abb's LOGGER does. Axis 5 at 30°: tool0 at (302 + 72 cos 30°, 0,
    // 630 - 72 sin 30°) = (364.354, 0, 594).
    let rob =
        "MODULE Rob\n  PROC main()\n    MoveAbsJ [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;\n    \
               WaitTime 1;\n  ENDPROC\nENDMODULE\n";
    let mon = "MODULE Mon\n  PROC main()\n    VAR jointtarget j;\n    VAR robtarget p;\n    WaitTime 0.8;\n    \
               j := CJointT();\n    p := CRobT(\\Tool:=tool0 \\WObj:=wobj0);\n    \
               TPWrite \"axis 5 \" \\Num:=j.robax.rax_5;\n    \
               TPWrite \"tcp \" + NumToStr(p.trans.x, 1) + \" \" + NumToStr(p.trans.z, 1);\n  ENDPROC\nENDMODULE\n";
    let toml = "[[task]]\nname = \"T_ROB1\"\nmodules = [\"r/Rob.mod\"]\n\n\
                [[task]]\nname = \"MON\"\ntype = \"NORMAL\"\nmodules = [\"m/Mon.mod\"]\n";
    write(&dir, &[("rapid.toml", toml), ("r/Rob.mod", rob), ("m/Mon.mod", mon)]);
    let out = rapid_in(&dir, &["run", "--quiet", "rapid.toml"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "axis 5 30\ntcp 364.4 594.0\n");
    // With a second robot (MultiMove) the group must be named: without it MON reads no
    // robot, CJointT 9E9, and its CRobT stops the task, saying why.
    let two = toml.replace(
        "[[task]]\nname = \"MON\"",
        "[[task]]\nname = \"T_ROB2\"\nmotion = true\nmodules = [\"r2/Rob.mod\"]\n\n[[task]]\nname = \"MON\"",
    );
    write(&dir, &[("rapid.toml", &two), ("r2/Rob.mod", rob)]);
    let out = rapid_in(&dir, &["run", "--quiet", "rapid.toml"]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(text(&out.stdout), "");
    let stderr = text(&out.stderr);
    assert!(
        stderr.contains("CRobT: the task is no motion task and uses no motion task's mechanical unit group"),
        "{stderr}"
    );
}

/// A folder's `rapid.toml` with only the formatter's `[fmt]` table (docs/fmt.md) is
/// not a manifest: the folder is checked and run as a folder of modules. An explicit
/// `.toml` PATH is still read as a manifest, and one without tasks is still refused.
#[test]
fn a_rapid_toml_with_only_fmt_settings_leaves_the_folder_a_folder() {
    let dir = scratch("fmt_only");
    write(
        &dir,
        &[
            ("proj/rapid.toml", "[fmt]\nindent_width = 4\n"),
            ("proj/Main.mod", "MODULE Main\n  PROC main()\n    TPWrite \"from the folder\";\n  ENDPROC\nENDMODULE\n"),
        ],
    );
    let check = rapid_in(&dir, &["check", "proj"]);
    assert!(check.status.success(), "check failed:\n{}", text(&check.stderr));
    let run = rapid_in(&dir, &["run", "proj"]);
    assert!(run.status.success(), "run failed:\n{}", text(&run.stderr));
    assert_eq!(text(&run.stdout), "from the folder\n");
    let explicit = rapid_in(&dir, &["check", "proj/rapid.toml"]);
    assert!(!explicit.status.success());
    assert!(text(&explicit.stdout).contains("the manifest configures no task"), "{}", text(&explicit.stdout));
}

/// `[system] controller_ip` is the controller's own address, as `--controller-ip` gives
/// it: a TCP server the program binds to it listens on the loopback, where a client
/// reaches it. 192.0.2.44 (TEST-NET-1) is no address of the host, so without the mapping
/// the bind fails; `--controller-ip` given too wins, and the manifest's address is then
/// no controller's.
#[test]
fn the_manifests_controller_ip_binds_the_loopback() {
    use crate::sockets_controller_ip::{echo_server, free_port, greet_on_the_loopback};

    let port = free_port();
    let dir = scratch("controller_ip");
    let toml = "[system]\ncontroller_ip = \"192.0.2.44\"\n\n[[task]]\nname = \"T_ROB1\"\nmodules = [\"srv.mod\"]\n";
    write(&dir, &[("rapid.toml", toml), ("srv.mod", &echo_server("192.0.2.44", port))]);
    greet_on_the_loopback(crate::fixture::spawn_in(&dir, &["run", "rapid.toml"]), port, "192.0.2.44");

    // The flag wins: with another controller address the manifest's is the OS's to
    // bind, which has no such address, and the program stops with a socket error.
    let out = rapid_in(&dir, &["run", "--controller-ip", "10.11.12.13", "rapid.toml"]);
    assert_ne!(out.status.code(), Some(0), "{}", text(&out.stdout));
    assert!(!text(&out.stderr).contains("note: SocketBind"), "{}", text(&out.stderr));
}

#[test]
fn a_malformed_controller_ip_is_a_finding_at_its_line() {
    let dir = scratch("controller_ip_bad");
    let toml = "[system]\nname = \"cell\"\ncontroller_ip = \"192.168.125\"\n\n[[task]]\nname = \"T_ROB1\"\nmodules = [\"Main.mod\"]\n";
    write(&dir, &[("rapid.toml", toml), ("Main.mod", "MODULE Main\n  PROC main()\n  ENDPROC\nENDMODULE\n")]);
    let out = rapid_in(&dir, &["check", "rapid.toml"]);
    assert_eq!(out.status.code(), Some(1));
    let report = text(&out.stdout);
    finding_at(&report, "`controller_ip` `192.168.125` is not an IPv4 address", "rapid.toml:3:17");
    assert!(report.contains("found 1 error"), "{report}");
}
