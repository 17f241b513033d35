//! The clocks a task reads: the calendar (wall clock) and a monotonic clock for the
//! waits on the outside world (socket timeouts). The controller's own clock, the one
//! WaitTime and ClkRead use, is the VM's virtual time and is not here.

use std::cell::Cell;
use std::time::Duration;

/// The clocks of a world. Methods take `&self`: one clock is shared by the parts of a
/// task that wait (the sockets) and the calendar.
pub trait Clock {
    /// Seconds since 1970-01-01 00:00 UTC now (the calendar CDate and CTime start from).
    fn wall_seconds(&self) -> f64;
    /// Time since an origin of the clock's choosing, never going back.
    fn elapsed(&self) -> Duration;
    /// Lets `d` pass (a poll step of a socket wait): a real clock sleeps, a fake one
    /// moves on.
    fn sleep(&self, d: Duration);
}

/// A clock that stands still unless told to move: the calendar shows `wall_seconds`
/// plus what [`StoppedClock::advance`] or [`Clock::sleep`] added; for tests, and the
/// clock of a closed world (1970-01-01).
#[derive(Debug, Default)]
pub struct StoppedClock {
    wall: Cell<f64>,
    elapsed: Cell<Duration>,
}

impl StoppedClock {
    /// A clock whose calendar shows `wall_seconds` since 1970.
    pub fn at(wall_seconds: f64) -> StoppedClock {
        StoppedClock { wall: Cell::new(wall_seconds), elapsed: Cell::new(Duration::ZERO) }
    }

    /// Moves both clocks on by `d`.
    pub fn advance(&self, d: Duration) {
        self.elapsed.set(self.elapsed.get() + d);
        self.wall.set(self.wall.get() + d.as_secs_f64());
    }
}

impl Clock for StoppedClock {
    fn wall_seconds(&self) -> f64 {
        self.wall.get()
    }

    fn elapsed(&self) -> Duration {
        self.elapsed.get()
    }

    fn sleep(&self, d: Duration) {
        self.advance(d);
    }
}
