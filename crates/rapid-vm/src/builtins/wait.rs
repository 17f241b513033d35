//! The waiting instructions' mechanism (WaitTime, WaitUntil, WaitDI …, a dialog a
//! front end answers later, WaitSyncTask): a built-in that waits keeps when its wait
//! began per call depth and instruction (`Resources::waiting`), sets `ctx.wait` and
//! runs again (`StopKind::Repeat`) at the next time anything may change: an
//! extension's next event (a signal change), the next interrupt, its deadline.

use super::{Ctx, StopKind};

/// How long to wait before looking again when nothing is scheduled: no signal can
/// change then except at the deadline, so this only bounds a wait without \MaxTime.
const IDLE_POLL: f64 = 3600.0;

/// When the wait of the instruction being run began: the first try's time, kept across
/// its repeats (per call depth and instruction); now on a first try.
pub fn wait_started(ctx: &Ctx<'_>) -> f64 {
    match ctx.resources.waiting {
        Some((depth, pc, at)) if (depth, pc) == wait_key(ctx) => at,
        _ => ctx.time,
    }
}

/// The instruction waits on from `started` and runs again at the next change an
/// extension knows of (a signal's), the next interrupt that may come, `also`, or `deadline`,
/// whichever is first.
pub fn wait_again(ctx: &mut Ctx<'_>, started: f64, deadline: Option<f64>, also: Option<f64>) {
    let now = ctx.time;
    let (depth, pc) = wait_key(ctx);
    ctx.resources.waiting = Some((depth, pc, started));
    let io_next = next_event(ctx);
    let interrupt_next = super::interrupts::next_due(ctx);
    let next = [io_next, interrupt_next, also].into_iter().flatten().min_by(f64::total_cmp).unwrap_or(now + IDLE_POLL);
    let until = deadline.map_or(next, |d| d.min(next)).max(now);
    // A change due now (or a rounding tie) still moves the clock a little, so the wait
    // always ends.
    ctx.wait = Some((until - now).max(1e-6));
    ctx.stop = StopKind::Repeat;
}

/// The wait of the instruction being run is over (it ends in success or in an error):
/// the next wait starts afresh.
pub fn wait_over(ctx: &mut Ctx<'_>) {
    ctx.resources.waiting = None;
}

/// The call depth and instruction of the waiting call.
fn wait_key(ctx: &Ctx<'_>) -> (usize, u32) {
    let pc = ctx.chain.last().map_or(0, |frame| frame.position().1);
    (ctx.chain.len(), pc)
}

/// The next change an extension knows of by itself (a scheduled signal change, a
/// stimulus line), the earliest any extension names (`TaskHooks::next_event`).
pub fn next_event(ctx: &mut Ctx<'_>) -> Option<f64> {
    let mut next: Option<f64> = None;
    for hooks in ctx.builtins.hooks() {
        if let Some(at) = hooks.next_event(ctx.resources) {
            next = Some(next.map_or(at, |n| n.min(at)));
        }
    }
    next
}
