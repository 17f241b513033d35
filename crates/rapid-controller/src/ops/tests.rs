//! Program stop and start through the controller's API: waits keep their remaining
//! time, safe interrupts survive the stop, the others do not (§1.11).

use rapid_sema::SourceInput;
use rapid_signals::SharedIoAccess;
use rapid_vm::RecordingHost;

use crate::{Controller, ProgramState, StartMode, StopKind, SystemExit, TaskSpec};

fn controller(program: &str) -> Controller {
    with_signals(program, "")
}

/// A controller for one NORMAL task, with the digital inputs `inputs` (space
/// separated) as its I/O system when any are given.
fn with_signals(program: &str, inputs: &str) -> Controller {
    let files = [SourceInput::from_text("T_ROB1.mod", program)];
    let names: Vec<&str> = inputs.split_whitespace().collect();
    let predefined = names
        .iter()
        .map(|n| rapid_sema::PredefinedData { name: (*n).to_owned(), type_name: "signaldi".to_owned() })
        .collect();
    let options = rapid_sema::Options { predefined, ..rapid_sema::Options::default() };
    let loaded = match crate::builtin_set::load_with(&files, "main", &options) {
        Ok(loaded) => loaded,
        Err(err) => panic!("the test program does not load: {err:?}"),
    };
    let spec = TaskSpec::normal("T_ROB1", true);
    let io = (!names.is_empty()).then(|| {
        let signals: String = names.iter().map(|n| format!("\n      -Name \"{n}\" -SignalType \"DI\"\n")).collect();
        let eio =
            rapid_config::eio::read(&rapid_config::parse(&format!("EIO:CFG_1.0:6:0::\n#\nEIO_SIGNAL:\n{signals}")));
        match crate::boot::io_config::io_system(&eio) {
            Ok(io) => io,
            Err(message) => panic!("{message}"),
        }
    });
    match Controller::new(vec![(spec, loaded)], io) {
        Ok(controller) => controller,
        Err(message) => panic!("{message}"),
    }
}

/// Runs until the clock reaches `until` (or the run ends); a stopped program stands
/// until then.
fn run_until(controller: &mut Controller, host: &mut RecordingHost, until: f64) -> SystemExit {
    for _ in 0..100_000 {
        match controller.run(host, 1000) {
            SystemExit::Budget => {}
            SystemExit::Wait(seconds) => {
                if controller.time >= until {
                    return SystemExit::Wait(seconds);
                }
                controller.advance(seconds.min(until - controller.time));
            }
            SystemExit::Stopped => {
                controller.advance((until - controller.time).max(0.0));
                return SystemExit::Stopped;
            }
            SystemExit::Ended => return SystemExit::Ended,
        }
    }
    panic!("the run did not settle");
}

#[test]
fn a_wait_keeps_its_remaining_time_across_a_stop() {
    let mut c = controller(
        "MODULE M
  PROC main()
    VAR clock k;
    ClkStart k;
    WaitTime 2;
    TPWrite \"waited \" \\Num:=ClkRead(k);
  ENDPROC
ENDMODULE",
    );
    let mut host = RecordingHost::default();
    run_until(&mut c, &mut host, 0.5);
    c.stop(StopKind::Stop);
    run_until(&mut c, &mut host, 1.5);
    assert_eq!(c.program_state(), ProgramState::Stopped);
    assert!(c.start(&mut host, StartMode::Continuous));
    assert_eq!(run_until(&mut c, &mut host, 100.0), SystemExit::Ended);
    // 2 s of wait plus the 1 s the program stood.
    assert_eq!(host.lines, ["waited 3"]);
    assert!((c.time - 3.0).abs() < 1e-3, "{}", c.time);
}

