//! Calls and returns, late binding, and error recovery: ERROR handlers found by table
//! lookup, RETRY, TRYNEXT, RAISE, propagation to callers, the system error handler
//! (§1.12), and UNDO handlers run on EXIT (§1.13; what UNDO context forbids is in
//! `undo.rs`).

use std::rc::Rc;

use super::{ActiveError, Exit, Frame, RaisedAt, Unhandled, Vm, MAX_CALL_DEPTH, MAX_RETRIES};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::events::EventKind;
use crate::ir::{ArgSpec, Callee, Code};
use crate::value::{Place, Root, Value};

impl Vm {
    pub(super) fn push_frame(&mut self, code: Rc<Code>, args: Vec<Value>) {
        let base = self.storage.stack.len() as u32;
        self.storage.stack.extend(args);
        self.storage.stack.extend(code.local_defaults.iter().cloned());
        self.frames.push(Frame::new(code, base));
    }

    /// `Call(site)`: collects the arguments the caller pushed and enters the callee.
    pub(super) fn call(
        &mut self,
        code: &Code,
        site: u32,
        host: &mut dyn crate::host::Host,
    ) -> Result<Option<Exit>, RapidError> {
        let site = &code.sites[site as usize];
        let at = self.storage.stack.len() - site.n_pushed as usize;
        // The common call passes every parameter: the caller pushed them in order,
        // so the callee's frame starts right there, nothing copied.
        if let Callee::Routine(idx) = site.callee {
            if site.n_pushed as usize == site.args.len() {
                let Some(callee) = self.routines.get(idx as usize).cloned().flatten() else {
                    // Its module was erased or unloaded (EraseModule, UnLoad) after this
                    // call was compiled: the controller's unresolved-reference error.
                    return Err(self.error(Err::RefUnknownProc, "the called routine's module is no longer loaded"));
                };
                return self.enter_in_place(callee, at);
            }
        }
        let mut args = std::mem::take(&mut self.arg_scratch);
        args.clear();
        let base = self.frame().base;
        // Conditional arguments read the caller's slots (below the pushed values)
        // first; then the pushed values move into place without a copy.
        for spec in &site.args {
            args.push(match spec {
                ArgSpec::Conditional { slot, by_ref } => self.forward(base + slot, *by_ref)?,
                ArgSpec::Switch => Value::SwitchOn,
                _ => Value::Absent,
            });
        }
        let mut pushed = self.storage.stack.drain(at..);
        for (spec, arg) in site.args.iter().zip(args.iter_mut()) {
            if matches!(spec, ArgSpec::Value | ArgSpec::Place) {
                *arg = pushed.next().unwrap_or(Value::Absent);
            }
        }
        drop(pushed);
        match site.callee {
            Callee::Builtin(id) => {
                let outcome = self.run_builtin(id, &args, host);
                self.remember_repeated(&outcome, id, &args);
                self.arg_scratch = args;
                self.after_builtin(outcome)
            }
            Callee::Routine(idx) => {
                let Some(callee) = self.routines.get(idx as usize).cloned().flatten() else {
                    // Its module was erased or unloaded (EraseModule, UnLoad) after this
                    // call was compiled: the controller's unresolved-reference error.
                    return Err(self.error(Err::RefUnknownProc, "the called routine's module is no longer loaded"));
                };
                self.enter(callee, args)
            }
            Callee::Late => Err(RapidError::fatal("late call through a plain call site")),
        }
    }

