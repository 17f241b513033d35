//! TriggStopProc: a supervision that, when the program stops, sets the process
//! outputs (DO1, GO1 … GO4) to 0 and records in a restartdata persistent what they
//! and the shadow output were, so a restart can take the process up again.
//!
//! What `rapid run` can show: a `Stop` (or `Break`) instruction. Stopped while the
//! robot moves, the robot stops on its path there (as StopMove: what the path would
//! still set is held) and `restartstop` and `stoponpath` are TRUE. The robot is taken
//! to stand at once, so the values before the stop and at standstill are the same and
//! the shadow output has no flanks in between. A quick stop (QSTOP: emergency stop) or
//! the operator's stop do not happen in `rapid run`.

use crate::RobotResources;
use std::rc::Rc;

use super::Res;
use rapid_signals::IoAccess;
use rapid_vm::ext::{present, Ctx, Err, Place, Resources, Storage, Value};

/// The supervision TriggStopProc set up.
#[derive(Debug, Clone, PartialEq)]
pub struct StopProc {
    /// The restartdata persistent.
    restart: Place,
    do1: Option<u32>,
    go: [Option<u32>; 4],
    shadow: u32,
}

rapid_vm::ext::layout! {
    static TRIGG_STOP_PROC: TriggStopProcArgs = "TriggStopProc" {
        do1: "DO1", go1: "GO1", go2: "GO2", go3: "GO3", go4: "GO4", shadow: "ShadowDO",
    }
}

/// `TriggStopProc RestartRef [\DO1] [\GO1] [\GO2] [\GO3] [\GO4] ShadowDO`: from now on,
/// every program stop sets the process outputs to 0 and fills RestartRef.
// uncertain: a second TriggStopProc replaces the first (one supervision per task).
pub(crate) fn trigg_stop_proc(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *TRIGG_STOP_PROC;
    let Value::Ref(restart) = &args[0] else {
        return Err(ctx.error(Err::ArgValue, "TriggStopProc's RestartRef must be a persistent restartdata"));
    };
    let restart = (**restart).clone();
    let mut signal = |idx: usize| -> Result<Option<u32>, rapid_vm::ext::RapidError> {
        if present(args.get(idx)) {
            rapid_signals::signal(ctx, &args[idx]).map(Some)
        } else {
            Ok(None)
        }
    };
    let do1 = signal(at.do1)?;
    let go = [signal(at.go1)?, signal(at.go2)?, signal(at.go3)?, signal(at.go4)?];
    let shadow = rapid_signals::signal(ctx, &args[at.shadow])?;
    ctx.resources.robot_mut().trigg.stop_proc = Some(StopProc { restart, do1, go, shadow });
    Ok(None)
}

/// The program stopped at `now` (Stop, Break): the supervision's work.
pub(crate) fn program_stopped(resources: &mut Resources, storage: &mut Storage, now: f64) {
    let Some(proc) = resources.robot_mut().trigg.stop_proc.clone() else { return };
    let moving = resources.robot_mut().moving_at(now);
    if moving {
        super::super::pause::hold(resources, now);
    }
    resources.io_mut().advance(now);
    let value = |id: Option<u32>| id.and_then(|id| resources.io().system.as_ref()?.value(id)).unwrap_or(0.0);
    let process = [proc.do1, proc.go[0], proc.go[1], proc.go[2], proc.go[3]].map(value);
    let shadow = value(Some(proc.shadow));
    let num = |x: f64| Value::Num(x as f32);
    // restartstop, stoponpath, then (pre, post) of DO1 and GO1 … GO4, preshadowval,
    // shadowflanks, postshadowval.
    let mut fields = vec![Value::Bool(moving), Value::Bool(moving)];
    for v in process {
        fields.extend([num(v), num(v)]);
    }
    fields.extend([num(shadow), num(0.0), num(shadow)]);
    if let Ok(Value::Record(record)) = storage.get(&proc.restart).cloned() {
        let mut record = record;
        let target = Rc::make_mut(&mut record);
        for (slot, field) in target.fields.iter_mut().zip(fields) {
            *slot = field;
        }
        let _ = storage.set(&proc.restart, Value::Record(record));
    }
    let outputs = [proc.do1, proc.go[0], proc.go[1], proc.go[2], proc.go[3]];
    if let Some(io) = resources.io_mut().system.as_mut() {
        for id in outputs.into_iter().flatten() {
            let _ = io.set(id, 0.0, now);
        }
    }
}
