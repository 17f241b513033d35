//! The scheduler (§1.20 优先级): round-robin one basic step (a statement) each among the
//! busy tasks whose foreground tasks are idle; the controller clock moves on while every
//! runnable task waits, and by a nominal statement time while tasks compute, so a task
//! that polls in a loop does not stop the clock for the others.

use rapid_signals::{SharedIoAccess, SignalsVm};
use rapid_tasks::{SharedTasking, SharedTaskingAccess, TaskInfo};
use rapid_vm::builtins::tasks::SharedTasks;
use rapid_vm::builtins::Shared;
use rapid_vm::{Exit, Host, Loaded};

use crate::pers::{PersStore, TaskPers};
use crate::task::{TaskEnd, TaskKind, TaskSpec, TrustLevel};
use crate::types::{type_map, TypeMap};

/// Controller time one basic step (a statement) takes while tasks compute.
// uncertain: RobotWare does not publish instruction times; a microsecond is the order
// of a simple RAPID statement on an IRC5. It only matters for tasks that loop
// without waiting.
pub const INSTRUCTION_TIME: f64 = 1e-6;

/// Instructions the remaining (static) tasks may run after the last NORMAL task ended.
const MAX_DRAIN_STEPS: u64 = 100_000;

/// Entries the controller-wide event log keeps for IError across tasks.
const MAX_SHARED_EVENTS: usize = 100_000;

/// Why [`Controller::run`] returned.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SystemExit {
    /// The instruction budget is spent; call `run` again.
    Budget,
    /// Every runnable task waits: move the clock on by this much ([`Controller::advance`]).
    Wait(f64),
    /// The run is over: every NORMAL task has ended (or, in a system of static tasks
    /// only, every task), or the system stopped them (trust level).
    Ended,
    /// The program is stopped (a controller operation) and nothing scheduled can
    /// start it again: [`Controller::start`] would.
    Stopped,
}

/// Where a task stands.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum State {
    Ready,
    /// Waiting until the clock reaches `until`; a wait that `rechecks` may be woken
    /// early when the shared state changes past `epoch`.
    Waiting {
        until: f64,
        rechecks: bool,
        epoch: u64,
    },
    Ended(TaskEnd),
}

/// One task under the controller.
pub struct Task {
    pub spec: TaskSpec,
    pub loaded: Loaded,
    pub(crate) state: State,
    pers: TaskPers,
    /// Index of the task this one stands behind.
    foreground: Option<usize>,
    /// The sequence number of the first entry of its event log not yet in the
    /// controller-wide log.
    events_copied: u64,
}

impl Task {
    /// How the task ended, if it has.
    pub fn end(&self) -> Option<&TaskEnd> {
        match &self.state {
            State::Ended(end) => Some(end),
            _ => None,
        }
    }
}

/// The system failure a static task's stop caused, by its trust level.
#[derive(Debug, Clone, PartialEq)]
pub struct SystemStop {
    pub task: String,
    pub trust: TrustLevel,
}

