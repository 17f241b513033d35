//! External units from a backup's `SYSPAR/MOC.cfg` (`rapid_config::moc::mechanical_units`):
//! what can be read of them becomes the unit a manifest's `[[unit]]` gives; the rest is
//! named in a note (`super::motion::choose_model`). The attribute names and their links are
//! those RobotWare writes (a public backup with a track was our source).
// uncertain: only the mechanics `TRACK` is known to us (a linear axis); a unit with any
// other is not read. The highest speed is the motor's (`STRESS_DUTY_CYCLE
// -speed_absolute_max`, rad/s) over the gear ratio (`TRANSMISSION -transm_joint`); the
// controller's own speed limit for the axis may be lower. A track moves along its
// SINGLE's base frame's x axis.

use rapid_config::moc::{MechUnit, SingleAxis};
use rapid_config::CfgFile;
use rapid_motion::external::{ExternalAxis, ExternalUnit};

use super::cell::{TaskUnit, RAMP_TIME};

/// MOC.cfg gives lengths in metres, programs see millimetres.
const MM_PER_M: f64 = 1000.0;

/// The units read from MOC.cfg, and those that could not be, with why.
#[derive(Debug, Default)]
pub struct MocUnits {
    pub units: Vec<TaskUnit>,
    pub unread: Vec<(String, String)>,
}

/// Reads the external units of a MOC file. They belong to the first motion task.
// uncertain: SYS.cfg's mechanical unit groups are not read; a MultiMove system's units
// go to the first motion task.
pub fn read(file: &CfgFile) -> MocUnits {
    let mut read = MocUnits::default();
    for mech in rapid_config::moc::mechanical_units(file) {
        match unit(&mech) {
            Ok(unit) => read.units.push(TaskUnit { task: None, unit }),
            Err(why) => read.unread.push((mech.name.clone(), why)),
        }
    }
    read
}

fn unit(mech: &MechUnit) -> Result<ExternalUnit, String> {
    if mech.axes.is_empty() {
        return Err("it has no axis (-use_single_0)".to_owned());
    }
    let axes = mech.axes.iter().map(axis).collect::<Result<Vec<_>, _>>()?;
    let carries_robot = mech.carries_robot && matches!(axes.as_slice(), [a] if a.linear);
    // A track moves along its SINGLE's base frame's x axis (the world's without one).
    let (pos, orient) = mech.axes[0].base_frame;
    let frame = (pos != [0.0; 3] || orient != [1.0, 0.0, 0.0, 0.0])
        .then(|| rapid_motion::pose::pose(pos.map(|m| m * 1000.0), orient));
    Ok(ExternalUnit {
        name: mech.name.clone(),
        axes,
        active_at_start: mech.active_at_start,
        deactivation_forbidden: mech.deactivation_forbidden,
        frame,
        carries_robot,
    })
}

/// A track's axis in the units programs see (mm): MOC.cfg has metres.
fn axis(single: &SingleAxis) -> Result<ExternalAxis, String> {
    let name = &single.single;
    match single.mechanics.as_deref() {
        Some(m) if m.eq_ignore_ascii_case("TRACK") => {}
        Some(m) => return Err(format!("its axis {name} is of mechanics `{m}`, which is not read (only TRACK)")),
        None => return Err(format!("its axis {name} has no mechanics (SINGLE_TYPE)")),
    }
    let logical = single.logical_axis.filter(|a| (7..=12).contains(a));
    let Some(logical) = logical else { return Err(format!("its axis {name} has no logical axis 7 … 12 (JOINT)")) };
    let scale = MM_PER_M;
    let (Some(lower), Some(upper)) = (single.lower, single.upper) else {
        return Err(format!("its axis {name} has no working range (ARM -lower_joint_bound, -upper_joint_bound)"));
    };
    let (min, max) = (lower * scale, upper * scale);
    let speed = match (single.motor_speed_max, single.transmission) {
        (Some(motor), Some(ratio)) if motor > 0.0 && ratio.abs() > 0.0 => motor / ratio.abs() * scale,
        _ => return Err(format!("its axis {name} has no speed (STRESS_DUTY_CYCLE, TRANSMISSION)")),
    };
    if !(min.is_finite() && max.is_finite() && min < max && speed.is_finite()) {
        return Err(format!("its axis {name} has an empty working range or no speed"));
    }
    let acc = single.acc.filter(|a| a.is_finite() && *a > 0.0).map_or(speed / RAMP_TIME, |a| a * scale);
    let start = 0f64.clamp(min, max);
    let mount = rapid_motion::Pose::identity();
    Ok(ExternalAxis { logical: logical as u8, linear: true, min, max, max_speed: speed, acc, start, mount })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A track as RobotWare links it, with our own values: 10 m long, the motor's
    /// 300 rad/s over a ratio of 300 rad/m (1 m/s), 2.5 m/s².
    const TRACK: &str = "MOC:CFG_1.0:6:0::
#
MECHANICAL_UNIT:

      -name \"TRK1\" -use_single_0 \"TRK1\" -activate_at_start_up  -deactivation_forbidden

      -name \"STN1\" -use_single_0 \"STN1\"
#
ROBOT:

      -name \"ROB_1\" -use_robot_type \"ROB1_120_0.58_3\" -base_frame_coordinated \"TRK1\"
#
SINGLE:

      -name \"TRK1\" -use_single_type \"TRK1\" -use_joint \"TRK1\"

      -name \"STN1\" -use_single_type \"STN1\" -use_joint \"STN1\"
#
SINGLE_TYPE:

      -name \"TRK1\" -mechanics \"TRACK\"

      -name \"STN1\" -mechanics \"SOMETHING_ELSE\"
#
JOINT:

      -name \"TRK1\" -logical_axis 7 -use_arm \"TRK1\" -use_transmission \"TRK1\" -use_drive_system \"TRK1\"
#
ARM:

      -name \"TRK1\" -use_acc_data \"TRK1\" -upper_joint_bound 10 -lower_joint_bound -0.1
#
ACC_DATA:

      -name \"TRK1\" -wc_acc 2.5 -wc_dec 2.5
#
TRANSMISSION:

      -name \"TRK1\" -transm_joint 300
#
DRIVE_SYSTEM:

      -name \"TRK1\" -use_stress_duty_cycle \"TRK1\"
#
STRESS_DUTY_CYCLE:

      -name \"TRK1\" -speed_absolute_max 300 -torque_absolute_max 30
";

    #[test]
    fn a_track_is_read_in_millimetres_and_carries_the_robot() {
        let read = read(&rapid_config::parse(TRACK));
        assert_eq!(read.units.len(), 1);
        let unit = &read.units[0].unit;
        assert_eq!((unit.name.as_str(), unit.active_at_start, unit.deactivation_forbidden), ("TRK1", true, true));
        assert!(unit.carries_robot);
        let axis = &unit.axes[0];
        assert_eq!((axis.logical, axis.linear), (7, true));
        assert!((axis.min + 100.0).abs() < 1e-9 && (axis.max - 10_000.0).abs() < 1e-9);
        assert!((axis.max_speed - 1000.0).abs() < 1e-9 && (axis.acc - 2500.0).abs() < 1e-9);
        assert_eq!(axis.start, 0.0);
        assert_eq!(
            read.unread,
            [(
                "STN1".to_owned(),
                "its axis STN1 is of mechanics `SOMETHING_ELSE`, which is not read (only TRACK)".to_owned()
            )]
        );
    }
}
