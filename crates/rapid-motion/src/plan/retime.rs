//! The operator's speed override changed while the robot moves (the FlexPendant's
//! override, RWS's `speedratio`): the path stays, and the speed along the rest of it
//! scales by the ratio of the new override to the old from that instant on.
//!
//! Each stretch of path is timed again as the planner times it:
//! - a move's own path (a trapezoid) is shaped again with its speed cap and its end
//!   speed scaled and its accelerations as they were: the robot brakes (or speeds up)
//!   to the new speed at the path's own rate, cruises, and meets the next corner at
//!   the scaled speed;
//! - a corner path and a stop's braking have their time stretched (their speeds
//!   scaled): their shape comes from the speeds at their ends, which scale alike;
//! - a corner path under way at the change, and a stop's braking under way, finish as
//!   planned (they are short); what follows them is re-timed;
//! - standing still (a stop point's settle time, a pause) lasts as long as it did.
//!
//! [`retime`] re-times a robot's planned moves and returns the map from old times to
//! new ones ([`Retiming`]), for the events placed on the old time axis (triggers, the
//! program's wait for a stop point) and for the planner's clock
//! ([`super::Planner::retime`]).
// uncertain: how fast the real controller brings the robot to the new speed is not
// published; the path's own acceleration (AccSet, PathAccLim) is taken.

use super::profile::{Caps, Phase, Profile, EPS_LEN};
use super::sample::{Piece, PlannedMove};

/// How old times (on the path as planned before the change) map to new ones.
#[derive(Debug, Clone, PartialEq)]
pub struct Retiming {
    /// When the change took effect: earlier times stay.
    from: f64,
    /// The stretches re-timed, in time order.
    stretches: Vec<Stretch>,
    /// What the speed at the end of the last move was scaled by: the ratio, or 1 when
    /// the move ended in a corner under way at the change.
    end_scale: f64,
}

/// One piece of the path before and after: where it starts, and its profile (None
/// for a move standing still, whose time only moves).
#[derive(Debug, Clone, PartialEq)]
struct Stretch {
    old_t0: f64,
    new_t0: f64,
    profiles: Option<(Profile, Profile)>,
}

impl Stretch {
    fn old_end(&self) -> f64 {
        self.old_t0 + self.profiles.as_ref().map_or(0.0, |(old, _)| old.duration)
    }

    fn new_end(&self) -> f64 {
        self.new_t0 + self.profiles.as_ref().map_or(0.0, |(_, new)| new.duration)
    }

    /// The new time of old time `t`, on or after this stretch's start.
    fn map(&self, t: f64) -> f64 {
        match &self.profiles {
            Some((old, new)) if t <= self.old_end() => {
                let (s, _) = old.at(t - self.old_t0);
                self.new_t0 + new.time_at(s)
            }
            // Standing still after it: as long as before.
            _ => self.new_end() + (t - self.old_end()),
        }
    }
}

impl Retiming {
    /// Nothing re-timed: every time stays.
    pub fn none(from: f64) -> Retiming {
        Retiming { from, stretches: Vec::new(), end_scale: 1.0 }
    }

    /// The new time of old time `t` (a time of the path as it was planned).
    pub fn map(&self, t: f64) -> f64 {
        if t.is_nan() || t <= self.from {
            return t;
        }
        let after = self.stretches.partition_point(|s| s.old_t0 <= t);
        match after.checked_sub(1).and_then(|i| self.stretches.get(i)) {
            Some(stretch) => stretch.map(t),
            None => t,
        }
    }

    /// What the speed at the end of the last move re-timed was scaled by.
    pub fn end_scale(&self) -> f64 {
        self.end_scale
    }
}

/// Re-times `moves` (a robot's planned moves, in time order) from time `t` on, their
/// speeds scaled by `ratio` (the new override over the old: 0.5 from 100 % to 50 %).
/// Moves over by `t` stay; a move that starts later starts when the one before it now
/// ends (a gap before it kept). A ratio that is not a positive number changes nothing.
pub fn retime(moves: &mut [PlannedMove], t: f64, ratio: f64) -> Retiming {
    let mut retiming = Retiming::none(t);
    if !(ratio.is_finite() && ratio > 0.0 && t.is_finite()) || (ratio - 1.0).abs() < 1e-12 {
        return retiming;
    }
    // What the next span's start speed has been scaled by (the end of the span before).
    let mut carried = 1.0;
    // The end of the move before: (old, new).
    let mut before: Option<(f64, f64)> = None;
    for planned in moves.iter_mut() {
        if planned.end <= t {
            before = Some((planned.end, planned.end));
            continue;
        }
        let old_end = planned.end;
        let new_start = match before {
            Some((old, new)) if planned.start > t => new + (planned.start - old).max(0.0),
            _ => planned.start,
        };
        carried = retime_move(planned, t, ratio, new_start, carried, &mut retiming.stretches);
        before = Some((old_end, planned.end));
    }
    retiming.end_scale = carried;
    retiming
}