/// The tasks of one controller and what they share.
pub struct Controller {
    pub tasks: Vec<Task>,
    pub(crate) shared: Shared,
    pub(crate) pers: PersStore,
    /// `maps[a][b]`: renumbering of task a's record types into task b's.
    maps: Vec<Vec<TypeMap>>,
    /// The controller clock, seconds.
    pub time: f64,
    /// Basic steps (statements) executed, all tasks together; a task run alone counts
    /// its VM's instructions ([`Controller::runs_alone`]).
    pub steps: u64,
    /// Set when a static task's stop stopped the NORMAL tasks.
    pub system_stop: Option<SystemStop>,
    /// Each task's STOP event routines, run when it stops (by index).
    pub stop_routines: Vec<Vec<String>>,
    /// The STOP event routine in which a task failed (its index, the routine), when one
    /// did: its error is the task's [`TaskEnd::Failed`].
    pub failed_stop_routine: Option<(usize, String)>,
    /// A task run alone (`alone.rs`): the instructions executed when the clock was last
    /// charged for computing.
    pub(crate) charged: Option<u64>,
    /// The run's bound on steps, if it has one ([`Controller::set_step_bound`]).
    pub(crate) step_bound: Option<u64>,
    /// Instructions run since the last NORMAL task ended.
    drained: u64,
    /// The controller lives on after the program's cycle (a served controller): the
    /// end of every NORMAL task stops the program, STATIC and SEMISTATIC tasks run on
    /// ([`Controller::set_lives_on`]). Without it (`rapid run`) the run ends there.
    lives_on: bool,
    /// Run mode: the cycles each NORMAL task runs (1: cycle mode; 0: continuous
    /// until stopped), and how many each has ended.
    cycles: u64,
    cycles_ended: Vec<u64>,
    /// Program stop and start, system inputs and outputs (`ops.rs`).
    pub(crate) ops: crate::ops::Operations,
    /// Breakpoints and step targets of the front-end API (`api/debug.rs`); idle
    /// unless a front end sets one.
    pub(crate) watch: crate::api::debug::Watch,
}

impl Controller {
    /// A controller for `tasks` (in configuration order) sharing `io`. Fails when the
    /// tasks disagree on a global persistent's type or size, or a task names a
    /// foreground task the system does not have.
    pub fn new(tasks: Vec<(TaskSpec, Loaded)>, io: Option<rapid_io::IoSystem>) -> Result<Controller, String> {
        let infos: Vec<TaskInfo> = tasks
            .iter()
            .map(|(spec, _)| TaskInfo {
                name: spec.name.clone(),
                motion: spec.motion,
                robot: spec.motion && spec.robot,
                normal: spec.kind == TaskKind::Normal,
                active: true,
                executing: true,
                rmq: spec.rmq_config(),
                robot_of: spec.robot_of.clone(),
            })
            .collect();
        let names = infos.iter().map(|t| t.name.clone()).collect();
        let mut shared = Shared { tasks: SharedTasks::new(names), ..Shared::default() };
        shared.lent.insert(SharedTasking::new(infos));
        shared.io_mut().system = io;
        let maps = tasks
            .iter()
            .map(|(_, from)| tasks.iter().map(|(_, to)| type_map(&from.types_by_name, &to.types_by_name)).collect())
            .collect();
        let mut pers = PersStore::default();
        let mut built = Vec::with_capacity(tasks.len());
        for (idx, (spec, mut loaded)) in tasks.into_iter().enumerate() {
            let view = pers.register(idx, &spec.name, &loaded, &spec.shared_files)?;
            loaded.vm.resources_mut().tasks.me = spec.name.clone();
            // The host's disk, network and clocks, unless the embedder gave its own.
            crate::host_std::install(&mut loaded.vm);
            // A socket wait must not block the process: the other tasks run meanwhile.
            crate::bindings::sockets::of_mut(loaded.vm.resources_mut()).set_cooperative(true);
            loaded.vm.exchange_shared(&mut shared);
            loaded.vm.connect_configured_signals();
            loaded.vm.exchange_shared(&mut shared);
            built.push(Task { spec, loaded, state: State::Ready, pers: view, foreground: None, events_copied: 0 });
        }
        for idx in 0..built.len() {
            let Some(name) = built[idx].spec.foreground.clone() else { continue };
            let Some(fg) = built.iter().position(|t| t.spec.name.eq_ignore_ascii_case(&name)) else {
                return Err(format!(
                    "task {} runs behind task `{name}`, which the system does not have",
                    built[idx].spec.name
                ));
            };
            built[idx].foreground = Some(fg);
        }
        let stop_routines = vec![Vec::new(); built.len()];
        let cycles_ended = vec![0; built.len()];
        Ok(Controller {
            tasks: built,
            shared,
            pers,
            maps,
            time: 0.0,
            steps: 0,
            system_stop: None,
            stop_routines,
            failed_stop_routine: None,
            charged: None,
            step_bound: None,
            drained: 0,
            lives_on: false,
            cycles: 1,
            cycles_ended,
            ops: crate::ops::Operations::default(),
            watch: crate::api::debug::Watch::default(),
        })
    }

