//! Laying the special triggers out on a final move (its path and timing are known):
//! a ramp becomes a series of output orders at the 4 ms path resolution, TriggSpeed
//! an output following the TCP speed at the same resolution, and a check or an
//! inhibited output a deferred action at its time (decided when the robot is there).

use rapid_motion::kinematics::Opw;
use rapid_motion::plan::{PlannedMove, DEFAULT_STEP};

use super::super::robot::Action;
use super::state::{Run, Special, TriggState};

/// Where path distances are measured: every millisecond.
const MARK_STEP: f64 = 0.001;

/// Path length travelled since the move's start at times along it.
struct Marks {
    /// (time, mm since the move's start), in time order.
    marks: Vec<(f64, f64)>,
}

impl Marks {
    fn of(kin: &Opw, planned: &PlannedMove) -> Marks {
        let steps = (((planned.end - planned.start) / MARK_STEP).ceil().max(0.0) as usize).min(2_000_000);
        let mut marks = Vec::with_capacity(steps + 1);
        let mut last = planned.sample(kin, planned.start).tcp.translation.vector;
        let mut travelled = 0.0;
        marks.push((planned.start, 0.0));
        for i in 1..=steps {
            let t = (planned.start + i as f64 * MARK_STEP).min(planned.end);
            let here = planned.sample(kin, t).tcp.translation.vector;
            travelled += (here - last).norm();
            last = here;
            marks.push((t, travelled));
        }
        Marks { marks }
    }

    /// The distance at time `t` (linear between marks).
    fn s_at(&self, t: f64) -> f64 {
        let i = self.marks.partition_point(|&(mt, _)| mt < t);
        match (i.checked_sub(1).and_then(|j| self.marks.get(j)), self.marks.get(i)) {
            (Some(&(t0, s0)), Some(&(t1, s1))) if t1 > t0 => s0 + (s1 - s0) * (t - t0) / (t1 - t0),
            (_, Some(&(_, s))) | (Some(&(_, s)), None) => s,
            (None, None) => 0.0,
        }
    }

    /// The first time the distance reaches `s` (None: not on this move).
    fn t_at(&self, s: f64) -> Option<f64> {
        let i = self.marks.partition_point(|&(_, ms)| ms < s);
        let &(t1, s1) = self.marks.get(i)?;
        match i.checked_sub(1).and_then(|j| self.marks.get(j)) {
            Some(&(t0, s0)) if s1 > s0 => Some(t0 + (t1 - t0) * (s - s0) / (s1 - s0)),
            _ => Some(t1),
        }
    }

    fn end(&self) -> f64 {
        self.marks.last().map_or(0.0, |&(t, _)| t)
    }
}

/// The times of the 4 ms grid after `from` up to `to` (the grid every trace shares).
fn grid(from: f64, to: f64) -> impl Iterator<Item = f64> {
    let first = (from / DEFAULT_STEP).floor() as i64 + 1;
    let last = (to / DEFAULT_STEP).floor() as i64;
    (first..=last.min(first + 10_000_000)).map(|k| k as f64 * DEFAULT_STEP)
}

impl TriggState {
    /// A final move: the runs going on from earlier moves continue over it, and its
    /// special events (`(time, shift, key)`) are laid out as outputs in `due`, or put
    /// there as deferred actions.
    pub fn on_move(
        &mut self,
        kin: &Opw,
        planned: &PlannedMove,
        events: &[(f64, f64, u32)],
        due: &mut Vec<(f64, Action)>,
    ) {
        if self.runs.is_empty() && events.is_empty() {
            return;
        }
        let marks = Marks::of(kin, planned);
        let speeds: Vec<f64> = events
            .iter()
            .filter(|(_, _, key)| matches!(self.live.get(key), Some(Special::Speed { .. })))
            .map(|&(at, _, _)| at)
            .collect();
        // The next TriggSpeed after `t` on this move ends the one before it.
        let next_speed = |t: f64| speeds.iter().copied().filter(|&s| s > t).fold(f64::INFINITY, f64::min);
        for run in std::mem::take(&mut self.runs) {
            match run {
                Run::Ramp { special, done } => self.ramp(&marks, planned.start, special, done, due),
                Run::Speed(special) => {
                    self.speed(kin, planned, planned.start, next_speed(f64::NEG_INFINITY), special, due)
                }
            }
        }
        for &(at, shift, key) in events {
            let Some(special) = self.live.remove(&key) else { continue };
            if special.deferred() {
                self.live.insert(key, special);
                due.push(((at + shift).max(planned.start), Action::Special(key)));
                continue;
            }
            match special {
                Special::Ramp { .. } => self.ramp(&marks, at, special, 0.0, due),
                Special::Speed { .. } => self.speed(kin, planned, at, next_speed(at), special, due),
                _ => {}
            }
        }
    }

