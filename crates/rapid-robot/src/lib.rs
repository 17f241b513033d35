//! rapid-robot: the robot's side of RAPID, an extension of the interpreter core
//! (`rapid_vm::ext::Extension`, [`EXTENSION`]). It holds the task's robot state
//! ([`robot::RobotState`]: its model, planned motion and where it is), the motion
//! settings ([`MotionState`]), the built-ins that move the robot or read where it is
//! (§1.7 motion settings, §1.8 motion: moves, read-backs, search, triggers, world
//! zones, conveyors and tracking, independent axes, the path recorder, StorePath,
//! servo and supervision), MultiMove's synchronized movement (`syncmove`), the
//! active tool, work object and payload (`sysdata`), and what the trace and the
//! report read of a robot. It plans through rapid-motion and sets trigger outputs
//! through rapid-signals (the task's I/O state, `rapid_signals::IoAccess`) on
//! rapid-io's model.
//!
//! What it must not know: no controller (task scheduling, system assembly,
//! configuration files: the controller hands it a built robot and links its tasks,
//! `foreign::link`), no CLI or output format, no `std::net` or `std::fs`, no wall
//! clock: time is the task's virtual time it is given.
//!
//! The settings live in [`MotionState`]; the parts RAPID can read back are mirrored
//! into the system data C_MOTSET (motsetdata) and C_PROGDISP (progdisp) each time an
//! instruction changes them. At PP to Main both go back to their defaults: the state
//! by [`MotionState::reset`], the system data by their catalogue initial values,
//! which equal [`Settings::default`].

mod arm7;
mod calib;
pub mod conveyor;
pub mod corr;
mod data;
pub mod extax;
mod fit;
pub mod foreign;
mod frame;
mod hooks;
pub mod indep;
mod inpos;
mod layout;
mod moves;
pub mod pause;
mod position;
mod readback;
pub mod recorder;
mod retime;
pub mod robot;
mod search;
pub mod servo;
mod settings;
mod stepbwd;
pub mod store;
mod syncmove;
pub mod sysdata;
pub mod testsign;
mod torque;
mod track;
mod tracking;
mod trigg;
mod units;
mod zone_watch;
pub mod zones;

pub use hooks::EXTENSION;
pub(crate) use moves::{apply_due_events, motion_error};
pub(crate) use pause::abandon_paths;
pub use readback::robot_reply;
pub(crate) use settings::set_payload;
pub(crate) use tracking::stop_following_other_tasks;
pub(crate) use trigg::{poll as poll_triggers, program_stopped};

use std::rc::Rc;

use nalgebra::Isometry3;
use rapid_sema::types::TypeId;

use rapid_vm::ext::{native, Ctx, Family, Value};

