//! The controller's side of the planner's clock: a robot with nothing to do stands
//! still until the program gives it its next move.

use super::Planner;

impl Planner {
    /// The robot stands still until `t`: a move pushed now starts no earlier. No
    /// effect while a move waits for its successor (that move is under way).
    pub fn idle_until(&mut self, t: f64) {
        if self.pending.is_none() && t.is_finite() && t > self.time {
            self.time = t;
        }
    }
}
