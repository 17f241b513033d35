//! `rapid run`'s one path: every program runs under the controller
//! (`rapid_controller::Controller`, assembled by `rapid_controller::assembly`). A
//! module, a folder, a `.pgf` or a backup of one task is a system of one task run alone (the controller runs it in slices,
//! `Controller::runs_alone`), reported as a program: its error and its event log name
//! no task. A system of several tasks (SYS.cfg `CAB_TASKS`) has every task loaded
//! from its `RAPID/TASKn` folder, and the controller runs them pseudo-parallel, sharing
//! the I/O system and the global persistents. The run ends when every NORMAL task has
//! ended; each task's unhandled error is reported with the task's name.
//!
//! A single task runs as a system too when the I/O configuration has system inputs or
//! outputs (`SYSSIG_IN`, `SYSSIG_OUT`): the controller stops and starts the program
//! on their rising edges and sets the outputs (`rapid_controller::ops`). A program
//! stopped that nothing in the stimulus starts again ends the run (exit 0).

// The CLI is the one crate that talks to the terminal; run reports on stderr.
#![allow(clippy::print_stderr)]

use rapid_robot::RobotResources;
use std::io::{self, BufWriter};

use rapid_controller::api::Session;
use rapid_controller::assembly::inputs::Inputs;
use rapid_controller::assembly::Assembled;
use rapid_controller::{Bound, ClockPolicy, Controller, EventRoutineFailure, RunBounds, TaskEnd, TaskKind, TrustLevel};
use rapid_sema::SourceInput;

use super::run::{self as single, refuse, StdoutHost};
use crate::args::RunArgs;
use crate::commands::ExitStatus;

pub(crate) fn run(args: &RunArgs, assembled: Assembled) -> anyhow::Result<ExitStatus> {
    let Assembled { mut controller, alone, robots: numbers, model_note, inputs: tasks, program_memory } = assembled;
    print_program_memory_notes(&program_memory, &tasks);
    let mut host =
        StdoutHost { out: BufWriter::new(io::stdout().lock()), broken: false, answers: single::pendant_answers(args)? };
    // Power on and a start from main: every task's POWER_ON, then START event routines
    // (each task has its routines: the assembly's system findings).
    if let Err(failure) = controller.power_on(&mut host) {
        host.flush();
        let routine = failure.routine.as_str();
        return match (&failure.unhandled, alone) {
            (Some(unhandled), true) => report_event_routine_failure(&controller, &tasks[0].modules, routine, unhandled),
            _ => refuse(&refusal(&controller, &failure)),
        };
    }
    // The one run loop, through the controller API as every front end drives it;
    // nothing outside the system changes a run of `rapid run` (the stimulus is part
    // of it), so a run that can no longer progress ends.
    let mut session = Session::running(controller);
    session.set_clock(if args.realtime { ClockPolicy::Realtime } else { ClockPolicy::Virtual });
    let bounds = RunBounds { max_steps: args.max_steps, max_time: args.max_time, closed: true };
    let bounded = session.run_to_end(&mut host, &mut crate::pace::Pacer::default(), bounds);
    let mut controller = session.into_controller();
    host.flush();
    if bounded == Some(Bound::Stuck) {
        report_stuck(&controller, alone);
    }
    // A program alone is reported as it stops: what ended it, then its outputs.
    let alone_status = alone.then(|| report_alone(&controller, &tasks[0].modules, bounded.as_ref(), args));
    if alone {
        if let Some((_, routine)) = controller.failed_stop_routine.clone() {
            if let Some(TaskEnd::Failed(unhandled)) = controller.tasks[0].end() {
                return report_event_routine_failure(&controller, &tasks[0].modules, &routine, unhandled);
            }
        }
    }
    // A run the time bound stopped ends at the bound: the last wait may have moved the
    // clock past it, and neither the program nor the motion is reported beyond it.
    let limit = match bounded {
        Some(Bound::Time(max)) => max,
        _ => f64::INFINITY,
    };
    let program_end = controller.time.min(limit);
    for task in &mut controller.tasks {
        let name = task.spec.name.clone();
        let bound = bounded.as_ref().is_some_and(|b| !matches!(b, Bound::Stopped));
        let failed = matches!(task.end(), Some(TaskEnd::Failed(_))) || bound;
        let status = if failed { ExitStatus::Failure } else { ExitStatus::Success };
        task.loaded.vm.time = program_end;
        single::log_stop(&mut task.loaded.vm, &name, status);
    }
    let mut cycle = program_end;
    let robot_names: Vec<Option<String>> = numbers.iter().map(|n| n.map(|n| format!("ROB_{n}"))).collect();
    for idx in 0..controller.tasks.len() {
        // Each task finishes its motion with the system's I/O in hand: the outputs its
        // last moves set and the I/O system brought to the motion's end (a system of
        // tasks as a program alone: the tasks share the one I/O system).
        controller.exchange_shared_with(idx);
        let task = &mut controller.tasks[idx];
        let name = task.spec.name.clone();
        let resources = task.loaded.vm.resources_mut();
        let robot_name = robot_names.get(idx).cloned().flatten();
        let who = (name.as_str(), robot_name.as_deref());
        let ends = (program_end, limit);
        let finished = crate::motion_out::finish(resources, ends, who, model_note.as_deref(), args);
        controller.exchange_shared_with(idx);
        cycle = cycle.max(finished?);
        controller.tasks[idx].loaded.vm.log_extension_events();
    }
    write_motion_outputs(&mut controller, &tasks, &robot_names, cycle, args)?;
    if controller.tasks.iter_mut().any(|task| task.loaded.vm.resources_mut().controller.warm_start) {
        eprintln!("{}", single::WARM_START);
    }
    let status = match alone_status {
        Some(status) => status,
        None => {
            let status = report(&controller, &tasks, bounded);
            if args.cycles == 1 {
                note_exit_cycles(&controller);
            }
            status
        }
    };
    finish(&controller, &tasks, args, alone)?;
    Ok(status)
}