#[test]
fn a_stopped_program_nothing_restarts_reports_stopped() {
    let mut c = controller("MODULE M\n  PROC main()\n    WaitTime 1;\n    TPWrite \"end\";\n  ENDPROC\nENDMODULE");
    let mut host = RecordingHost::default();
    run_until(&mut c, &mut host, 0.2);
    c.stop(StopKind::Quick);
    assert_eq!(run_until(&mut c, &mut host, 10.0), SystemExit::Stopped);
    assert!(host.lines.is_empty());
    // A start of a running program does nothing; of the stopped one, it goes on.
    assert!(c.start(&mut host, StartMode::Cycle));
    assert!(!c.start(&mut host, StartMode::Cycle));
    assert_eq!(run_until(&mut c, &mut host, 100.0), SystemExit::Ended);
    assert_eq!(host.lines, ["end"]);
    let events: Vec<u32> = c.tasks[0].loaded.vm.event_log().iter().map(|e| e.number).collect();
    assert_eq!(events, [151, 150]);
}

#[test]
fn only_safe_interrupts_outlive_a_stop() {
    // Timers of 0.5 s (safe) and 0.6 s (plain) come due while the program stands
    // (0.2 .. 1.0): the safe one's trap runs first at the start, the plain one's never.
    let mut c = controller(
        "MODULE M
  VAR intnum safe;
  VAR intnum plain;
  PROC main()
    CONNECT safe WITH tSafe;
    CONNECT plain WITH tPlain;
    ITimer \\SingleSafe, 0.5, safe;
    ITimer \\Single, 0.6, plain;
    WaitTime 2;
    TPWrite \"end\";
  ENDPROC
  TRAP tSafe
    TPWrite \"safe\";
  ENDTRAP
  TRAP tPlain
    TPWrite \"plain\";
  ENDTRAP
ENDMODULE",
    );
    let mut host = RecordingHost::default();
    run_until(&mut c, &mut host, 0.2);
    c.stop(StopKind::Stop);
    run_until(&mut c, &mut host, 1.0);
    assert!(host.lines.is_empty());
    c.start(&mut host, StartMode::Continuous);
    assert_eq!(run_until(&mut c, &mut host, 100.0), SystemExit::Ended);
    assert_eq!(host.lines, ["safe", "end"]);
    assert!((c.time - 2.8).abs() < 1e-3, "{}", c.time);
}

#[test]
fn the_queue_keeps_only_safe_interrupts_at_a_stop() {
    // Both timers fire at 0.1 while interrupts are disabled: queued. The stop at 0.3
    // discards the plain one; after the start, IEnable lets the safe one's trap run.
    let mut c = controller(
        "MODULE M
  VAR intnum safe;
  VAR intnum plain;
  PROC main()
    CONNECT safe WITH tSafe;
    CONNECT plain WITH tPlain;
    IDisable;
    ITimer \\Single, 0.1, plain;
    ITimer \\SingleSafe, 0.1, safe;
    WaitTime 0.5;
    IEnable;
    WaitTime 0.1;
    TPWrite \"end\";
  ENDPROC
  TRAP tSafe
    TPWrite \"safe\";
  ENDTRAP
  TRAP tPlain
    TPWrite \"plain\";
  ENDTRAP
ENDMODULE",
    );
    let mut host = RecordingHost::default();
    run_until(&mut c, &mut host, 0.3);
    c.stop(StopKind::Stop);
    run_until(&mut c, &mut host, 0.4);
    c.start(&mut host, StartMode::Continuous);
    assert_eq!(run_until(&mut c, &mut host, 100.0), SystemExit::Ended);
    assert_eq!(host.lines, ["safe", "end"]);
}

#[test]
fn a_safe_signal_interrupt_queues_while_stopped() {
    // diA rises at 1.0 while the program stands (0.5 .. 1.5): of the two interrupts on
    // it only the safe one's trap runs, at the start; WaitTime 2 since 0 stood 1 s.
    let mut c = with_signals(
        "MODULE M
  VAR intnum safe;
  VAR intnum plain;
  PROC main()
    CONNECT safe WITH tSafe;
    CONNECT plain WITH tPlain;
    ISignalDI \\SingleSafe, diA, 1, safe;
    ISignalDI diA, 1, plain;
    WaitTime 2;
    TPWrite \"end\";
  ENDPROC
  TRAP tSafe
    TPWrite \"safe\";
  ENDTRAP
  TRAP tPlain
    TPWrite \"plain\";
  ENDTRAP
ENDMODULE",
        "diA",
    );
    let id = c.io_system().and_then(|io| io.id("diA")).expect("diA");
    c.shared_mut().io_mut().stimulus.push_back((1.0, id, 1.0));
    let mut host = RecordingHost::default();
    run_until(&mut c, &mut host, 0.5);
    c.stop(StopKind::Stop);
    run_until(&mut c, &mut host, 1.5);
    assert!(c.start(&mut host, StartMode::Continuous));
    assert_eq!(run_until(&mut c, &mut host, 100.0), SystemExit::Ended);
    assert_eq!(host.lines, ["safe", "end"]);
    assert!((c.time - 3.0).abs() < 1e-3, "{}", c.time);
}

