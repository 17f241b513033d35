//! Breakpoints and stepping for a debugger (§1.11 step mode, §1.21 backward).
//!
//! A breakpoint names a file and a line; it is resolved, in every NORMAL task that
//! runs that file, to the outermost statement starting on the line (the first one when
//! several do). Before the scheduler runs a statement of a NORMAL task, the controller
//! looks whether the task stands at a breakpoint's statement ([`Controller::break_before`],
//! the one hook in `schedule.rs`); if it does, the program stops there, as a stop
//! ordered from the pendant (every NORMAL task at its next instruction, the STOP event
//! routines, the robot on its path), before the statement runs. When execution goes
//! on, the statement the task stands on is passed once.
//!
//! Steps are the controller's FWD step (`ops/step.rs`: one statement of one task,
//! calls entered), with a target depth for step over (back at the depth it started
//! at, or shallower) and step out (shallower), or a motion instruction to run (the
//! move step: on until a statement has given the robot a move); a breakpoint met on
//! the way ends the step there. The check costs a flag test per statement when no breakpoint is set
//! and no step is under way; the interpreter's loop is not touched.
// uncertain: breakpoints in STATIC and SEMISTATIC tasks are not offered: a program
// stop does not stop those tasks, so a breakpoint could not hold them.
// uncertain: a module loaded at run time (Load) after the breakpoint was set is not
// searched for it; set the breakpoint again after the load.

use rapid_robot::RobotResources;
use rustc_hash::FxHashMap;

use crate::schedule::Controller;
use crate::task::TaskKind;
use crate::{ProgramState, StopKind};

/// How far a step goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StepKind {
    /// One statement, entering a routine it calls.
    Into,
    /// One statement of the routine the task stands in, calls run whole.
    Over,
    /// On until the routine the task stands in has returned.
    Out,
    /// On until a motion instruction has run, calls entered: the step ends at the
    /// statement after it (wherever that is), or where the task ends. The PC SDK's
    /// `ExecutionMode.StepMotion`, "execute to next motion instruction"; RWS's
    /// `execmode=stepmotion`. A motion instruction is one that gives the task's robot
    /// a move (§2: MoveL, SearchC, TriggJ, …): the step counts the moves the robot
    /// was given. A move to a stop point ends the step once the robot stands there;
    /// a fly-by move once the instruction is done (the robot is then held on its path,
    /// as after any step).
    Motion,
}

/// A place in a task's program: its file and line (1-based) and the routine.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Location {
    pub task: String,
    pub routine: String,
    /// The file's path as the task was loaded with it.
    pub file: String,
    pub line: u32,
    /// 1-based character column of the statement's start.
    pub column: u32,
}

/// A breakpoint the program stopped at.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BreakpointHit {
    /// The breakpoint as it was set: (file, line); for an error, where the task stands.
    pub file: String,
    pub line: u32,
    /// Where the task stands: the statement the breakpoint resolved to.
    pub at: Location,
    /// The program stopped at an error (an exception breakpoint), not at a line.
    pub error: Option<ErrorHit>,
}

/// The error an exception breakpoint stopped at.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ErrorHit {
    /// The predefined name (`ERR_DIVZERO`), or empty for a user error number.
    pub name: String,
    /// The ERRNO value.
    pub errno: i32,
    pub message: String,
    /// No ERROR handler takes it: going on, the task stops with it. Otherwise the task
    /// stands at the first statement of the ERROR handler that takes it.
    pub uncaught: bool,
}

/// One breakpoint as set by a front end.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Breakpoint {
    pub(crate) file: String,
    pub(crate) line: u32,
}

/// A step under way: its task, kind, the depth it started at and how many moves
/// the task's robot had been given then.
#[derive(Debug, Clone, Copy)]
struct StepTarget {
    task: usize,
    kind: StepKind,
    depth: usize,
    moves: u64,
}

