//! The controller's panel and motion system for front ends (an RWS server's
//! `/rw/panel` and `/rw/motionsystem`): motors on/off, the run mode's cycles, the
//! operator's speed override, and each robot's axes and flange as the controller
//! reports them at its current time.

use super::{ApiError, Session};
use crate::ProgramState;
use rapid_robot::RobotResources;

/// A robot (mechanical unit) as the motion system reports it now.
#[derive(Debug, Clone, PartialEq)]
pub struct MechUnitView {
    /// The task that moves it.
    pub task: String,
    /// Axes 1..6, degrees.
    pub joints: [f64; 6],
    /// External axes a..f (9E9 where the unit has none).
    pub extax: [f64; 6],
    /// The flange (tool0) in the robot's base frame: x, y, z in mm.
    pub trans: [f64; 3],
    /// The flange's orientation, q1..q4 (scalar first).
    pub orient: [f64; 4],
    /// cf1, cf4, cf6, cfx.
    pub conf: [i32; 4],
    /// The robot's base frame in the world now (on a track, where the track has it).
    pub base_trans: [f64; 3],
    pub base_orient: [f64; 4],
}

impl Session {
    /// Whether the motors are on (they are from power on in automatic mode).
    pub fn motors_on(&self) -> bool {
        self.controller.motors_on()
    }

    /// Motors on or off; motors off stops a running program at once (a quick stop).
    pub fn set_motors(&mut self, on: bool) {
        self.controller.set_motors(on);
        if !on && matches!(self.controller.program_state(), ProgramState::Stopping { .. }) {
            self.settle();
        }
        self.gather();
    }

    /// The operator's speed override in percent (the FlexPendant's, RWS's speed
    /// ratio): 100 unless set.
    pub fn speed_override(&self) -> f64 {
        self.controller.tasks.first().map_or(100.0, |t| t.loaded.vm.resources().controller.speed_override)
    }

    /// Sets the operator's speed override, 1 to 100 percent, for every task: the
    /// programmed speeds of the moves planned from now on are scaled by it, as the
    /// planner scales them by VelSet's override and SpeedRefresh (CSpeedOverride
    /// reads it), and a robot under way slows down or speeds up at once along its
    /// path (`rapid_motion::plan::retime`), the program's wait for it moving with it.
    /// A robot held (a program stop, StopMove), searching, on a stored path, under
    /// path correction or following a conveyor keeps the speeds it was planned with.
    pub fn set_speed_override(&mut self, percent: f64) -> Result<(), ApiError> {
        if !(1.0..=100.0).contains(&percent) {
            // A real controller takes 0 %: the robot then stands still within its
            // move, which the planner cannot hold (a zero speed is an error to it).
            return Err(ApiError::Unsupported(format!("a speed override of {percent} % (1 to 100 are)")));
        }
        let now = self.controller.time;
        for idx in 0..self.controller.tasks.len() {
            let resources = self.controller.tasks[idx].loaded.vm.resources_mut();
            let ratio = percent / resources.controller.speed_override;
            resources.controller.speed_override = percent;
            if let Some(map) = resources.robot_mut().retime(now, ratio) {
                self.controller.follow_retimed_robot(idx, &map);
            }
        }
        Ok(())
    }

    /// The run mode from the next start on: each NORMAL task runs `cycles` cycles
    /// (1: cycle mode, "once"; 0: continuous until stopped, "forever").
    pub fn set_cycles(&mut self, cycles: u64) {
        self.controller.set_cycles(cycles);
    }

    /// The controller lives on after the program's cycle, as a served one does
    /// ([`crate::Controller::set_lives_on`]).
    pub fn set_lives_on(&mut self, lives_on: bool) {
        self.controller.set_lives_on(lives_on);
    }

    /// Whether every NORMAL task has ended (the cycle is over: a new start begins
    /// at Main).
    pub fn all_normal_ended(&self) -> bool {
        let mut normal = self.controller.tasks.iter().filter(|t| t.spec.kind == crate::TaskKind::Normal).peekable();
        normal.peek().is_some() && normal.all(|t| t.end().is_some())
    }

    /// The robots of the tasks that move one, in task order (ROB_1 first).
    pub fn mechunits(&mut self) -> Vec<MechUnitView> {
        let time = self.controller.time;
        let mut units = Vec::new();
        for task in &mut self.controller.tasks {
            if !task.spec.robot {
                continue;
            }
            let robot = task.loaded.vm.resources_mut().robot_mut();
            let joints = robot.joints_at(time);
            let extax = robot.extax_read(time);
            let (flange, conf) = robot.flange_of(&joints);
            let base = robot.track_base_at(time);
            units.push(MechUnitView {
                base_trans: rapid_motion::pose::trans(&base),
                base_orient: rapid_motion::pose::orient(&base),
                task: task.spec.name.clone(),
                joints,
                extax,
                trans: rapid_motion::pose::trans(&flange),
                orient: rapid_motion::pose::orient(&flange),
                conf,
            });
        }
        units
    }

    /// The folder the file devices live in (`HOME:` is `<root>/HOME`), as the first
    /// task was given it.
    pub fn file_root(&self) -> Option<std::path::PathBuf> {
        let task = self.controller.tasks.first()?;
        task.loaded.vm.resources().devices.root().map(std::path::Path::to_path_buf)
    }
}

impl crate::Controller {
    /// Task `idx`'s robot was re-timed (`map`: old times to new): a move instruction of
    /// the task waiting for its robot (to stand at a stop point) waits until the robot
    /// now gets there.
    fn follow_retimed_robot(&mut self, idx: usize, map: &rapid_motion::plan::Retiming) {
        if !self.waits_for_robot(idx) {
            return;
        }
        if let crate::schedule::State::Waiting { until, .. } = &mut self.tasks[idx].state {
            *until = map.map(*until);
        }
    }

    /// Whether task `idx` waits inside a motion instruction (its program counter moved
    /// on past it), not in a WaitTime or any other wait.
    fn waits_for_robot(&self, idx: usize) -> bool {
        let vm = &self.tasks[idx].loaded.vm;
        if !self.waits_in_instruction(idx) {
            return false;
        }
        let Some((code, pc)) = vm.top_position() else { return false };
        let Some(stmt) = pc.checked_sub(1).and_then(|pc| code.stmt_at(pc)) else { return false };
        let Some(text) = vm.program_source(code.file).and_then(|s| s.text.get(stmt.span.start as usize..)) else {
            return false;
        };
        let word: String = text.chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect();
        super::exec::is_motion_instruction(&word)
    }
}