pub(crate) static FAMILY: Family = Family {
    file: file!(),
    builtins: &[
        native("VelSet", settings::vel_set),
        native("AccSet", settings::acc_set),
        native("ConfJ", settings::conf_j),
        native("ConfL", settings::conf_l),
        native("SingArea", settings::sing_area),
        native("CirPathMode", settings::cir_path_mode),
        native("PathAccLim", settings::path_acc_lim),
        native("IndAMove", indep::ind_a_move),
        native("IndCMove", indep::ind_c_move),
        native("IndDMove", indep::ind_d_move),
        native("IndRMove", indep::ind_r_move),
        native("IndReset", indep::ind_reset),
        native("IndInpos", indep::ind_inpos),
        native("IndSpeed", indep::ind_speed),
        native("WorldAccLim", settings::world_acc_lim),
        native("GripLoad", settings::grip_load),
        native("PathResol", settings::path_resol),
        native("CornerPathWarning", settings::corner_path_warning),
        native("MotionProcessModeSet", settings::motion_process_mode_set),
        native("SpeedRefresh", settings::speed_refresh),
        native("CSpeedOverride", settings::c_speed_override),
        native("PDispSet", settings::pdisp_set),
        native("PDispOff", settings::pdisp_off),
        native("EOffsSet", settings::eoffs_set),
        native("EOffsOff", settings::eoffs_off),
        native("Offs", position::offs),
        native("RelTool", position::rel_tool),
        native("ORobT", position::orob_t),
        native("MirPos", position::mir_pos),
        native("Distance", position::distance),
        native("DefFrame", fit::def_frame),
        native("DefDFrame", fit::def_d_frame),
        native("DefAccFrame", fit::def_acc_frame),
        native("MoveJ", moves::move_j),
        native("MoveL", moves::move_l),
        native("MoveC", moves::move_c),
        native("MoveAbsJ", moves::move_abs_j),
        native("MoveExtJ", extax::move_ext_j),
        native("WaitWObj", tracking::wait_wobj),
        native("DropWObj", tracking::drop_wobj),
        native("WaitRob", moves::wait_rob),
        native("CJointT", readback::c_joint_t),
        native("CRobT", readback::c_rob_t),
        native("CPos", readback::c_pos),
        native("CalcRobT", readback::calc_rob_t),
        native("CalcJointT", readback::calc_joint_t),
        native("PDispOn", readback::pdisp_on),
        native("EOffsOn", readback::eoffs_on),
        native("SearchL", search::search_l),
        native("SearchC", search::search_c),
        native("SearchExtJ", search::search_ext_j),
        native("MoveJDO", moves::move_j_do),
        native("MoveJAO", moves::move_j_ao),
        native("MoveJGO", moves::move_j_go),
        native("MoveLDO", moves::move_l_do),
        native("MoveLAO", moves::move_l_ao),
        native("MoveLGO", moves::move_l_go),
        native("MoveCDO", moves::move_c_do),
        native("MoveCAO", moves::move_c_ao),
        native("MoveCGO", moves::move_c_go),
        native("MoveJSync", moves::move_j_sync),
        native("MoveLSync", moves::move_l_sync),
        native("MoveCSync", moves::move_c_sync),
        native("TriggIO", trigg::trigg_io),
        native("TriggEquip", trigg::trigg_equip),
        native("TriggInt", trigg::trigg_int),
        native("TriggL", trigg::trigg_l),
        native("TriggJ", trigg::trigg_j),
        native("TriggC", trigg::trigg_c),
        native("TriggAbsJ", trigg::trigg_abs_j),
        native("TriggLIOs", trigg::trigg_l_ios),
        native("TriggJIOs", trigg::trigg_j_ios),
        native("TriggCheckIO", trigg::trigg_check_io),
        native("TriggRampAO", trigg::trigg_ramp_ao),
        native("TriggSpeed", trigg::trigg_speed),
        native("TriggDataCopy", trigg::trigg_data_copy),
        native("TriggDataReset", trigg::trigg_data_reset),
        native("TriggDataValid", trigg::trigg_data_valid),
        native("TriggStopProc", trigg::trigg_stop_proc),
        native("StopMove", pause::stop_move),
        native("StartMove", pause::start_move),
        native("IsStopMoveAct", pause::is_stop_move_act),
        native("ClearPath", pause::clear_path),
        native("PathLevel", pause::path_level),
        native("StartMoveRetry", pause::start_move_retry),
        native("StopMoveReset", pause::stop_move_reset),
        native("StorePath", store::store_path),
        native("RestoPath", store::resto_path),
        native("PathRecStart", recorder::path_rec_start),
        native("PathRecStop", recorder::path_rec_stop),
        native("PathRecValidBwd", recorder::path_rec_valid_bwd),
        native("PathRecValidFwd", recorder::path_rec_valid_fwd),
        native("PathRecMoveBwd", recorder::path_rec_move_bwd),
        native("PathRecMoveFwd", recorder::path_rec_move_fwd),
        native("StepBwdPath", stepbwd::step_bwd_path),
        native("WZBoxDef", zones::wz_box_def),
        native("WZCylDef", zones::wz_cyl_def),
        native("WZSphDef", zones::wz_sph_def),
        native("WZHomeJointDef", zones::wz_home_joint_def),
        native("WZLimJointDef", zones::wz_lim_joint_def),
        native("WZDOSet", zones::wz_do_set),
        native("WZLimSup", zones::wz_lim_sup),
        native("WZEnable", zones::wz_enable),
        native("WZDisable", zones::wz_disable),
        native("WZFree", zones::wz_free),
        native("RobName", units::rob_name),
        native("MaxRobSpeed", units::max_rob_speed),
        native("MaxRobReorientSpeed", units::max_rob_reorient_speed),
        native("GetNextMechUnit", units::get_next_mech_unit),
        native("IsMechUnitActive", units::is_mech_unit_active),
        native("ActUnit", units::act_unit),
        native("DeactUnit", units::deact_unit),
        native("MechUnitLoad", units::mech_unit_load),
        native("ReadMotor", units::read_motor),
        native("MotionSup", servo::motion_sup),
        native("SoftAct", servo::soft_act),
        native("SoftDeact", servo::soft_deact),
        native("TuneServo", servo::tune_servo),
        native("TuneReset", servo::tune_reset),
        native("ActEventBuffer", servo::act_event_buffer),
        native("DeactEventBuffer", servo::deact_event_buffer),
        native("SpeedLimAxis", servo::speed_lim_axis),
        native("SpeedLimCheckPoint", servo::speed_lim_check_point),
        native("PFRestart", servo::pf_restart),
        native("TestSignDefine", testsign::test_sign_define),
        native("TestSignReset", testsign::test_sign_reset),
        native("TestSignRead", testsign::test_sign_read),
        native("GetMotorTorque", torque::get_motor_torque),
        native("ParIdRobValid", torque::par_id_rob_valid),
        native("MToolTCPCalib", calib::m_tool_tcp_calib),
        native("MToolRotCalib", calib::m_tool_rot_calib),
        native("SToolTCPCalib", calib::s_tool_tcp_calib),
        native("SToolRotCalib", calib::s_tool_rot_calib),
        native("CalcRotAxisFrame", calib::calc_rot_axis_frame),
        native("CalcRotAxFrameZ", calib::calc_rot_ax_frame_z),
        native("CorrCon", corr::corr_con),
        native("CorrWrite", corr::corr_write),
        native("CorrDiscon", corr::corr_discon),
        native("CorrClear", corr::corr_clear),
        native("CorrRead", corr::corr_read),
    ],
};