/// Re-times one move that ends after `t`, starting it at `new_start`; its stretches go
/// to `out`. Returns what its end speed was scaled by.
fn retime_move(
    planned: &mut PlannedMove,
    t: f64,
    ratio: f64,
    new_start: f64,
    mut carried: f64,
    out: &mut Vec<Stretch>,
) -> f64 {
    let first = out.len();
    let mut cursor = new_start;
    if planned.spans.is_empty() {
        out.push(Stretch { old_t0: planned.start, new_t0: new_start, profiles: None });
    }
    for span in &mut planned.spans {
        let old_t0 = span.t0;
        let old_end = old_t0 + span.profile.duration;
        if old_end <= t {
            // Walked already.
            cursor = old_end;
            carried = 1.0;
            continue;
        }
        let under_way = old_t0 <= t;
        let new_t0 = if under_way { old_t0 } else { cursor };
        let is_corner = matches!(span.piece, Piece::Corner(_));
        let new = match (span.profile.caps, under_way) {
            (Some(caps), true) if !is_corner => {
                let (_, v) = span.profile.at(t - old_t0);
                Some(span.profile.reshaped(t - old_t0, v, ratio, caps))
            }
            // A corner or a braking under way finishes as planned.
            (_, true) => None,
            (Some(caps), false) if !is_corner => {
                let u = span.profile.phases.first().map_or(0.0, |p| p.v0) * carried;
                Some(span.profile.reshaped(0.0, u, ratio, caps))
            }
            (_, false) => Some(span.profile.scaled(ratio)),
        };
        carried = if new.is_some() { ratio } else { 1.0 };
        let new = new.unwrap_or_else(|| span.profile.clone());
        out.push(Stretch { old_t0, new_t0, profiles: Some((span.profile.clone(), new.clone())) });
        span.t0 = new_t0;
        span.profile = new;
        cursor = new_t0 + span.profile.duration;
    }
    // The move's own times, through its stretches (a settle time after them kept).
    let mine = &out[first..];
    let through = |old: f64| match mine.iter().rposition(|s| s.old_t0 <= old) {
        Some(i) => mine[i].map(old),
        None => new_start + (old - planned.start),
    };
    let (zone_entry, end) = (through(planned.zone_entry), through(planned.end));
    if planned.corner_time > 0.0 {
        planned.corner_time = (end - zone_entry).max(0.0);
    }
    planned.start = new_start;
    planned.zone_entry = zone_entry;
    planned.end = end;
    carried
}

impl super::Planner {
    /// The speed override changed at time `t`, the speeds scaled by `ratio` from then
    /// on; `retiming` is what [`retime`] made of the moves laid out. The planner's clock
    /// follows, and the move waiting for its successor is planned at the new speed:
    /// from its start, or, when the robot is on it already, from where it is at `t`
    /// (as it walked it until then, the stop plan standing for it).
    pub fn retime(&mut self, t: f64, ratio: f64, retiming: &Retiming) {
        if !(ratio.is_finite() && ratio > 0.0 && t.is_finite()) || (ratio - 1.0).abs() < 1e-12 {
            return;
        }
        let under_way = self.time < t;
        if !under_way {
            self.time = retiming.map(self.time);
        }
        let start = self.time;
        let Some(pending) = self.pending.as_mut() else { return };
        if under_way {
            let own = pending.own_profile(0.0, pending.prep.limits.length - pending.s_start);
            pending.head = Some(own.walked(t - start));
        } else {
            pending.v_start *= retiming.end_scale();
        }
        pending.prep.limits.cap *= ratio;
    }
}

