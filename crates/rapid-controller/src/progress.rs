//! Whether a run can still progress ([`crate::Bound::Stuck`]), for a run nothing
//! outside the system changes (`rapid run`: no front end sets signals).
//!
//! The rule, conservative: the run cannot progress when the program runs and every
//! NORMAL task that has not ended waits for ever, at least one of them on an input:
//! - a signal wait (WaitDI, WaitGI, WaitAI) without `\MaxTime` on an input of the
//!   configuration that nothing in the system sets: no stimulus reaction and no
//!   cross-connection sets it (a task cannot set an input);
//! - or a WaitSyncTask without `\TimeOut` whose task list names only NORMAL tasks that
//!   wait so too (none of them can arrive);
//!
//! and nothing else can change anything: no stimulus line or scheduled order (a
//! delayed set, a pulse's end, a path event) is pending, no robot is still moving (its
//! path may set outputs a reaction follows), no task holds a socket open, and no such
//! waiting task has an interrupt that may still come (a timer, or a signal interrupt:
//! its trap could end the cycle). Other tasks (STATIC, SEMISTATIC) may go on running:
//! they cannot set an input nor arrive at a sync point of NORMAL tasks only. A wait on
//! an output, a WaitUntil (it may read a clock), a WaitTime, an RMQ or socket wait, a
//! prompt (under `rapid run` a dialog without an answer raises ERR_TP_NO_CLIENT and does
//! not wait), or a NORMAL task that is not waiting: the run can progress.

use rapid_robot::RobotResources;
use rapid_signals::SharedIoAccess;
use rapid_tasks::TaskingAccess;
use rapid_vm::value::Value;
use rapid_vm::Vm;

use crate::schedule::{Controller, State};
use crate::task::TaskKind;

/// The signal waits a change from outside ends (their first argument is the signal).
const SIGNAL_WAITS: [&str; 3] = ["waitdi", "waitgi", "waitai"];

/// What one NORMAL task of a run that can no longer progress waits for.
#[derive(Debug, Clone, PartialEq)]
pub struct StuckWait {
    pub task: String,
    /// The waiting statement as written, white space run together.
    pub statement: String,
    /// Why it waits for ever: the input and its value, or the sync point's tasks.
    pub why: String,
    /// Where the statement is: the file as loaded, its 1-based line.
    pub file: String,
    pub line: u32,
    /// When the wait began (controller seconds).
    pub since: f64,
}

/// A task's wait that cannot end by itself.
enum Wait {
    /// On an input nothing in the system sets.
    Input(StuckWait),
    /// At a sync point (WaitSyncTask without `\TimeOut`) with these tasks (lower case).
    Sync(StuckWait, Vec<String>),
}

impl Controller {
    /// Whether the run can no longer progress (the rule above). A task at a sync
    /// point waits for ever when every task of its list is a NORMAL task that waits
    /// so too; at least one task waits on an input.
    pub(crate) fn cannot_progress(&self) -> bool {
        self.stuck().is_some()
    }

    /// What each NORMAL task waits for, when the run can no longer progress; empty
    /// otherwise.
    pub fn stuck_waits(&self) -> Vec<StuckWait> {
        self.stuck().unwrap_or_default()
    }

    fn stuck(&self) -> Option<Vec<StuckWait>> {
        if self.program_state() != crate::ProgramState::Running {
            return None;
        }
        let io = self.shared.io();
        let system = io.system.as_ref()?;
        if system.next_event_time().is_some() || !io.stimulus.is_empty() || !io.path_orders.is_empty() {
            return None;
        }
        let outside = self.tasks.iter().any(|t| {
            let resources = t.loaded.vm.resources();
            crate::bindings::sockets::of(resources).is_some_and(|s| s.is_open())
                || resources.robot().still_from() > self.time
        });
        if outside {
            return None;
        }
        let waiting: Vec<usize> = (0..self.tasks.len())
            .filter(|&idx| {
                let task = &self.tasks[idx];
                task.spec.kind == TaskKind::Normal && !matches!(task.state, State::Ended(_))
            })
            .collect();
        let names: Vec<String> = waiting.iter().map(|&idx| self.tasks[idx].spec.name.to_ascii_lowercase()).collect();
        let mut waits = Vec::new();
        let mut inputs = 0;
        for &idx in &waiting {
            match self.endless_wait(idx)? {
                Wait::Input(wait) => {
                    inputs += 1;
                    waits.push(wait);
                }
                Wait::Sync(wait, list) if list.iter().all(|t| names.contains(t)) => waits.push(wait),
                Wait::Sync(..) => return None,
            }
        }
        (inputs > 0).then_some(waits)
    }

    /// Task `idx`'s wait, when it is one that cannot end by itself.
    fn endless_wait(&self, idx: usize) -> Option<Wait> {
        let task = &self.tasks[idx];
        let State::Waiting { rechecks: true, .. } = task.state else { return None };
        let vm = &task.loaded.vm;
        let interrupts = &vm.resources().interrupts;
        if interrupts.next_timer().is_some() || interrupts.watches_signals() {
            return None;
        }
        let statement = waiting_statement(vm)?;
        let lower = statement.to_ascii_lowercase();
        let (word, rest) = lower.split_once(char::is_whitespace)?;
        if lower.contains("\\maxtime") || lower.contains("\\timeout") {
            return None;
        }
        let args: Vec<&str> = rest.split(',').map(str::trim).collect();
        let at = self.location_of(idx)?;
        let mut wait = StuckWait {
            task: task.spec.name.clone(),
            statement: statement.clone(),
            why: String::new(),
            file: at.file,
            line: at.line,
            since: self.time,
        };
        if word == "waitsynctask" {
            let list = task_list(vm, args.get(1)?)?;
            wait.since = vm.resources().tasking().sync_wait_started().unwrap_or(self.time);
            wait.why = format!("its sync point's tasks {} wait too", list.join(", "));
            return Some(Wait::Sync(wait, list.iter().map(|t| t.to_ascii_lowercase()).collect()));
        }
        if !SIGNAL_WAITS.contains(&word) {
            return None;
        }
        let io = self.shared.io();
        let system = io.system.as_ref()?;
        let id = system.id(args.first()?)?;
        let def = system.def(id)?;
        if !def.kind.is_input() || system.is_cross_result(id) || io.reactions.iter().any(|r| r.target == id) {
            return None;
        }
        wait.since = vm.resources().wait_started().unwrap_or(self.time);
        wait.why = format!("{} is {}", def.name, system.value(id).unwrap_or(0.0));
        Some(Wait::Input(wait))
    }
}

/// The task names of the `tasks` array data `name` of task `vm` (WaitSyncTask's
/// list), when it is one.
fn task_list(vm: &Vm, name: &str) -> Option<Vec<String>> {
    let (global, _) = vm.global_by_name(name)?;
    let Value::Array(array) = vm.global(global)? else { return None };
    array
        .elems
        .iter()
        .map(|e| match e {
            Value::Record(r) => match r.fields.first() {
                Some(Value::Str(name)) => Some(name.to_string()),
                _ => None,
            },
            _ => None,
        })
        .collect()
}

/// The statement task `vm` stands on, white space run together.
fn waiting_statement(vm: &Vm) -> Option<String> {
    let (code, pc) = vm.top_position()?;
    let stmt = code.stmt_at(pc)?;
    let text = &vm.program_source(code.file)?.text;
    let written = text.get(stmt.span.start as usize..stmt.span.end as usize)?;
    let written = written.trim_end_matches(';');
    Some(written.split_whitespace().collect::<Vec<_>>().join(" "))
}
