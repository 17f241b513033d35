//! World-zone supervision along the robot's path (WZDOSet outputs, WZLimSup stops):
//! every planned move is sampled at the 4 ms path resolution and each active zone
//! watched for the robot going in or out.
//!
//! A move waiting for its successor (a fly-by point) is supervised as soon as it is
//! given, up to where it could start braking: its path is final there (the
//! successor only changes what comes after), and the program may give that successor
//! long after the robot passed the zone (0.1 s before braking, §2.3). The rest is
//! supervised when the move becomes final.

use rapid_motion::plan::PlannedMove;
use rapid_motion::{Joints, Kinematics};

use super::robot::{Action, RobotState};

impl RobotState {
    /// Whether the robot at `joints` (TCP of the active tool) is in zone `i`.
    fn in_zone(&self, i: usize, joints: &Joints, eax: Option<&[f64; 6]>, tcp: &nalgebra::Vector3<f64>) -> bool {
        self.zones.get(i).copied().flatten().is_some_and(|z| z.shape.contains(tcp, joints, eax))
    }

    /// The TCP deceleration moves are planned with: the model's, scaled by AccSet,
    /// capped by PathAccLim/WorldAccLim, mm/s².
    fn braking_decel(&self) -> f64 {
        let settings = self.planner.settings();
        let nominal = rapid_motion::plan::AccelLimits::nominal(&self.model.max_speeds).tcp * settings.acc_factor();
        settings.tcp_dec_max.filter(|cap| cap.is_finite() && *cap > 0.0).map_or(nominal, |cap| nominal.min(cap))
    }

    /// A zone just activated (or enabled): its output follows where the robot is now.
    pub fn start_zone(&mut self, i: usize, now: f64) {
        let joints = self.joints_at(now);
        // In the world: on a track, where the track has the robot's base.
        let tcp = (self.track_base_at(now) * self.kin.forward(&joints) * self.active.tframe).translation.vector;
        let eax = self.extax_of(self.eax_at(now));
        let inside = self.in_zone(i, &joints, eax.as_ref(), &tcp);
        if self.zone_inside.len() <= i {
            self.zone_inside.resize(i + 1, false);
        }
        self.zone_inside[i] = inside;
        self.zone_event(i, inside, now);
    }

    /// What zone `i` does when the robot is found in it (or out of it) at `time`: a
    /// WZDOSet output follows, a WZLimSup zone entered stops the robot.
    fn zone_event(&mut self, i: usize, inside: bool, time: f64) {
        match self.zones[i].map(|z| z.kind) {
            Some(super::zones::ZoneKind::DoSet { signal, value, .. }) => {
                self.due.push((time, Action::ZoneSet { signal, value: if inside { value } else { 1.0 - value } }));
            }
            Some(super::zones::ZoneKind::LimSup) if inside => {
                self.zone_violation.get_or_insert(time);
            }
            _ => {}
        }
    }

    /// World zones along `planned` at the 4 ms path resolution, from where they were
    /// last supervised to `until`: outputs where the TCP (or the axes) go in or out, a
    /// WZLimSup zone entered.
    fn supervise_zones(&mut self, planned: &PlannedMove, until: f64) {
        let active: Vec<usize> = (0..self.zones.len()).filter(|&i| self.zones[i].is_some_and(|z| z.enabled)).collect();
        if active.is_empty() {
            return;
        }
        if self.zone_inside.len() < self.zones.len() {
            self.zone_inside.resize(self.zones.len(), false);
        }
        let mut crossings = Vec::new();
        // Where the robot is: following a moving work object, carried with it.
        let samples: Vec<_> = planned
            .samples(&self.kin, rapid_motion::plan::DEFAULT_STEP)
            .map(|sample| self.carried_sample(planned, sample))
            .collect();
        let before = |z: &super::zones::Zone| matches!(z.kind, super::zones::ZoneKind::DoSet { before: true, .. });
        let braking = match active.iter().any(|&i| self.zones[i].is_some_and(|z| before(&z))) {
            true => super::zones::braking_places(&samples, self.braking_decel()),
            false => Vec::new(),
        };
        let from = self.zones_until;
        self.zones_until = self.zones_until.max(until);
        for (k, sample) in samples.iter().enumerate() {
            if sample.time <= from || sample.time > until {
                continue;
            }
            for &i in &active {
                // A `\Before` zone looks at where the robot would stand if it braked now.
                let at = match braking.get(k) {
                    Some(&j) if self.zones[i].is_some_and(|z| before(&z)) => &samples[j],
                    _ => sample,
                };
                let base = planned.eax_at(at.time).map_or_else(|| self.track_base_at(at.time), |e| self.track_base(&e));
                let tcp = base * at.tcp;
                let eax = self.extax_of(planned.eax_at(at.time).map(|mut e| {
                    self.independent.apply_eax(&mut e, at.time);
                    e
                }));
                let inside = self.in_zone(i, &at.joints, eax.as_ref(), &tcp.translation.vector);
                if inside != self.zone_inside[i] {
                    self.zone_inside[i] = inside;
                    crossings.push((i, inside, sample.time));
                }
            }
        }
        for (i, inside, time) in crossings {
            self.zone_event(i, inside, time);
        }
    }

    /// The path ends at `t` (ClearPath, a search's stop): what was supervised beyond it
    /// never happens; each zone is as the robot stands at `t`.
    pub(super) fn zones_stop_at(&mut self, t: f64) {
        if self.zones_until <= t {
            return;
        }
        self.zones_until = t;
        let joints = self.joints_at(t);
        let tcp = (self.track_base_at(t) * self.kin.forward(&joints) * self.active.tframe).translation.vector;
        let eax = self.extax_of(self.eax_at(t));
        for i in 0..self.zone_inside.len() {
            self.zone_inside[i] = self.in_zone(i, &joints, eax.as_ref(), &tcp);
        }
    }

    /// The zones along a move that became final, from where they were supervised.
    pub(super) fn supervise_final(&mut self, planned: &PlannedMove) {
        self.supervise_zones(planned, planned.end);
    }

    /// The zones along the move waiting for its successor, up to where it could start
    /// braking.
    pub(super) fn supervise_provisional(&mut self) {
        if self.zones.iter().all(Option::is_none) {
            return;
        }
        if let Some((provisional, braking)) = self.planner.provisional() {
            self.supervise_zones(&provisional, braking);
        }
    }
}
