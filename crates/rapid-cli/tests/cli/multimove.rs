//! Synchronized movement of two robots (MultiMove: SyncMoveOn, SyncMoveOff, `\ID`),
//! run on small backups with two motion tasks. Expected outputs are worked out by hand
//! from the timing model in the comments.

use std::fs;
use std::path::{Path, PathBuf};

use crate::fixture::{rapid_in, scratch_in, system, text, Scratch, TaskDef};

/// A fresh, empty scratch folder for one test.
fn scratch(name: &str) -> Scratch {
    scratch_in("multimove", name)
}

#[test]
fn two_robots_move_synchronized_and_take_the_same_time() {
    let dir = scratch("multimove");
    // Two motion tasks meet at SyncMoveOn; then their moves with \ID:=10 start together
    // and take the time the slower needs. Worked by hand (IRB 120, path acceleration
    // 10 m/s²): T_ROB1's 100 mm at v100 takes 100/100 + 100/10000 = 1.01 s; T_ROB2's
    // 50 mm alone would take 0.51 s, but in synchronized movement it is given 1.01 s
    // too. Both stop at fine points (+0.05 s settle): ClkRead 1.06 in both tasks.
    // TasksInSync sees both; after SyncMoveOff neither moves synchronized.
    let body = |dy: u32| {
        format!(
            "MODULE M\n  VAR syncident sync1;\n  VAR syncident sync2;\n  PERS tasks all{{2}} := [[\"T_ROB1\"],[\"T_ROB2\"]];\n  \
             VAR tasks seen{{2}};\n  VAR clock c;\n  VAR robtarget here;\n  PROC main()\n    ConfL \\Off;\n    \
             MoveAbsJ [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;\n    SyncMoveOn sync1, all;\n    \
             TPWrite GetTaskName() + \" sync \" + ValToStr(IsSyncMoveOn()) + \" \" \\Num:=TasksInSync(seen);\n    \
             here := CRobT(\\Tool:=tool0);\n    ClkStart c;\n    \
             MoveL Offs(here, 0, {dy}, 0) \\ID:=10, v100, fine, tool0;\n    ClkStop c;\n    \
             TPWrite GetTaskName() + \" moved in \" \\Num:=ClkRead(c);\n    SyncMoveOff sync2;\n    \
             TPWrite GetTaskName() + \" after \" \\Bool:=IsSyncMoveOn();\n  ENDPROC\nENDMODULE\n"
        )
    };
    let (rob1, rob2) = (body(100), body(50));
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\" -MotionTask", module: &rob1 },
        TaskDef { name: "T_ROB2", attrs: "-Type \"NORMAL\" -MotionTask", module: &rob2 },
    ];
    system(&dir, &tasks, "");
    let out = rapid_in(&dir, &["run", "--quiet", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let mut lines: Vec<String> = text(&out.stdout).lines().map(str::to_owned).collect();
    lines.sort();
    assert_eq!(
        lines,
        [
            "T_ROB1 after FALSE",
            "T_ROB1 moved in 1.06",
            "T_ROB1 sync TRUE 2",
            "T_ROB2 after FALSE",
            "T_ROB2 moved in 1.06",
            "T_ROB2 sync TRUE 2",
        ]
    );
}

#[test]
fn synchronized_movement_errors_are_the_controllers() {
    let dir = scratch("multimove_errors");
    // T_ROB2 never comes to SyncMoveOn: T_ROB1's \TimeOut of 1 s ends in
    // ERR_SYNCMOVEON, which its handler takes (at 1 s of controller time).
    let rob1 = "MODULE M\n  VAR syncident sync1;\n  PERS tasks all{2} := [[\"T_ROB1\"],[\"T_ROB2\"]];\n  PROC main()\n    \
                SyncMoveOn sync1, all \\TimeOut:=1;\n  ERROR\n    IF ERRNO = ERR_SYNCMOVEON THEN\n      \
                TPWrite \"timed out at \" \\Num:=Round(ClkRead(clock1));\n      RETURN;\n    ENDIF\n  ENDPROC\nENDMODULE\n";
    let rob2 = "MODULE M\n  PROC main()\n    WaitTime 3;\n  ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef {
            name: "T_ROB1",
            attrs: "-Type \"NORMAL\" -MotionTask",
            module: &rob1.replace("PROC main()\n", "PROC main()\n    ClkStart clock1;\n"),
        },
        TaskDef { name: "T_ROB2", attrs: "-Type \"NORMAL\" -MotionTask", module: rob2 },
    ];
    system(&dir, &tasks, "");
    let out = rapid_in(&dir, &["run", "--quiet", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "timed out at 1\n");

    // In synchronized movement a move without \ID stops the task with a clear message.
    let dir = scratch("multimove_no_id");
    let body = "MODULE M\n  VAR syncident sync1;\n  PERS tasks all{2} := [[\"T_ROB1\"],[\"T_ROB2\"]];\n  PROC main()\n    \
                SyncMoveOn sync1, all;\n    MoveAbsJ [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;\n  \
                ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\" -MotionTask", module: body },
        TaskDef { name: "T_ROB2", attrs: "-Type \"NORMAL\" -MotionTask", module: body },
    ];
    system(&dir, &tasks, "");
    let out = rapid_in(&dir, &["run", "--quiet", "sys"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(text(&out.stderr).contains("needs \\ID"), "{}", text(&out.stderr));
}

#[test]
fn all_motion_tasks_stops_and_starts_every_robot() {
    let dir = scratch("all_motion_tasks");
    // T_ROB2 stops both robots 0.3 s into their moves (StopMove \AllMotionTasks) and
    // starts them 0.5 s later. Worked by hand: T_ROB1's 100 mm at v100 takes 1.01 s
    // + 0.05 settle = 1.06 s, now 0.5 s more: 1.56. T_ROB2's own 50 mm (\Conc) takes
    // 0.51 + 0.05 = 0.56 s, with the stop 1.06 when WaitRob returns.
    let prelude = "MODULE M\n  VAR clock c;\n  VAR robtarget here;\n  PROC main()\n    ConfL \\Off;\n    \
                   MoveAbsJ [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;\n    \
                   here := CRobT(\\Tool:=tool0);\n    ClkStart c;\n";
    let rob1 = format!(
        "{prelude}    MoveL Offs(here, 0, 100, 0), v100, fine, tool0;\n    \
         TPWrite \"T_ROB1 \" \\Num:=ClkRead(c);\n  ENDPROC\nENDMODULE\n"
    );
    let rob2 = format!(
        "{prelude}    MoveL \\Conc, Offs(here, 0, 50, 0), v100, fine, tool0;\n    WaitTime 0.3;\n    \
         StopMove \\AllMotionTasks;\n    WaitTime 0.5;\n    StartMove \\AllMotionTasks;\n    WaitRob \\InPos;\n    \
         TPWrite \"T_ROB2 \" \\Num:=ClkRead(c);\n  ENDPROC\nENDMODULE\n"
    );
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\" -MotionTask", module: &rob1 },
        TaskDef { name: "T_ROB2", attrs: "-Type \"NORMAL\" -MotionTask", module: &rob2 },
    ];
    system(&dir, &tasks, "");
    let out = rapid_in(&dir, &["run", "--quiet", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "T_ROB2 1.06\nT_ROB1 1.56\n");
}

