//! Running a system to its end or to a bound, the controller clock moved under a
//! clock policy: every front end's one run loop. [`Controller::run_until`] runs it
//! to the end (`rapid run`); the API's [`crate::api::Session`] runs it a bounded turn
//! at a time and moves the clock with the same [`Controller::move_clock`].
//!
//! The controller keeps no wall clock of its own: the front end's [`WallClock`] says
//! where the wall clock is (and sleeps to it, or tells its caller when to come back)
//! and whether the user asked the run to end. While a task talks to the outside world
//! (a socket open or waited on) the clock is paced whatever the policy: a peer must
//! see the controller's time pass as its own does.
//!
//! A run nothing outside the system can change ([`RunBounds::closed`]) also ends when
//! it can no longer progress ([`Bound::Stuck`], the rule in `progress.rs`).

use rapid_vm::Host;

use crate::schedule::{Controller, SystemExit};

/// Statements (all tasks together) between looks at the bounds.
const SLICE: u64 = 1 << 14;

/// Instructions of a task run alone between looks at the bounds.
const SLICE_ALONE: u64 = 1 << 16;

/// How the controller clock keeps to the wall clock.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum ClockPolicy {
    /// Virtual time: waits are jumped over at once (simulation as fast as the host
    /// computes). It follows the wall clock while a task talks to the outside world,
    /// and (the API's pendant) while a dialog waits for the operator.
    #[default]
    Virtual,
    /// Waits take wall-clock time divided by `rate` (2.0: twice as fast as real);
    /// computing moves the clock by the nominal instruction time only.
    Paced { rate: f64 },
    /// The wall clock throughout (`--realtime`): waits take their time, and computing
    /// moves the clock too.
    Realtime,
}

impl ClockPolicy {
    /// The rates (controller seconds per wall-clock second) the clock follows the
    /// wall clock at while tasks compute and while every task waits; None: it does
    /// not. `outside`: a task talks to the outside world, which paces a virtual clock
    /// in real time.
    fn rates(self, outside: bool) -> (Option<f64>, Option<f64>) {
        match self {
            ClockPolicy::Realtime => (Some(1.0), Some(1.0)),
            ClockPolicy::Virtual if outside => (Some(1.0), Some(1.0)),
            ClockPolicy::Virtual => (None, None),
            // The front end chose the rate: the outside world sees it too.
            ClockPolicy::Paced { rate } if rate > 0.0 && rate.is_finite() => (None, Some(rate)),
            ClockPolicy::Paced { .. } => (None, Some(1.0)),
        }
    }
}

/// The wall clock as the front end keeps it.
pub trait WallClock {
    /// The controller clock moves from `from` to `to` (a wait; `from == to` for a
    /// stretch of computing). Paced (`rate` controller seconds per wall-clock second):
    /// the controller time the wall clock allows, never past `limit` — a blocking
    /// clock sleeps until `to` and may return later when the wall clock was ahead; a
    /// clock that must not block returns earlier and tells its caller when to come
    /// back. Not paced (`None`): returns `to`.
    fn wait(&mut self, rate: Option<f64>, from: f64, to: f64, limit: f64) -> f64;

    /// Whether the user asked the run to end (Ctrl-C).
    fn interrupted(&self) -> bool;
}

/// The bounds of a run.
#[derive(Debug, Clone, Copy, Default)]
pub struct RunBounds {
    /// Steps ([`Controller::steps`]) the run may take.
    pub max_steps: Option<u64>,
    /// Controller seconds the run may last.
    pub max_time: Option<f64>,
    /// Nothing outside the system changes it while it runs (no front end sets
    /// signals or answers prompts; `rapid run`): a run that can no longer progress
    /// ends ([`Bound::Stuck`]).
    pub closed: bool,
}

/// Why [`Controller::run_until`] returned before the system ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Bound {
    /// More steps than the bound.
    Steps(u64),
    /// The clock reached the bound short of a wait's end, or passed it computing.
    Time(f64),
    /// The interpreter failed (a panic caught): our fault, not the program's.
    InternalError,
    /// The user ended the run.
    Interrupted,
    /// The program was stopped (a system input) and nothing in the stimulus starts it
    /// again.
    Stopped,
    /// Every NORMAL task waits for something only a change from outside the system
    /// could bring ([`Controller::stuck_waits`] says what).
    Stuck,
}

