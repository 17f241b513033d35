//! Power on and the first start from main, as a run begins: each task's event log says
//! its program pointer was set to its entry routine and its program started, then every
//! task's POWER_ON event routines run, then every task's START ones (SYS.cfg
//! `CAB_EXEC_HOOKS`, given with [`Controller::set_event_routines`]).

use rapid_vm::{Host, Unhandled};

use crate::schedule::Controller;

/// An event routine of the start that could not run.
#[derive(Debug, Clone, PartialEq)]
pub struct EventRoutineFailure {
    /// The task (index).
    pub task: usize,
    /// The system event: `POWER_ON` or `START`.
    pub shelf: &'static str,
    pub routine: String,
    /// The error no ERROR handler handled; `None`: the task has no such procedure.
    pub unhandled: Option<Box<Unhandled>>,
}

impl Controller {
    /// Power on and a start from main (what `rapid run` is): the event log's entries,
    /// then the POWER_ON and START event routines of every task, each run to its end.
    /// The first routine that fails ends it.
    pub fn power_on(&mut self, host: &mut dyn Host) -> Result<(), EventRoutineFailure> {
        use rapid_vm::events::{PP_RESET, PROGRAM_STARTED};
        for task in &mut self.tasks {
            let name = &task.spec.name;
            let vm = &mut task.loaded.vm;
            vm.log_state(PP_RESET, format!("The program pointer of task {name} was set to its entry routine."));
            vm.log_state(PROGRAM_STARTED, format!("Program execution in task {name} has been started."));
        }
        // A system's check names every routine its tasks lack (E0704) before it starts.
        let missing_fails = self.runs_alone();
        for shelf in ["POWER_ON", "START"] {
            let event = rapid_config::sys::SHELVES.iter().position(|s| *s == shelf).map_or(0, |i| i as u8 + 1);
            for task in 0..self.tasks.len() {
                for routine in self.hooks_of(shelf, task) {
                    let unhandled = match self.run_event_routine(task, host, &routine, event) {
                        Ok(true) => continue,
                        Ok(false) if !missing_fails => continue,
                        Ok(false) => None,
                        Err(unhandled) => Some(Box::new(unhandled)),
                    };
                    return Err(EventRoutineFailure { task, shelf, routine, unhandled });
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use rapid_vm::RecordingHost;

    use crate::test_support::one_task;

    const HOOKS: &str = "MODULE M\n  PROC main()\n    TPWrite \"main\";\n  ENDPROC\n  PROC on_power()\n    \
                         TPWrite \"power\";\n  ENDPROC\n  PROC on_start()\n    TPWrite \"start\";\n    \
                         reg1 := 1 / reg2;\n  ENDPROC\nENDMODULE";

    #[test]
    fn power_on_runs_power_on_then_start_routines_and_names_the_one_that_failed() {
        let mut c = one_task(HOOKS);
        c.set_event_routines("START", vec![vec!["on_start".to_owned()]]);
        c.set_event_routines("POWER_ON", vec![vec!["on_power".to_owned()]]);
        let mut host = RecordingHost::default();
        let failure = c.power_on(&mut host).expect_err("on_start divides by zero");
        assert_eq!(host.lines, ["power", "start"]);
        assert_eq!((failure.task, failure.shelf, failure.routine.as_str()), (0, "START", "on_start"));
        assert!(failure.unhandled.is_some_and(|u| u.routine == "on_start"));
        // The program pointer was set and the program started, as the event log says.
        let numbers: Vec<u32> = c.tasks[0].loaded.vm.event_log().iter().map(|e| e.number).collect();
        assert_eq!(&numbers[..2], [rapid_vm::events::PP_RESET.0, rapid_vm::events::PROGRAM_STARTED.0]);
    }

    #[test]
    fn a_routine_a_task_alone_lacks_is_a_failure() {
        let mut c = one_task(HOOKS);
        c.set_event_routines("POWER_ON", vec![vec!["on_nothing".to_owned()]]);
        let failure = c.power_on(&mut RecordingHost::default()).expect_err("no such procedure");
        assert_eq!((failure.shelf, failure.routine.as_str()), ("POWER_ON", "on_nothing"));
        assert!(failure.unhandled.is_none());
    }
}
