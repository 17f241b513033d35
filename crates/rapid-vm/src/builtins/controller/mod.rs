//! Controller-level support (manual §1.17, §1.20): the state the controller keeps
//! outside any program — operating mode, the operator's speed override, the program
//! pointer flags, a requested warm start — and the built-ins that read or change it:
//! OpMode's answer (sysinfo.rs reads [`ControllerState::mode`]), CSpeedOverride's
//! (motion reads [`ControllerState::speed_override`]), ResetPPMoved,
//! PPMovedInManMode, IsStopStateEvent and WarmStart here. (Task and mechanical unit
//! information is the tasks extension's, rapid-tasks; the active tool, work object and
//! payload are the robot's.)
//!
//! `rapid run` sets the mode and the override once, before the program starts
//! (`--mode`, `--speed-override`); nothing changes them while it runs, as on a real
//! controller where only the operator turns the key or moves the override.

use super::{native, present, Ctx, Family, StopKind};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::Value;

type Res = Result<Option<Value>, RapidError>;

pub(super) static FAMILY: Family = Family {
    file: file!(),
    builtins: &[
        native("ResetPPMoved", reset_pp_moved),
        native("PPMovedInManMode", pp_moved_in_man_mode),
        native("IsStopStateEvent", is_stop_state_event),
        native("WarmStart", warm_start),
    ],
};

/// The TCP speed limit of manual reduced speed mode, in mm/s (manual: in manual
/// reduced speed the robot moves at most 250 mm/s, whatever the program asks).
pub const MANUAL_REDUCED_TCP_LIMIT: f64 = 250.0;

/// The position of the operating mode key; the number is OpMode's symnum.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum OpMode {
    /// OP_AUTO: production, no enabling device.
    #[default]
    Auto = 1,
    /// OP_MAN_PROG: manual reduced speed (TCP at most 250 mm/s).
    ManualReduced = 2,
    /// OP_MAN_TEST: manual full speed.
    ManualFull = 3,
}

impl OpMode {
    pub fn is_manual(self) -> bool {
        self != OpMode::Auto
    }

    /// The value OpMode() returns (OP_AUTO 1, OP_MAN_PROG 2, OP_MAN_TEST 3).
    pub fn symnum(self) -> f32 {
        f32::from(self as u8)
    }
}

/// How the program is being run, as RunMode reports it (its symnum: RUN_CONT_CYCLE 1,
/// RUN_INSTR_FWD 2, RUN_INSTR_BWD 3, RUN_STEP_MOVE 5). The controller sets it as the
/// operator starts or steps the program; `rapid run` runs continuously.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum RunMode {
    /// Continuous or cycle running.
    #[default]
    ContCycle = 1,
    /// Stepping forward (FWD step: step into, over, out).
    InstrFwd = 2,
    /// Stepping backward (BWD step).
    InstrBwd = 3,
    /// Running to the next motion instruction (move step).
    StepMove = 5,
}

impl RunMode {
    /// The value RunMode() returns.
    pub fn symnum(self) -> f32 {
        f32::from(self as u8)
    }

    /// Whether a move instruction ends with the robot standing at its target, its
    /// zone taken as a stop point. The overview manual's figure of step execution
    /// ("step forward until the robot is at p5… the second forward step moves the
    /// robot to p2") has each forward step of a move end with the robot at the
    /// programmed point, and a forward step of MoveC stop the robot at its circle
    /// point; a fly-by point would leave it short, moving on while the program stands.
    // uncertain: the manual says nothing of a move step (RUN_STEP_MOVE) ending at its
    // target; we take it as a forward step that goes on to the next move.
    pub fn moves_end_at_targets(self) -> bool {
        self != RunMode::ContCycle
    }
}

