//! `rapid run` as a client of the controller's one run loop: what the loop decides
//! (the bounds, a run that can no longer progress) and what the CLI does after it
//! (the motion finished with the system's I/O, the cycle time reported).

use std::fs;

use crate::fixture::{rapid_in, scratch_in, system, text, Scratch, TaskDef};

fn scratch(name: &str) -> Scratch {
    scratch_in("run_loop", name)
}

/// A robot at p0, then a MoveLDO to a fly-by point 100 mm away that sets doEnd at the
/// point: the program ends while the robot is still on its way there.
const LAST_MOVE_SETS: &str = "MODULE S\n  CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];\n  \
                              PROC main()\n    MoveJ p0, v1000, fine, tool0;\n    \
                              MoveLDO Offs(p0, 100, 0, 0), v100, z10, tool0, doEnd, 1;\n  ENDPROC\nENDMODULE\n";

const DO_END: &str = "\n      -Name \"doEnd\" -SignalType \"DO\"\n";

#[test]
fn a_system_of_tasks_finishes_its_motion_with_the_shared_io() {
    // The output a task's last move sets at its point is set after the program has
    // ended, when the controller brings the robot to the end of its path: with one
    // task and with two alike, the I/O log shows it.
    for two in [false, true] {
        let dir = scratch(if two { "finish_two" } else { "finish_one" });
        let other = "MODULE O\n  PROC main()\n    TPWrite \"other\";\n  ENDPROC\nENDMODULE\n";
        let mut tasks = vec![TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\" -MotionTask", module: LAST_MOVE_SETS }];
        if two {
            tasks.push(TaskDef { name: "T_B", attrs: "-Type \"NORMAL\"", module: other });
        }
        system(&dir, &tasks, DO_END);
        let out = rapid_in(&dir, &["run", "--quiet", "--io-log", "io.csv", "sys"]);
        assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
        let log = fs::read_to_string(dir.join("io.csv")).expect("io log");
        assert!(log.lines().any(|l| l.contains(",doEnd,0,1,")), "two tasks {two}: {log}");
    }
}