    /// Run mode: each NORMAL task runs `cycles` cycles, the end of its entry routine
    /// or ExitCycle starting the next (continuous mode, data kept); 0 runs on until a
    /// task stops. 1, the default, is cycle mode.
    pub fn set_cycles(&mut self, cycles: u64) {
        self.cycles = cycles;
    }

    /// The I/O system the tasks share (its change log), if there is one.
    pub fn io_system(&self) -> Option<&rapid_io::IoSystem> {
        self.shared.io().system.as_ref()
    }

    /// The shared state, to configure before the run (the stimulus).
    pub fn shared_mut(&mut self) -> &mut Shared {
        &mut self.shared
    }

    /// Whether a task talks to the outside world (waits on a socket, or holds one
    /// open): the clock must then move in wall-clock time, so that the peer has the time
    /// the program gives it and sees the controller's time pass as its own does.
    pub fn talks_to_outside_world(&self) -> bool {
        self.tasks.iter().any(|t| {
            let Some(sockets) = crate::bindings::sockets::of(t.loaded.vm.resources()) else { return false };
            sockets.is_open() || (matches!(t.state, State::Waiting { .. }) && sockets.is_polling())
        })
    }

    /// Moves the clock on (after [`SystemExit::Wait`]).
    pub fn advance(&mut self, seconds: f64) {
        self.time += seconds;
    }

    /// Runs event routine `routine` (of system event `event`) in task `idx` to its end,
    /// with the shared state handed in; the task then starts its entry afresh. Ok(false)
    /// when the task has no such procedure.
    pub fn run_event_routine(
        &mut self,
        idx: usize,
        host: &mut dyn Host,
        routine: &str,
        event: u8,
    ) -> Result<bool, rapid_vm::Unhandled> {
        let entry = self.tasks[idx].loaded.entry;
        self.with_task(idx, host, |vm, host| vm.run_event_routine(host, routine, event, entry))
    }

    /// Runs `f` on task `idx`'s VM at the controller's time with the shared state and
    /// the persistents handed in, and takes them (and the clock) back after.
    pub(crate) fn with_task<R>(
        &mut self,
        idx: usize,
        host: &mut dyn Host,
        f: impl FnOnce(&mut rapid_vm::Vm, &mut dyn Host) -> R,
    ) -> R {
        let time = self.time;
        let task = &mut self.tasks[idx];
        self.pers.copy_in(idx, &mut task.pers, &mut task.loaded.vm, &self.maps);
        task.loaded.vm.time = time;
        task.loaded.vm.exchange_shared(&mut self.shared);
        let outcome = f(&mut task.loaded.vm, host);
        task.loaded.vm.exchange_shared(&mut self.shared);
        self.pers.copy_out(idx, &mut task.pers, &mut task.loaded.vm);
        self.publish_events(idx);
        self.time = self.time.max(self.tasks[idx].loaded.vm.time);
        outcome
    }

    /// Hands the state the tasks share (the I/O system, the stimulus, the task list) to
    /// task `idx`'s VM, or takes it back when called again: what runs on the task
    /// outside [`Controller::run`] (finishing its robot's last moves, which set
    /// outputs and bring the I/O system to the end of the motion) sees the system.
    pub fn exchange_shared_with(&mut self, idx: usize) {
        self.tasks[idx].loaded.vm.exchange_shared(&mut self.shared);
    }

