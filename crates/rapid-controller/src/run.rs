//! Running a system to its end or to a bound, the controller clock moved under a
//! clock policy: every front end's one run loop ([`Controller::run_until`]).
//!
//! The controller keeps no wall clock of its own: the front end's [`WallClock`] says
//! where the wall clock is (and sleeps to it) and whether the user asked the run to
//! end. While a task talks to the outside world (a socket open or waited on) the
//! clock is paced whatever the policy: a peer must see the controller's time pass as
//! its own does.

use rapid_vm::Host;

use crate::schedule::{Controller, SystemExit};

/// Statements (all tasks together) between looks at the bounds.
const SLICE: u64 = 1 << 14;

/// Instructions of a task run alone between looks at the bounds.
const SLICE_ALONE: u64 = 1 << 16;

/// How the controller clock keeps to the wall clock.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ClockPolicy {
    /// Virtual time: waits are jumped over at once (paced only while a task talks to
    /// the outside world).
    #[default]
    Virtual,
    /// Paced throughout: the controller clock keeps to the wall clock (`--realtime`).
    Realtime,
}

/// The wall clock as the front end keeps it.
pub trait WallClock {
    /// The controller clock moves from `from` to `to` (a wait; `from == to` for a
    /// stretch of computing). When `paced`, waits until the wall clock reaches `to`
    /// (never past `limit`) and returns the controller time then, later than `to` when
    /// the wall clock was ahead; otherwise returns `to`.
    fn wait(&mut self, paced: bool, from: f64, to: f64, limit: f64) -> f64;

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
}

/// Why [`Controller::run_until`] returned before the system ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Bound {
    /// More steps than the bound.
    Steps(u64),
    /// The clock passed the bound.
    Time(f64),
    /// The interpreter failed (a panic caught): our fault, not the program's.
    InternalError,
    /// The user ended the run.
    Interrupted,
    /// The program was stopped (a system input) and nothing in the stimulus starts it
    /// again.
    Stopped,
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
            // While the program talks to the outside world the clock is the wall
            // clock, computing too: a peer's data and the time bound come in its time.
            let paced = policy == ClockPolicy::Realtime || self.talks_to_outside_world();
            match exit {
                SystemExit::Ended => return None,
                SystemExit::Stopped => return Some(Bound::Stopped),
                SystemExit::Budget => {
                    let to = clock.wait(paced, self.time, self.time, limit);
                    self.advance(to - self.time);
                }
                SystemExit::Wait(seconds) => {
                    let from = self.time;
                    let to = clock.wait(paced, from, from + seconds, limit);
                    self.advance(to - from);
                }
            }
            // The clock moves while tasks compute too (the nominal instruction time): a
            // loop that never waits is bounded as well.
            if let Some(max) = bounds.max_time {
                if self.time > max {
                    return Some(Bound::Time(max));
                }
            }
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
        fn wait(&mut self, paced: bool, from: f64, to: f64, _limit: f64) -> f64 {
            if paced {
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
}