    /// A ramp from time `from_t` on this move, `done` mm (or s) into its length: an
    /// output order at every 4 ms until its end; carried on when the move ends first.
    fn ramp(&mut self, marks: &Marks, from_t: f64, special: Special, done: f64, due: &mut Vec<(f64, Action)>) {
        let Special::Ramp { signal, from, to, length, by_time, lag } = special else { return };
        let value = |progress: f64| from + (to - from) * (progress / length).clamp(0.0, 1.0);
        let s0 = marks.s_at(from_t);
        let progress_at = |t: f64| if by_time { done + (t - from_t) } else { done + (marks.s_at(t) - s0) };
        let left = length - done;
        if left <= 0.0 {
            due.push((from_t - lag, Action::Set { signal, value: to }));
            return;
        }
        let finish = if by_time { Some(from_t + left).filter(|&t| t <= marks.end()) } else { marks.t_at(s0 + left) };
        let end = finish.unwrap_or_else(|| marks.end());
        for t in grid(from_t, end) {
            if finish.is_some_and(|f| t >= f) {
                break;
            }
            due.push((t - lag, Action::Set { signal, value: value(progress_at(t)) }));
        }
        match finish {
            Some(f) => due.push((f - lag, Action::Set { signal, value: to })),
            None => {
                let done = progress_at(marks.end());
                self.runs.push(Run::Ramp { special, done });
            }
        }
    }

    /// TriggSpeed from time `from_t` on this move until `until` (the next TriggSpeed)
    /// or the move's end: the output at every 4 ms; it goes on over the next move
    /// unless the robot stops at this move's point (the end of the move chain).
    // uncertain: the manual's "until the next TriggSpeed" is kept; a stop point ends
    // the output (it falls to 0 there with the speed), a non-trigger move after a
    // fly-by point does not.
    fn speed(
        &mut self,
        kin: &Opw,
        planned: &PlannedMove,
        from_t: f64,
        until: f64,
        special: Special,
        due: &mut Vec<(f64, Action)>,
    ) {
        let Special::Speed { signal, scale, lag, dip, max, err_do } = special else { return };
        let speed_at = |t: f64| planned.sample(kin, t.clamp(planned.start, planned.end)).tcp_speed;
        let mut last = f64::NAN;
        let mut overflow = false;
        let end = until.min(planned.end);
        for t in std::iter::once(from_t).chain(grid(from_t, end)) {
            if t >= until {
                break;
            }
            // A dip is announced DipLag before the robot slows, the rest ScaleLag.
            let ahead = if dip > lag { speed_at(t + dip - lag) } else { f64::INFINITY };
            let mut value = scale * speed_at(t).min(ahead);
            if let Some(max) = max.filter(|&m| value > m) {
                value = max;
                if let (Some(id), false) = (err_do, overflow) {
                    due.push((t - lag, Action::Set { signal: id, value: 1.0 }));
                }
                overflow = true;
            }
            if value != last {
                due.push((t - lag, Action::Set { signal, value }));
                last = value;
            }
        }
        let driven_until = if until <= planned.end {
            until - lag
        } else if planned.corner_time > 0.0 {
            self.runs.push(Run::Speed(special));
            f64::INFINITY
        } else {
            if last != 0.0 {
                due.push((planned.zone_entry - lag, Action::Set { signal, value: 0.0 }));
            }
            planned.zone_entry - lag
        };
        self.speed_outputs.retain(|&(s, _)| s != signal);
        self.speed_outputs.push((signal, driven_until));
    }
}