/// Where the motion family's system data and types are in the loaded program (set
/// once at load; kept at PP to Main).
#[derive(Debug, Clone, Copy, Default)]
pub struct MotionLinks {
    /// The global holding C_MOTSET.
    pub motset: Option<u32>,
    /// The global holding C_PROGDISP.
    pub progdisp: Option<u32>,
    /// The record type `pose` (results of DefFrame and its kin).
    pub pose: Option<TypeId>,
    /// The globals of tool0, wobj0 and load0: the system data active at PP to Main
    /// (see `motion::sysdata`).
    pub sysdata: [Option<u32>; 3],
}

/// How the robot passes singular points (SingArea).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SingMode {
    #[default]
    Off,
    Wrist,
    LockAxis4,
}

/// How the tool is reoriented on circular paths (CirPathMode); the number is the
/// value C_MOTSET.cirpathreori shows.
// uncertain: the numbering 0..5 in switch order is assumed, not published.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum CirPathMode {
    #[default]
    PathFrame = 0,
    ObjectFrame = 1,
    CirPointOri = 2,
    Wrist45 = 3,
    Wrist46 = 4,
    Wrist56 = 5,
}

/// loaddata: mass kg, centre of gravity mm, axes of moment, inertia kgm².
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Load {
    pub mass: f64,
    pub cog: [f64; 3],
    pub aom: [f64; 4],
    pub inertia: [f64; 3],
}

/// `load0`: the payload the controller assumes when none is declared.
pub const LOAD0: Load = Load { mass: 0.001, cog: [0.0, 0.0, 0.001], aom: [1.0, 0.0, 0.0, 0.0], inertia: [0.0; 3] };