    /// Answers the request a task made of the controller (another task's data or
    /// robot), if one waits; the asking task is woken to read the reply.
    pub(crate) fn serve_request(&mut self, host: &mut dyn Host) {
        use rapid_vm::builtins::tasks::{Reply, Request};
        let Some((who, request)) = self.shared.tasks.request.take() else { return };
        let reply = match request {
            Request::ReadData { task, name } => self.read_data(who, task, &name),
            Request::WriteData { task, name, value } => self.write_data(who, task, &name, &value),
            Request::Robot { task } => rapid_robot::robot_reply(self.tasks[task].loaded.vm.resources_mut(), self.time),
            Request::SaveModule { task, module, dest } => {
                match self.tasks[task].loaded.vm.save_module_for_another_task(&module, dest) {
                    Ok(()) => Reply::Done,
                    Err(error) => Reply::Failed(Box::new(error)),
                }
            }
            Request::AllMotionTasks { name } => {
                self.motion_in_other_tasks(who, name, host);
                Reply::Done
            }
        };
        self.shared.tasks.reply = Some((who, reply));
        self.shared.tasks.epoch += 1;
    }

    /// StopMove/StartMove/StopMoveReset `\AllMotionTasks` of task `who`: the same for
    /// the robot of every other motion task, each with the shared state handed in.
    fn motion_in_other_tasks(&mut self, who: usize, name: &str, host: &mut dyn Host) {
        for idx in 0..self.tasks.len() {
            if idx == who || !self.tasks[idx].spec.motion {
                continue;
            }
            let time = self.time;
            let vm = &mut self.tasks[idx].loaded.vm;
            vm.time = time;
            vm.exchange_shared(&mut self.shared);
            vm.motion_for_another_task(name, host);
            vm.exchange_shared(&mut self.shared);
        }
    }

    /// GetDataVal from task `who` of task `task`'s module data `name`.
    fn read_data(&self, who: usize, task: usize, name: &str) -> rapid_vm::builtins::tasks::Reply {
        use rapid_vm::builtins::tasks::Reply;
        let vm = &self.tasks[task].loaded.vm;
        match vm.global_by_name(name).and_then(|(global, _)| vm.global(global)) {
            Some(value) => Reply::Value(crate::types::renumber(value, &self.maps[task][who])),
            None => Reply::Missing,
        }
    }

    /// SetDataVal from task `who` into task `task`'s module data `name`; a shared
    /// persistent goes to the store at once.
    fn write_data(
        &mut self,
        who: usize,
        task: usize,
        name: &str,
        value: &rapid_vm::value::Value,
    ) -> rapid_vm::builtins::tasks::Reply {
        use rapid_vm::builtins::tasks::Reply;
        let value = crate::types::renumber(value, &self.maps[who][task]);
        let target = &mut self.tasks[task];
        // Up to date first, so that marking the store seen below skips nothing.
        self.pers.copy_in(task, &mut target.pers, &mut target.loaded.vm, &self.maps);
        let Some((global, constant)) = target.loaded.vm.global_by_name(name) else { return Reply::Missing };
        if constant {
            return Reply::Constant;
        }
        if !target.loaded.vm.global(global).is_some_and(|old| rapid_vm::builtins::same_type(old, &value)) {
            return Reply::WrongType;
        }
        target.loaded.vm.set_global(global, value);
        self.pers.copy_out(task, &mut target.pers, &mut target.loaded.vm);
        Reply::Done
    }

    /// Copies what task `idx` logged into the controller-wide log, where the other
    /// tasks' IError interrupts see it (the controller has one event log).
    // uncertain: the controller's log is bounded; past MAX_SHARED_EVENTS entries the
    // other tasks see no more (each task's own log still keeps its newest entries).
    fn publish_events(&mut self, idx: usize) {
        let task = &mut self.tasks[idx];
        let entries = task.loaded.vm.event_log();
        let start = entries.partition_point(|e| e.seq < task.events_copied);
        let Some(last) = entries.last() else { return };
        if start == entries.len() {
            return;
        }
        task.events_copied = last.seq + 1;
        if self.shared.tasks.events.len() < MAX_SHARED_EVENTS {
            self.shared.tasks.log_events(idx, &entries[start..]);
        }
    }