/// What the controller keeps for the task outside the program.
#[derive(Debug, Clone)]
pub struct ControllerState {
    /// The operating mode key.
    pub mode: OpMode,
    /// The operator's speed override on the FlexPendant, percent (1..100).
    pub speed_override: f64,
    /// The PP was moved by the operator in manual mode (PPMovedInManMode); cleared by
    /// ResetPPMoved.
    pp_moved_in_man: bool,
    /// During the stop state before the start the PP was moved (\PPMoved), to Main
    /// or to a routine (\PPToMain): IsStopStateEvent.
    stop_pp_moved: bool,
    stop_pp_to_main: bool,
    /// WarmStart was executed: the run ends and the caller reports the restart.
    pub warm_start: bool,
    /// `Stop \AllMoveTasks` was executed: the other NORMAL tasks stop too.
    pub stop_all_moves: bool,
    /// How the program is being run (RunMode): set by the controller as it starts or
    /// steps the program.
    pub run_mode: RunMode,
}

impl Default for ControllerState {
    fn default() -> ControllerState {
        ControllerState::new(OpMode::Auto, 100.0)
    }
}

impl ControllerState {
    /// The state at the start of `rapid run`: the operator loaded the program, put
    /// the mode key at `mode`, the override at `speed_override`, moved the PP to Main
    /// and pressed Start. That PP to Main is the one PP move of the run: it happened
    /// in the stop state before the start, and in manual mode it counts as moved in
    /// manual mode.
    // uncertain: the manual does not say whether loading a program and PP to Main
    // before the first start set these flags; we take the start of `rapid run` as the
    // operator's PP to Main + Start, so a program sees that its PP was put at Main.
    pub fn new(mode: OpMode, speed_override: f64) -> ControllerState {
        ControllerState {
            mode,
            speed_override,
            pp_moved_in_man: mode.is_manual(),
            stop_pp_moved: true,
            stop_pp_to_main: true,
            warm_start: false,
            stop_all_moves: false,
            run_mode: RunMode::ContCycle,
        }
    }

    /// The TCP speed limit the mode imposes on every movement, mm/s, for the motion
    /// planner: 250 in manual reduced speed, none otherwise.
    pub fn tcp_speed_limit(&self) -> Option<f64> {
        match self.mode {
            OpMode::ManualReduced => Some(MANUAL_REDUCED_TCP_LIMIT),
            OpMode::Auto | OpMode::ManualFull => None,
        }
    }
}

/// `ResetPPMoved`: clears the "PP moved in manual mode" state.
fn reset_pp_moved(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    ctx.resources.controller.pp_moved_in_man = false;
    Ok(None)
}

/// `PPMovedInManMode()`: TRUE when the operator moved the PP in manual mode since
/// the last ResetPPMoved (see [`ControllerState::new`]: the PP to Main before a
/// manual-mode run counts).
fn pp_moved_in_man_mode(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    let controller = &ctx.resources.controller;
    Ok(Some(Value::Bool(controller.mode.is_manual() && controller.pp_moved_in_man)))
}

/// `IsStopStateEvent([\PPMoved] | [\PPToMain])`: whether the PP was moved (or moved
/// to Main or a routine) during the last stop state. `rapid run` starts once, after
/// a PP to Main, and never stops and restarts, so both stay TRUE for the whole run.
// uncertain: with neither switch the manual gives no answer; ERR_ARGVALERR here, as
// GetSysInfo without a switch.
fn is_stop_state_event(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let controller = &ctx.resources.controller;
    let answer = if present(args.first()) {
        controller.stop_pp_moved
    } else if present(args.get(1)) {
        controller.stop_pp_to_main
    } else {
        return Err(ctx.error(Err::ArgValue, "IsStopStateEvent needs \\PPMoved or \\PPToMain"));
    };
    Ok(Some(Value::Bool(answer)))
}

/// `WarmStart`: restarts the controller. A restart would start the program again
/// from power on and so run forever; the run ends here instead, as a stop, and
/// `rapid run` says that a warm start was requested (exit status 0).
fn warm_start(ctx: &mut Ctx<'_>, _args: &[Value]) -> Res {
    ctx.resources.controller.warm_start = true;
    ctx.stop = StopKind::Stop;
    Ok(None)
}
