//! The executor's side of interrupts (§1.11): noticing events (timers due, signal
//! changes) and running TRAP routines between instructions. While anything can fire,
//! `Vm::run` executes one instruction at a time and looks before each; waits end at
//! the next possible interrupt (`builtins::interrupts::next_due`) so traps run in time.

use super::Vm;
use crate::builtins::interrupts::{Source, FOREIGN_EVENT};
use crate::value::Value;

impl Vm {
    /// Queues the interrupts whose events have happened by now.
    pub(super) fn poll_interrupts(&mut self) {
        let now = self.time;
        for hooks in self.builtins.hooks() {
            hooks.poll(&mut self.resources, &self.storage, now);
        }
        let interrupts = &mut self.resources.interrupts;
        let mut fired = Vec::new();
        // Interrupts the robot's path triggers (TriggInt) at their time.
        interrupts.scheduled.retain(|&(t, number)| {
            let due = t <= now;
            if due {
                fired.push(number);
            }
            !due
        });
        for (idx, slot) in interrupts.table.iter_mut().enumerate() {
            let Some(interrupt) = slot else { continue };
            if let Some(Source::Timer { period, next, single }) = &mut interrupt.source {
                if *next <= now {
                    fired.push(idx as u32 + 1);
                    if *single {
                        interrupt.source = None;
                    } else {
                        *next += *period;
                    }
                }
            }
        }
        for (idx, slot) in self.resources.interrupts.table.iter_mut().enumerate() {
            let Some(interrupt) = slot else { continue };
            let Some(Source::Pers { place, last, single }) = &mut interrupt.source else { continue };
            let Ok(now_value) = self.storage.get(place) else { continue };
            if now_value != last {
                *last = now_value.clone();
                fired.push(idx as u32 + 1);
                if *single {
                    interrupt.source = None;
                }
            }
        }
        self.poll_error_interrupts();
        self.dispatch_messages();
        let interrupts = &mut self.resources.interrupts;
        if interrupts.watches_signals() {
            // The extension keeping the signals hands the changes since the last look.
            let from = interrupts.seen_changes;
            let mut changes = Vec::new();
            let mut seen = None;
            for hooks in self.builtins.hooks() {
                if let Some(len) = hooks.signal_changes(&mut self.resources, now, from, &mut changes) {
                    seen = Some(len);
                }
            }
            let interrupts = &mut self.resources.interrupts;
            for &(signal, new) in &changes {
                for (idx, slot) in interrupts.table.iter_mut().enumerate() {
                    let Some(interrupt) = slot else { continue };
                    let (fires, single) = match &mut interrupt.source {
                        Some(Source::Signal { id, value, single }) if *id == signal => {
                            (*value == 2.0 || *value == new, *single)
                        }
                        // ISignalAI/AO: every new value is a sample of the analog signal.
                        Some(Source::Analog { id, trigger, single }) if *id == signal => (trigger.sample(new), *single),
                        _ => continue,
                    };
                    if fires {
                        fired.push(idx as u32 + 1);
                        if single {
                            interrupt.source = None;
                        }
                    }
                }
            }
            interrupts.seen_changes = seen.unwrap_or(0);
        }
        for number in fired {
            self.resources.interrupts.fire(number);
        }
    }

    /// Interrupts for what reached the task from other tasks or from outside (RMQ
    /// messages, which the extension keeping the queues hands to the IRMQMessage trap
    /// ordered for their type: `TaskHooks::deliver`). Whatever reaches a task changes
    /// the shared change count (`SharedTasks::epoch`), so the extensions are asked
    /// only when it moved since they were last asked: once per run of a controller's
    /// task is a look at one number.
    pub(super) fn dispatch_messages(&mut self) {
        let epoch = self.resources.tasks.shared.epoch;
        if self.resources.tasks.delivered_at == Some(epoch) {
            return;
        }
        self.resources.tasks.delivered_at = Some(epoch);
        for hooks in self.builtins.hooks() {
            hooks.deliver(&mut self.resources);
        }
    }

    /// Queues the error interrupts (IError) of event-log entries logged since the last
    /// look, remembering which entry fired each (GetTrapData).
    fn poll_error_interrupts(&mut self) {
        let first_unseen = self.resources.interrupts.next_event;
        let mut fired = Vec::new();
        for event in self.events.entries().iter().filter(|e| e.seq >= first_unseen) {
            fired.extend(self.resources.interrupts.error_interrupts_for(event).map(|number| (number, event.seq)));
        }
        if let Some(last) = self.events.entries().last() {
            self.resources.interrupts.next_event = first_unseen.max(last.seq + 1);
        }
        fired.extend(self.foreign_error_events());
        for (number, seq) in fired {
            let before = self.resources.interrupts.queue.len();
            self.resources.interrupts.fire(number);
            if self.resources.interrupts.queue.len() > before {
                self.resources.interrupts.events.push((number, seq));
            }
        }
    }

