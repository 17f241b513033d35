//! Speed profiles along a path parameter: trapezoids (accelerate, cruise,
//! decelerate) with given start and end speeds, and the single phase of
//! constant acceleration that walks a corner's curve parameter.

/// Smallest length (in the path's unit) we treat as a move at all.
pub(crate) const EPS_LEN: f64 = 1e-9;

/// A stretch of constant acceleration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Phase {
    pub(super) t0: f64,
    pub(super) s0: f64,
    pub(super) v0: f64,
    pub(super) acc: f64,
    pub(super) dur: f64,
}

/// The speed profile over one piece of path: up to three phases of constant
/// acceleration, from `s = 0` at `t = 0` to `s = length` at `t = duration`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Profile {
    pub(super) phases: Vec<Phase>,
    pub(crate) length: f64,
    pub(crate) duration: f64,
    pub(crate) end_speed: f64,
    /// What a trapezoid was shaped by, so that its rest can be shaped again at
    /// another speed (`retime.rs`); None for a corner's blend and a braking.
    pub(crate) caps: Option<Caps>,
}

/// A trapezoid's speed cap and its acceleration and deceleration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Caps {
    pub(crate) cap: f64,
    pub(crate) acc: f64,
    pub(crate) dec: f64,
}

/// What a path allows: its length, its speed cap and its acceleration, all in
/// the path's own unit (mm, ° or the joint metric).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PieceLimits {
    pub(crate) length: f64,
    pub(crate) cap: f64,
    pub(crate) acc: f64,
    /// Deceleration: the acceleration unless PathAccLim limits braking apart.
    pub(crate) dec: f64,
}

impl PieceLimits {
    /// The fastest profile over `length` of this piece from speed `u` to `w`.
    pub(crate) fn profile(&self, u: f64, w: f64, length: f64) -> Profile {
        Profile::trapezoid_ad(u, w, self.cap, self.acc, self.dec, length)
    }
}

impl Profile {
    /// When the profile starts its final deceleration (its duration when it
    /// never decelerates).
    pub(crate) fn braking_start(&self) -> f64 {
        match self.phases.last() {
            Some(last) if last.acc < 0.0 => last.t0,
            _ => self.duration,
        }
    }

    /// The fastest profile over `length` from speed `u` to speed `w` that stays
    /// under `cap` with acceleration `acc`. When `u` and `w` cannot be joined at
    /// `acc` (the caller's speeds were infeasible), the piece is one phase of
    /// whatever constant acceleration joins them: bounded, never NaN.
    #[cfg(test)]
    pub(crate) fn trapezoid(u: f64, w: f64, cap: f64, acc: f64, length: f64) -> Profile {
        Profile::trapezoid_ad(u, w, cap, acc, acc, length)
    }

    /// [`Profile::trapezoid`] with its own deceleration `dec` (PathAccLim).
    pub(crate) fn trapezoid_ad(u: f64, w: f64, cap: f64, acc: f64, dec: f64, length: f64) -> Profile {
        let clean = |x: f64| if x.is_finite() { x.max(0.0) } else { 0.0 };
        let (u, w, length) = (clean(u), clean(w), clean(length));
        let acc = if acc.is_finite() && acc > 0.0 { acc } else { 1.0 };
        let dec = if dec.is_finite() && dec > 0.0 { dec } else { acc };
        let caps = Some(Caps { cap: clean(cap).max(1e-9), acc, dec });
        let cap = clean(cap).max(u).max(w).max(1e-9);
        if length <= EPS_LEN {
            return Profile { phases: Vec::new(), length, duration: 0.0, end_speed: w, caps };
        }
        // The peak where accelerating from u and braking to w meet over the length.
        let peak = if acc == dec {
            ((2.0 * acc * length + u * u + w * w) / 2.0).sqrt()
        } else {
            ((2.0 * acc * dec * length + dec * u * u + acc * w * w) / (acc + dec)).sqrt()
        };
        let peak = peak.min(cap);
        if peak < u.max(w) {
            let dur = 2.0 * length / (u + w);
            let phase = Phase { t0: 0.0, s0: 0.0, v0: u, acc: (w - u) / dur, dur };
            return Profile { phases: vec![phase], length, duration: dur, end_speed: w, caps };
        }
        let d_up = (peak * peak - u * u) / (2.0 * acc);
        let d_down = (peak * peak - w * w) / (2.0 * dec);
        let d_cruise = (length - d_up - d_down).max(0.0);
        let durs = [(peak - u) / acc, d_cruise / peak, (peak - w) / dec];
        let mut phases = Vec::with_capacity(3);
        let (mut t, mut s) = (0.0, 0.0);
        for (dur, (v0, a)) in durs.into_iter().zip([(u, acc), (peak, 0.0), (peak, -dec)]) {
            if dur > 0.0 {
                phases.push(Phase { t0: t, s0: s, v0, acc: a, dur });
                t += dur;
                s += v0 * dur + 0.5 * a * dur * dur;
            }
        }
        Profile { phases, length, duration: t, end_speed: w, caps }
    }

