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
        self.events.push(crate::events::Event {
            seq: 0,
            domain: crate::events::PROGRAM_DOMAIN,
            number: u32::try_from(error.errno).unwrap_or(0),
            kind,
            time: self.time,
            title: error.to_string(),
            lines: vec![format!("routine {}", place.routine)],
            place: Some(place),
        })
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