impl super::Pending {
    /// Its own profile over `length` of its path (from where it takes over), ending at
    /// speed `w`: the fastest its limits allow, or after the part walked before a
    /// re-timing, the rest shaped from where that left the robot.
    pub(super) fn own_profile(&self, w: f64, length: f64) -> Profile {
        let limits = &self.prep.limits;
        match &self.head {
            None => limits.profile(self.v_start, w, length),
            Some(head) => {
                let caps = Caps { cap: limits.cap, acc: limits.acc, dec: limits.dec };
                let rest = shaped(head.end_speed, w, caps, length - head.length);
                let mut phases = head.phases.clone();
                let (t0, s0) = (head.duration, head.length);
                phases.extend(rest.phases.iter().map(|p| Phase { t0: p.t0 + t0, s0: p.s0 + s0, ..*p }));
                Profile {
                    phases,
                    length: length.max(head.length),
                    duration: head.duration + rest.duration,
                    end_speed: rest.end_speed,
                    caps: Some(caps),
                }
            }
        }
    }
}

impl Profile {
    /// Path position `s` is reached at this time (the profile's inverse; clamped).
    pub(crate) fn time_at(&self, s: f64) -> f64 {
        if s.is_nan() || s <= 0.0 {
            return 0.0;
        }
        let Some(phase) = self.phases.iter().rev().find(|p| p.s0 <= s) else { return self.duration };
        let d = s - phase.s0;
        let tau = if phase.acc.abs() < 1e-12 {
            if phase.v0 > 0.0 {
                d / phase.v0
            } else {
                phase.dur
            }
        } else {
            // s0 + v0·τ + a·τ²/2 = s, the root within the phase.
            let disc = (phase.v0 * phase.v0 + 2.0 * phase.acc * d).max(0.0);
            (disc.sqrt() - phase.v0) / phase.acc
        };
        phase.t0 + tau.clamp(0.0, phase.dur)
    }

    /// The part walked by time `t`: a profile ending there, at the speed it had.
    fn walked(&self, t: f64) -> Profile {
        let t = if t.is_finite() { t.clamp(0.0, self.duration) } else { 0.0 };
        let (s, v) = self.at(t);
        Profile { phases: self.head(t), length: s, duration: t, end_speed: v, caps: self.caps }
    }

    /// The phases up to time `t`, the last cut there.
    fn head(&self, t: f64) -> Vec<Phase> {
        let mut head: Vec<Phase> = self.phases.iter().copied().filter(|p| p.t0 < t).collect();
        if let Some(last) = head.last_mut() {
            last.dur = last.dur.min(t - last.t0);
        }
        head
    }

    /// Walked at `ratio` times its speed throughout: its time stretched by 1/ratio
    /// (a corner's blend, a braking).
    fn scaled(&self, ratio: f64) -> Profile {
        let phases = self
            .phases
            .iter()
            .map(|p| Phase {
                t0: p.t0 / ratio,
                s0: p.s0,
                v0: p.v0 * ratio,
                acc: p.acc * ratio * ratio,
                dur: p.dur / ratio,
            })
            .collect();
        Profile {
            phases,
            length: self.length,
            duration: self.duration / ratio,
            end_speed: self.end_speed * ratio,
            caps: self.caps.map(|c| Caps { cap: c.cap * ratio, ..c }),
        }
    }

    /// As it was up to time `t`; from there, at speed `u`, shaped again with its cap
    /// and its end speed scaled by `ratio` and its accelerations `caps` kept.
    fn reshaped(&self, t: f64, u: f64, ratio: f64, caps: Caps) -> Profile {
        let (s_t, _) = self.at(t);
        let caps = Caps { cap: caps.cap * ratio, ..caps };
        let rest = shaped(u, self.end_speed * ratio, caps, self.length - s_t);
        let mut phases = if t > 0.0 { self.head(t) } else { Vec::new() };
        let t_rest = if t > 0.0 { t } else { 0.0 };
        phases.extend(rest.phases.iter().map(|p| Phase { t0: p.t0 + t_rest, s0: p.s0 + s_t, ..*p }));
        Profile {
            phases,
            length: self.length,
            duration: t_rest + rest.duration,
            end_speed: rest.end_speed,
            caps: Some(caps),
        }
    }
}

