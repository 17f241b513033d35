//! The host's clocks: the system calendar and `Instant`.

use std::time::{Duration, Instant, SystemTime};

use rapid_vm::world::Clock;

/// The host's wall clock, and a monotonic clock counting from its creation.
#[derive(Debug)]
pub struct StdClock {
    origin: Instant,
}

impl Default for StdClock {
    fn default() -> StdClock {
        StdClock { origin: Instant::now() }
    }
}

impl Clock for StdClock {
    fn wall_seconds(&self) -> f64 {
        SystemTime::now().duration_since(SystemTime::UNIX_EPOCH).map_or(0.0, |d| d.as_secs_f64())
    }

    fn elapsed(&self) -> Duration {
        self.origin.elapsed()
    }

    fn sleep(&self, d: Duration) {
        std::thread::sleep(d);
    }
}
