//! The operator's speed override changed while the robot moves (the FlexPendant's
//! override, RWS's speedratio): the rest of the robot's planned path is walked at the
//! new speed at once (`rapid_motion::plan::retime`), and what waits on the old time
//! axis — path events, the end of motion, the trace's facts — moves with it.

use rapid_motion::plan::{retime, Retiming};

use super::robot::RobotState;

impl RobotState {
    /// The speeds scaled by `ratio` (the new override over the old) from `now` on.
    /// None, and nothing changed, where the robot's state is one the re-timing does not
    /// cover yet: held by StopMove or a program stop, searching, a stored path, path
    /// correction, following a conveyor.
    // uncertain: TriggSpeed's ramps keep their times (they are re-timed by the next
    // move's planning only).
    pub fn retime(&mut self, now: f64, ratio: f64) -> Option<Retiming> {
        let covered = self.pause.is_none()
            && self.search.is_none()
            && self.stored.is_none()
            && !self.corr.active()
            && self.following.open().is_none();
        if !covered {
            return None;
        }
        let map = retime(self.ahead.make_contiguous(), now, ratio);
        if let Some(recorded) = &mut self.recorded {
            retime(recorded, now, ratio);
        }
        self.planner.retime(now, ratio, &map);
        for facts in &mut self.recorded_facts {
            (facts.start, facts.end, facts.passed) = (map.map(facts.start), map.map(facts.end), map.map(facts.passed));
        }
        for (t, _) in &mut self.due {
            *t = map.map(*t);
        }
        self.motion_end = map.map(self.motion_end);
        self.hold_until = self.hold_until.map(|t| map.map(t));
        self.zone_violation = self.zone_violation.map(|t| map.map(t));
        self.zones_until = map.map(self.zones_until);
        self.republish();
        Some(map)
    }
}
