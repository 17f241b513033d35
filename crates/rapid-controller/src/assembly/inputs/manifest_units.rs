//! `[[unit]]` tables of `rapid.toml`: the external mechanical units (a track, a
//! positioner) a motion task moves besides its arm, as a backup's MOC.cfg would
//! configure them. See docs/manifest.md.

use std::ops::Range;

use crate::boot::cell::{TaskConveyor, TaskUnit, RAMP_TIME};
use rapid_motion::external::{ExternalAxis, ExternalUnit};
use serde::Deserialize;
use toml::Spanned;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawUnit {
    name: Spanned<String>,
    task: Option<Spanned<String>>,
    active: Option<bool>,
    deactivation_forbidden: Option<bool>,
    base: Option<Spanned<Vec<f64>>>,
    orientation: Option<Spanned<Vec<f64>>>,
    carries_robot: Option<Spanned<bool>>,
    #[serde(default)]
    axis: Vec<Spanned<RawAxis>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawAxis {
    logical: Spanned<i64>,
    #[serde(rename = "type")]
    kind: Spanned<String>,
    min: Spanned<f64>,
    max: Spanned<f64>,
    speed: Spanned<f64>,
    acceleration: Option<Spanned<f64>>,
    start: Option<Spanned<f64>>,
    base: Option<Spanned<Vec<f64>>>,
    orientation: Option<Spanned<Vec<f64>>>,
}

/// Reads the units, reporting each problem with its place through `find`.
pub(super) fn read(raw: &[Spanned<RawUnit>], find: &mut dyn FnMut(Range<usize>, String)) -> Vec<TaskUnit> {
    let mut units: Vec<TaskUnit> = Vec::new();
    for spanned in raw {
        let raw = spanned.get_ref();
        let name = raw.name.get_ref().clone();
        if let Some(why) = super::manifest::identifier_problem(&name) {
            find(raw.name.span(), format!("unit name `{name}` {why}"));
        }
        if units.iter().any(|u| u.unit.name.eq_ignore_ascii_case(&name)) {
            find(raw.name.span(), format!("unit `{name}` is configured twice"));
        }
        if name.to_ascii_uppercase().starts_with("ROB_") {
            find(raw.name.span(), format!("unit name `{name}`: ROB_n names the robots"));
        }
        if raw.axis.is_empty() {
            find(spanned.span(), format!("unit `{name}` has no `[[unit.axis]]`"));
        }
        let task = raw.task.as_ref().map(|t| t.get_ref().clone());
        let axes: Vec<ExternalAxis> = raw.axis.iter().filter_map(|a| axis(&name, a.get_ref(), find)).collect();
        for a in &axes {
            let clash =
                units.iter().filter(|u| u.task == task).flat_map(|u| &u.unit.axes).any(|b| b.logical == a.logical);
            if clash || axes.iter().filter(|b| b.logical == a.logical).count() > 1 {
                find(spanned.span(), format!("unit `{name}`: logical axis {} is configured twice", a.logical));
            }
        }
        // A frame (base, orientation) lets the unit carry work objects (`ufmec`).
        let frame = (raw.base.is_some() || raw.orientation.is_some()).then(|| {
            let base = fixed::<3>(raw.base.as_ref(), [0.0; 3], "base", &name, find);
            let orientation = orientation(raw.orientation.as_ref(), &name, find);
            rapid_motion::pose::pose(base, orientation)
        });
        check_mounts(raw, frame.is_some(), find);
        let unit = ExternalUnit {
            name,
            axes,
            active_at_start: raw.active.unwrap_or(true),
            deactivation_forbidden: raw.deactivation_forbidden.unwrap_or(false),
            frame,
            carries_robot: carries_robot(raw, &units, find),
        };
        units.push(TaskUnit { task, unit });
    }
    units
}

/// An axis's `base`/`orientation` place it on the axis before it in a unit that
/// carries work objects; elsewhere they would mean nothing.
fn check_mounts(raw: &RawUnit, has_frame: bool, find: &mut dyn FnMut(Range<usize>, String)) {
    let name = raw.name.get_ref();
    let track = raw.carries_robot.as_ref().is_some_and(|f| *f.get_ref());
    for axis in raw.axis.iter().map(Spanned::get_ref) {
        let Some(key) = axis.base.as_ref().or(axis.orientation.as_ref()) else { continue };
        if track || !has_frame {
            find(
                key.span(),
                format!(
                    "unit `{name}`: an axis's base and orientation place it in a unit that carries work objects \
                     (give the unit a base or orientation; not on a track)"
                ),
            );
        }
    }
}

/// `carries_robot`: a track of one linear axis, and one such unit per task.
fn carries_robot(raw: &RawUnit, units: &[TaskUnit], find: &mut dyn FnMut(Range<usize>, String)) -> bool {
    let Some(flag) = raw.carries_robot.as_ref().filter(|f| *f.get_ref()) else { return false };
    let name = raw.name.get_ref();
    let linear_one = matches!(raw.axis.as_slice(), [a] if a.get_ref().kind.get_ref().eq_ignore_ascii_case("linear"));
    if !linear_one {
        find(flag.span(), format!("unit `{name}`: a unit that carries the robot is a track of one linear axis"));
    }
    let task = raw.task.as_ref().map(|t| t.get_ref());
    if units.iter().any(|u| u.unit.carries_robot && u.task.as_ref() == task) {
        find(flag.span(), format!("unit `{name}`: another unit carries this task's robot already"));
    }
    linear_one
}

/// One axis, or `None` (with findings) when it cannot be used.
fn axis(unit: &str, raw: &RawAxis, find: &mut dyn FnMut(Range<usize>, String)) -> Option<ExternalAxis> {
    let mut ok = true;
    let logical = *raw.logical.get_ref();
    if !(7..=12).contains(&logical) {
        find(raw.logical.span(), format!("unit `{unit}`: logical axis {logical} is not 7 … 12 (eax_a … eax_f)"));
        ok = false;
    }
    let linear = match raw.kind.get_ref().to_ascii_lowercase().as_str() {
        "linear" => true,
        "rotating" => false,
        other => {
            find(raw.kind.span(), format!("unit `{unit}`: unknown axis type `{other}` (linear or rotating)"));
            ok = false;
            true
        }
    };
    let (min, max) = (*raw.min.get_ref(), *raw.max.get_ref());
    if !(min.is_finite() && max.is_finite() && min < max) {
        find(raw.max.span(), format!("unit `{unit}`: the working range {min} … {max} is empty"));
        ok = false;
    }
    let speed = *raw.speed.get_ref();
    if !(speed.is_finite() && speed > 0.0) {
        find(raw.speed.span(), format!("unit `{unit}`: speed {speed} is not a positive number"));
        ok = false;
    }
    let acc = raw.acceleration.as_ref().map_or(speed / RAMP_TIME, |a| *a.get_ref());
    if let Some(a) = raw.acceleration.as_ref().filter(|a| !(a.get_ref().is_finite() && *a.get_ref() > 0.0)) {
        find(a.span(), format!("unit `{unit}`: acceleration {} is not a positive number", a.get_ref()));
        ok = false;
    }
    let start = raw.start.as_ref().map_or(min.max(0.0).min(max), |s| *s.get_ref());
    if let Some(s) = raw.start.as_ref().filter(|s| !(min..=max).contains(s.get_ref())) {
        find(s.span(), format!("unit `{unit}`: start {} is outside the working range {min} … {max}", s.get_ref()));
        ok = false;
    }
    // Where the axis sits on the one before it (the unit's frame for the first).
    let at = fixed::<3>(raw.base.as_ref(), [0.0; 3], "base", unit, find);
    let mount = rapid_motion::pose::pose(at, orientation(raw.orientation.as_ref(), unit, find));
    ok.then_some(ExternalAxis { logical: logical as u8, linear, min, max, max_speed: speed, acc, start, mount })
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawConveyor {
    name: Spanned<String>,
    task: Option<Spanned<String>>,
    sync: Spanned<String>,
    speed: Spanned<String>,
    base: Option<Spanned<Vec<f64>>>,
    orientation: Option<Spanned<Vec<f64>>>,
    start_window: Spanned<f64>,
    max_dist: Spanned<f64>,
    active: Option<bool>,
}

/// Reads the conveyors; `taken` are the unit names already used.
pub(super) fn read_conveyors(
    raw: &[Spanned<RawConveyor>],
    taken: &[String],
    find: &mut dyn FnMut(Range<usize>, String),
) -> Vec<TaskConveyor> {
    let mut conveyors: Vec<TaskConveyor> = Vec::new();
    for raw in raw.iter().map(Spanned::get_ref) {
        let name = raw.name.get_ref().clone();
        if let Some(why) = super::manifest::identifier_problem(&name) {
            find(raw.name.span(), format!("conveyor name `{name}` {why}"));
        }
        let used = taken.iter().chain(conveyors.iter().map(|c| &c.name)).any(|n| n.eq_ignore_ascii_case(&name));
        if used {
            find(raw.name.span(), format!("unit `{name}` is configured twice"));
        }
        let base = fixed::<3>(raw.base.as_ref(), [0.0; 3], "base", &name, find);
        let orientation = orientation(raw.orientation.as_ref(), &name, find);
        for (value, key) in [(&raw.start_window, "start_window"), (&raw.max_dist, "max_dist")] {
            if !(value.get_ref().is_finite() && *value.get_ref() > 0.0) {
                find(value.span(), format!("conveyor `{name}`: {key} {} is not a positive number", value.get_ref()));
            }
        }
        conveyors.push(TaskConveyor {
            task: raw.task.as_ref().map(|t| t.get_ref().clone()),
            name,
            sync: raw.sync.get_ref().clone(),
            speed: raw.speed.get_ref().clone(),
            base,
            orientation,
            start_window: *raw.start_window.get_ref(),
            max_dist: *raw.max_dist.get_ref(),
            active: raw.active.unwrap_or(true),
        });
    }
    conveyors
}

/// A unit quaternion (`[1, 0, 0, 0]` when absent).
pub(super) fn orientation(
    raw: Option<&Spanned<Vec<f64>>>,
    name: &str,
    find: &mut dyn FnMut(Range<usize>, String),
) -> [f64; 4] {
    let orientation = fixed::<4>(raw, [1.0, 0.0, 0.0, 0.0], "orientation", name, find);
    let norm = orientation.iter().map(|q| q * q).sum::<f64>().sqrt();
    if let Some(o) = raw.filter(|_| (norm - 1.0).abs() > 1e-3) {
        find(o.span(), format!("`{name}`: the orientation is not a unit quaternion"));
    }
    orientation
}

/// An array of exactly N numbers, or `default` when absent.
pub(super) fn fixed<const N: usize>(
    raw: Option<&Spanned<Vec<f64>>>,
    default: [f64; N],
    key: &str,
    name: &str,
    find: &mut dyn FnMut(Range<usize>, String),
) -> [f64; N] {
    let Some(raw) = raw else { return default };
    match <[f64; N]>::try_from(raw.get_ref().as_slice()) {
        Ok(values) if values.iter().all(|v| v.is_finite()) => values,
        _ => {
            find(raw.span(), format!("`{name}`: {key} takes {N} numbers"));
            default
        }
    }
}