    /// The curve parameter of a corner (0 to 1) walked with its rate changing
    /// linearly from `rate_in` to `rate_out` (1/s): the parabolic blend of
    /// constant acceleration when the curve is a quadratic Bézier.
    pub(crate) fn blend(rate_in: f64, rate_out: f64) -> Profile {
        let clean = |x: f64| if x.is_finite() { x.max(0.0) } else { 0.0 };
        let (r0, r1) = (clean(rate_in), clean(rate_out));
        if r0 + r1 <= 1e-12 {
            return Profile { phases: Vec::new(), length: 1.0, duration: 0.0, end_speed: r1, caps: None };
        }
        let dur = 2.0 / (r0 + r1);
        let phase = Phase { t0: 0.0, s0: 0.0, v0: r0, acc: (r1 - r0) / dur, dur };
        Profile { phases: vec![phase], length: 1.0, duration: dur, end_speed: r1, caps: None }
    }

    /// The profile braked from time `t` on (a stop on the path): the speed falls at a
    /// constant rate to 0 in `stop_time`, or sooner where the piece ends.
    pub(crate) fn braked_at(&self, t: f64, stop_time: f64) -> Profile {
        let t = if t.is_finite() { t.clamp(0.0, self.duration) } else { 0.0 };
        let stop_time = if stop_time.is_finite() { stop_time.max(0.0) } else { 0.0 };
        let (s, v) = self.at(t);
        let mut phases: Vec<Phase> = self.phases.iter().copied().filter(|p| p.t0 < t).collect();
        if let Some(last) = phases.last_mut() {
            last.dur = last.dur.min(t - last.t0);
        }
        let room = (self.length - s).max(0.0);
        let dur = match v > 0.0 {
            false => 0.0,
            true if v * stop_time / 2.0 <= room => stop_time,
            true => 2.0 * room / v,
        };
        let acc = if dur > 0.0 { -v / dur } else { 0.0 };
        phases.push(Phase { t0: t, s0: s, v0: v, acc, dur });
        Profile { phases, length: self.length, duration: t + dur, end_speed: 0.0, caps: None }
    }

    /// Path position and speed at time `t` (clamped to the profile).
    pub(crate) fn at(&self, t: f64) -> (f64, f64) {
        let t = if t.is_finite() { t.clamp(0.0, self.duration) } else { 0.0 };
        let Some(phase) = self.phases.iter().rev().find(|p| p.t0 <= t).or(self.phases.first()) else {
            return (self.length, self.end_speed);
        };
        let tau = (t - phase.t0).clamp(0.0, phase.dur);
        let s = phase.s0 + phase.v0 * tau + 0.5 * phase.acc * tau * tau;
        let v = phase.v0 + phase.acc * tau;
        (s.clamp(0.0, self.length), v.max(0.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-9
    }

    #[test]
    fn braking_falls_to_zero_in_the_stop_time_or_at_the_end() {
        // 100 mm at 100 mm/s with 1000 mm/s² ramps: 0.1 s and 5 mm to speed. Braked at
        // 0.5 s (at 45 mm, 100 mm/s) over 0.08 s: 100 · 0.08 / 2 = 4 mm more, at 0.58 s.
        let p = Profile::trapezoid(0.0, 0.0, 100.0, 1000.0, 100.0);
        let b = p.braked_at(0.5, 0.08);
        assert!(close(b.duration, 0.58));
        let (s, v) = b.at(0.58);
        assert!(close(s, 49.0) && close(v, 0.0), "{s} {v}");
        let (s, v) = b.at(0.54);
        assert!(close(s, 45.0 + 100.0 * 0.04 - 0.5 * 1250.0 * 0.04 * 0.04) && close(v, 50.0), "{s} {v}");
        // Braked at 0.9 s (at 85 mm) over 0.8 s would need 40 mm; 15 mm are left:
        // it stops at the end after 2 · 15 / 100 = 0.3 s.
        let b = p.braked_at(0.9, 0.8);
        assert!(close(b.duration, 1.2) && close(b.at(1.2).0, 100.0));
    }

    #[test]
    fn long_move_reaches_cruise() {
        // T = L/v + v/a = 1000/1000 + 1000/10000.
        let p = Profile::trapezoid(0.0, 0.0, 1000.0, 10_000.0, 1000.0);
        assert!(close(p.duration, 1.1));
        assert!(close(p.at(0.55).0, 500.0));
        assert!(close(p.at(0.55).1, 1000.0));
        assert_eq!(p.at(5.0), (1000.0, 0.0));
    }

    #[test]
    fn short_move_never_cruises() {
        // L = 10 < v²/a = 100: T = 2·√(L/a).
        let p = Profile::trapezoid(0.0, 0.0, 1000.0, 10_000.0, 10.0);
        assert!(close(p.duration, 2.0 * (10.0f64 / 10_000.0).sqrt()));
        assert!(close(p.at(p.duration / 2.0).0, 5.0));
    }

    #[test]
    fn blend_walks_the_parameter_once() {
        // Rates 2/s and 6/s: T = 2/(2 + 6) and the parameter reaches 1.
        let p = Profile::blend(2.0, 6.0);
        assert!(close(p.duration, 0.25));
        assert!(close(p.at(0.25).0, 1.0));
        assert!(close(p.at(0.125).1, 4.0));
        assert_eq!(Profile::blend(0.0, f64::NAN).duration, 0.0);
    }

    #[test]
    fn degenerate_inputs_stay_finite() {
        let p = Profile::trapezoid(f64::NAN, 0.0, 0.0, 0.0, 0.0);
        assert_eq!((p.duration, p.at(1.0).0), (0.0, 0.0));
        // Start faster than the piece can shed: one phase of harder braking.
        let p = Profile::trapezoid(1000.0, 0.0, 1000.0, 10_000.0, 1.0);
        assert!(close(p.duration, 0.002));
        assert!(p.at(0.001).0.is_finite());
    }
}
