//! External axes in the planner: a move's external axes go from where the last move
//! left them to its target along the same speed profile as the arm, so all axes start
//! and stop together (§2.2: the slowest sets the pace). Each moving axis bounds the
//! path speed as the reorientation does: it may not exceed its own speed (`v_leax` or
//! `v_reax`, and the axis's maximum) nor its acceleration.
//!
//! A move in which the arm stands still (MoveExtJ, or a target the arm is already at)
//! gets a path of unit length walked by the external axes alone.

use super::corner::CornerPath;
use super::data::SpeedData;
use super::profile::{PieceLimits, EPS_LEN};
use super::sample::{Piece, PlannedMove};
use super::segment::Prepared;
use crate::external::{Eax, ExternalMove};
use crate::MotionError;

/// Bounds `prep`'s path speed and acceleration by the external axes that move, and
/// keeps them with the move. `speed` is the effective speeddata (infinite under `\T`,
/// where only the axes' maxima bound them) and `acc_factor` AccSet's.
pub(crate) fn pace(
    prep: &mut Prepared,
    ext: &ExternalMove,
    speed: &SpeedData,
    acc_factor: f64,
) -> Result<(), MotionError> {
    let mut moving = ext.moving().peekable();
    if moving.peek().is_some() && prep.limits.length <= EPS_LEN {
        // The arm stands: the path is the external axes' own, of unit length.
        prep.limits = PieceLimits { length: 1.0, cap: f64::INFINITY, acc: f64::INFINITY, dec: f64::INFINITY };
        prep.axes_only = true;
    }
    let limits = &mut prep.limits;
    for (j, distance) in moving {
        let programmed = if ext.linear[j] { speed.v_leax } else { speed.v_reax };
        let allowed = programmed.min(ext.max_speed[j]);
        if allowed.is_nan() || allowed <= 0.0 {
            return Err(MotionError::InvalidData("the speed of a moving external axis is zero"));
        }
        let acc = ext.acc[j] * acc_factor;
        let acc = if acc.is_finite() && acc > 0.0 { acc } else { allowed };
        let per_unit = limits.length / distance;
        limits.cap = limits.cap.min(allowed * per_unit);
        limits.acc = limits.acc.min(acc * per_unit);
        limits.dec = limits.dec.min(acc * per_unit);
    }
    prep.eax = Some(Box::new(*ext));
    Ok(())
}

/// The external axes of a planned move: its own stretch (from the start to the target
/// over the path's length) and, at a fly-by point, the corner's ends.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct EaxTrack {
    pub(crate) ext: ExternalMove,
    pub(crate) length: f64,
    /// The axis values where the corner path leaves this move and where it joins the
    /// next; the corner moves them in a straight line between.
    // uncertain: how the controller blends external axes in a corner (pzone_eax) is not
    // published; they follow the TCP corner's progress.
    pub(crate) corner: Option<(Eax, Eax)>,
}

impl EaxTrack {
    /// The move's axis values at path parameter `s` of its own path.
    pub(crate) fn at(&self, s: f64) -> Eax {
        let f = if self.length > EPS_LEN { s / self.length } else { 1.0 };
        self.ext.at(f)
    }
}

/// Where the move's external axes are at path parameter `s` of the next move (the
/// corner's exit), for the corner before it.
pub(crate) fn at_start_of(next: &Prepared, s: f64) -> Option<Eax> {
    let ext = next.eax.as_ref()?;
    let f = if next.limits.length > EPS_LEN { s / next.limits.length } else { 1.0 };
    Some(ext.at(f))
}

impl PlannedMove {
    /// The external axes at time `t` (clamped to the move), or `None` when the
    /// system has none (or the move was planned without them).
    pub fn eax_at(&self, t: f64) -> Option<Eax> {
        let track = self.eax.as_ref()?;
        let t = if t.is_finite() { t.clamp(self.start, self.end) } else { self.end };
        let Some(span) = self.spans.iter().rev().find(|s| s.t0 <= t) else {
            return Some(track.ext.to);
        };
        let (s, _) = span.profile.at(t - span.t0);
        Some(match &span.piece {
            Piece::Own { s0, .. } => track.at(s0 + s),
            Piece::Corner(path) => {
                let len = span.profile.length;
                let f = if len > EPS_LEN { (s / len).clamp(0.0, 1.0) } else { 1.0 };
                match (path, track.corner) {
                    // The axes' own corner: on its parabola.
                    (CornerPath::Axes { curve, .. }, _) => curve.point(f),
                    (_, Some((from, to))) => std::array::from_fn(|j| from[j] + f * (to[j] - from[j])),
                    (_, None) => track.ext.to,
                }
            }
        })
    }

    /// The external axes where the move ends (at its corner's exit).
    pub fn eax_end(&self) -> Option<Eax> {
        self.eax_at(self.end)
    }

    /// Keeps the external axes standing at `eax` through this move (a pause of the
    /// path, which has no track of its own).
    pub fn hold_eax(&mut self, eax: Option<Eax>) {
        self.eax = eax.map(|at| {
            Box::new(EaxTrack {
                ext: ExternalMove { from: at, to: at, max_speed: [0.0; 6], acc: [0.0; 6], linear: [false; 6] },
                length: 0.0,
                corner: None,
            })
        });
    }
}