    /// The fast loop's call of a user routine when nothing about it needs the general
    /// path: every parameter pushed, IN nums already of their parameter's kind, no
    /// backward entry, depth below the limit. Enters the callee exactly as
    /// `enter_in_place` does and answers its frame base, and whether it runs `code`
    /// again (recursion: the loop keeps its code); `None` (nothing changed) otherwise.
    /// Skips the general call's `Result` plumbing: about a sixth of a call's cost
    /// (callgrind, bench/interp fib and varcall).
    #[inline]
    pub(super) fn enter_plain(&mut self, code: &Code, site: u32, pc: u32) -> Option<(usize, bool)> {
        let site = code.sites.get(site as usize)?;
        let Callee::Routine(idx) = site.callee else { return None };
        if site.n_pushed as usize != site.args.len()
            || self.frames.len() >= MAX_CALL_DEPTH
            || self.backward_entry.is_some()
        {
            return None;
        }
        let Some(Some(callee)) = self.routines.get(idx as usize) else { return None };
        let at = self.storage.stack.len().checked_sub(site.n_pushed as usize)?;
        let args = self.storage.stack.get(at..)?;
        let converted = |(like, arg): (&Option<Value>, &Value)| {
            like.as_ref().is_none_or(|like| std::mem::discriminant(like) == std::mem::discriminant(arg))
        };
        // One parameter is the common case, checked without setting up the zip.
        let converted = match (&callee.param_likes[..], args) {
            ([like], [arg]) => converted((like, arg)),
            (likes, args) => likes.iter().zip(args).all(converted),
        };
        if !converted {
            return None;
        }
        // Checked first: even an empty `extend` costs a call's worth of setup.
        if !callee.local_defaults.is_empty() {
            self.storage.stack.extend(callee.local_defaults.iter().cloned());
        }
        if let Some(caller) = self.frames.last_mut() {
            caller.pc = pc;
        }
        self.frames.enter(callee, at as u32);
        Some((at, std::ptr::eq(&**callee, code)))
    }

    /// The fast loop's return from a frame with a plain caller to go back to (not
    /// exiting, no BACKWARD handler or TRAP return point): exactly `return_from`, for
    /// `value` already popped. `Err(value)` hands the value back when the general path
    /// must do it.
    #[inline]
    pub(super) fn return_plain(&mut self, value: Option<Value>) -> Result<(), Option<Value>> {
        let n = self.frames.len();
        if n < 2 || self.exiting || self.frames[n - 1].return_to.is_some() {
            return Err(value);
        }
        let frame = &self.frames[n - 1];
        let base = frame.base as usize;
        let value = value.map(|value| match &frame.code.ret_like {
            Some(like) if std::mem::discriminant(like) != std::mem::discriminant(&value) => {
                super::coerce_like(like, value).unwrap_or(Value::Absent)
            }
            _ => value,
        });
        self.frames.leave();
        self.release_slots(base);
        if let Some(caller) = self.frames.last_mut() {
            caller.pc += 1;
        }
        if let Some(value) = value {
            self.storage.stack.push(value);
        }
        Ok(())
    }

    /// `return_plain` for a FUNC whose result, a num, is on top of the stack: the num
    /// is written as a fresh value where the frame began, never moved as a whole
    /// `Value` (each such move stalled on store forwarding, perf on bench/interp fib).
    /// `false` (nothing changed) when the general path must return.
    #[inline(always)]
    pub(super) fn return_num(&mut self, n: f32) -> bool {
        let depth = self.frames.len();
        if depth < 2 || self.exiting {
            return false;
        }
        let frame = &self.frames[depth - 1];
        if frame.return_to.is_some() || !matches!(frame.code.ret_like, None | Some(Value::Num(_))) {
            return false;
        }
        let base = frame.base as usize;
        self.frames.leave();
        if let Some(caller) = self.frames.last_mut() {
            caller.pc += 1;
        }
        // The result takes the frame's first slot in place when that slot holds a
        // plain value (a num parameter, typically): one slot fewer to release, and no
        // push (which LLVM left out of line here, about 20 instructions).
        match self.storage.stack.get(base) {
            Some(Value::Num(_) | Value::Dnum(_) | Value::Bool(_) | Value::Absent | Value::SwitchOn) => {
                // Checked here: the call alone cost as much as a slot's release. One
                // plain slot above (the result of `RETURN a + b`) is simply dropped.
                let stack = &mut self.storage.stack;
                if stack.len() == base + 2 && matches!(stack.last(), Some(Value::Num(_) | Value::Bool(_))) {
                    std::mem::forget(stack.pop());
                } else if stack.len() > base + 1 {
                    self.release_slots(base + 1);
                }
                super::num::put_num(&mut self.storage.stack[base], n);
            }
            _ => {
                self.release_slots(base);
                super::num::push_num(&mut self.storage.stack, n);
            }
        }
        true
    }