/// The program-memory notes (W0706) `rapid check` gives, on stderr before the run: a
/// real controller may refuse such a program, so the run says so too (the program still
/// runs; other warnings are `rapid check`'s business).
fn print_program_memory_notes(notes: &[(usize, rapid_sema::Diagnostic)], tasks: &[Inputs]) {
    for (task, note) in notes {
        let (path, line, column) = single::location(&tasks[*task].modules, note.file, note.span.start);
        eprintln!("warning[{}]: {path}:{line}:{column}: {}", note.code.as_str(), note.message);
    }
}

/// What ended a program run alone, said as the program's (no task named): a bound,
/// its unhandled error, ExitCycle in cycle mode. Its exit status.
fn report_alone(controller: &Controller, files: &[SourceInput], bound: Option<&Bound>, args: &RunArgs) -> ExitStatus {
    match bound {
        Some(Bound::Steps(max)) => {
            eprintln!("error: stopped after {max} steps (--max-steps); the program did not end");
            return ExitStatus::Failure;
        }
        Some(Bound::Time(max)) => {
            eprintln!("error: stopped at {max} s of controller time (--max-time); the program did not end");
            return ExitStatus::Failure;
        }
        Some(Bound::Interrupted) => {
            eprintln!("{}", single::interrupted_at(controller.time));
            return ExitStatus::Interrupted;
        }
        Some(Bound::InternalError) => {
            eprintln!("internal error: the interpreter failed; please report this program");
            return ExitStatus::Error;
        }
        Some(Bound::Stuck) => return ExitStatus::Stuck,
        Some(Bound::Stopped) | None => {}
    }
    let task = &controller.tasks[0];
    match task.end() {
        Some(TaskEnd::Failed(unhandled)) if controller.failed_stop_routine.is_none() => {
            let (path, line, column) = source_location(controller, 0, files, unhandled);
            eprintln!("error: {}", unhandled.error);
            eprintln!("  in routine {} at {path}:{line}:{column}", unhandled.routine);
            eprintln!("  the program stopped (no ERROR handler handled the error)");
            ExitStatus::Failure
        }
        Some(TaskEnd::Failed(_)) => ExitStatus::Failure,
        Some(TaskEnd::CycleEnded) if args.cycles == 1 => {
            eprintln!("{}", single::exit_cycle_note("the cycle"));
            ExitStatus::Success
        }
        _ => ExitStatus::Success,
    }
}

/// A run that can no longer progress: what each NORMAL task waits for, where and
/// since when (a program alone names no task).
fn report_stuck(controller: &Controller, alone: bool) {
    eprintln!(
        "error: the run can no longer progress at {:.3} s of controller time: every NORMAL task waits for \
         an input nothing in the system sets (no stimulus line, reaction, cross-connection or task), or for \
         tasks that wait so",
        controller.time
    );
    for wait in controller.stuck_waits() {
        let who = if alone { "the program".to_owned() } else { format!("task {}", wait.task) };
        eprintln!(
            "  {who} waits at {}:{} since {:.3} s: {} ({})",
            wait.file, wait.line, wait.since, wait.statement, wait.why
        );
    }
}