#[test]
fn a_backups_positioner_task_moves_no_robot() {
    // SYS.cfg gives T_STN1 the mechanical unit group stn1, which MOC.cfg gives no robot:
    // a positioner's task. TaskRunRob is FALSE there (TRUE in T_ROB1), TaskRunMec TRUE
    // in both, and T_ROB1's robot is ROB_1.
    let dir = scratch("positioner_task");
    let body =
        "MODULE M\n  PROC main()\n    TPWrite GetTaskName() + \" \" + RobName() + \" \" + ValToStr(TaskRunRob()) \
                + \" \" + ValToStr(TaskRunMec());\n  ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef {
            name: "T_STN1",
            attrs: "-Type \"NORMAL\" -MotionTask -UseMechanicalUnitGroup \"stn1\"",
            module: body,
        },
        TaskDef {
            name: "T_ROB1",
            attrs: "-Type \"NORMAL\" -MotionTask -UseMechanicalUnitGroup \"rob1\"",
            module: body,
        },
    ];
    let root = system(&dir, &tasks, "");
    let moc = "MOC:CFG_1.0:6:0::\n#\nMECHANICAL_UNIT_GROUP:\n\n      -name \"rob1\" -robot \"ROB_1\"\n\n      \
               -name \"stn1\" -mech_unit_1 \"STN1\"\n";
    fs::write(root.join("SYSPAR/MOC.cfg"), moc).expect("MOC.cfg");
    let out = rapid_in(&dir, &["run", "--quiet", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let mut lines: Vec<String> = text(&out.stdout).lines().map(str::to_owned).collect();
    lines.sort();
    assert_eq!(lines, ["T_ROB1 ROB_1 TRUE TRUE", "T_STN1  FALSE TRUE"]);
}

#[test]
fn every_robot_of_a_multimove_system_gets_a_trace() {
    // `--trace t.csv` traces T_ROB1's robot in t.csv and T_ROB2's in t.T_ROB2.csv. The
    // right robot of examples/twin_robots starts with axis 5 at 90° (its TCP at the
    // wrist centre (302, 0, 630) less tool0's 72 mm down: (302, 0, 558)), lifts the part
    // 100 mm, carries it 100 mm along y and puts it down: it ends at (302, 100, 558).
    // The two robots' traces end together (synchronized movement).
    let dir = scratch("traces");
    let trace = dir.join("t.csv");
    let example = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/twin_robots");
    let out =
        rapid_in(&dir, &["run", "--quiet", "--trace", trace.to_str().expect("path"), example.to_str().expect("path")]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let last = |path: PathBuf| -> Vec<String> {
        let text = fs::read_to_string(&path).unwrap_or_else(|_| panic!("no trace {}", path.display()));
        text.lines().last().expect("rows").split(',').map(str::to_owned).collect()
    };
    let (left, right) = (last(trace.clone()), last(dir.join("t.T_ROB2.csv")));
    assert_eq!(left[0], right[0], "the traces end together");
    let at: Vec<f64> = right[7..10].iter().map(|f| f.parse().expect("number")).collect();
    assert!((at[0] - 302.0).abs() < 0.01 && (at[1] - 100.0).abs() < 0.01 && (at[2] - 558.0).abs() < 0.01, "{right:?}");
    assert!(right.last().is_some_and(|l| l.ends_with("right.mod:21")), "{right:?}");
}

#[test]
fn stop_all_move_tasks_stops_the_other_normal_tasks() {
    // T_ROB1 stops at 0.5 s; with \AllMoveTasks T_ROB2, which counts every 0.2 s, stops
    // with it (it printed 1 and 2, at 0.2 and 0.4 s); without it T_ROB2 counts to 5.
    for (switch, counted) in [(" \\AllMoveTasks", 2), ("", 5)] {
        let dir = scratch(&format!("stop_all{}", counted));
        let stopper = format!("MODULE M\n  PROC main()\n    WaitTime 0.5;\n    Stop{switch};\n  ENDPROC\nENDMODULE\n");
        let counter = "MODULE M\n  PROC main()\n    FOR i FROM 1 TO 5 DO\n      WaitTime 0.2;\n      \
                       TPWrite \"count \" \\Num:=i;\n    ENDFOR\n  ENDPROC\nENDMODULE\n";
        let tasks = [
            TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\" -MotionTask", module: &stopper },
            TaskDef { name: "T_ROB2", attrs: "-Type \"NORMAL\" -MotionTask", module: counter },
        ];
        system(&dir, &tasks, "");
        let out = rapid_in(&dir, &["run", "--quiet", "sys"]);
        let stdout = text(&out.stdout);
        let expected: String = (1..=counted).map(|i| format!("count {i}\n")).collect();
        assert_eq!(stdout, expected, "{}", text(&out.stderr));
    }
}

#[test]
fn store_path_leaves_synchronized_movement_unless_keep_sync() {
    // Both tasks move synchronized. T_ROB1 stores its path: on level 2 it moves on its
    // own (IsSyncMoveOn FALSE, a move without \ID), 50 mm up at v100 alone: 50/100 +
    // 100/10000 = 0.51 s, +0.05 s settling at the fine point = 0.56 s, and back (StartMove
    // needs the robot within 10 mm of its stopped path). RestoPath makes it
    // synchronized again, and both tasks' \ID:=20 moves meet. With StorePath \KeepSync
    // the task stays synchronized on level 2, where a move needs \ID.
    let rob1 = |store: &str| {
        format!(
            "MODULE M\n  VAR syncident sync1;\n  VAR syncident sync2;\n  PERS tasks all{{2}} := [[\"T_ROB1\"],[\"T_ROB2\"]];\n  \
             VAR clock c;\n  VAR robtarget here;\n  PROC main()\n    ConfL \\Off;\n    \
             MoveAbsJ [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;\n    SyncMoveOn sync1, all;\n    \
             here := CRobT(\\Tool:=tool0);\n    {store};\n    \
             TPWrite \"T_ROB1 level 2 \" + ValToStr(IsSyncMoveOn());\n    ClkStart c;\n    \
             MoveL Offs(here, 0, 0, 50), v100, fine, tool0;\n    ClkStop c;\n    \
             TPWrite \"T_ROB1 level 2 move \" \\Num:=ClkRead(c);\n    MoveL here, v100, fine, tool0;\n    \
             RestoPath;\n    \
             TPWrite \"T_ROB1 restored \" + ValToStr(IsSyncMoveOn());\n    StartMove;\n    \
             MoveL Offs(here, 0, 100, 0) \\ID:=20, v100, fine, tool0;\n    SyncMoveOff sync2;\n    \
             TPWrite \"T_ROB1 off\";\n  ENDPROC\nENDMODULE\n"
        )
    };
    let rob2 = "MODULE M\n  VAR syncident sync1;\n  VAR syncident sync2;\n  PERS tasks all{2} := [[\"T_ROB1\"],[\"T_ROB2\"]];\n  \
                VAR robtarget here;\n  PROC main()\n    ConfL \\Off;\n    \
                MoveAbsJ [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;\n    SyncMoveOn sync1, all;\n    \
                here := CRobT(\\Tool:=tool0);\n    MoveL Offs(here, 0, 50, 0) \\ID:=20, v100, fine, tool0;\n    \
                SyncMoveOff sync2;\n    TPWrite \"T_ROB2 off\";\n  ENDPROC\nENDMODULE\n";
    let run = |name: &str, store: &str| {
        let dir = scratch(name);
        let rob1 = rob1(store);
        let tasks = [
            TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\" -MotionTask", module: &rob1 },
            TaskDef { name: "T_ROB2", attrs: "-Type \"NORMAL\" -MotionTask", module: rob2 },
        ];
        system(&dir, &tasks, "");
        rapid_in(&dir, &["run", "--quiet", "--max-time", "60", "sys"])
    };
    let out = run("store_path_sync", "StorePath");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let mut lines: Vec<String> = text(&out.stdout).lines().map(str::to_owned).collect();
    lines.sort();
    assert_eq!(
        lines,
        ["T_ROB1 level 2 FALSE", "T_ROB1 level 2 move 0.56", "T_ROB1 off", "T_ROB1 restored TRUE", "T_ROB2 off"]
    );

    let out = run("store_path_keep_sync", "StorePath \\KeepSync");
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stdout));
    let rob1_lines: Vec<String> =
        text(&out.stdout).lines().filter(|l| l.starts_with("T_ROB1")).map(str::to_owned).collect();
    assert_eq!(rob1_lines, ["T_ROB1 level 2 TRUE"]);
    assert!(text(&out.stderr).contains("needs \\ID"), "{}", text(&out.stderr));
}