/// The motion settings of the task (the values SYS_RESET sets are the defaults).
#[derive(Debug, Clone, PartialEq)]
pub struct Settings {
    /// VelSet: speed override in percent and TCP speed limit in mm/s.
    pub vel_override: f64,
    pub vel_max: f64,
    /// AccSet: acceleration, ramp and fine-point ramp in percent of normal.
    pub acc: f64,
    pub ramp: f64,
    pub fine_point_ramp: f64,
    pub sing: SingMode,
    /// ConfJ and ConfL: configuration supervision on.
    pub conf_j: bool,
    pub conf_l: bool,
    /// PathResol: path sample time in percent of the configured one.
    pub path_resol: f64,
    pub cir_path_mode: CirPathMode,
    /// GripLoad: the payload in the gripper.
    pub grip_load: Load,
    /// CornerPathWarning: corner path failures are reported.
    pub corner_path_warning: bool,
    /// SpeedRefresh: the task's speed override in percent.
    pub speed_refresh: f64,
    /// PDispSet/PDispOff: the program displacement frame.
    pub pdisp: Isometry3<f64>,
    /// EOffsSet/EOffsOff: the external axis offsets.
    pub eoffs: [f64; 6],
    /// PathAccLim: the TCP's acceleration and deceleration limits along the path, m/s².
    pub acc_max: Option<f64>,
    pub decel_max: Option<f64>,
    /// WorldAccLim `\On`: the tool's acceleration limit in the world frame, m/s².
    pub world_acc_max: Option<f64>,
}

impl Default for Settings {
    fn default() -> Settings {
        Settings {
            // uncertain: RW6 documents vmax.v_tcp (MaxRobSpeed) as the default Max;
            // 5000 as the catalogue's vmax until robot models land.
            vel_override: 100.0,
            vel_max: 5000.0,
            acc: 100.0,
            ramp: 100.0,
            fine_point_ramp: 100.0,
            sing: SingMode::Off,
            conf_j: true,
            conf_l: true,
            path_resol: 100.0,
            cir_path_mode: CirPathMode::PathFrame,
            grip_load: LOAD0,
            corner_path_warning: true,
            // uncertain: that SYS_RESET also sets the SpeedRefresh override back to 100.
            speed_refresh: 100.0,
            pdisp: Isometry3::identity(),
            eoffs: [0.0; 6],
            acc_max: None,
            decel_max: None,
            world_acc_max: None,
        }
    }
}

/// The robot's state in a task's extension slot (`Resources::extensions`), put in by
/// [`EXTENSION`] when the task is made.
#[derive(Default)]
pub struct RobotSide {
    /// The task's robot: its model, its planned motion, where it is.
    pub robot: robot::RobotState,
    /// The motion settings (reset to their defaults at PP to Main).
    pub motion: MotionState,
}

impl rapid_vm::ext::TaskState for RobotSide {
    fn close_all(&mut self) {
        self.motion.reset();
    }
}

/// A task's robot and motion settings, found in its resources (the robot's state in
/// the extension slot).
pub trait RobotResources {
    /// The task's robot. Every task made with the robot's extension has one (the
    /// extension puts it in as the task is made); a task without it has no robot
    /// built-ins to call, and no front end asks it about a robot.
    fn robot(&self) -> &robot::RobotState;
    /// The task's robot, to change (put in at its default if the task had none).
    fn robot_mut(&mut self) -> &mut robot::RobotState;
    /// The task's motion settings.
    fn motion(&self) -> &MotionState;
    /// The task's motion settings, to change.
    fn motion_mut(&mut self) -> &mut MotionState;
}

impl RobotResources for rapid_vm::ext::Resources {
    fn robot(&self) -> &robot::RobotState {
        &side(self).robot
    }

    fn robot_mut(&mut self) -> &mut robot::RobotState {
        &mut side_in(&mut self.extensions).robot
    }

    fn motion(&self) -> &MotionState {
        &side(self).motion
    }

    fn motion_mut(&mut self) -> &mut MotionState {
        &mut side_in(&mut self.extensions).motion
    }
}

fn side(resources: &rapid_vm::ext::Resources) -> &RobotSide {
    // Invariant, not input: see `RobotResources::robot`.
    resources.extensions.get::<RobotSide>().expect("a task asked about its robot has the robot extension")
}

/// The robot in `extensions` (a task's `Resources::extensions`), to change beside
/// the task's other resources (its I/O system).
pub fn robot_in(extensions: &mut rapid_vm::ext::Extensions) -> &mut robot::RobotState {
    &mut side_in(extensions).robot
}

