//! Waiting for signals (§1.9): WaitDI, WaitDO, WaitGI, WaitGO, WaitAI, WaitAO with
//! `\MaxTime` (ERR_WAIT_MAXTIME), `\TimeFlag` (DI/DO: no error, the flag is set) and
//! `\ValueAtTimeout` (groups and analog signals: the value when time ran out).
//!
//! While the condition does not hold, the instruction waits until the next signal
//! change the I/O system knows of (a scheduled order, a stimulus) or the deadline, and
//! is run again (`StopKind::Repeat`). The start of the wait is kept per call depth and
//! instruction, so the deadline counts from the first try.

use std::sync::LazyLock;

use rapid_vm::ext::{
    native, present, visualize_step, wait_again, wait_started, BoxArgs, Ctx, Err, Family, RapidError, Value,
};

use crate::io::{signal, IoAccess};

type Res = Result<Option<Value>, RapidError>;

/// What a wait compares the signal with.
#[derive(Clone, Copy)]
enum Compare {
    Eq,
    NotEq,
    Lt,
    Gt,
}

impl Compare {
    fn holds(self, value: f64, target: f64) -> bool {
        match self {
            Compare::Eq => value == target,
            Compare::NotEq => value != target,
            Compare::Lt => value < target,
            Compare::Gt => value > target,
        }
    }
}

/// Where the arguments of one wait instruction are (`signature::ABSENT` where it has
/// no such parameter).
#[derive(Debug, PartialEq, Eq)]
struct Layout {
    signal: usize,
    /// WaitGI/GO's `\NOTEQ`, `\LT`, `\GT`; WaitAI/AO's `\LT`, `\GT`.
    not_eq: usize,
    lt: usize,
    gt: usize,
    value: usize,
    dvalue: Option<usize>,
    max_time: usize,
    /// `\TimeFlag` (DI/DO) or `\ValueAtTimeout` (and `\DvalueAtTimeout`).
    time_flag: Option<usize>,
    at_timeout: Option<(usize, Option<usize>)>,
    visualize: usize,
}

impl Layout {
    /// The layout of wait instruction `name`, by the parameter names of its
    /// declaration (see `signature.rs`).
    fn of(name: &str) -> Layout {
        let sig = rapid_vm::ext::signature(name);
        Layout {
            signal: sig.at("Signal"),
            not_eq: sig.at("NOTEQ"),
            lt: sig.at("LT"),
            gt: sig.at("GT"),
            value: sig.at("Value"),
            dvalue: sig.opt("Dvalue"),
            max_time: sig.at("MaxTime"),
            time_flag: sig.opt("TimeFlag"),
            at_timeout: sig.opt("ValueAtTimeout").map(|at| (at, sig.opt("DvalueAtTimeout"))),
            visualize: sig.at("Visualize"),
        }
    }
}

/// WaitDI and WaitDO share a layout, as do WaitGI/WaitGO and WaitAI/WaitAO (a test
/// checks they agree).
static DIGITAL: LazyLock<Layout> = LazyLock::new(|| Layout::of("WaitDI"));
static GROUP: LazyLock<Layout> = LazyLock::new(|| Layout::of("WaitGI"));
static ANALOG: LazyLock<Layout> = LazyLock::new(|| Layout::of("WaitAI"));
/// Where their `\Visualize` arguments are.
static DIGITAL_BOX: LazyLock<BoxArgs> = LazyLock::new(|| BoxArgs::of("WaitDI"));
static GROUP_BOX: LazyLock<BoxArgs> = LazyLock::new(|| BoxArgs::of("WaitGI"));
static ANALOG_BOX: LazyLock<BoxArgs> = LazyLock::new(|| BoxArgs::of("WaitAI"));

fn wait_digital(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    wait(ctx, args, &DIGITAL, &DIGITAL_BOX, Compare::Eq)
}

/// WaitGI/WaitGO compare with `\NOTEQ`, `\LT` or `\GT`, else for equality.
fn wait_group(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let layout = &*GROUP;
    let compare = if present(args.get(layout.not_eq)) {
        Compare::NotEq
    } else if present(args.get(layout.lt)) {
        Compare::Lt
    } else if present(args.get(layout.gt)) {
        Compare::Gt
    } else {
        Compare::Eq
    };
    wait(ctx, args, layout, &GROUP_BOX, compare)
}

/// WaitAI/WaitAO take `\LT` or `\GT` (one of them).
fn wait_analog(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let layout = &*ANALOG;
    let compare = if present(args.get(layout.lt)) { Compare::Lt } else { Compare::Gt };
    wait(ctx, args, layout, &ANALOG_BOX, compare)
}

