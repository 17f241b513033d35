//! The executor's entries in the task's event log (§1.12): the system error handler's
//! entry for an unhandled error, the warning a handled error leaves, and where each
//! happened.

use super::{Exit, Frame, Vm};
use crate::error::RapidError;

impl Vm {
    /// The system error handler's event-log entry for an error nothing handled:
    /// program domain, the error's number, its name and message, where it happened.
    /// The controller's own numbering of these entries is not public (uncertain).
    pub(super) fn log_if_unhandled(&mut self, exit: &Exit) {
        let Exit::Unhandled(unhandled) = exit else { return };
        let place = crate::events::EventPlace {
            routine: unhandled.routine.clone(),
            file: unhandled.file,
            span: unhandled.span,
        };
        self.log_program_event(crate::events::EventKind::Error, &unhandled.error, place);
    }

    /// Logs `error` in the program domain; returns the entry's index. An error that
    /// an ERROR handler takes still leaves a warning (§1.12), one that none takes an
    /// error entry from the system error handler. Returns the entry's number.
    pub(super) fn log_program_event(
        &mut self,
        kind: crate::events::EventKind,
        error: &RapidError,
        place: crate::events::EventPlace,
    ) -> u64 {
        let (domain, number) = match error.event {
            Some(code) => (code / 10_000, code % 10_000),
            None => (crate::events::PROGRAM_DOMAIN, u32::try_from(error.errno).unwrap_or(0)),
        };
        // A short title and the message in short strings, as the controller logs its
        // errors (a program that joins them into one string of its own still fits).
        let (title, details) =
            crate::events::split_error_text(error.name, error.errno, &error.message, error.event.is_some());
        self.events.push(crate::events::Event {
            seq: 0,
            domain,
            number,
            kind,
            time: self.time,
            title,
            details,
            lines: vec![format!("routine {}", place.routine)],
            place: Some(place),
        })
    }

    /// Logs what the extensions noticed since they were last asked (a robot's fly-by
    /// points run as stop points), each placed at its statement.
    pub fn log_extension_events(&mut self) {
        for at in 0..self.builtins.hooks().len() {
            let hooks = self.builtins.hooks()[at];
            let events = hooks.take_events(&mut self.resources, self.time);
            self.log_pending(events);
        }
    }

    /// Logs events an extension handed over, placing each at its statement and the
    /// routine that holds it.
    pub(super) fn log_pending(&mut self, events: Vec<crate::embed::PendingEvent>) {
        for pending in events {
            let place = pending.at.map(|(file, span)| crate::events::EventPlace {
                routine: self.routine_holding(file, span).unwrap_or_default(),
                file,
                span,
            });
            self.events.push(crate::events::Event { place, ..pending.event });
        }
    }

    /// The name of the routine whose code in `file` holds the statement at `span`.
    fn routine_holding(&self, file: usize, span: rapid_syntax::Span) -> Option<String> {
        let holds =
            |c: &&std::rc::Rc<crate::ir::Code>| c.file == file && c.span.start <= span.start && span.end <= c.span.end;
        self.routines.iter().flatten().find(holds).map(|c| c.name.clone())
    }

    /// Where `frame` is: its routine and the statement at its PC (for a caller, its call).
    pub(super) fn place_of(frame: &Frame) -> crate::events::EventPlace {
        let span = frame.code.stmt_at(frame.pc).map_or(frame.code.span, |s| s.span);
        crate::events::EventPlace { routine: frame.code.name.clone(), file: frame.code.file, span }
    }

    /// SkipWarn: the warning of the error the running handler took is not kept.
    pub(super) fn drop_handled_warning(&mut self) {
        let warning = self.frames.last_mut().and_then(|f| f.active.as_mut()).and_then(|a| a.warning.take());
        if let Some(seq) = warning {
            self.events.remove(seq);
        }
    }
}
