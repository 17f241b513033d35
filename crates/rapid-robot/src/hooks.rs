//! The robot as an extension of the language (`rapid_vm::ext`): its families and the
//! hooks through which the interpreter's loop asks it about the move under way. The
//! core loop reaches the robot only through these.

use crate::RobotResources;
use rapid_sema::symbols::Def;

use super::{syncmove, sysdata};
use super::{MotionLinks, RobotSide};
use rapid_vm::ext::{Ctx, Extension, PendingEvent, RapidError, Resources, Storage, TaskHooks};

/// The robot's built-ins and hooks.
pub static EXTENSION: Extension = Extension {
    name: "robot",
    families: &[&syncmove::FAMILY, &sysdata::FAMILY, &super::FAMILY],
    hooks: Some(&RobotHooks),
    init: Some(|resources| resources.extensions.insert(super::RobotSide::default())),
};

/// The motion event of a fly-by point run as a stop point: (number, title).
const CORNER_PATH_FAILURE: (u32, &str) = (24, "Corner path failure");

struct RobotHooks;

/// The warning of a fly-by point run as a stop point at `now`, to be placed at `at`.
fn corner_failure(now: f64, at: Option<(usize, rapid_syntax::Span)>) -> PendingEvent {
    let event = rapid_vm::ext::Event {
        seq: 0,
        domain: rapid_vm::ext::MOTION_DOMAIN,
        number: CORNER_PATH_FAILURE.0,
        kind: rapid_vm::ext::EventKind::Warning,
        time: now,
        title: CORNER_PATH_FAILURE.1.to_string(),
        details: Vec::new(),
        lines: vec!["The fly-by point was run as a stop point: no next move was ready in time.".to_string()],
        place: None,
    };
    PendingEvent { event, at }
}

impl TaskHooks for RobotHooks {
    fn stands_still(&self, ctx: &mut Ctx<'_>) -> Result<bool, RapidError> {
        syncmove::robot_stands(ctx)
    }

    fn exit_cycle(&self, ctx: &mut Ctx<'_>) -> Result<(), RapidError> {
        super::abandon_paths(ctx)
    }

    fn program_hold(&self, resources: &Resources) -> Option<f64> {
        resources.robot().program_hold()
    }

    fn release_hold(&self, resources: &mut Resources) {
        resources.robot_mut().hold_until = None;
    }

    fn held(&self, resources: &Resources) -> bool {
        resources.robot().pause.is_some()
    }

    fn poll(&self, resources: &mut Resources, storage: &Storage, now: f64) {
        // Trigger actions decided at the robot's place (TriggCheckIO, `\Inhib`).
        super::poll_triggers(resources, storage, now);
    }

    fn program_stopped(&self, resources: &mut Resources, storage: &mut Storage, now: f64) {
        // TriggStopProc's supervision sees the program stop.
        super::program_stopped(resources, storage, now);
    }

    fn after_builtin(&self, resources: &mut Resources, now: f64, events: &mut Vec<PendingEvent>) -> bool {
        let Some(side) = resources.extensions.get_mut::<RobotSide>() else { return false };
        if !side.robot.corner_failures.is_empty() {
            let failures = std::mem::take(&mut side.robot.corner_failures);
            if side.motion.settings.corner_path_warning {
                events.extend(failures.into_iter().map(|at| corner_failure(now, at)));
            }
        }
        // Another task reading this task's external axes sees its path stop and go on.
        side.robot.publish_pause();
        side.robot.program_hold().is_some()
    }

    /// The motion warning for each fly-by point that became a stop point since the last
    /// look (the robot had to stop there: the next move came too late), placed at the
    /// move that programmed it; `CornerPathWarning FALSE` keeps them out of the log.
    // uncertain: number and title as we remember RobotWare 6's event log (50024 "Corner
    // path failure"); the message line is ours.
    fn take_events(&self, resources: &mut Resources, now: f64) -> Vec<PendingEvent> {
        let Some(side) = resources.extensions.get_mut::<RobotSide>() else { return Vec::new() };
        let failures = std::mem::take(&mut side.robot.corner_failures);
        if !side.motion.settings.corner_path_warning {
            return Vec::new();
        }
        failures.into_iter().map(|at| corner_failure(now, at)).collect()
    }

    fn loaded(&self, resources: &mut Resources, prog: &rapid_sema::Program) {
        let global_named = |name: &str| match prog.interner.get(name).and_then(|sym| prog.scopes.builtins.get(&sym)) {
            Some(Def::Data(idx)) => Some(*idx),
            _ => None,
        };
        resources.motion_mut().links = MotionLinks {
            motset: global_named("C_MOTSET"),
            progdisp: global_named("C_PROGDISP"),
            pose: prog.types.find("pose"),
            sysdata: [global_named("tool0"), global_named("wobj0"), global_named("load0")],
        };
    }
}