#[test]
fn synchronized_moves_of_robots_already_at_their_targets_are_no_error() {
    let dir = scratch("zero_length");
    // Both robots stand at the jointtarget their synchronized MoveAbsJ \ID:=10 asks
    // for: the common time is 0, which is no move time to give (a \T of 0 is invalid);
    // each move is the zero-length move it would be alone, and the program goes on
    // (abb-motion-program-exec's first MoveAbsJ of a MultiMove program does this).
    let body = "MODULE M\n  VAR syncident sync1;\n  VAR syncident sync2;\n  \
                PERS tasks all{2} := [[\"T_ROB1\"],[\"T_ROB2\"]];\n  \
                CONST jointtarget j := [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\n  PROC main()\n    \
                MoveAbsJ j, v1000, fine, tool0;\n    SyncMoveOn sync1, all;\n    \
                MoveAbsJ j \\ID:=10, v1000, fine, tool0;\n    SyncMoveOff sync2;\n    \
                TPWrite GetTaskName() + \" stood\";\n  ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\" -MotionTask", module: body },
        TaskDef { name: "T_ROB2", attrs: "-Type \"NORMAL\" -MotionTask", module: body },
    ];
    system(&dir, &tasks, "");
    let out = rapid_in(&dir, &["run", "--quiet", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let mut lines: Vec<String> = text(&out.stdout).lines().map(str::to_owned).collect();
    lines.sort();
    assert_eq!(lines, ["T_ROB1 stood", "T_ROB2 stood"]);
}

#[test]
fn a_synchronized_trigg_int_trap_runs_on_time_in_a_func() {
    let dir = scratch("multimove_trigg_func");
    // abb_motion_program_exec's MultiMove habit: the synchronized TriggL inside an
    // IF ... ELSE of a FUNC called from an assignment. §1.11: a trap runs at any time
    // during a move instruction, in a FUNC as anywhere, so TriggInt's trap (\Start,
    // 0.001 s) runs 0.001 s after each move starts, in both tasks, not when the
    // program goes on after the fine point. The moves are 100 mm at v100 for both
    // robots: 1.01 s to stand at the point, +0.05 s settle (multimove.rs's first
    // test): 1.06 s.
    let module = "MODULE M\n  VAR syncident sync1;\n  VAR syncident sync2;\n  \
                  PERS tasks all{2} := [[\"T_ROB1\"],[\"T_ROB2\"]];\n  VAR triggdata td;\n  VAR intnum ti;\n  \
                  VAR clock c;\n  VAR num at := -1;\n  VAR bool ok;\n  \
                  CONST robtarget p0 := [[300,-100,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];\n  \
                  PROC main()\n    ConfL \\Off;\n    MoveL p0, v500, fine, tool0;\n    CONNECT ti WITH on_trigg;\n    \
                  TriggInt td, 0.001 \\Start, ti;\n    SyncMoveOn sync1, all;\n    ClkStart c;\n    \
                  TriggL Offs(p0, 0, 100, 0) \\ID:=1, v100, td, fine, tool0;\n    \
                  TPWrite GetTaskName() + \" statement \" + NumToStr(at, 3) + \" \" + NumToStr(ClkRead(c), 2);\n    \
                  at := -1;\n    ClkReset c;\n    ClkStart c;\n    ok := go();\n    \
                  TPWrite GetTaskName() + \" func \" + NumToStr(at, 3) + \" \" + NumToStr(ClkRead(c), 2);\n    \
                  SyncMoveOff sync2;\n  ENDPROC\n  FUNC bool go()\n    IF IsSyncMoveOn() THEN\n      \
                  TriggL p0 \\ID:=2, v100, td, fine, tool0;\n    ELSE\n      TriggL p0, v100, td, fine, tool0;\n    \
                  ENDIF\n    RETURN TRUE;\n  ENDFUNC\n  TRAP on_trigg\n    at := ClkRead(c);\n  ENDTRAP\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\" -MotionTask", module },
        TaskDef { name: "T_ROB2", attrs: "-Type \"NORMAL\" -MotionTask", module },
    ];
    system(&dir, &tasks, "");
    let out = rapid_in(&dir, &["run", "--quiet", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let mut lines: Vec<String> = text(&out.stdout).lines().map(str::to_owned).collect();
    lines.sort();
    assert_eq!(
        lines,
        [
            "T_ROB1 func 0.001 1.06",
            "T_ROB1 statement 0.001 1.06",
            "T_ROB2 func 0.001 1.06",
            "T_ROB2 statement 0.001 1.06",
        ]
    );
}
