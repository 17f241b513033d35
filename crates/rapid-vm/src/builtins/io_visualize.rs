//! `\Visualize` of the wait instructions (WaitUntil, WaitDI, WaitDO, WaitGI, WaitGO,
//! WaitAI, WaitAO; RobotWare 6): while the instruction waits, a message box (`\Header`,
//! then `\Message` or the lines of `\MsgArray`) is shown on the pendant through the
//! host. It takes no answer: the wait runs and ends exactly as without it, and the box
//! closes when it ends. `\VisualizeTime` closes the box after that many seconds while
//! the wait goes on; `\UIActiveSignal` is 1 while the box is shown, 0 after. `\Wrap`,
//! `\Icon` and `\Image` only change how the box looks (accepted, not drawn).
//! A wait whose condition holds at once shows no box. The box is the language's (the
//! core's WaitUntil shows it too); `\UIActiveSignal` is set through the extension that
//! keeps the signals (`TaskHooks::signal_of`, `set_signal`).

use super::{present, Ctx};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::Value;

/// Where the box's arguments are in one wait instruction's parameter list.
#[derive(Debug, PartialEq, Eq)]
pub struct BoxArgs {
    pub(crate) visualize: usize,
    header: usize,
    message: usize,
    msg_array: usize,
    visualize_time: usize,
    ui_active: usize,
}

impl BoxArgs {
    /// The positions in the declaration of `name` (see `signature.rs`).
    pub fn of(name: &str) -> BoxArgs {
        let sig = super::signature::of(name);
        BoxArgs {
            visualize: sig.at("Visualize"),
            header: sig.at("Header"),
            message: sig.at("Message"),
            msg_array: sig.at("MsgArray"),
            visualize_time: sig.at("VisualizeTime"),
            ui_active: sig.at("UIActiveSignal"),
        }
    }
}

/// A box shown (or shown and closed by `\VisualizeTime`) for the wait at a call depth.
#[derive(Debug, Clone)]
pub(crate) struct ShownBox {
    depth: usize,
    open: bool,
    text: String,
    close_at: Option<f64>,
    ui_active: Option<u32>,
}

/// One try of a wait with `\Visualize` (nothing without it): `done` when the wait
/// ends at this try (the condition holds, or time ran out). Opens the box at the
/// first try that waits, closes it when the wait ends or `\VisualizeTime` is over.
/// Answers when the box must close while the wait goes on, so the wait looks again then.
pub fn step(ctx: &mut Ctx<'_>, args: &[Value], at: &BoxArgs, done: bool) -> Result<Option<f64>, RapidError> {
    if !present(args.get(at.visualize)) {
        return Ok(None);
    }
    let depth = ctx.chain.len();
    let shown = ctx.resources.boxes.iter().position(|b| b.depth == depth);
    match (shown, done) {
        (None, true) => Ok(None),
        (Some(idx), true) => {
            let shown = ctx.resources.boxes.remove(idx);
            if shown.open {
                close(ctx, &shown)?;
            }
            Ok(None)
        }
        (None, false) => {
            let shown = open(ctx, args, at, depth)?;
            let close_at = shown.close_at;
            ctx.resources.boxes.push(shown);
            Ok(close_at)
        }
        (Some(idx), false) => {
            let shown = ctx.resources.boxes[idx].clone();
            match shown.close_at {
                Some(t) if shown.open && ctx.time >= t => {
                    ctx.resources.boxes[idx].open = false;
                    close(ctx, &shown)?;
                    Ok(None)
                }
                Some(t) if shown.open => Ok(Some(t)),
                _ => Ok(None),
            }
        }
    }
}

static UNTIL_BOX: std::sync::LazyLock<BoxArgs> = std::sync::LazyLock::new(|| BoxArgs::of("WaitUntil"));

/// WaitUntil's `run`, which its compiled loop calls only for the box of `\Visualize`:
/// `Cond` TRUE when the wait ends. The loop polls, so `\VisualizeTime` closes the box
/// at the first poll after it.
pub(crate) fn wait_until_box(ctx: &mut Ctx<'_>, args: &[Value]) -> Result<Option<Value>, RapidError> {
    static COND: std::sync::LazyLock<usize> = std::sync::LazyLock::new(|| super::signature::of("WaitUntil").at("Cond"));
    let done = matches!(args.get(*COND), Some(Value::Bool(true)));
    step(ctx, args, &UNTIL_BOX, done)?;
    Ok(None)
}

/// Shows the box of the wait at `depth`.
fn open(ctx: &mut Ctx<'_>, args: &[Value], at: &BoxArgs, depth: usize) -> Result<ShownBox, RapidError> {
    let mut lines = Vec::new();
    if present(args.get(at.header)) {
        lines.push(ctx.string(&args[at.header])?);
    }
    if present(args.get(at.message)) {
        lines.push(ctx.string(&args[at.message])?);
    } else if present(args.get(at.msg_array)) {
        if let Value::Array(array) = ctx.value(&args[at.msg_array])? {
            for elem in array.elems.iter() {
                lines.push(ctx.string(elem)?);
            }
        }
    }
    let close_at = ctx.opt_num(args.get(at.visualize_time))?.map(|t| ctx.time + t.max(0.0));
    let ui_active = match args.get(at.ui_active) {
        Some(arg) if present(Some(arg)) => Some(signal_of(ctx, arg)?),
        _ => None,
    };
    let shown = ShownBox { depth, open: true, text: lines.join("\n"), close_at, ui_active };
    let task = ctx.resources.tasks.me.clone();
    ctx.host.visualize_open(&crate::host::Prompt { task: &task, text: &shown.text });
    set_active(ctx, shown.ui_active, 1.0)?;
    Ok(shown)
}

fn close(ctx: &mut Ctx<'_>, shown: &ShownBox) -> Result<(), RapidError> {
    let task = ctx.resources.tasks.me.clone();
    ctx.host.visualize_close(&crate::host::Prompt { task: &task, text: &shown.text });
    set_active(ctx, shown.ui_active, 0.0)
}

/// `\UIActiveSignal`: the digital output that tells the box is shown.
fn set_active(ctx: &mut Ctx<'_>, signal: Option<u32>, value: f64) -> Result<(), RapidError> {
    let Some(id) = signal else { return Ok(()) };
    for hooks in ctx.builtins.hooks() {
        if let Some(set) = hooks.set_signal(ctx, id, value) {
            return set;
        }
    }
    Err(no_signals(ctx))
}

/// The signal signal data (an argument) is connected to, from the extension that keeps
/// the signals (`TaskHooks::signal_of`).
fn signal_of(ctx: &mut Ctx<'_>, arg: &Value) -> Result<u32, RapidError> {
    for hooks in ctx.builtins.hooks() {
        if let Some(id) = hooks.signal_of(ctx, arg) {
            return id;
        }
    }
    Err(no_signals(ctx))
}

/// No extension keeps signals: the data can be connected to none.
fn no_signals(ctx: &Ctx<'_>) -> RapidError {
    ctx.error(Err::NoAliasIoDef, "this task has no I/O system")
}