    /// Finishes a built-in call: pushes its result, moves past the call, and turns
    /// the wait or stop it asked for into the run's exit.
    pub(super) fn after_builtin(
        &mut self,
        outcome: Result<(Option<Value>, Option<f64>, crate::builtins::StopKind), RapidError>,
    ) -> Result<Option<Exit>, RapidError> {
        let (result, wait, stop) = outcome?;
        if stop == crate::builtins::StopKind::Repeat {
            // The arguments are gone from the stack: the statement starts over.
            let frame = self.frame_mut();
            frame.pc = frame.code.stmt_at(frame.pc).map_or(frame.pc, |s| s.start);
            self.wait_rechecks = true;
            return Ok(Some(Exit::Wait(wait.unwrap_or(0.0))));
        }
        if let Some(value) = result {
            self.push(value);
        }
        self.frame_mut().pc += 1;
        match stop {
            crate::builtins::StopKind::Repeat => Ok(None),
            crate::builtins::StopKind::None => {
                self.wait_rechecks = false;
                Ok(wait.map(Exit::Wait))
            }
            crate::builtins::StopKind::Stop => {
                for hooks in self.builtins.hooks() {
                    hooks.program_stopped(&mut self.resources, &mut self.storage, self.time);
                }
                Ok(Some(Exit::Stopped))
            }
            crate::builtins::StopKind::Retry => self.retry(),
            crate::builtins::StopKind::ExitCycle => {
                self.cycle_exit = true;
                Ok(self.exit())
            }
        }
    }

    /// Enters `callee` whose arguments are the top values of the stack from `at`.
    fn enter_in_place(&mut self, callee: Rc<Code>, at: usize) -> Result<Option<Exit>, RapidError> {
        if self.frames.len() >= MAX_CALL_DEPTH {
            return Err(RapidError::fatal(format!(
                "more than {MAX_CALL_DEPTH} nested routine calls (runaway recursion?)"
            )));
        }
        for (offset, like) in callee.param_likes.iter().enumerate() {
            if let Some(like) = like {
                let slot = &mut self.storage.stack[at + offset];
                if std::mem::discriminant(slot) != std::mem::discriminant(like) {
                    let value = std::mem::replace(slot, Value::Absent);
                    let coerced = super::coerce_like(like, value).map_err(|f| self.fault(f))?;
                    self.storage.stack[at + offset] = coerced;
                }
            }
        }
        self.storage.stack.extend(callee.local_defaults.iter().cloned());
        let (pc, return_to) = self.entry_point(&callee);
        self.frames.push(Frame { pc, return_to, ..Frame::new(callee, at as u32) });
        Ok(None)
    }

    pub(super) fn enter(&mut self, callee: Rc<Code>, mut args: Vec<Value>) -> Result<Option<Exit>, RapidError> {
        if self.frames.len() >= MAX_CALL_DEPTH {
            return Err(RapidError::fatal(format!(
                "more than {MAX_CALL_DEPTH} nested routine calls (runaway recursion?)"
            )));
        }
        // IN arguments take the numeric kind of their parameter.
        for (arg, like) in args.iter_mut().zip(&callee.param_likes) {
            if let Some(like) = like {
                let value = std::mem::replace(arg, Value::Absent);
                *arg = super::coerce_like(like, value).map_err(|f| self.fault(f))?;
            }
        }
        let (pc, return_to) = self.entry_point(&callee);
        self.push_frame(callee, args);
        let frame = self.frame_mut();
        frame.pc = pc;
        frame.return_to = return_to;
        Ok(None)
    }