fn side_in(extensions: &mut rapid_vm::ext::Extensions) -> &mut RobotSide {
    extensions.get_or_default::<RobotSide>()
}

/// The motion family's part of the task's resources.
#[derive(Debug, Clone, Default)]
pub struct MotionState {
    pub links: MotionLinks,
    pub settings: Settings,
    /// The active tool, work object and payload (GetSysData, SetSysData, GripLoad),
    /// by `motion::sysdata` kind; `None` is the default tool0, wobj0, load0.
    pub active: [Option<sysdata::Active>; 3],
    /// Servo tuning, soft servo, supervision, speed limits, test signals.
    pub servo: servo::ServoState,
}

impl MotionState {
    /// PP to Main, a new program, a restart: every setting back to its default
    /// (manual 1.7, SYS_RESET).
    pub fn reset(&mut self) {
        self.settings = Settings::default();
        self.active = Default::default();
        // uncertain: that every servo and supervision setting (test signals included)
        // goes back to its default at PP to Main, as TuneServo's and SoftAct's do.
        self.servo = servo::ServoState::default();
    }
}

/// Writes the readable settings into C_MOTSET and C_PROGDISP.
fn mirror(ctx: &mut Ctx<'_>) {
    let state = ctx.resources.motion_mut();
    let s = &state.settings;
    if let Some(global) = state.links.motset {
        let leaves = [
            (&[0, 0][..], num(s.vel_override)),
            (&[0, 1], num(s.vel_max)),
            (&[1, 0], num(s.acc)),
            (&[1, 1], num(s.ramp)),
            (&[1, 2], num(s.fine_point_ramp)),
            (&[2, 0], Value::Bool(s.sing == SingMode::Wrist)),
            (&[2, 1], Value::Bool(s.sing == SingMode::LockAxis4)),
            (&[3, 0], Value::Bool(s.conf_j)),
            (&[3, 1], Value::Bool(s.conf_l)),
            (&[4], num(s.path_resol)),
            (&[7], Value::Bool(s.acc_max.is_some())),
            (&[8], num(s.acc_max.unwrap_or(-1.0))),
            (&[9], Value::Bool(s.decel_max.is_some())),
            (&[10], num(s.decel_max.unwrap_or(-1.0))),
            (&[11], num(s.cir_path_mode as i32 as f64)),
            (&[12], Value::Bool(s.world_acc_max.is_some())),
            (&[13], num(s.world_acc_max.unwrap_or(-1.0))),
        ];
        write_leaves(ctx.storage.globals.get_mut(global), &leaves);
    }
    if let Some(global) = state.links.progdisp {
        let t = s.pdisp.translation.vector;
        let q = s.pdisp.rotation.into_inner();
        let e = s.eoffs;
        let leaves = [
            (&[0, 0, 0][..], num(t.x)),
            (&[0, 0, 1], num(t.y)),
            (&[0, 0, 2], num(t.z)),
            (&[0, 1, 0], num(q.w)),
            (&[0, 1, 1], num(q.i)),
            (&[0, 1, 2], num(q.j)),
            (&[0, 1, 3], num(q.k)),
            (&[1, 0], num(e[0])),
            (&[1, 1], num(e[1])),
            (&[1, 2], num(e[2])),
            (&[1, 3], num(e[3])),
            (&[1, 4], num(e[4])),
            (&[1, 5], num(e[5])),
        ];
        write_leaves(ctx.storage.globals.get_mut(global), &leaves);
    }
}

fn num(x: f64) -> Value {
    Value::Num(x as f32)
}

fn write_leaves(target: Option<&mut Value>, leaves: &[(&[usize], Value)]) {
    let Some(target) = target else { return };
    for (path, value) in leaves {
        set_leaf(target, path, value.clone());
    }
}

/// Replaces the component at `path` (field indices) of a record value; a path that
/// does not fit the value changes nothing.
fn set_leaf(target: &mut Value, path: &[usize], value: Value) {
    let Some((&first, rest)) = path.split_first() else {
        *target = value;
        return;
    };
    let Value::Record(record) = target else { return };
    let Some(field) = Rc::make_mut(record).fields.get_mut(first) else { return };
    set_leaf(field, rest, value);
}