/// What the controller watches for the API (breakpoints, step targets).
#[derive(Debug, Default)]
pub(crate) struct Watch {
    pub(crate) points: Vec<Breakpoint>,
    /// By task: the statements breakpoints resolved to, (file index, statement
    /// start offset) → breakpoint index.
    resolved: Vec<FxHashMap<(usize, u32), usize>>,
    /// By task: the position to pass once when execution goes on from it
    /// (depth, file, statement start offset).
    passed: Vec<Option<(usize, usize, u32)>>,
    step: Option<StepTarget>,
    /// A breakpoint ended the step under way.
    step_broken: bool,
    /// The breakpoint the program last stopped at, not yet taken by the API.
    pub(crate) hit: Option<BreakpointHit>,
    /// Exception breakpoints: (raised, uncaught).
    errors: (bool, bool),
}

impl Watch {
    /// Whether the scheduler must look before each statement.
    pub(crate) fn is_active(&self) -> bool {
        !self.points.is_empty() || self.step.is_some() || self.errors.0 || self.errors.1
    }

    /// The step under way ends at its task's next statement (a front end's stop).
    pub(crate) fn end_step(&mut self) {
        if self.step.is_some() {
            self.step_broken = true;
        }
    }
}

/// The 1-based line and character column of byte `offset` in `text`.
pub(crate) fn line_col(text: &str, offset: u32) -> (u32, u32) {
    let offset = (offset as usize).min(text.len());
    let before = text.get(..offset).unwrap_or("");
    let line = before.matches('\n').count() as u32 + 1;
    let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) as u32 + 1;
    (line, col)
}

/// Whether the path `given` names the file `path` (the same path, or its file name in
/// any letter case).
pub(crate) fn names_file(path: &str, given: &str) -> bool {
    if path == given {
        return true;
    }
    let base = |p: &str| p.rsplit(['/', '\\']).next().unwrap_or(p).to_ascii_lowercase();
    base(path) == base(given) && (!given.contains(['/', '\\']) || path.ends_with(given))
}

impl Controller {
    /// Task `idx`'s position as (depth, file, start offset) of the statement its
    /// innermost routine stands at the start of, if it stands at one.
    fn statement_position(&self, idx: usize) -> Option<(usize, usize, u32)> {
        let vm = &self.tasks[idx].loaded.vm;
        let (code, pc) = vm.top_position()?;
        let at = code.stmts.partition_point(|s| s.start < pc);
        let stmt = code.stmts.get(at).filter(|s| s.start == pc)?;
        Some((vm.depth(), code.file, stmt.span.start))
    }

    /// The scheduler's hook before task `idx` runs a statement: true when it stands
    /// at a breakpoint (the program is then stopping, or the step under way ends).
    pub(crate) fn break_before(&mut self, idx: usize) -> bool {
        if self.tasks[idx].spec.kind != TaskKind::Normal {
            return false;
        }
        if self.error_stop(idx) {
            return true;
        }
        if self.step_done_before(idx) {
            return true;
        }
        let Some(position) = self.statement_position(idx) else { return false };
        if let Some(passed) = self.watch.passed.get_mut(idx) {
            if *passed == Some(position) {
                return false;
            }
            *passed = None;
        }
        let (_, file, start) = position;
        let Some(&point) = self.watch.resolved.get(idx).and_then(|r| r.get(&(file, start))) else { return false };
        let Some(at) = self.location_of(idx) else { return false };
        let bp = &self.watch.points[point];
        self.watch.hit = Some(BreakpointHit { file: bp.file.clone(), line: bp.line, at, error: None });
        self.pass_current(idx);
        if self.watch.step.is_some() {
            self.watch.step_broken = true;
        } else {
            self.stop(StopKind::Stop);
        }
        true
    }

    /// Whether task `idx` stands at an error an exception breakpoint watches (the VM
    /// noted it while running its last statement): the program stops, as at a line.
    fn error_stop(&mut self, idx: usize) -> bool {
        let Some(stop) = self.tasks[idx].loaded.vm.take_error_stop() else { return false };
        let Some(at) = self.location_of(idx) else { return false };
        let error = ErrorHit {
            name: stop.error.name.to_owned(),
            errno: stop.error.errno,
            message: stop.error.message.clone(),
            uncaught: stop.uncaught,
        };
        self.watch.hit = Some(BreakpointHit { file: at.file.clone(), line: at.line, at, error: Some(error) });
        self.pass_current(idx);
        if self.watch.step.is_some() {
            self.watch.step_broken = true;
        } else {
            self.stop(StopKind::Stop);
        }
        true
    }