    /// Where a call enters its routine: the start, or its BACKWARD handler when the
    /// call is being executed backward.
    fn entry_point(&mut self, callee: &Code) -> (u32, Option<u32>) {
        match (self.backward_entry.take(), callee.backward_handler) {
            (Some(stmt), Some(pc)) => (pc, Some(stmt)),
            _ => (0, None),
        }
    }

    /// A conditional argument: the caller's optional parameter, when it was passed.
    pub(super) fn forward(&self, index: u32, by_ref: bool) -> Result<Value, RapidError> {
        let raw = &self.storage.stack[index as usize];
        Ok(match raw {
            Value::Absent => Value::Absent,
            Value::SwitchOn => Value::SwitchOn,
            Value::Ref(place) if by_ref => Value::Ref(place.clone()),
            Value::Ref(place) => self.storage.get(place).map_err(|f| self.fault(f))?.clone(),
            _ if by_ref => Value::Ref(Box::new(Place { root: Root::Stack(index), path: Vec::new() })),
            value => value.clone(),
        })
    }

    /// Leaves the top frame; the caller continues after its call.
    pub(super) fn return_from(&mut self, value: Option<Value>) -> Option<Exit> {
        let Some(frame) = self.frames.pop() else { return Some(Exit::Done) };
        self.release_slots(frame.base as usize);
        // The end of an UNDO handler goes on with the next one of the chain; a routine
        // the handler called returns to it as usual (§1.13: the rest of the handler runs).
        if self.exiting && frame.undoing {
            return self.continue_exit();
        }
        let Some(caller) = self.frames.last_mut() else { return Some(Exit::Done) };
        caller.pc = frame.return_to.unwrap_or(caller.pc + 1);
        if let Some(mut value) = value {
            if let Some(like) = &frame.code.ret_like {
                // A value of the result's kind already is what the conversion gives.
                if std::mem::discriminant(like) != std::mem::discriminant(&value) {
                    value = super::coerce_like(like, value).unwrap_or(Value::Absent);
                }
            }
            self.push(value);
        }
        None
    }

    /// `RAISE n`: user numbers 1..90 (and booked ones); anything else ERR_ILLRAISE.
    pub(super) fn user_error(&self, n: f64) -> RapidError {
        let n_int = n as i32;
        let booked = super::is_booked(n_int, self.next_booked);
        let predefined = self.errnos.values().any(|&v| v == n_int);
        if n.fract() == 0.0 && ((1..=rapid_limits::RAISE_ERRNO_MAX).contains(&n_int) || booked || predefined) {
            let name = self.errnos.iter().find(|(_, &v)| v == n_int).map_or("", |(k, _)| *k);
            return RapidError {
                errno: n_int,
                name,
                message: format!("error {n_int} raised by the program"),
                fatal: false,
                event: None,
            };
        }
        self.error(Err::IllegalRaise, format!("RAISE {n}: user error numbers are 1..90"))
    }

    /// Bare RAISE in an ERROR handler: the same error, raised at the call in the caller;
    /// this RAISE is where it was raised last. Only the system calls a trap, so out of a
    /// trap it goes to the system error handler (§1.12).
    pub(super) fn re_raise(&mut self) -> Result<Option<Exit>, RapidError> {
        let Some(active) = self.frame_mut().active.take() else {
            return Err(RapidError::fatal("RAISE without a number outside an ERROR handler"));
        };
        let frame = self.frames.pop().expect("a running frame");
        let raised_at = Self::raised_here(&frame);
        self.storage.stack.truncate(frame.base as usize);
        if self.frames.is_empty() || frame.interrupted {
            let exit = Self::unhandled(active.error, &raised_at);
            return Ok(Some(self.give_up(exit)));
        }
        Ok(self.raise_from(active.error, raised_at))
    }