/// Where an unhandled error of task `idx` was raised: its file (one of the task's
/// `files`, or a module loaded at run time), line and column.
fn source_location(
    controller: &Controller,
    idx: usize,
    files: &[SourceInput],
    unhandled: &rapid_vm::Unhandled,
) -> (String, u32, u32) {
    let loaded_module = controller.tasks[idx].loaded.vm.program_source(unhandled.file);
    match files.get(unhandled.file).or(loaded_module) {
        Some(source) => single::location(std::slice::from_ref(source), 0, unhandled.span.start),
        None => single::location(&[], 0, 0),
    }
}

/// An event routine of the start that failed, as a system's refusal says it.
fn refusal(controller: &Controller, failure: &EventRoutineFailure) -> String {
    let EventRoutineFailure { task, shelf, routine, unhandled } = failure;
    let name = &controller.tasks[*task].spec.name;
    let Some(unhandled) = unhandled else {
        return format!("task {name} has no procedure `{routine}` for its {shelf} event routine");
    };
    let source = controller.tasks[*task].loaded.vm.program_source(unhandled.file);
    let (path, line, column) =
        single::location(source.map(std::slice::from_ref).unwrap_or(&[]), 0, unhandled.span.start);
    let raised = format!("raised in routine {} at {path}:{line}:{column}", unhandled.routine);
    format!("{} in the {shelf} event routine {routine} of task {name}, {raised}", unhandled.error)
}

/// An event routine of a program alone failed: said as the program's, and nothing
/// more of the run is reported.
fn report_event_routine_failure(
    controller: &Controller,
    files: &[SourceInput],
    routine: &str,
    unhandled: &rapid_vm::Unhandled,
) -> anyhow::Result<ExitStatus> {
    let (path, line, column) = source_location(controller, 0, files, unhandled);
    eprintln!("error: {}", unhandled.error);
    eprintln!("  in routine {} at {path}:{line}:{column}", unhandled.routine);
    eprintln!("  the event routine {routine} stopped (no ERROR handler handled the error)");
    Ok(ExitStatus::Failure)
}

/// Prints what ended the run badly: a bound, each task's unhandled error, a static
/// task's stop that stopped the system. Success when none.
fn report(controller: &Controller, tasks: &[Inputs], bound: Option<Bound>) -> ExitStatus {
    let mut status = ExitStatus::Success;
    match bound {
        Some(Bound::Steps(max)) => {
            eprintln!("error: stopped after {max} steps (--max-steps); the program did not end");
            status = ExitStatus::Failure;
        }
        Some(Bound::Time(max)) => {
            eprintln!("error: stopped at {max} s of controller time (--max-time); the program did not end");
            status = ExitStatus::Failure;
        }
        Some(Bound::Stopped) => {
            eprintln!(
                "the program is stopped at {:.3} s of controller time and nothing in the stimulus starts it again; the run ends here",
                controller.time
            );
        }
        Some(Bound::Interrupted) => {
            eprintln!("{}", single::interrupted_at(controller.time));
            status = ExitStatus::Interrupted;
        }
        Some(Bound::InternalError) => {
            eprintln!("internal error: the interpreter failed; please report this program");
            return ExitStatus::Error;
        }
        Some(Bound::Stuck) => status = ExitStatus::Stuck,
        None => {}
    }
    for (task, input) in controller.tasks.iter().zip(tasks) {
        let Some(TaskEnd::Failed(unhandled)) = task.end() else { continue };
        let modules = &input.modules;
        let loaded_module = task.loaded.vm.program_source(unhandled.file);
        let (path, line, column) = match modules.get(unhandled.file).or(loaded_module) {
            Some(source) => single::location(std::slice::from_ref(source), 0, unhandled.span.start),
            None => single::location(&[], 0, 0),
        };
        eprintln!("error: {}", unhandled.error);
        eprintln!("  in task {}, routine {} at {path}:{line}:{column}", task.spec.name, unhandled.routine);
        eprintln!("  the task stopped (no ERROR handler handled the error)");
        status = ExitStatus::Failure;
    }
    if let Some(stop) = &controller.system_stop {
        let state = match stop.trust {
            TrustLevel::SysFail => "the system is in SYS_FAIL (only a restart resets it)",
            TrustLevel::SysHalt => "the system halted (motors off)",
            _ => "the system stopped",
        };
        eprintln!(
            "error: task {} stopped; its TrustLevel {} stopped every NORMAL task: {state}",
            stop.task,
            stop.trust.name()
        );
        status = ExitStatus::Failure;
    }
    status
}

