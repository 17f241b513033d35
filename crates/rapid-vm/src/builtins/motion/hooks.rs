//! The robot as an extension of the language (`crate::embed`): its families and the
//! hooks through which the interpreter's loop asks it about the move under way. The
//! core loop reaches the robot only through these.

use rapid_sema::symbols::Def;

use super::super::syncmove;
use super::MotionLinks;
use crate::builtins::Resources;
use crate::embed::{Extension, PendingEvent, TaskHooks};
use crate::exec::storage::Storage;

/// The robot's built-ins and hooks.
pub static EXTENSION: Extension =
    Extension { name: "robot", families: &[&syncmove::FAMILY, &super::FAMILY], hooks: Some(&RobotHooks), init: None };

/// The motion event of a fly-by point run as a stop point: (number, title).
const CORNER_PATH_FAILURE: (u32, &str) = (24, "Corner path failure");

struct RobotHooks;

impl TaskHooks for RobotHooks {
    fn program_hold(&self, resources: &Resources) -> Option<f64> {
        resources.robot.program_hold()
    }

    fn release_hold(&self, resources: &mut Resources) {
        resources.robot.hold_until = None;
    }

    fn held(&self, resources: &Resources) -> bool {
        resources.robot.pause.is_some()
    }

    fn poll(&self, resources: &mut Resources, storage: &Storage, now: f64) {
        // Trigger actions decided at the robot's place (TriggCheckIO, `\Inhib`).
        super::poll_triggers(resources, storage, now);
    }

    fn program_stopped(&self, resources: &mut Resources, storage: &mut Storage, now: f64) {
        // TriggStopProc's supervision sees the program stop.
        super::program_stopped(resources, storage, now);
    }

    fn after_builtin(&self, resources: &mut Resources) {
        // Another task reading this task's external axes sees its path stop and go on.
        resources.robot.publish_pause();
    }

    /// The motion warning for each fly-by point that became a stop point since the last
    /// look (the robot had to stop there: the next move came too late), placed at the
    /// move that programmed it; `CornerPathWarning FALSE` keeps them out of the log.
    // uncertain: number and title as we remember RobotWare 6's event log (50024 "Corner
    // path failure"); the message line is ours.
    fn take_events(&self, resources: &mut Resources, now: f64) -> Vec<PendingEvent> {
        if resources.robot.corner_failures.is_empty() {
            return Vec::new();
        }
        let failures = std::mem::take(&mut resources.robot.corner_failures);
        if !resources.motion.settings.corner_path_warning {
            return Vec::new();
        }
        let event = || crate::events::Event {
            seq: 0,
            domain: crate::events::MOTION_DOMAIN,
            number: CORNER_PATH_FAILURE.0,
            kind: crate::events::EventKind::Warning,
            time: now,
            title: CORNER_PATH_FAILURE.1.to_string(),
            details: Vec::new(),
            lines: vec!["The fly-by point was run as a stop point: no next move was ready in time.".to_string()],
            place: None,
        };
        failures.into_iter().map(|at| PendingEvent { event: event(), at }).collect()
    }

    fn loaded(&self, resources: &mut Resources, prog: &rapid_sema::Program) {
        let global_named = |name: &str| match prog.interner.get(name).and_then(|sym| prog.scopes.builtins.get(&sym)) {
            Some(Def::Data(idx)) => Some(*idx),
            _ => None,
        };
        resources.motion.links = MotionLinks {
            motset: global_named("C_MOTSET"),
            progdisp: global_named("C_PROGDISP"),
            pose: prog.types.find("pose"),
            sysdata: [global_named("tool0"), global_named("wobj0"), global_named("load0")],
        };
    }
}