    /// Stops at errors in every NORMAL task (`raised`: before the ERROR handler that
    /// takes one runs; `uncaught`: before a task stops with one no handler takes).
    pub(crate) fn watch_errors(&mut self, raised: bool, uncaught: bool) {
        self.watch.errors = (raised, uncaught);
        for task in self.tasks.iter_mut().filter(|t| t.spec.kind == TaskKind::Normal) {
            task.loaded.vm.watch_errors(raised, uncaught);
        }
    }

    /// Execution goes on from where task `idx` stands: a breakpoint there is passed.
    pub(crate) fn pass_current(&mut self, idx: usize) {
        let position = self.statement_position(idx);
        if self.watch.passed.len() < self.tasks.len() {
            self.watch.passed.resize(self.tasks.len(), None);
        }
        self.watch.passed[idx] = position;
    }

    /// The location of task `idx`'s program pointer (its innermost routine's statement).
    /// A task waiting in an instruction that has moved its program counter on (a move
    /// to a fine point waits for the robot after it) still stands on that instruction,
    /// as the pendant shows it: its statement is then the one holding the instruction
    /// before the counter.
    pub(crate) fn location_of(&self, idx: usize) -> Option<Location> {
        let vm = &self.tasks[idx].loaded.vm;
        let frame = vm.call_stack().pop()?;
        let (code, pc) = vm.top_position()?;
        let waited = (self.waits_in_instruction(idx) && pc > 0).then(|| code.stmt_at(pc - 1)).flatten();
        let start = waited.map_or(frame.span.start, |s| s.span.start);
        Some(self.location(idx, &frame.routine, frame.file, start))
    }

    /// The location of offset `start` of file `file` in task `idx`.
    pub(crate) fn location(&self, idx: usize, routine: &str, file: usize, start: u32) -> Location {
        let task = &self.tasks[idx];
        let source = task.loaded.vm.program_source(file);
        let (line, column) = source.map_or((0, 0), |s| line_col(&s.text, start));
        Location {
            task: task.spec.name.clone(),
            routine: routine.to_owned(),
            file: source.map_or_else(String::new, |s| s.path.clone()),
            line,
            column,
        }
    }

    /// Adds a breakpoint at `line` of `file`: the statements it resolved to, one per
    /// NORMAL task that runs the file (empty when no task has a statement starting on
    /// that line).
    pub(crate) fn add_breakpoint(&mut self, file: &str, line: u32) -> Vec<Location> {
        let point = match self.watch.points.iter().position(|p| p.file == file && p.line == line) {
            Some(point) => point,
            None => {
                self.watch.points.push(Breakpoint { file: file.to_owned(), line });
                self.watch.points.len() - 1
            }
        };
        self.watch.resolved.resize_with(self.tasks.len(), FxHashMap::default);
        let mut found = Vec::new();
        for idx in 0..self.tasks.len() {
            if self.tasks[idx].spec.kind != TaskKind::Normal {
                continue;
            }
            if let Some((routine, file_idx, start)) = self.statement_on_line(idx, file, line) {
                self.watch.resolved[idx].insert((file_idx, start), point);
                found.push(self.location(idx, &routine, file_idx, start));
            }
        }
        if found.is_empty() {
            self.remove_breakpoint(file, line);
        }
        found
    }

    /// Removes the breakpoint at `line` of `file`; false when there was none.
    pub(crate) fn remove_breakpoint(&mut self, file: &str, line: u32) -> bool {
        let Some(point) = self.watch.points.iter().position(|p| p.file == file && p.line == line) else {
            return false;
        };
        self.watch.points.remove(point);
        for resolved in &mut self.watch.resolved {
            resolved.retain(|_, p| *p != point);
            for p in resolved.values_mut() {
                if *p > point {
                    *p -= 1;
                }
            }
        }
        true
    }