#[test]
fn a_computing_task_stops_at_its_next_instruction_and_goes_on() {
    let mut c = controller(
        "MODULE M
  PROC main()
    VAR num n := 0;
    FOR i FROM 1 TO 1000 DO
      n := n + i;
    ENDFOR
    TPWrite \"sum \" \\Num:=n;
  ENDPROC
ENDMODULE",
    );
    let mut host = RecordingHost::default();
    assert_eq!(c.run(&mut host, 777), SystemExit::Budget);
    c.stop(StopKind::Stop);
    assert_eq!(c.run(&mut host, 100), SystemExit::Stopped);
    assert_eq!(c.program_state(), ProgramState::Stopped);
    assert!(c.tasks[0].loaded.vm.at_instruction_boundary());
    // Stopped, the task runs nothing.
    let steps = c.steps;
    assert_eq!(c.run(&mut host, 100), SystemExit::Stopped);
    assert_eq!(c.steps, steps);
    assert!(c.start(&mut host, StartMode::Continuous));
    assert_eq!(run_until(&mut c, &mut host, 100.0), SystemExit::Ended);
    assert_eq!(host.lines, ["sum 500500"]);
}

#[test]
fn start_main_starts_the_program_afresh_with_its_start_event_routine() {
    let mut c = controller(
        "MODULE M
  PROC main()
    TPWrite \"begin\";
    WaitTime 1;
    TPWrite \"end\";
  ENDPROC
  PROC on_start()
    TPWrite \"START event\";
  ENDPROC
  PROC on_stop()
    TPWrite \"STOP event\";
  ENDPROC
ENDMODULE",
    );
    c.set_event_routines("START", vec![vec!["on_start".to_owned()]]);
    c.set_event_routines("STOP", vec![vec!["on_stop".to_owned()]]);
    let mut host = RecordingHost::default();
    run_until(&mut c, &mut host, 0.5);
    c.stop(StopKind::Stop);
    run_until(&mut c, &mut host, 0.7);
    assert!(c.start_main(&mut host));
    assert_eq!(run_until(&mut c, &mut host, 100.0), SystemExit::Ended);
    assert_eq!(host.lines, ["begin", "STOP event", "START event", "begin", "end"]);
    assert!((c.time - 1.7).abs() < 1e-3, "{}", c.time);
    let events: Vec<u32> = c.tasks[0].loaded.vm.event_log().iter().map(|e| e.number).collect();
    assert_eq!(events, [151, 2, 150]);
}

#[test]
fn motors_off_stops_the_program_and_a_start_needs_them_on() {
    let mut c = controller("MODULE M\n  PROC main()\n    WaitTime 1;\n    TPWrite \"end\";\n  ENDPROC\nENDMODULE");
    let mut host = RecordingHost::default();
    run_until(&mut c, &mut host, 0.2);
    c.set_motors(false);
    run_until(&mut c, &mut host, 0.4);
    assert_eq!(c.program_state(), ProgramState::Stopped);
    assert!(!c.start(&mut host, StartMode::Continuous));
    c.set_motors(true);
    assert!(c.start(&mut host, StartMode::Continuous));
    assert_eq!(run_until(&mut c, &mut host, 100.0), SystemExit::Ended);
    assert_eq!(host.lines, ["end"]);
}