/// In cycle mode ExitCycle ends a NORMAL task's run, where a controller in continuous
/// mode starts its next cycle: say so, naming the tasks.
fn note_exit_cycles(controller: &Controller) {
    let ended: Vec<&str> = controller
        .tasks
        .iter()
        .filter(|t| t.spec.kind == TaskKind::Normal && t.end() == Some(&TaskEnd::CycleEnded))
        .map(|t| t.spec.name.as_str())
        .collect();
    if !ended.is_empty() {
        eprintln!("{}", single::exit_cycle_note(&format!("the cycle of {}", ended.join(", "))));
    }
}

/// `--trace` and `--report` of the first motion task's robot, a trace of each other
/// motion task's; `robot_names` are the tasks' robots (`ROB_n`), by task.
fn write_motion_outputs(
    controller: &mut Controller,
    tasks: &[Inputs],
    robot_names: &[Option<String>],
    cycle: f64,
    args: &RunArgs,
) -> anyhow::Result<()> {
    // The motion tasks that were recorded: the first with a robot gets the trace and
    // the report, the others a trace each (a positioner's task, its axes only).
    let mut recorded: Vec<usize> = (0..controller.tasks.len())
        .filter(|&i| controller.tasks[i].loaded.vm.resources_mut().robot_mut().recorded.is_some())
        .collect();
    if let Some(first) = recorded.iter().position(|&i| controller.tasks[i].spec.robot) {
        let primary = recorded.remove(first);
        recorded.insert(0, primary);
    }
    for (k, &at) in recorded.iter().enumerate() {
        let arm = controller.tasks[at].spec.robot;
        let robot = std::mem::take(controller.tasks[at].loaded.vm.resources_mut().robot_mut());
        let vm = &controller.tasks[at].loaded.vm;
        let files: &[SourceInput] = tasks.get(at).map_or(&[], |t| &t.modules);
        let sources = |file: usize| files.get(file).or_else(|| vm.program_source(file));
        let outputs = crate::motion_out::RunOutputs {
            robot: &robot,
            sources: &sources,
            io: controller.io_system(),
            program: crate::motion_out::program_name(args),
            task: &controller.tasks[at].spec.name,
            robot_name: robot_names.get(at).and_then(Option::as_deref).filter(|_| arm),
            cycle,
        };
        match (k, arm) {
            (0, true) => crate::motion_out::write_outputs(&outputs, args)?,
            _ => crate::motion_out::write_task_trace(&outputs, args)?,
        }
        // The recorded path (every planned move of the run) goes back to the system
        // when the process ends, without the time freeing it piece by piece would take.
        std::mem::forget(robot);
    }
    Ok(())
}

/// The logs and saves asked for, after the run.
fn finish(controller: &Controller, tasks: &[Inputs], args: &RunArgs, alone: bool) -> anyhow::Result<()> {
    if args.event_log {
        for task in &controller.tasks {
            for event in task.loaded.vm.event_log() {
                // A program alone: its entries name no task.
                match alone {
                    true => eprintln!("event {event}"),
                    false => eprintln!("event {} {event}", task.spec.name),
                }
            }
        }
    }
    // Every task's save and the log are attempted even when one fails.
    let mut saved = Ok(());
    if args.save_pers {
        let mut written = std::collections::HashSet::new();
        for (task, input) in controller.tasks.iter().zip(tasks) {
            let modules: &[SourceInput] = &input.modules;
            let result = crate::save::save_persistents(&task.loaded, modules, &mut written);
            if saved.is_ok() {
                saved = result;
            }
        }
    }
    let logged = args.elog.as_deref().map_or(Ok(()), |path| {
        let events: Vec<crate::elog::TaskEvents<'_>> = controller
            .tasks
            .iter()
            .zip(tasks)
            .map(|(task, input)| crate::elog::TaskEvents {
                // A program alone is the controller's main task.
                task: if alone { crate::elog::MAIN_TASK } else { &task.spec.name },
                vm: &task.loaded.vm,
                files: &input.modules,
            })
            .collect();
        crate::elog::write(path, &events)
    });
    saved?;
    logged?;
    if let Some(path) = &args.io_log {
        single::write_io_log(controller.io_system(), path)?;
    }
    Ok(())
}
