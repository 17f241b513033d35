//! The controller state `rapid run` starts with (`--mode`, `--speed-override`) and
//! the controller-level built-ins in systems of several tasks: every task sees the
//! one mode and override, GetTSPStatus and MotionPlannerNo follow the task
//! configuration, and WarmStart in one task ends the whole run.

use std::fs;
use std::process::Output;

use crate::fixture::{rapid_in, scratch_in, system_of, text, Scratch};

/// A fresh, empty scratch folder for one test.
fn scratch(name: &str) -> Scratch {
    scratch_in("controller_state", name)
}

/// A program that prints the mode and the override.
const SHOW: &str = "MODULE show\n  PROC main()\n    TPWrite \"mode \" \\Num:=OpMode();\n    \
                    TPWrite \"override \" \\Num:=CSpeedOverride();\n  ENDPROC\nENDMODULE\n";

/// Runs SHOW with `options` in a fresh folder.
fn show(name: &str, options: &[&str]) -> Output {
    let dir = scratch(name);
    fs::write(dir.join("show.mod"), SHOW).expect("module");
    let mut args = vec!["run"];
    args.extend_from_slice(options);
    args.push("show.mod");
    rapid_in(&dir, &args)
}

#[test]
fn the_run_starts_in_automatic_mode_at_full_override() {
    let out = show("defaults", &[]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    // OP_AUTO is 1 (catalogue symnum).
    assert_eq!(text(&out.stdout), "mode 1\noverride 100\n");
}

#[test]
fn each_mode_key_position_is_what_op_mode_answers() {
    // OP_AUTO 1, OP_MAN_PROG 2 (manual reduced speed), OP_MAN_TEST 3 (manual full).
    for (mode, symnum) in [("auto", 1), ("manual-reduced", 2), ("manual-full", 3)] {
        let out = show(mode, &["--mode", mode, "--speed-override", "25"]);
        assert_eq!(out.status.code(), Some(0), "{mode}: {}", text(&out.stderr));
        assert_eq!(text(&out.stdout), format!("mode {symnum}\noverride 25\n"), "{mode}");
    }
}

#[test]
fn an_override_outside_1_to_100_or_an_unknown_mode_is_refused() {
    for bad in ["0", "101", "50.5", "-3"] {
        let option = format!("--speed-override={bad}");
        let out = show(&format!("override_{bad}"), &[&option]);
        assert_eq!(out.status.code(), Some(2), "{bad}: the command line is wrong");
        assert!(text(&out.stderr).contains("--speed-override"), "{bad}: {}", text(&out.stderr));
        assert!(out.stdout.is_empty(), "{bad}: nothing runs");
    }
    for edge in ["1", "100"] {
        let out = show(&format!("override_{edge}"), &["--speed-override", edge]);
        assert_eq!(text(&out.stdout), format!("mode 1\noverride {edge}\n"));
    }
    let out = show("mode_bogus", &["--mode", "teach"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("--mode"), "{}", text(&out.stderr));
}

#[test]
fn warm_start_ends_the_run_with_a_message_and_success() {
    let dir = scratch("warm_single");
    let module = "MODULE warm\n  PROC main()\n    TPWrite \"before\";\n    WarmStart;\n    \
                  TPWrite \"after\";\n  ENDPROC\nENDMODULE\n";
    fs::write(dir.join("warm.mod"), module).expect("module");
    let out = rapid_in(&dir, &["run", "warm.mod"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "before\n");
    assert!(text(&out.stderr).contains("warm start"), "{}", text(&out.stderr));
}

#[test]
fn tasks_of_a_system_share_the_mode_and_report_their_configuration() {
    let dir = scratch("three_tasks");
    // T_ROB1 moves the robot; T_B is a NORMAL task without one; T_MON is STATIC.
    let rob = "MODULE Rob\n  PROC main()\n    WaitTime 1;\n    \
               TPWrite \"T_ROB1 planner \" \\Num:=MotionPlannerNo();\n    \
               TPWrite \"T_ROB1 tsp \" \\Num:=GetTSPStatus(\"T_ROB1\");\n    \
               TPWrite \"T_MON tsp \" \\Num:=GetTSPStatus(\"T_MON\");\n    \
               TPWrite \"T_B tsp \" \\Num:=GetTSPStatus(\"T_B\");\n  ENDPROC\nENDMODULE\n";
    let b = "MODULE B\n  PROC main()\n    WaitTime 2;\n    \
             TPWrite \"T_B mode \" \\Num:=OpMode();\n    \
             TPWrite \"T_B override \" \\Num:=CSpeedOverride();\n    \
             TPWrite \"T_B planner \" \\Num:=MotionPlannerNo();\n  ENDPROC\nENDMODULE\n";
    let mon = "MODULE Mon\n  PROC main()\n    WaitTime 10;\n  ENDPROC\nENDMODULE\n";
    let sys = system_of(
        &dir,
        &[
            ("T_ROB1", "-Type \"NORMAL\" -MotionTask", rob),
            ("T_B", "-Type \"NORMAL\"", b),
            ("T_MON", "-Type \"STATIC\"", mon),
        ],
    );
    let out = rapid_in(&dir, &["run", "--mode", "manual-full", "--speed-override", "30", sys.to_str().expect("path")]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    // TSP_STATUS_ACT 3 for the NORMAL tasks, TSP_STATUS_NOT_NORMAL_TASK 0 for the
    // STATIC one; T_B has no robot and uses the planner of the motion task, 1.
    assert_eq!(
        text(&out.stdout),
        "T_ROB1 planner 1\nT_ROB1 tsp 3\nT_MON tsp 0\nT_B tsp 3\nT_B mode 3\nT_B override 30\nT_B planner 1\n"
    );
}

#[test]
fn warm_start_in_one_task_stops_every_task() {
    let dir = scratch("warm_system");
    let rob = "MODULE Rob\n  PROC main()\n    WaitTime 0.5;\n    TPWrite \"restart\";\n    \
               WarmStart;\n  ENDPROC\nENDMODULE\n";
    // T_B would never end on its own.
    let b = "MODULE B\n  PROC main()\n    WHILE TRUE DO\n      WaitTime 1;\n    ENDWHILE\n  \
             ENDPROC\nENDMODULE\n";
    let sys = system_of(&dir, &[("T_ROB1", "-Type \"NORMAL\" -MotionTask", rob), ("T_B", "-Type \"NORMAL\"", b)]);
    let out = rapid_in(&dir, &["run", "--max-time", "100", sys.to_str().expect("path")]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "restart\n");
    assert!(text(&out.stderr).contains("warm start"), "{}", text(&out.stderr));
}

#[test]
fn warm_start_in_a_static_task_is_no_task_failure() {
    let dir = scratch("warm_static");
    let rob = "MODULE Rob\n  PROC main()\n    WHILE TRUE DO\n      WaitTime 1;\n    ENDWHILE\n  \
               ENDPROC\nENDMODULE\n";
    let mon = "MODULE Mon\n  PROC main()\n    WaitTime 2;\n    WarmStart;\n  ENDPROC\nENDMODULE\n";
    // A STATIC task that stops applies its trust level (SysFail by default); one that
    // asked for a warm start only ends the run.
    let sys = system_of(&dir, &[("T_ROB1", "-Type \"NORMAL\" -MotionTask", rob), ("T_MON", "-Type \"STATIC\"", mon)]);
    let out = rapid_in(&dir, &["run", "--max-time", "100", sys.to_str().expect("path")]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let stderr = text(&out.stderr);
    assert!(stderr.contains("warm start") && !stderr.contains("TrustLevel"), "{stderr}");
}

/// A tooldata declaration with TCP z and mass, for the task modules below.
fn tool(name: &str, z: u32) -> String {
    format!("  PERS tooldata {name} := [TRUE, [[0, 0, {z}], [1, 0, 0, 0]], [1, [0, 0, 1], [1, 0, 0, 0], 0, 0, 0]];\n")
}

#[test]
fn get_sys_data_reads_the_motion_tasks_active_tool_from_another_task() {
    let dir = scratch("sysdata_tasks");
    // T_ROB1 moves the robot and activates tWeld (a global PERS both tasks declare).
    let rob = format!(
        "MODULE Rob\n{}  PROC main()\n    SetSysData tWeld;\n    WaitTime 2;\n  ENDPROC\nENDMODULE\n",
        tool("tWeld", 150)
    );
    // T_B has no robot: without \TaskName it reads its motion task's data.
    let b = format!(
        "MODULE B\n{}{}  VAR string name;\n  PROC main()\n    WaitTime 1;\n    \
         GetSysData tRead \\ObjectName:=name;\n    TPWrite \"T_B: \" + name + \" z \" \\Num:=tRead.tframe.trans.z;\n    \
         GetSysData \\TaskName:=\"T_ROB1\", tRead \\ObjectName:=name;\n    TPWrite \"T_ROB1: \" + name;\n    \
         GetSysData \\TaskName:=\"T_NOSUCH\", tRead;\n  ERROR\n    \
         IF ERRNO = ERR_TASKNAME TPWrite \"ERR_TASKNAME\";\n    TRYNEXT;\n  ENDPROC\nENDMODULE\n",
        tool("tWeld", 150),
        tool("tRead", 0)
    );
    let sys = system_of(&dir, &[("T_ROB1", "-Type \"NORMAL\" -MotionTask", &rob), ("T_B", "-Type \"NORMAL\"", &b)]);
    let out = rapid_in(&dir, &["run", sys.to_str().expect("path")]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "T_B: tWeld z 150\nT_ROB1: tWeld\nERR_TASKNAME\n");
}

#[test]
fn another_tasks_own_tool_is_read_through_the_controller() {
    let dir = scratch("sysdata_local");
    // tMine is T_ROB1's own persistent (T_B declares no tMine): GetSysData and CTool
    // in T_B ask T_ROB1 for its value; the name comes with it.
    let rob = format!(
        "MODULE Rob\n{}  PROC main()\n    SetSysData tMine;\n    WaitTime 2;\n  ENDPROC\nENDMODULE\n",
        tool("tMine", 10)
    );
    let b = format!(
        "MODULE B\n{}  VAR string name;\n  PROC main()\n    WaitTime 1;\n    \
         GetSysData \\TaskName:=\"T_ROB1\", tRead \\ObjectName:=name;\n    \
         TPWrite name + \" z \" \\Num:=tRead.tframe.trans.z;\n    \
         tRead := tool0;\n    tRead := CTool(\\TaskName:=\"T_ROB1\");\n    \
         TPWrite \"CTool z \" \\Num:=tRead.tframe.trans.z;\n  ENDPROC\nENDMODULE\n",
        tool("tRead", 0)
    );
    let sys = system_of(&dir, &[("T_ROB1", "-Type \"NORMAL\" -MotionTask", &rob), ("T_B", "-Type \"NORMAL\"", &b)]);
    let out = rapid_in(&dir, &["run", sys.to_str().expect("path")]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "tMine z 10\nCTool z 10\n");
}