#[test]
fn a_quick_stop_runs_the_qstop_event_routines_and_a_restart_the_restart_ones() {
    let mut c = controller(
        "MODULE M
  PROC main()
    WaitTime 1;
    TPWrite \"end\";
  ENDPROC
  PROC on_stop()
    TPWrite \"STOP\";
  ENDPROC
  PROC on_qstop()
    TPWrite \"QSTOP \" \\Num:=EventType();
  ENDPROC
  PROC on_restart()
    TPWrite \"RESTART \" \\Num:=EventType();
  ENDPROC
ENDMODULE",
    );
    c.set_event_routines("STOP", vec![vec!["on_stop".to_owned()]]);
    c.set_event_routines("QSTOP", vec![vec!["on_qstop".to_owned()]]);
    c.set_event_routines("RESTART", vec![vec!["on_restart".to_owned()]]);
    let mut host = RecordingHost::default();
    run_until(&mut c, &mut host, 0.5);
    c.stop(StopKind::Quick);
    run_until(&mut c, &mut host, 0.6);
    assert!(c.start(&mut host, StartMode::Continuous));
    assert_eq!(run_until(&mut c, &mut host, 100.0), SystemExit::Ended);
    // EventType: EVENT_QSTOP 4, EVENT_RESTART 5 (the order of SYS.cfg's shelves).
    assert_eq!(host.lines, ["QSTOP 4", "RESTART 5", "end"]);
}

/// Runs a step to its end: until the program stands stopped again.
fn finish_step(controller: &mut Controller, host: &mut RecordingHost) {
    for _ in 0..100_000 {
        if controller.program_state() == ProgramState::Stopped {
            return;
        }
        match controller.run(host, 1000) {
            SystemExit::Wait(seconds) => controller.advance(seconds),
            SystemExit::Budget | SystemExit::Stopped => {}
            SystemExit::Ended => return,
        }
    }
    panic!("the step did not end");
}

#[test]
fn safe_interrupts_queue_while_stepping_and_run_at_the_start() {
    // Stopped at 0.1 inside WaitTime 0.3 (0.2 s left); the timers come due at 0.5
    // (safe) and 0.6 (plain) while the program stands. The first step finishes the
    // wait (1.0 + 0.2 = 1.2 s) and no trap runs; the second runs TPWrite "one", still
    // no trap. The continuous start runs the queued safe trap first; the plain
    // interrupt is gone (§1.11 安全中断).
    let mut c = controller(
        "MODULE M
  VAR intnum safe;
  VAR intnum plain;
  PROC main()
    CONNECT safe WITH tSafe;
    CONNECT plain WITH tPlain;
    ITimer \\SingleSafe, 0.5, safe;
    ITimer \\Single, 0.6, plain;
    WaitTime 0.3;
    TPWrite \"one\";
    TPWrite \"two\";
    TPWrite \"three\";
  ENDPROC
  PROC on_step()
    TPWrite \"STEP \" \\Num:=EventType();
  ENDPROC
  TRAP tSafe
    TPWrite \"safe\";
  ENDTRAP
  TRAP tPlain
    TPWrite \"plain\";
  ENDTRAP
ENDMODULE",
    );
    // The STEP event routine runs as each step begins (EVENT_STEP 7, the order of
    // SYS.cfg's shelves).
    c.set_event_routines("STEP", vec![vec!["on_step".to_owned()]]);
    let mut host = RecordingHost::default();
    // A running program takes no step.
    assert!(!c.step_forward(&mut host, 0));
    run_until(&mut c, &mut host, 0.1);
    c.stop(StopKind::Stop);
    run_until(&mut c, &mut host, 1.0);
    assert!(c.step_forward(&mut host, 0));
    finish_step(&mut c, &mut host);
    assert_eq!(host.lines, ["STEP 7"]);
    assert!((c.time - 1.2).abs() < 1e-3, "{}", c.time);
    assert!(c.step_forward(&mut host, 0));
    finish_step(&mut c, &mut host);
    assert_eq!(host.lines, ["STEP 7", "STEP 7", "one"]);
    assert!(c.start(&mut host, StartMode::Continuous));
    assert_eq!(run_until(&mut c, &mut host, 100.0), SystemExit::Ended);
    assert_eq!(host.lines, ["STEP 7", "STEP 7", "one", "safe", "two", "three"]);
}