    /// The outermost (first) statement of task `idx` starting on `line` of `file`:
    /// its routine, file index and start offset.
    fn statement_on_line(&self, idx: usize, file: &str, line: u32) -> Option<(String, usize, u32)> {
        let vm = &self.tasks[idx].loaded.vm;
        let mut best: Option<(String, usize, u32)> = None;
        for code in vm.codes() {
            let Some(source) = vm.program_source(code.file) else { continue };
            if !names_file(&source.path, file) {
                continue;
            }
            for stmt in &code.stmts {
                if line_col(&source.text, stmt.span.start).0 != line {
                    continue;
                }
                if best.as_ref().is_none_or(|(_, _, start)| stmt.span.start < *start) {
                    best = Some((code.name.clone(), code.file, stmt.span.start));
                }
            }
        }
        best
    }

    /// Whether task `idx`, about to run a statement, has done the step under way: it
    /// ran an instruction and stands at its next one, at the step's depth. A statement
    /// that waited (a move to a fine point) ends its step when the wait ends, before
    /// the scheduler runs the next statement in the same round.
    fn step_done_before(&self, idx: usize) -> bool {
        let ProgramState::Stepping { task, from_steps } = self.program_state() else { return false };
        task == idx && self.statement_done(idx, from_steps) && self.target_met(idx)
    }

    /// Whether the step under way in task `idx` has reached its target: its depth,
    /// or (a move step) a move given to the robot. A task that has ended has no
    /// further to go.
    fn target_met(&self, idx: usize) -> bool {
        let Some(target) = self.watch.step.filter(|t| t.task == idx) else { return true };
        let vm = &self.tasks[idx].loaded.vm;
        let depth = vm.depth();
        self.watch.step_broken
            || matches!(self.tasks[idx].state, crate::schedule::State::Ended(_))
            || match target.kind {
                StepKind::Into => true,
                StepKind::Over => depth <= target.depth,
                StepKind::Out => depth < target.depth,
                StepKind::Motion => vm.resources().robot().moves > target.moves,
            }
    }

    /// A step of `kind` begins in task `idx` (the FWD step has started).
    pub(crate) fn watch_step(&mut self, idx: usize, kind: StepKind) {
        let vm = &self.tasks[idx].loaded.vm;
        let (depth, moves) = (vm.depth(), vm.resources().robot().moves);
        self.watch.step = Some(StepTarget { task: idx, kind, depth, moves });
        self.watch.step_broken = false;
    }

    /// The hook of `ops/step.rs`: whether the step under way in task `task`, which
    /// has run a statement, has reached its target (then it is forgotten).
    pub(crate) fn step_target_reached(&mut self, task: usize) -> bool {
        let reached = self.target_met(task);
        if reached {
            self.watch.step = None;
            self.watch.step_broken = false;
        }
        reached
    }
}

#[cfg(test)]
mod tests {
    use super::{line_col, names_file};

    #[test]
    fn offsets_become_lines_and_columns() {
        let text = "MODULE M\n  PROC main()\n    x := 1;\n";
        // "x" is the 5th character of line 3.
        let offset = text.find("x :=").map_or(0, |o| o as u32);
        assert_eq!(line_col(text, offset), (3, 5));
        assert_eq!(line_col(text, 0), (1, 1));
    }

    #[test]
    fn a_file_is_named_by_its_path_or_its_file_name() {
        assert!(names_file("sys/T_ROB1/MainModule.mod", "sys/T_ROB1/MainModule.mod"));
        assert!(names_file("sys/T_ROB1/MainModule.mod", "mainmodule.mod"));
        assert!(names_file("sys/T_ROB1/MainModule.mod", "T_ROB1/MainModule.mod"));
        assert!(!names_file("sys/T_ROB1/MainModule.mod", "T_ROB2/MainModule.mod"));
        assert!(!names_file("sys/T_ROB1/MainModule.mod", "Other.mod"));
    }
}
