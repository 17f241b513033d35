//! Signal interrupts (§1.11): ISignalDI, ISignalDO, ISignalGI, ISignalGO, ISignalAI,
//! ISignalAO order an interrupt on a signal's changes. The interrupt table, its queue
//! and the traps are the interpreter's (`rapid_vm::builtins::interrupts`); this family
//! sets the interrupt's source, and the executor matches the changes the I/O hands it
//! (`TaskHooks::signal_changes`, in `io.rs`) against it.

use rapid_vm::ext::{
    interrupt_number, present, AnalogTrigger, Ctx, Err, Family, InterruptSource as Source, RapidError, SampleTrigger,
    Value,
};

use crate::io::{connected, IoAccess};

type Res = Result<Option<Value>, RapidError>;

rapid_vm::ext::layout! {
    static ISIGNAL_D: DigitalArgs = "ISignalDI" | "ISignalDO" {
        single: "Single", single_safe: "SingleSafe", signal: "Signal", trigg_value: "TriggValue", interrupt: "Interrupt",
    }
    static ISIGNAL_G: GroupArgs = "ISignalGI" | "ISignalGO" {
        single: "Single", single_safe: "SingleSafe", signal: "Signal", interrupt: "Interrupt",
    }
    static ISIGNAL_A: AnalogArgs = "ISignalAI" | "ISignalAO" {
        single: "Single", single_safe: "SingleSafe", signal: "Signal", condition: "Condition", high: "HighValue",
        low: "LowValue", delta: "DeltaValue", dpos: "DPos", dneg: "DNeg", interrupt: "Interrupt",
    }
}

/// `rapid_io::AnalogTrigger` as the interpreter's analog interrupt condition.
#[derive(Debug, Clone)]
struct Analog(rapid_io::AnalogTrigger);

impl SampleTrigger for Analog {
    fn sample(&mut self, value: f64) -> bool {
        self.0.sample(value)
    }

    fn clone_box(&self) -> Box<dyn SampleTrigger> {
        Box::new(self.clone())
    }
}

/// `ISignalDI/ISignalDO [\Single] | [\SingleSafe] Signal TriggValue Interrupt`:
/// TriggValue 0 (falling to 0), 1 (rising to 1) or 2 (any change).
fn isignal_digital(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *ISIGNAL_D;
    let single = present(args.get(at.single)) || present(args.get(at.single_safe));
    let id = connected(ctx, &args[at.signal])?;
    let value = ctx.num(&args[at.trigg_value])?;
    if ![0.0, 1.0, 2.0].contains(&value) {
        return Err(ctx.error(Err::ArgValue, format!("TriggValue {value} is not 0, 1 or 2")));
    }
    let n = interrupt_number(ctx, &args[at.interrupt])?;
    watch_signal(ctx, n, Source::Signal { id, value, single }, present(args.get(at.single_safe)));
    Ok(None)
}

/// `ISignalGI/ISignalGO [\Single] | [\SingleSafe] Signal Interrupt`: every change of the
/// group's value.
fn isignal_group(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *ISIGNAL_G;
    let single = present(args.get(at.single)) || present(args.get(at.single_safe));
    let id = connected(ctx, &args[at.signal])?;
    let n = interrupt_number(ctx, &args[at.interrupt])?;
    watch_signal(ctx, n, Source::Signal { id, value: 2.0, single }, present(args.get(at.single_safe)));
    Ok(None)
}

/// `ISignalAI/ISignalAO [\Single] | [\SingleSafe] Signal Condition HighValue LowValue
/// DeltaValue [\DPos] | [\DNeg] Interrupt`: new values of an analog signal that meet
/// the condition (`rapid_io::AnalogTrigger`); the reference value is the signal's value now.
fn isignal_analog(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *ISIGNAL_A;
    let single = present(args.get(at.single)) || present(args.get(at.single_safe));
    let id = connected(ctx, &args[at.signal])?;
    let condition = ctx.num(&args[at.condition])?;
    let (high, low, delta) = (ctx.num(&args[at.high])?, ctx.num(&args[at.low])?, ctx.num(&args[at.delta])?);
    let direction = if present(args.get(at.dpos)) {
        rapid_io::AioDirection::Pos
    } else if present(args.get(at.dneg)) {
        rapid_io::AioDirection::Neg
    } else {
        rapid_io::AioDirection::Both
    };
    let current = ctx.resources.io().system.as_ref().and_then(|io| io.value(id)).unwrap_or(0.0);
    let trigger = rapid_io::AnalogTrigger::new(condition, high, low, delta, direction, current)
        .map_err(|err| ctx.error(Err::ArgValue, err.to_string()))?;
    let trigger = AnalogTrigger(Box::new(Analog(trigger)));
    let n = interrupt_number(ctx, &args[at.interrupt])?;
    watch_signal(ctx, n, Source::Analog { id, trigger, single }, present(args.get(at.single_safe)));
    Ok(None)
}

/// Orders interrupt `n` on a signal (`safe`: `\SingleSafe`): only changes from now on
/// count.
fn watch_signal(ctx: &mut Ctx<'_>, n: u32, source: Source, safe: bool) {
    let logged = ctx.resources.io().system.as_ref().map_or(0, |io| io.changes().len());
    let interrupts = &mut ctx.resources.interrupts;
    interrupts.seen_changes = interrupts.seen_changes.max(logged);
    if let Some(interrupt) = interrupts.get_mut(n) {
        interrupt.source = Some(source);
        interrupt.safe = safe;
    }
}

pub(crate) static FAMILY: Family = Family {
    file: file!(),
    builtins: &[
        rapid_vm::ext::native("ISignalDI", isignal_digital),
        rapid_vm::ext::native("ISignalDO", isignal_digital),
        rapid_vm::ext::native("ISignalGI", isignal_group),
        rapid_vm::ext::native("ISignalGO", isignal_group),
        rapid_vm::ext::native("ISignalAI", isignal_analog),
        rapid_vm::ext::native("ISignalAO", isignal_analog),
    ],
};