    /// Runs at most `budget` basic steps (statements), all tasks together.
    /// A task run alone ([`Controller::runs_alone`]) counts instructions rather than
    /// statements, as its VM runs in slices.
    pub fn run(&mut self, host: &mut dyn Host, budget: u64) -> SystemExit {
        if self.runs_alone() {
            return self.run_alone(host, budget);
        }
        // Statements are charged one by one here; a task alone again starts afresh.
        self.charged = None;
        let mut remaining = budget;
        while remaining > 0 {
            self.operate(host);
            self.wake();
            let mut runnable = self.runnable();
            if self.lives_on && self.is_over() {
                // The cycle is over: the program stops, the static tasks run on.
                self.cycle_over();
                if runnable.is_empty() {
                    return self.idle();
                }
            } else if self.is_over() {
                // The other tasks finish the interrupts under way now (a trap for the
                // last error, say), without the clock moving on to their next wait:
                // each looks once, then only those with a trap to run go on.
                if self.drained > 0 {
                    runnable.retain(|&idx| self.tasks[idx].loaded.vm.has_interrupt_work());
                }
                if runnable.is_empty() || self.drained >= MAX_DRAIN_STEPS {
                    self.halt_the_rest();
                    return SystemExit::Ended;
                }
                self.drained += runnable.len() as u64;
            } else if runnable.is_empty() {
                return self.idle();
            }
            for idx in runnable {
                if remaining == 0 {
                    break;
                }
                // API hook: a breakpoint where the task stands stops the program first.
                if self.watch.is_active() && self.break_before(idx) {
                    return SystemExit::Budget;
                }
                remaining -= 1;
                self.step(idx, host);
                if matches!(self.tasks[idx].state, State::Ended(_)) {
                    self.after_end(idx);
                }
            }
        }
        SystemExit::Budget
    }

    /// Nothing can run now: wait for the next task to wake or (with system inputs) the
    /// next I/O event. A stopped program waits only for what may start it again (static
    /// tasks run meanwhile); when nothing can, `Stopped`.
    fn idle(&mut self) -> SystemExit {
        let operation = self.next_operation();
        // A system output shows when a robot stands still: the clock stops there.
        let motion_end = self.next_motion_end();
        let earliest = |times: &mut dyn Iterator<Item = f64>| times.min_by(f64::total_cmp);
        let next = if self.program_state() == crate::ops::ProgramState::Stopped {
            let Some(operation) = operation else { return SystemExit::Stopped };
            let statics = self.tasks.iter().filter(|t| t.spec.kind != TaskKind::Normal).filter_map(|t| match t.state {
                State::Waiting { until, .. } => Some(until),
                _ => None,
            });
            earliest(&mut statics.chain([Some(operation), motion_end].into_iter().flatten()))
        } else {
            earliest(&mut [self.next_wake(), operation, motion_end].into_iter().flatten())
        };
        match next {
            Some(until) => SystemExit::Wait((until - self.time).max(0.0)),
            None => {
                self.halt_the_rest();
                SystemExit::Ended
            }
        }
    }