#[test]
fn a_run_stopped_by_max_time_reports_no_cycle_time_past_the_bound() {
    // A 100 mm move at v5 takes twenty seconds; the program goes on at once (a fly-by
    // point) and waits a second at a time. Stopped at 2 s, the cycle time the run
    // reports is the bound, not the end of the move nor the 3 s the last wait reached.
    let dir = scratch("max_time_cycle");
    let program = "MODULE S\n  CONST robtarget p0 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];\n  \
                   PROC main()\n    MoveJ p0, v1000, fine, tool0;\n    MoveL Offs(p0, 0, 0, -100), v5, z10, tool0;\n    \
                   WHILE TRUE DO\n      WaitTime 1;\n    ENDWHILE\n  ENDPROC\nENDMODULE\n";
    fs::write(dir.join("slow.mod"), program).expect("module");
    let out = rapid_in(&dir, &["run", "--max-time", "2", "slow.mod"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    let stderr = text(&out.stderr);
    let line = stderr.lines().find(|l| l.starts_with("cycle time")).unwrap_or_else(|| panic!("{stderr}"));
    let seconds: f64 =
        line.split(": ").nth(1).and_then(|s| s.split(' ').next()).and_then(|s| s.parse().ok()).expect("time");
    assert!(line.contains("2 moves"), "{line}");
    assert!(seconds <= 2.0, "{line}");
}

#[test]
fn a_cell_without_its_stimulus_says_it_cannot_progress() {
    // examples/press_cell without its stimulus: T_ROB1 waits for diPartPresent, which
    // only the stimulus sets (an input; no cross-connection), and T_PRESS waits at its
    // first sync point with T_ROB1. Nothing can change: the run ends at once, at 0 s,
    // with its own exit status, naming each wait where it is.
    let root = crate::fixture::repo_root();
    let out = crate::fixture::rapid_cmd(&root.join("examples"), &["run", "press_cell"]).output().expect("rapid");
    assert_eq!(out.status.code(), Some(3), "{}", text(&out.stderr));
    let stderr = text(&out.stderr);
    assert!(stderr.contains("error: the run can no longer progress at 0.000 s"), "{stderr}");
    assert!(
        stderr.contains(
            "task T_ROB1 waits at press_cell/RAPID/TASK1/PROGMOD/Robot.mod:14 since 0.000 s: WaitDI diPartPresent, 1 \
             (diPartPresent is 0)"
        ),
        "{stderr}"
    );
    assert!(
        stderr
            .contains("task T_PRESS waits at press_cell/RAPID/TASK2/PROGMOD/Press.mod:11 since 0.000 s: WaitSyncTask"),
        "{stderr}"
    );
}

const WAITS_FOR_GO: &str = "MODULE S\n  PROC main()\n    TPWrite \"waiting\";\n    WaitTime 2;\n    \
                            WaitDI diGo, 1;\n    TPWrite \"going\";\n  ENDPROC\nENDMODULE\n";

const SIGNALS: &str = "\n      -Name \"diGo\" -SignalType \"DI\"\n\n      -Name \"doGo\" -SignalType \"DO\"\n";

#[test]
fn a_program_waiting_for_an_input_nothing_sets_stops_with_its_wait() {
    let dir = scratch("stuck_alone");
    system(&dir, &[TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: WAITS_FOR_GO }], SIGNALS);
    let out = rapid_in(&dir, &["run", "sys"]);
    assert_eq!(out.status.code(), Some(3), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "waiting\n");
    // The wait began after the WaitTime: at 2 s; the program alone names no task.
    let stderr = text(&out.stderr);
    assert!(stderr.contains("can no longer progress at 2.000 s"), "{stderr}");
    assert!(
        stderr.contains(
            "the program waits at sys/RAPID/TASK1/PROGMOD/Main.mod:5 since 2.000 s: WaitDI diGo, 1 (diGo is 0)"
        ),
        "{stderr}"
    );
}

#[test]
fn what_may_still_change_the_input_lets_the_run_go_on() {
    // A stimulus line still to come: the run waits for it (2 s to 5 s) and ends.
    let dir = scratch("stuck_not_stimulus");
    system(&dir, &[TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: WAITS_FOR_GO }], SIGNALS);
    fs::write(dir.join("go.stim"), "at 5 s set diGo 1\n").expect("stimulus");
    let out = rapid_in(&dir, &["run", "--stimulus", "go.stim", "sys"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), "waiting\ngoing\n");
    // A reaction that sets it (were doGo ever set) counts as a setter: bounded by
    // --max-time, not said to be stuck.
    let dir = scratch("stuck_not_reaction");
    system(&dir, &[TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: WAITS_FOR_GO }], SIGNALS);
    fs::write(dir.join("go.stim"), "when doGo = 1 set diGo 1\n").expect("stimulus");
    let out = rapid_in(&dir, &["run", "--stimulus", "go.stim", "--max-time", "100", "sys"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    assert!(text(&out.stderr).contains("(--max-time)"), "{}", text(&out.stderr));
    // \MaxTime ends the wait with ERR_WAIT_MAXTIME; a timer interrupt's trap may run.
    for (name, wait) in [
        ("stuck_not_maxtime", "WaitDI diGo, 1 \\MaxTime:=3;"),
        ("stuck_not_timer", "CONNECT tick WITH on_tick;\n    ITimer 1, tick;\n    WaitDI diGo, 1;"),
    ] {
        let dir = scratch(name);
        let module = format!(
            "MODULE S\n  VAR intnum tick;\n  PROC main()\n    {wait}\n  ENDPROC\n  TRAP on_tick\n  ENDTRAP\nENDMODULE\n"
        );
        system(&dir, &[TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: &module }], SIGNALS);
        let out = rapid_in(&dir, &["run", "--max-time", "100", "sys"]);
        assert_eq!(out.status.code(), Some(1), "{name}: {}", text(&out.stderr));
        assert!(!text(&out.stderr).contains("no longer progress"), "{name}: {}", text(&out.stderr));
    }
}
