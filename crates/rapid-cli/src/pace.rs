//! Pacing the controller clock in wall-clock time: with `--realtime`, and while the
//! program talks to the outside world (a socket open or waited on), where a peer must
//! see the controller's time pass as its own does.
//!
//! The clock is held to an anchor (a wall-clock instant and the controller time then),
//! not slept wait by wait: sleeping each wait's length lets the time spent computing
//! and every sleep's overshoot add up, and the controller fell a tenth behind the wall
//! clock over a second of 10 ms waits. When the run computes longer than the controller
//! time it took, the clock catches up with the wall clock, as a real controller's does;
//! when it computes faster, it waits for the wall clock (a stretch of computing is paced
//! as a wait of no length).

use std::time::{Duration, Instant};

/// The longest single sleep (a wait of days is still bounded).
const MAX_SLEEP: f64 = 86_400.0;

/// Sleeps are cut into slices this long, so that Ctrl-C ends a long wait at once.
const SLICE: Duration = Duration::from_millis(50);

/// Where wall-clock time and controller time were last tied together.
#[derive(Default)]
pub(crate) struct Pacer {
    anchor: Option<(Instant, f64)>,
}

impl rapid_controller::WallClock for Pacer {
    /// The controller clock moves from `from` to `to` (a wait). Paced at `rate`
    /// (controller seconds per wall-clock second), sleeps until the wall clock reaches
    /// `to` (never past `limit`, the `--max-time`) and returns the clock then, which is
    /// later than `to` when the wall clock was ahead; otherwise returns `to` and lets
    /// the next paced stretch start a new anchor.
    fn wait(&mut self, rate: Option<f64>, from: f64, to: f64, limit: f64) -> f64 {
        let Some(rate) = rate else {
            self.anchor = None;
            return to;
        };
        let (wall0, clock0) = *self.anchor.get_or_insert_with(|| (Instant::now(), from));
        let target = to.min(limit);
        let due = wall0 + Duration::from_secs_f64(((target - clock0) / rate).clamp(0.0, MAX_SLEEP));
        while let Some(left) = due.checked_duration_since(Instant::now()) {
            if crate::interrupt::requested() {
                break;
            }
            std::thread::sleep(left.min(SLICE));
        }
        let now = clock0 + wall0.elapsed().as_secs_f64() * rate;
        to.max(now.min(limit))
    }

    fn interrupted(&self) -> bool {
        crate::interrupt::requested()
    }
}

#[cfg(test)]
mod tests {
    use rapid_controller::WallClock;

    use super::*;

    #[test]
    fn an_unpaced_wait_jumps_and_a_paced_one_keeps_to_the_wall_clock() {
        let mut pacer = Pacer::default();
        let started = Instant::now();
        assert_eq!(pacer.wait(None, 0.0, 100.0, f64::INFINITY), 100.0);
        assert!(pacer.anchor.is_none());
        // Ten 10 ms waits take 100 ms of wall-clock time in all, however long each
        // sleep overshoots: the anchor set at the first holds them to it.
        let mut clock = 100.0;
        for _ in 0..10 {
            clock = pacer.wait(Some(1.0), clock, clock + 0.010, f64::INFINITY);
        }
        let elapsed = started.elapsed().as_secs_f64();
        assert!(elapsed >= 0.100, "{elapsed}");
        // The clock followed the wall clock: what it says is what passed since the anchor.
        assert!(clock >= 100.100 && clock <= 100.0 + elapsed + 0.001, "{clock} {elapsed}");
    }

    #[test]
    fn a_paced_wait_stops_at_the_limit() {
        let mut pacer = Pacer::default();
        let started = Instant::now();
        // The wall clock is at the limit, short of the wait's end: the clock says `to`.
        assert_eq!(pacer.wait(Some(1.0), 0.0, 0.05, 0.02), 0.05);
        assert!(started.elapsed() >= Duration::from_millis(20));
    }
}