    pub(super) fn retry(&mut self) -> Result<Option<Exit>, RapidError> {
        let frame = self.frame_mut();
        let Some(active) = frame.active.take() else { return Err(RapidError::fatal("RETRY outside an ERROR handler")) };
        if frame.last_retry_stmt == Some(active.stmt.start) {
            frame.retries += 1;
        } else {
            frame.retries = 1;
            frame.last_retry_stmt = Some(active.stmt.start);
        }
        if frame.retries > MAX_RETRIES {
            let mut error =
                self.error(Err::TooManyRetries, format!("more than {MAX_RETRIES} RETRY of one instruction"));
            error.fatal = true;
            return Err(error);
        }
        let frame = self.frame_mut();
        frame.pc = active.stmt.start;
        let keep = frame.base + frame.code.n_locals;
        self.storage.stack.truncate(keep as usize);
        Ok(None)
    }

    /// The end of a routine's code: a FUNC must have returned; the end of an ERROR
    /// handler hands the error to the system error handler (§1.12).
    pub(super) fn fell_off_end(&mut self) -> Result<Option<Exit>, RapidError> {
        let frame = self.frame();
        if let Some(active) = &frame.active {
            let mut error = active.error.clone();
            error.fatal = true;
            let raised_at = active.raised_at.clone();
            return Ok(self.raise_from(error, raised_at));
        }
        if frame.code.is_func {
            return Err(self.error(Err::FuncNoReturn, format!("FUNC {} ended without RETURN", frame.code.name)));
        }
        Ok(self.return_from(None))
    }

    /// Raises `error` at the top frame's current instruction: its ERROR handler takes
    /// it, or it propagates to the caller's call; at the top, the system error handler.
    pub(super) fn raise(&mut self, error: RapidError) -> Option<Exit> {
        let raised_at = Self::raised_here(self.frames.last()?);
        self.raise_from(error, raised_at)
    }

    /// `raise` of an error raised last at `raised_at`, which the system error handler
    /// reports if no handler handles it (propagation to callers does not move it).
    fn raise_from(&mut self, error: RapidError, raised_at: RaisedAt) -> Option<Exit> {
        loop {
            let frame = self.frames.last()?;
            let in_handler = frame.active.is_some() || frame.undoing;
            let handler = frame.code.error_handler.as_ref().filter(|h| self.handler_takes(h, &error));
            match handler {
                Some(handler) if !error.fatal && !in_handler && !self.exiting => {
                    let stmt = frame.code.stmt_at(frame.pc).unwrap_or(crate::ir::StmtRange {
                        start: frame.pc,
                        end: frame.pc + 1,
                        span: frame.code.span,
                        depth: 0,
                        calls: None,
                    });
                    let handler_pc = handler.pc;
                    if let Some(global) = self.errno_global {
                        if let Some(slot) = self.storage.globals.get_mut(global) {
                            *slot = Value::Num(error.errno as f32);
                        }
                    }
                    let place = Self::place_of(frame);
                    let warning = Some(self.log_program_event(EventKind::Warning, &error, place));
                    self.note_raised(&error);
                    let frame = self.frames.last_mut()?;
                    if frame.last_retry_stmt != Some(stmt.start) {
                        frame.retries = 0;
                    }
                    frame.active = Some(Box::new(ActiveError { error, stmt, warning, raised_at }));
                    frame.pc = handler_pc;
                    let keep = frame.base + frame.code.n_locals;
                    self.storage.stack.truncate(keep as usize);
                    return None;
                }
                _ if error.fatal || in_handler || self.frames.len() == 1 || frame.interrupted => {
                    if self.exiting && super::undo::in_undo_context(&self.frames) {
                        // §1.13: a run error in UNDO context skips the rest of the UNDO.
                        let place = crate::events::EventPlace {
                            routine: raised_at.code.name.clone(),
                            file: raised_at.code.file,
                            span: raised_at.span,
                        };
                        let cause = if error.name.is_empty() { "a run error" } else { error.name };
                        self.log_undo_aborted(cause, Some(place));
                    }
                    let exit = Self::unhandled(error, &raised_at);
                    return Some(self.give_up(exit));
                }
                _ => {
                    let frame = self.frames.pop()?;
                    self.storage.stack.truncate(frame.base as usize);
                }
            }
        }
    }