    /// Runs one basic step (a statement, [`rapid_vm::Vm::run_statement`]) of task `idx`
    /// with the shared state handed in: a statement reading and writing a shared
    /// persistent is not cut by another task's.
    fn step(&mut self, idx: usize, host: &mut dyn Host) {
        let time = self.time;
        let task = &mut self.tasks[idx];
        self.pers.copy_in(idx, &mut task.pers, &mut task.loaded.vm, &self.maps);
        task.loaded.vm.time = time;
        task.loaded.vm.exchange_shared(&mut self.shared);
        let exit = task.loaded.vm.run_statement(host);
        task.loaded.vm.exchange_shared(&mut self.shared);
        self.pers.copy_out(idx, &mut task.pers, &mut task.loaded.vm);
        self.publish_events(idx);
        self.serve_request(host);
        self.steps += 1;
        // A built-in that waited on the outside world (a socket) moved the task's clock.
        self.time = self.time.max(self.tasks[idx].loaded.vm.time) + INSTRUCTION_TIME;
        let epoch = self.epoch();
        let rechecks = self.tasks[idx].loaded.vm.wait_rechecks;
        let stopped = exit == Exit::Stopped;
        let held = stopped && self.stop_instruction_holds(idx);
        let state = match exit {
            Exit::Stopped if held => State::Ready,
            Exit::Budget => State::Ready,
            Exit::Wait(seconds) => State::Waiting { until: time + seconds, rechecks, epoch },
            Exit::Done => self.cycle_end(idx, TaskEnd::Done),
            Exit::CycleEnded => self.cycle_end(idx, TaskEnd::CycleEnded),
            Exit::Stopped => State::Ended(TaskEnd::Stopped),
            Exit::Unhandled(unhandled) => State::Ended(TaskEnd::Failed(unhandled)),
        };
        self.tasks[idx].state = state;
        // WarmStart restarts the whole controller: every task stops with the one that
        // asked (the caller reports the restart and ends the run).
        if self.tasks[idx].loaded.vm.resources_mut().controller.warm_start {
            self.halt_the_rest();
            return;
        }
        if held {
            self.stopped_by_instruction(host);
        }
        if self.tasks[idx].state == State::Ended(TaskEnd::Stopped) {
            self.run_stop_routines(idx, host);
        }
        let controller = &mut self.tasks[idx].loaded.vm.resources_mut().controller;
        if std::mem::take(&mut controller.stop_all_moves) && stopped {
            self.stop_other_normal_tasks(idx, host);
        }
    }

    /// `Stop \AllMoveTasks` in task `idx`: every other running NORMAL task stops as a
    /// Stop instruction would stop it.
    // uncertain: with system inputs the controller may hold them for a restart; here
    // they end as a task does whose Stop does not hold.
    fn stop_other_normal_tasks(&mut self, idx: usize, host: &mut dyn Host) {
        for other in 0..self.tasks.len() {
            let task = &self.tasks[other];
            if other == idx || task.spec.kind != TaskKind::Normal || matches!(task.state, State::Ended(_)) {
                continue;
            }
            self.tasks[other].state = State::Ended(TaskEnd::Stopped);
            self.run_stop_routines(other, host);
        }
    }

    /// The STOP event routines of a task that stopped (EVENT_STOP, 3); an error in
    /// one is the task's failure.
    pub(crate) fn run_stop_routines(&mut self, idx: usize, host: &mut dyn Host) {
        for routine in self.stop_routines[idx].clone() {
            if let Err(unhandled) = self.run_event_routine(idx, host, &routine, 3) {
                self.tasks[idx].state = State::Ended(TaskEnd::Failed(unhandled));
                self.failed_stop_routine = Some((idx, routine));
                return;
            }
        }
    }

    /// The end of a task's cycle: a NORMAL task has run its cycles (one in cycle
    /// mode) or starts the next; a static task runs continuously, so it starts its
    /// entry routine again. EXIT ends a task for good (no restart is allowed).
    // uncertain: STATIC and SEMISTATIC tasks run in continuous mode on the controller,
    // so the end of main starts main again rather than stopping the task.
    pub(crate) fn cycle_end(&mut self, idx: usize, end: TaskEnd) -> State {
        let task = &mut self.tasks[idx];
        if task.loaded.vm.ended_by_exit() {
            return State::Ended(end);
        }
        if task.spec.kind == TaskKind::Normal {
            self.cycles_ended[idx] += 1;
            if self.cycles != 0 && self.cycles_ended[idx] >= self.cycles {
                return State::Ended(end);
            }
        }
        let entry = task.loaded.entry;
        if task.loaded.vm.start_routine(entry) {
            State::Ready
        } else {
            State::Ended(end)
        }
    }

