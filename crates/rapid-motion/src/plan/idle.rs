//! The controller's side of the planner's clock: a robot with nothing to do stands
//! still until the program gives it its next move.

use super::{Joints, Planner};

impl Planner {
    /// The robot stands still until `t`: a move pushed now starts no earlier. No
    /// effect while a move waits for its successor (that move is under way).
    pub fn idle_until(&mut self, t: f64) {
        if self.pending.is_none() && t.is_finite() && t > self.time {
            self.time = t;
        }
    }
}

impl Planner {
    /// The robot was stopped at `joints` at time `t` (a search hit): what was planned
    /// after is dropped, and the next move starts from there.
    pub fn restart_from(&mut self, joints: Joints, t: f64) {
        self.pending = None;
        self.joints = joints;
        if t.is_finite() {
            self.time = t;
        }
    }
}

impl super::PlannedMove {
    /// The move cut short at time `t` (the robot stopped there): it ends at `t`,
    /// standing where it was then. No effect at or after its end.
    pub fn cut_at<K: crate::Kinematics + ?Sized>(&mut self, kin: &K, t: f64) {
        if t.is_nan() || t >= self.end {
            return;
        }
        let t = t.max(self.start);
        self.end_joints = self.sample(kin, t).joints;
        self.end = t;
        self.zone_entry = self.zone_entry.min(t);
        self.corner_time = 0.0;
    }
}

impl super::PlannedMove {
    /// The move braked from time `t` (a stop on the path): the speed falls to 0 in
    /// `stop_time` along the path, or sooner where the piece it is on ends; the move
    /// ends where the robot stands then. No effect at or after its end.
    pub fn brake_at<K: crate::Kinematics + ?Sized>(&mut self, kin: &K, t: f64, stop_time: f64) {
        if t.is_nan() || t >= self.end {
            return;
        }
        let t = t.max(self.start);
        let Some(i) = self.spans.iter().rposition(|s| s.t0 <= t) else {
            self.cut_at(kin, t);
            return;
        };
        let span = &mut self.spans[i];
        span.profile = span.profile.braked_at(t - span.t0, stop_time);
        let end = span.t0 + span.profile.duration;
        self.spans.truncate(i + 1);
        self.end = end;
        self.end_joints = self.sample(kin, end).joints;
        self.zone_entry = end;
        self.corner_time = 0.0;
    }
}

impl Planner {
    /// The robot stood still `dt` seconds (StopMove … StartMove): what was planned
    /// from `from` on happens that much later.
    pub fn delay_from(&mut self, from: f64, dt: f64) {
        if self.time >= from && dt.is_finite() {
            self.time += dt;
        }
    }
}

impl super::PlannedMove {
    /// The robot standing at `joints` from `start` to `end` (a pause of the path).
    pub fn standing(joints: Joints, mount: super::Mount, start: f64, end: f64) -> super::PlannedMove {
        super::PlannedMove {
            start,
            zone_entry: end,
            end,
            corner_time: 0.0,
            zone: 0.0,
            corner_path_failure: false,
            end_joints: joints,
            spans: Vec::new(),
            mount,
            eax: None,
        }
    }

    /// The same move `dt` seconds later.
    pub fn shift(&mut self, dt: f64) {
        self.start += dt;
        self.zone_entry += dt;
        self.end += dt;
        for span in &mut self.spans {
            span.t0 += dt;
        }
    }

    /// The tool frame the move was planned with.
    pub fn tool(&self) -> super::Mount {
        self.mount
    }
}