    /// IError on the other tasks' entries of the controller-wide log: (interrupt,
    /// entry named with [`FOREIGN_EVENT`]).
    fn foreign_error_events(&mut self) -> Vec<(u32, u64)> {
        let me = self.resources.tasks.index();
        let shared = &self.resources.tasks.shared.events;
        let start = self.resources.interrupts.next_foreign.min(shared.len());
        let mut fired = Vec::new();
        for (offset, (task, event)) in shared[start..].iter().enumerate() {
            if *task == me {
                continue;
            }
            let entry = FOREIGN_EVENT | (start + offset) as u64;
            fired.extend(self.resources.interrupts.error_interrupts_for(event).map(|number| (number, entry)));
        }
        self.resources.interrupts.next_foreign = shared.len();
        fired
    }

    /// While the program waits for the robot (a move with interrupts ordered), the wait
    /// is cut at the next interrupt that may come, so its trap runs while the robot
    /// moves (§1.11); the rest of the wait follows here, before the next instruction.
    /// None once the robot's time has come, or while a trap runs.
    pub(super) fn motion_hold(&mut self) -> Option<f64> {
        let until = self.program_hold()?;
        if until <= self.time {
            for hooks in self.builtins.hooks() {
                hooks.release_hold(&mut self.resources);
            }
            return None;
        }
        if self.frames.iter().any(|f| f.interrupted) {
            return None;
        }
        let signals = if self.resources.interrupts.watches_signals() { self.next_extension_event() } else { None };
        let next = [self.resources.interrupts.next_timer(), signals].into_iter().flatten().fold(until, f64::min);
        self.wait_rechecks = true;
        // A robot held by StopMove waits for ever: look again within the hour.
        Some((next - self.time).clamp(1e-6, 3600.0))
    }

    /// Starts the trap of the first queued interrupt, when one may run now: interrupts
    /// are enabled, no trap is running, and the interrupted routine is between
    /// instructions (at the start of a statement).
    pub(super) fn enter_trap_if_due(&mut self) {
        let interrupts = &self.resources.interrupts;
        // A stopped program (also while it is stepped) runs no trap: the safe
        // interrupts queued wait for the start (§1.11).
        if interrupts.queue.is_empty()
            || interrupts.disabled
            || interrupts.stop.is_some()
            || self.frames.iter().any(|f| f.interrupted)
        {
            return;
        }
        let Some(top) = self.frames.last() else { return };
        // Between instructions: at a statement's start, or at the routine's end, or
        // between two polls of WaitUntil, which the traps' data may end, or while a
        // move's wait for the robot is held (§1.11: traps run "at any time" during wait
        // and move instructions). The held wait follows the move's statement wherever
        // the next instruction is: a statement's start, but also the jump that ends an
        // IF's THEN branch or a loop's body, where the operand stack is as empty as
        // between statements.
        let at_statement = top.code.stmt_at(top.pc).is_some_and(|s| s.start == top.pc)
            || matches!(top.code.instrs.get(top.pc as usize), Some(crate::ir::Instr::FellOffEnd))
            || matches!(top.code.instrs.get((top.pc as usize).wrapping_sub(1)), Some(crate::ir::Instr::WaitPop))
            || self.program_hold().is_some_and(|until| until > self.time);
        if !at_statement || top.undoing || self.exiting {
            return;
        }
        let Some(number) = self.resources.interrupts.queue.pop_front() else { return };
        let interrupts = &mut self.resources.interrupts;
        interrupts.trap_event =
            interrupts.events.iter().position(|&(n, _)| n == number).map(|i| interrupts.events.remove(i).1);
        let trap = self.resources.interrupts.get_mut(number).map(|i| i.trap);
        self.resources.interrupts.started(number);
        let Some(code) = trap.and_then(|t| self.routines.get(t as usize).cloned().flatten()) else { return };
        if let Some(global) = self.intno_global {
            if let Some(slot) = self.storage.globals.get_mut(global) {
                *slot = Value::Num(number as f32);
            }
        }
        let resume = top.pc;
        self.push_frame(code, Vec::new());
        let frame = self.frame_mut();
        frame.return_to = Some(resume);
        frame.interrupted = true;
    }
}