    /// A task ended: the others see it no longer executing; a static task's stop
    /// applies its trust level.
    pub(crate) fn after_end(&mut self, idx: usize) {
        self.ops.outputs_stale = true;
        let name = self.tasks[idx].spec.name.clone();
        self.shared.tasking_mut().set_executing(&name, false);
        // A task that asked for a warm start did not fail: its trust level is not applied.
        let warm_start = self.tasks[idx].loaded.vm.resources_mut().controller.warm_start;
        let spec = &self.tasks[idx].spec;
        if spec.kind == TaskKind::Normal || spec.trust == TrustLevel::NoSafety || warm_start {
            return;
        }
        self.system_stop = Some(SystemStop { task: name, trust: spec.trust });
        for other in 0..self.tasks.len() {
            if self.tasks[other].spec.kind == TaskKind::Normal && !matches!(self.tasks[other].state, State::Ended(_)) {
                self.tasks[other].state = State::Ended(TaskEnd::Halted);
                let other_name = self.tasks[other].spec.name.clone();
                self.shared.tasking_mut().set_executing(&other_name, false);
            }
        }
    }

    /// Everything a waiting task may be waiting for: signal changes, sync points,
    /// semaphores and shared persistents.
    pub(crate) fn epoch(&self) -> u64 {
        let tasks = self.shared.tasks.epoch + self.shared.tasking().epoch;
        self.shared.io().change_count() as u64 + tasks + self.pers.generation
    }

    /// Waiting tasks whose time has come, or whose condition may now hold.
    fn wake(&mut self) {
        let (now, epoch) = (self.time, self.epoch());
        for task in &mut self.tasks {
            if let State::Waiting { until, rechecks, epoch: seen } = task.state {
                if until <= now || (rechecks && seen != epoch) {
                    task.state = State::Ready;
                }
            }
        }
    }

    /// Ready tasks none of whose foreground tasks is busy, in configuration order.
    fn runnable(&self) -> Vec<usize> {
        (0..self.tasks.len())
            .filter(|&idx| self.tasks[idx].state == State::Ready && self.foreground_idle(idx) && self.may_run(idx))
            .collect()
    }

    fn foreground_idle(&self, idx: usize) -> bool {
        let mut at = self.tasks[idx].foreground;
        // The chain is at most as long as the task list (a cycle ends the walk).
        for _ in 0..self.tasks.len() {
            let Some(fg) = at else { return true };
            if self.tasks[fg].state == State::Ready {
                return false;
            }
            at = self.tasks[fg].foreground;
        }
        true
    }

    /// The earliest time a waiting task wakes.
    fn next_wake(&self) -> Option<f64> {
        self.tasks
            .iter()
            .filter_map(|t| match t.state {
                State::Waiting { until, .. } => Some(until),
                _ => None,
            })
            .min_by(f64::total_cmp)
    }

    /// Whether the controller lives on after the program's cycle (a served
    /// controller): the end of every NORMAL task then stops the program as the end
    /// of a cycle does on the controller, and STATIC and SEMISTATIC tasks (a logger,
    /// an error reporter) run on, as they do on the controller, until it is shut down.
    pub fn set_lives_on(&mut self, lives_on: bool) {
        self.lives_on = lives_on;
    }

    /// Over when every NORMAL task has ended; a system of static tasks only runs
    /// until they all have.
    fn is_over(&self) -> bool {
        let normal: Vec<&Task> = self.tasks.iter().filter(|t| t.spec.kind == TaskKind::Normal).collect();
        let ended = |t: &&Task| matches!(t.state, State::Ended(_));
        if normal.is_empty() {
            self.tasks.iter().all(|t| ended(&t))
        } else {
            normal.iter().all(ended)
        }
    }

    /// The run is over: tasks still running (static ones) stop.
    fn halt_the_rest(&mut self) {
        for task in &mut self.tasks {
            if !matches!(task.state, State::Ended(_)) {
                task.state = State::Ended(TaskEnd::Halted);
            }
        }
    }
}