fn wait(ctx: &mut Ctx<'_>, args: &[Value], layout: &Layout, shown: &BoxArgs, compare: Compare) -> Res {
    let id = signal(ctx, &args[layout.signal])?;
    let target = match layout.dvalue {
        Some(d) if present(args.get(d)) => ctx.num(&args[d])?,
        _ => ctx.num(&args[layout.value])?,
    };
    let value = ctx.resources.io().system.as_ref().and_then(|io| io.value(id)).unwrap_or(0.0);
    let now = ctx.time;
    let started = wait_started(ctx);
    if compare.holds(value, target) {
        ctx.resources.end_wait();
        visualize_step(ctx, args, shown, true)?;
        if let Some(flag) = layout.time_flag.filter(|&f| present(args.get(f))) {
            ctx.store(&args[flag], Value::Bool(false))?;
        }
        return Ok(None);
    }
    let deadline = ctx.opt_num(args.get(layout.max_time))?.map(|max| started + max);
    if deadline.is_some_and(|d| now >= d) {
        ctx.resources.end_wait();
        visualize_step(ctx, args, shown, true)?;
        return timed_out(ctx, args, layout, value);
    }
    // The box (with \Visualize) is shown while the wait goes on, unchanged.
    let box_closes = visualize_step(ctx, args, shown, false)?;
    wait_again(ctx, started, deadline, box_closes);
    Ok(None)
}

/// Past `\MaxTime`: with `\TimeFlag` the flag is set and execution goes on; otherwise
/// ERR_WAIT_MAXTIME, after storing the value in `\ValueAtTimeout`.
fn timed_out(ctx: &mut Ctx<'_>, args: &[Value], layout: &Layout, value: f64) -> Res {
    if let Some(flag) = layout.time_flag.filter(|&f| present(args.get(f))) {
        ctx.store(&args[flag], Value::Bool(true))?;
        return Ok(None);
    }
    if let Some((num, dnum)) = layout.at_timeout {
        if present(args.get(num)) {
            ctx.store(&args[num], Value::Num(value as f32))?;
        }
        if let Some(d) = dnum.filter(|&d| present(args.get(d))) {
            ctx.store(&args[d], Value::Dnum(value))?;
        }
    }
    Err(ctx.error(Err::WaitMaxTime, "the signal did not reach the value within \\MaxTime"))
}

pub(crate) static FAMILY: Family = Family {
    file: file!(),
    builtins: &[
        native("WaitDI", wait_digital),
        native("WaitDO", wait_digital),
        native("WaitGI", wait_group),
        native("WaitGO", wait_group),
        native("WaitAI", wait_analog),
        native("WaitAO", wait_analog),
    ],
};

#[cfg(test)]
mod tests {
    use super::*;
    use rapid_vm::ext::ABSENT;

    // Positions counted by hand from the manual's syntax:
    // WaitDI Signal Value [\MaxTime] [\TimeFlag] [\Visualize] …
    // WaitGI Signal [\NOTEQ]|[\LT]|[\GT] Value|Dvalue [\MaxTime] [\ValueAtTimeout]|[\DvalueAtTimeout] [\Visualize] …
    // WaitAI Signal [\LT]|[\GT] Value [\MaxTime] [\ValueAtTimeout] [\Visualize] …
    #[test]
    fn layouts_from_the_signatures() {
        let digital = Layout {
            signal: 0,
            not_eq: ABSENT,
            lt: ABSENT,
            gt: ABSENT,
            value: 1,
            dvalue: None,
            max_time: 2,
            time_flag: Some(3),
            at_timeout: None,
            visualize: 4,
        };
        assert_eq!(*DIGITAL, digital);
        assert_eq!(Layout::of("WaitDO"), digital);
        let group = Layout {
            signal: 0,
            not_eq: 1,
            lt: 2,
            gt: 3,
            value: 4,
            dvalue: Some(5),
            max_time: 6,
            time_flag: None,
            at_timeout: Some((7, Some(8))),
            visualize: 9,
        };
        assert_eq!(*GROUP, group);
        assert_eq!(Layout::of("WaitGO"), group);
        let analog = Layout {
            signal: 0,
            not_eq: ABSENT,
            lt: 1,
            gt: 2,
            value: 3,
            dvalue: None,
            max_time: 4,
            time_flag: None,
            at_timeout: Some((5, None)),
            visualize: 6,
        };
        assert_eq!(*ANALOG, analog);
        assert_eq!(Layout::of("WaitAO"), analog);
    }
}