    fn handler_takes(&self, handler: &crate::ir::Handler, error: &RapidError) -> bool {
        handler.numbers.is_empty()
            || handler.numbers.iter().any(|&n| {
                let number = if n < 0 {
                    // A data object's number, read now (booked errnum variables).
                    self.storage.globals.get((-n - 1) as u32).and_then(Value::as_f64).map_or(i32::MIN, |v| v as i32)
                } else {
                    n
                };
                number == error.errno || self.errnos.get("LONG_JMP_ALL_ERR") == Some(&number)
            })
    }

    /// The statement at `frame`'s PC (the failing one, or a RAISE), or its routine.
    fn raised_here(frame: &Frame) -> RaisedAt {
        let span = frame.code.stmt_at(frame.pc).map_or(frame.code.span, |s| s.span);
        RaisedAt { code: frame.code.clone(), span }
    }

    /// The system error handler's report: the error where it was raised last (§1.12:
    /// the program pointer is put at the erroneous instruction).
    // uncertain: the manual does not say where the PP goes for an error an ERROR handler
    // passed on with RAISE; we take that RAISE, the instruction that raised it last
    // (the failing statement's warning is in the event log already).
    fn unhandled(error: RapidError, at: &RaisedAt) -> Exit {
        let code = &at.code;
        Exit::Unhandled(Unhandled { error, routine: code.name.clone(), file: code.file, span: at.span })
    }

    /// EXIT: runs the UNDO handlers of the call chain, innermost first, then ends.
    pub(super) fn exit(&mut self) -> Option<Exit> {
        self.exiting = true;
        self.continue_exit()
    }

    pub(super) fn continue_exit(&mut self) -> Option<Exit> {
        while let Some(frame) = self.frames.last_mut() {
            match frame.code.undo_handler {
                Some(pc) if !frame.undoing => {
                    frame.undoing = true;
                    frame.active = None;
                    frame.pc = pc;
                    let keep = frame.base + frame.code.n_locals;
                    self.storage.stack.truncate(keep as usize);
                    return None;
                }
                _ => {
                    let frame = self.frames.pop()?;
                    self.storage.stack.truncate(frame.base as usize);
                }
            }
        }
        Some(if self.cycle_exit { Exit::CycleEnded } else { Exit::Done })
    }

    /// A boxed place naming a whole variable, from the pool when one is free (the
    /// common VAR argument; `pooled_place` without copying an empty path).
    #[inline]
    pub(super) fn pooled_root(&mut self, root: Root) -> Box<Place> {
        match self.place_pool.pop() {
            Some(mut place) => {
                place.root = root;
                place.path.clear();
                place
            }
            None => Box::new(Place { root, path: Vec::new() }),
        }
    }

    /// A boxed place, from the pool when one is free.
    pub(super) fn pooled_place(&mut self, root: Root, path: &[crate::value::PathStep]) -> Box<Place> {
        match self.place_pool.pop() {
            Some(mut place) => {
                place.root = root;
                place.path.clear();
                place.path.extend_from_slice(path);
                place
            }
            None => Box::new(Place { root, path: path.to_vec() }),
        }
    }

    /// Empties a returning frame's slots (from `base` up): the boxes of references go
    /// back to the pool, plain values need no drop code. One pass, popping: a
    /// separate pass for the references and `truncate` cost about twice as much per
    /// call (callgrind, bench/interp fib and varcall).
    pub(super) fn release_slots(&mut self, base: usize) {
        const POOL_LIMIT: usize = 256;
        let stack = &mut self.storage.stack;
        while stack.len() > base {
            // Looked at in place first: a popped plain value is forgotten, never
            // handed to the general drop code.
            match stack.last() {
                Some(Value::Num(_) | Value::Dnum(_) | Value::Bool(_) | Value::Absent | Value::SwitchOn) => {
                    std::mem::forget(stack.pop());
                }
                Some(Value::Ref(_)) if self.place_pool.len() < POOL_LIMIT => {
                    if let Some(Value::Ref(place)) = stack.pop() {
                        self.place_pool.push(place);
                    }
                }
                _ => drop(stack.pop()),
            }
        }
    }
}