/// The fastest profile over `length` from speed `u` to `w` under `caps`; from a
/// start above the cap the robot first brakes to it.
fn shaped(u: f64, w: f64, caps: Caps, length: f64) -> Profile {
    let clean = |x: f64| if x.is_finite() { x.max(0.0) } else { 0.0 };
    let (u, w, length) = (clean(u), clean(w), clean(length));
    if u <= caps.cap || length <= EPS_LEN {
        return Profile::trapezoid_ad(u, w, caps.cap, caps.acc, caps.dec, length);
    }
    let down = (u * u - caps.cap * caps.cap) / (2.0 * caps.dec);
    let brake = (caps.cap * caps.cap - w * w).max(0.0) / (2.0 * caps.dec);
    if down + brake > length {
        // No room to cruise: one phase from u to w over the length.
        let dur = 2.0 * length / (u + w).max(1e-12);
        let phase = Phase { t0: 0.0, s0: 0.0, v0: u, acc: (w - u) / dur, dur };
        return Profile { phases: vec![phase], length, duration: dur, end_speed: w, caps: Some(caps) };
    }
    let slow = Phase { t0: 0.0, s0: 0.0, v0: u, acc: -caps.dec, dur: (u - caps.cap) / caps.dec };
    let rest = Profile::trapezoid_ad(caps.cap, w, caps.cap, caps.acc, caps.dec, length - down);
    let mut phases = vec![slow];
    phases.extend(rest.phases.iter().map(|p| Phase { t0: p.t0 + slow.dur, s0: p.s0 + down, ..*p }));
    Profile { phases, length, duration: slow.dur + rest.duration, end_speed: w, caps: Some(caps) }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-9
    }

    #[test]
    fn a_cruise_at_half_speed_takes_twice_its_time() {
        // 100 mm, cap 100 mm/s, 1000 mm/s²: 0.1 s (5 mm) up, 0.9 s (90 mm) of cruise,
        // 0.1 s (5 mm) down; at 0.5 s it stands at 45 mm at 100 mm/s.
        let p = Profile::trapezoid(0.0, 0.0, 100.0, 1000.0, 100.0);
        let caps = p.caps.unwrap();
        let r = p.reshaped(0.5, 100.0, 0.5, caps);
        // From 100 to 50 mm/s at 1000 mm/s²: 0.05 s over (100² − 50²)/2000 = 3.75 mm;
        // braking 50 → 0: 0.05 s over 1.25 mm; the 50 mm between at 50 mm/s take 1 s,
        // where at 100 mm/s they took 0.5 s.
        assert!(close(r.duration, 0.5 + 0.05 + 1.0 + 0.05), "{}", r.duration);
        assert!(close(r.time_at(45.0 + 3.75), 0.55));
        assert!(close(r.time_at(45.0 + 3.75 + 50.0), 1.55));
        let (s, v) = r.at(1.05);
        assert!(close(s, 48.75 + 25.0) && close(v, 50.0), "{s} {v}");
        // Before the change nothing moved.
        assert_eq!(r.at(0.3), p.at(0.3));
        // Faster again (50 → 100 %): up at 1000 mm/s², as the trapezoid ramps.
        let back = r.reshaped(1.05, 50.0, 2.0, r.caps.unwrap());
        let (s, v) = back.at(1.10);
        assert!(close(v, 100.0) && close(s, 73.75 + 3.75), "{s} {v}");
    }

    #[test]
    fn a_blend_is_stretched_and_the_inverse_holds() {
        // Rates 2/s and 6/s: 0.25 s; at half speed 0.5 s, rates 1/s and 3/s.
        let p = Profile::blend(2.0, 6.0).scaled(0.5);
        assert!(close(p.duration, 0.5) && close(p.end_speed, 3.0));
        assert!(close(p.at(0.5).0, 1.0));
        for t in [0.0, 0.1, 0.25, 0.4, 0.5] {
            assert!(close(p.time_at(p.at(t).0), t), "{t}");
        }
    }

    #[test]
    fn no_room_to_cruise_brakes_straight_to_the_end_speed() {
        // 2 mm left at 100 mm/s, new cap 10 mm/s, 1000 mm/s²: braking to the cap alone
        // needs 4.95 mm, so one phase from 100 to 0 over 2 mm: 2·2/100 = 0.04 s.
        let caps = Caps { cap: 10.0, acc: 1000.0, dec: 1000.0 };
        let p = shaped(100.0, 0.0, caps, 2.0);
        assert!(close(p.duration, 0.04) && close(p.at(0.04).0, 2.0));
    }

    #[test]
    fn times_before_the_change_stay_and_a_ratio_of_one_changes_nothing() {
        let mut none: Vec<PlannedMove> = Vec::new();
        let map = retime(&mut none, 1.0, 0.5);
        assert_eq!((map.map(0.5), map.map(3.0)), (0.5, 3.0));
        assert_eq!(retime(&mut none, 1.0, f64::NAN).end_scale(), 1.0);
    }
}