impl Controller {
    /// Runs the system to its end (`None`) or to a bound, moving the clock over every
    /// wait under `policy` with the front end's `clock`. A task alone runs in slices of
    /// its VM ([`Controller::runs_alone`]); the bounds are looked at between slices.
    pub fn run_until(
        &mut self,
        host: &mut dyn Host,
        clock: &mut dyn WallClock,
        policy: ClockPolicy,
        bounds: RunBounds,
    ) -> Option<Bound> {
        let limit = bounds.max_time.unwrap_or(f64::INFINITY);
        loop {
            if clock.interrupted() {
                return Some(Bound::Interrupted);
            }
            let slice = if self.runs_alone() { SLICE_ALONE } else { SLICE };
            // Defence in depth: an interpreter bug must not take the front end down
            // with it; it is reported as what it is.
            let step = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| self.run(host, slice)));
            let Ok(exit) = step else { return Some(Bound::InternalError) };
            if let Some(max) = bounds.max_steps {
                if self.steps > max {
                    return Some(Bound::Steps(max));
                }
            }
            match exit {
                SystemExit::Ended => return None,
                SystemExit::Stopped => return Some(Bound::Stopped),
                SystemExit::Wait(_) if bounds.closed && self.cannot_progress() => return Some(Bound::Stuck),
                SystemExit::Budget | SystemExit::Wait(_) => {}
            }
            let clipped = self.move_clock(exit, clock, policy, limit);
            // The clock moves while tasks compute too (the nominal instruction time): a
            // loop that never waits is bounded as well.
            if let Some(max) = bounds.max_time {
                if clipped || self.time > max {
                    return Some(Bound::Time(max));
                }
            }
        }
    }

    /// Moves the clock after [`Controller::run`] returned `exit`: over a wait
    /// (never past `limit`), or, while it follows the wall clock, over the time a
    /// stretch of computing took. True when `limit` cut a wait short.
    pub fn move_clock(&mut self, exit: SystemExit, clock: &mut dyn WallClock, policy: ClockPolicy, limit: f64) -> bool {
        // While the program talks to the outside world the clock is the wall clock,
        // computing too: a peer's data and the time bound come in its time.
        let (computing, waiting) = policy.rates(self.talks_to_outside_world());
        let from = self.time;
        match exit {
            SystemExit::Budget if computing.is_some() || waiting.is_none() => {
                let to = clock.wait(computing, from, from, limit);
                self.advance(to - from);
                false
            }
            SystemExit::Wait(seconds) => {
                let end = from + seconds;
                let to = clock.wait(waiting, from, end.min(limit).max(from), limit);
                self.advance(to - from);
                end > limit
            }
            SystemExit::Budget | SystemExit::Ended | SystemExit::Stopped => false,
        }
    }
}

#[cfg(test)]
mod tests {
    use rapid_vm::RecordingHost;

    use super::{Bound, ClockPolicy, RunBounds, WallClock};
    use crate::test_support::one_task;

    /// A wall clock that is never paced to: it records the paced stretches asked for.
    #[derive(Default)]
    struct Recorded {
        paced: Vec<(f64, f64)>,
        interrupt: bool,
    }

    impl WallClock for Recorded {
        fn wait(&mut self, rate: Option<f64>, from: f64, to: f64, _limit: f64) -> f64 {
            if rate.is_some() {
                self.paced.push((from, to));
            }
            to
        }

        fn interrupted(&self) -> bool {
            self.interrupt
        }
    }

    const WAITS: &str = "MODULE M\n  PROC main()\n    WaitTime 2;\n    TPWrite \"two\";\n    WaitTime 3;\n    \
                         TPWrite \"five\";\n  ENDPROC\nENDMODULE";

    #[test]
    fn virtual_time_jumps_the_waits_and_realtime_paces_them() {
        let mut c = one_task(WAITS);
        let (mut host, mut clock) = (RecordingHost::default(), Recorded::default());
        assert_eq!(c.run_until(&mut host, &mut clock, ClockPolicy::Virtual, RunBounds::default()), None);
        assert_eq!(host.lines, ["two", "five"]);
        assert_eq!(c.time, 5.0);
        assert!(clock.paced.is_empty());

        let mut c = one_task(WAITS);
        let (mut host, mut clock) = (RecordingHost::default(), Recorded::default());
        assert_eq!(c.run_until(&mut host, &mut clock, ClockPolicy::Realtime, RunBounds::default()), None);
        assert_eq!(clock.paced, [(0.0, 2.0), (2.0, 5.0)]);
    }

    #[test]
    fn a_bound_or_the_user_ends_the_run() {
        let mut c = one_task(WAITS);
        let mut host = RecordingHost::default();
        let bounds = RunBounds { max_time: Some(3.0), ..RunBounds::default() };
        let end = c.run_until(&mut host, &mut Recorded::default(), ClockPolicy::Virtual, bounds);
        assert_eq!(end, Some(Bound::Time(3.0)));
        assert_eq!(host.lines, ["two"]);

        let mut c = one_task(WAITS);
        let mut clock = Recorded { interrupt: true, ..Recorded::default() };
        let end = c.run_until(&mut host, &mut clock, ClockPolicy::Virtual, RunBounds::default());
        assert_eq!(end, Some(Bound::Interrupted));
        assert_eq!(c.time, 0.0);
    }

    #[test]
    fn each_policy_follows_the_wall_clock_where_it_says() {
        // (while computing, while waiting); the outside world paces a virtual clock in
        // real time.
        assert_eq!(ClockPolicy::Virtual.rates(false), (None, None));
        assert_eq!(ClockPolicy::Virtual.rates(true), (Some(1.0), Some(1.0)));
        assert_eq!(ClockPolicy::Paced { rate: 4.0 }.rates(false), (None, Some(4.0)));
        assert_eq!(ClockPolicy::Paced { rate: 0.0 }.rates(false), (None, Some(1.0)));
        assert_eq!(ClockPolicy::Paced { rate: 4.0 }.rates(true), (None, Some(4.0)));
        assert_eq!(ClockPolicy::Realtime.rates(false), (Some(1.0), Some(1.0)));
    }

    #[test]
    fn a_paced_wait_is_cut_at_the_time_bound() {
        // WaitTime 2 then 3, paced at twice real time, bounded at 3 s: the second wait
        // is asked for up to the bound only, and the run ends there.
        let mut c = one_task(WAITS);
        let (mut host, mut clock) = (RecordingHost::default(), Recorded::default());
        let bounds = RunBounds { max_time: Some(3.0), ..RunBounds::default() };
        let end = c.run_until(&mut host, &mut clock, ClockPolicy::Paced { rate: 2.0 }, bounds);
        assert_eq!(end, Some(Bound::Time(3.0)));
        assert_eq!(clock.paced, [(0.0, 2.0), (2.0, 3.0)]);
        assert_eq!(c.time, 3.0);
    }
}