#[test]
fn a_safe_signal_interrupt_during_a_step_waits_for_the_start() {
    // diA rises at 0.5 while the stepped WaitTime runs (stopped at 0.2 inside
    // WaitTime 1, stepped from 0.3: it ends at 0.3 + 0.8 = 1.1): the safe interrupt
    // queues, the plain one is dropped, and no trap runs in the step.
    let mut c = with_signals(
        "MODULE M
  VAR intnum safe;
  VAR intnum plain;
  PROC main()
    CONNECT safe WITH tSafe;
    CONNECT plain WITH tPlain;
    ISignalDI \\SingleSafe, diA, 1, safe;
    ISignalDI diA, 1, plain;
    WaitTime 1;
    TPWrite \"end\";
  ENDPROC
  TRAP tSafe
    TPWrite \"safe\";
  ENDTRAP
  TRAP tPlain
    TPWrite \"plain\";
  ENDTRAP
ENDMODULE",
        "diA",
    );
    let id = c.io_system().and_then(|io| io.id("diA")).expect("diA");
    c.shared_mut().io_mut().stimulus.push_back((0.5, id, 1.0));
    let mut host = RecordingHost::default();
    run_until(&mut c, &mut host, 0.2);
    c.stop(StopKind::Stop);
    run_until(&mut c, &mut host, 0.3);
    assert!(c.step_forward(&mut host, 0));
    finish_step(&mut c, &mut host);
    assert!(host.lines.is_empty(), "{:?}", host.lines);
    assert!((c.time - 1.1).abs() < 1e-3, "{}", c.time);
    assert!(c.start(&mut host, StartMode::Continuous));
    assert_eq!(run_until(&mut c, &mut host, 100.0), SystemExit::Ended);
    assert_eq!(host.lines, ["safe", "end"]);
}

#[test]
fn a_wait_goes_on_after_the_restart_routines() {
    // Stopped at 0.5 inside WaitTime 2 (1.5 s left), started at 1.5; the RESTART
    // routine waits 1 s, so the wait goes on from 2.5 and ends at 4.0: the clock,
    // started at 0, reads 4.
    let mut c = controller(
        "MODULE M
  VAR clock k;
  PROC main()
    ClkStart k;
    WaitTime 2;
    TPWrite \"waited \" \\Num:=ClkRead(k);
  ENDPROC
  PROC on_restart()
    WaitTime 1;
  ENDPROC
ENDMODULE",
    );
    c.set_event_routines("RESTART", vec![vec!["on_restart".to_owned()]]);
    let mut host = RecordingHost::default();
    run_until(&mut c, &mut host, 0.5);
    c.stop(StopKind::Stop);
    run_until(&mut c, &mut host, 1.5);
    assert!(c.start(&mut host, StartMode::Continuous));
    assert_eq!(run_until(&mut c, &mut host, 100.0), SystemExit::Ended);
    assert_eq!(host.lines, ["waited 4"]);
}

#[test]
fn a_step_lets_the_robot_finish_the_stopped_move() {
    // Stopped 0.3 s into a 200 mm MoveL at v100 (2 s and its ramps): the robot stands
    // on its path. A step finishes the move instruction: without the robot going on
    // the step would never end. The TPWrite after it runs only at the start.
    let mut c = controller(
        "MODULE M
  VAR robtarget here;
  PROC main()
    MoveL [[400,-100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;
    TPWrite \"at A\";
    MoveL [[400,100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v100, fine, tool0;
    here := CRobT();
    TPWrite \"y \" \\Num:=Round(here.trans.y);
  ENDPROC
ENDMODULE",
    );
    let mut host = RecordingHost::default();
    while host.lines.is_empty() {
        let t = c.time + 0.01;
        assert_ne!(run_until(&mut c, &mut host, t), SystemExit::Ended);
    }
    let t = c.time + 0.3;
    run_until(&mut c, &mut host, t);
    c.stop(StopKind::Stop);
    let t = c.time + 1.0;
    run_until(&mut c, &mut host, t);
    assert!(c.step_forward(&mut host, 0));
    finish_step(&mut c, &mut host);
    assert_eq!(host.lines, ["at A"]);
    assert!(c.start(&mut host, StartMode::Continuous));
    assert_eq!(run_until(&mut c, &mut host, 1000.0), SystemExit::Ended);
    assert_eq!(host.lines, ["at A", "y 100"]);
}
