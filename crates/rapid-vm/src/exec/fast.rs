//! The fast loop: the instructions of hot code that need nothing but nums, bools,
//! strings, jumps, one-dimensional num arrays and calls of built-ins with every
//! argument pushed run here without leaving the loop; anything else is handed back
//! to `Vm::step`.

use super::num::{
    drop_plain, element_1d, element_1d_mut, fast_num_op, push_bool, push_num, put_result, set_num, FastResult,
};
use super::{Exit, RapidError, Value, Vm};
use crate::ir::{ArgSpec, Callee, Instr, Operand};
use crate::value::{Root, MAX_STRING_CHARS};

/// The instructions the fast loop has no arm for: `Vm::step` runs them. Those whose
/// declaration says `fast: false` (`crate::instrs`), as the test below checks.
macro_rules! step_only {
    () => {
        Instr::StoreGlobal(..)
            | Instr::Aggregate(..)
            | Instr::PlaceField(..)
            | Instr::PlaceIndex(..)
            | Instr::LoadPlace
            | Instr::StorePlace
            | Instr::Index(..)
            | Instr::Unary(..)
            | Instr::MakeArray(..)
            | Instr::Pop
            | Instr::LateCall(..)
            | Instr::UnknownFunc(..)
            | Instr::Raise
            | Instr::ReRaise
            | Instr::Retry
            | Instr::TryNext
            | Instr::Exit
            | Instr::UndoReturn
            | Instr::ForInit { .. }
            | Instr::Present(..)
            | Instr::Placeholder
            | Instr::NameWithNumber
            | Instr::PushTime
            | Instr::WaitPop
            | Instr::RaiseWaitTimeout
            | Instr::Connect(..)
            | Instr::ReadSignal(..)
    };
}

/// Why the fast loop stopped.
pub(super) enum Fast {
    /// The budget ran out.
    Budget,
    /// The instruction at pc (already counted) needs `Vm::step`.
    Step,
    /// A built-in call ended in something other than a plain result (an error, a
    /// wait, a stop): the outcome `Vm::step` would have given.
    Called(Result<Option<Exit>, RapidError>),
}

impl Vm {
    /// Runs the top frame's instructions that need nothing but num arithmetic,
    /// jumps, loads/stores of nums, bools and strings and plain built-in calls,
    /// without leaving the loop.
    pub(super) fn run_fast(&mut self, remaining: &mut u64, host: &mut dyn crate::host::Host) -> Fast {
        let (mut code, mut base, mut pc) = {
            let frame = self.frame();
            (frame.code.clone(), frame.base as usize, frame.pc)
        };
        // The loop goes on in the frame now on top, at its pc. Its code is cloned only
        // when it is another routine's (not in recursion).
        macro_rules! resume_top_frame {
            () => {{
                let frame = self.frame();
                if !std::rc::Rc::ptr_eq(&code, &frame.code) {
                    code = frame.code.clone();
                }
                (base, pc) = (frame.base as usize, frame.pc);
                continue;
            }};
        }
        // After a call or a return the loop goes on in the frame now on top.
        macro_rules! continue_in_top_frame {
            ($outcome:expr) => {
                match $outcome {
                    Ok(None) if !self.frames.is_empty() && !self.exiting => resume_top_frame!(),
                    outcome => break Fast::Called(outcome),
                }
            };
        }
        let budget = *remaining;
        let mut left = budget;
        let outcome = loop {
            if left == 0 {
                break Fast::Budget;
            }
            left -= 1;
            let Some(&instr) = code.instrs.get(pc as usize) else { break Fast::Step };
            let stack = &mut self.storage.stack;
            match instr {
                Instr::Const(i) => match &code.consts[i as usize] {
                    Value::Num(n) => push_num(stack, *n),
                    Value::Bool(b) => push_bool(stack, *b),
                    Value::Str(s) => stack.push(Value::Str(s.clone())),
                    _ => break Fast::Step,
                },
                Instr::LoadLocal(slot) => match &stack[base + slot as usize] {
                    Value::Num(n) => push_num(stack, *n),
                    Value::Bool(b) => push_bool(stack, *b),
                    Value::Str(s) => stack.push(Value::Str(s.clone())),
                    // Records are shared until written: a load is a reference count.
                    Value::Record(r) => stack.push(Value::Record(r.clone())),
                    // A VAR parameter referring to a whole num in a caller's slot.
                    Value::Ref(place) if place.path.is_empty() => match place.root {
                        Root::Stack(at) => match stack[at as usize] {
                            Value::Num(n) => push_num(stack, n),
                            _ => break Fast::Step,
                        },
                        Root::Global(idx) => match self.storage.globals.get(idx) {
                            Some(&Value::Num(n)) => push_num(stack, n),
                            _ => break Fast::Step,
                        },
                    },
                    _ => break Fast::Step,
                },
                Instr::StoreLocal(slot) => {
                    let mut at = base + slot as usize;
                    if let Value::Ref(place) = &stack[at] {
                        match (place.path.is_empty(), place.root) {
                            (true, Root::Stack(target)) => at = target as usize,
                            // A VAR parameter referring to a whole module-level num.
                            (true, Root::Global(idx)) => {
                                let (Some(&Value::Num(n)), Some(Value::Num(x))) =
                                    (stack.last(), self.storage.globals.get_mut(idx))
                                else {
                                    break Fast::Step;
                                };
                                *x = n;
                                drop_plain(stack.pop());
                                pc += 1;
                                continue;
                            }
                            _ => break Fast::Step,
                        }
                    }
                    match (stack.last(), &stack[at]) {
                        (Some(&Value::Num(n)), Value::Num(_)) => {
                            drop_plain(stack.pop());
                            set_num(&mut stack[at], n);
                        }
                        (Some(&Value::Bool(b)), Value::Bool(_)) => {
                            drop_plain(stack.pop());
                            if let Value::Bool(x) = &mut stack[at] {
                                *x = b;
                            }
                        }
                        (Some(Value::Str(_)), Value::Str(_)) | (Some(Value::Record(_)), Value::Record(_)) => {
                            if let Some(value) = stack.pop() {
                                stack[at] = value;
                            }
                        }
                        _ => break Fast::Step,
                    }
                }
                Instr::Field(field) => {
                    let Some(Value::Record(record)) = stack.last() else { break Fast::Step };
                    let Some(value) = record.fields.get(field as usize).cloned() else { break Fast::Step };
                    if let Some(top) = stack.last_mut() {
                        *top = value;
                    }
                }
                Instr::LoadGlobal(idx) => match self.storage.globals.get(idx) {
                    Some(Value::Num(n)) => push_num(stack, *n),
                    Some(Value::Str(s)) => stack.push(Value::Str(s.clone())),
                    Some(Value::Record(r)) => stack.push(Value::Record(r.clone())),
                    _ => break Fast::Step,
                },
                // The commonest num forms (`n - 1`, `a + b` of two results) first, with
                // no dispatch on the operand kinds; anything else takes the arms below.
                Instr::BinOp { op, lhs: Operand::Local(slot), rhs: Operand::Const(k) }
                    if is_num(stack.get(base + slot as usize)) && is_num(code.consts.get(k as usize)) =>
                {
                    let (Some(&Value::Num(a)), Some(&Value::Num(b))) =
                        (stack.get(base + slot as usize), code.consts.get(k as usize))
                    else {
                        break Fast::Step;
                    };
                    let Some(res) = fast_num_op(op, a, b) else { break Fast::Step };
                    match res {
                        FastResult::Num(n) => push_num(stack, n),
                        FastResult::Bool(b) => push_bool(stack, b),
                    }
                }
                Instr::BinOp { op, lhs: Operand::Stack, rhs: Operand::Stack }
                    if matches!(&stack[stack.len().saturating_sub(2)..], [Value::Num(_), Value::Num(_)]) =>
                {
                    let len = stack.len();
                    let (Value::Num(a), Value::Num(b)) = (&stack[len - 2], &stack[len - 1]) else {
                        break Fast::Step;
                    };
                    let Some(res) = fast_num_op(op, *a, *b) else { break Fast::Step };
                    drop_plain(stack.pop());
                    put_result(stack.last_mut(), res);
                }
                Instr::Binary(rapid_syntax::ast::BinaryOp::Add)
                    if matches!(&stack[stack.len() - 2..], [Value::Str(_), Value::Str(_)]) =>
                {
                    let (Some(Value::Str(b)), Some(Value::Str(a))) = (stack.pop(), stack.last()) else {
                        break Fast::Step;
                    };
                    let Some(joined) = concat(a, &b) else {
                        stack.push(Value::Str(b));
                        break Fast::Step;
                    };
                    if let Some(slot) = stack.last_mut() {
                        *slot = joined;
                    }
                }
                Instr::Binary(op) => {
                    let len = stack.len();
                    if let (Value::Num(a), Value::Num(b)) = (&stack[len - 2], &stack[len - 1]) {
                        if let Some(res) = fast_num_op(op, *a, *b) {
                            drop_plain(stack.pop());
                            put_result(stack.last_mut(), res);
                            pc += 1;
                            continue;
                        }
                    }
                    // Every other operand type (pos, orient, dnum, ...) and every
                    // error, exactly as `Vm::step` does it.
                    let (Some(rhs), Some(lhs)) = (stack.pop(), stack.pop()) else { break Fast::Step };
                    match crate::ops::binary(op, lhs, rhs, self.types) {
                        Ok(value) => stack.push(value),
                        Err(fault) => {
                            self.frame_mut().pc = pc;
                            break Fast::Called(Err(self.fault(fault)));
                        }
                    }
                }
                Instr::MakeRecord(ty, n) => super::instr::make_record(stack, ty, n),
                Instr::BinOp { op: rapid_syntax::ast::BinaryOp::Add, lhs, rhs }
                    if is_str(lhs, stack, base, &code.consts, usize::from(rhs == crate::ir::Operand::Stack))
                        && is_str(rhs, stack, base, &code.consts, 0) =>
                {
                    let lhs_depth = usize::from(rhs == crate::ir::Operand::Stack);
                    // `a + b + "literal"` (Stack + Stack, then the constant pushed and
                    // added): joined at once when the budget allows all three
                    // instructions, so the intermediate string is never allocated.
                    if let (true, Some(joined)) = (left >= 2, concat_with_next(&code, pc, lhs, rhs, stack)) {
                        stack.pop();
                        if let Some(top) = stack.last_mut() {
                            *top = joined;
                        }
                        left -= 2;
                        pc += 3;
                        continue;
                    }
                    let joined = match (
                        str_at(lhs, stack, base, &code.consts, lhs_depth),
                        str_at(rhs, stack, base, &code.consts, 0),
                    ) {
                        (Some(a), Some(b)) => concat(a, b),
                        _ => None,
                    };
                    let Some(joined) = joined else { break Fast::Step };
                    match (lhs == crate::ir::Operand::Stack, rhs == crate::ir::Operand::Stack) {
                        (true, true) => {
                            stack.pop();
                            if let Some(top) = stack.last_mut() {
                                *top = joined;
                            }
                        }
                        (true, false) | (false, true) => {
                            if let Some(top) = stack.last_mut() {
                                *top = joined;
                            }
                        }
                        (false, false) => stack.push(joined),
                    }
                }
                Instr::BinOp { op, lhs, rhs } => {
                    let globals = self.storage.globals.values();
                    let num_at = |operand, stack: &Vec<Value>, depth| {
                        num_operand(operand, stack, base, globals, &code.consts, depth)
                    };
                    let rhs_on_stack = rhs == crate::ir::Operand::Stack;
                    let lhs_depth = usize::from(rhs_on_stack);
                    let (Some(a), Some(b)) = (num_at(lhs, stack, lhs_depth), num_at(rhs, stack, 0)) else {
                        // Other operand types (pos, orient, dnum, ...): `ops::binary` here,
                        // exactly as `Vm::step` does it, rather than a round trip through
                        // `step` (bench/interp pos). References and absent optional
                        // parameters still take `step`.
                        match self.binop_general(op, lhs, rhs, &code.consts, base) {
                            None => break Fast::Step,
                            Some(Ok(())) => {
                                pc += 1;
                                continue;
                            }
                            Some(Err(fault)) => {
                                self.frame_mut().pc = pc;
                                break Fast::Called(Err(self.fault(fault)));
                            }
                        }
                    };
                    let Some(res) = fast_num_op(op, a, b) else { break Fast::Step };
                    // The result takes the place of the deepest stack operand, written
                    // in place; with no stack operand it is pushed.
                    match (lhs == crate::ir::Operand::Stack, rhs_on_stack) {
                        (true, true) => {
                            drop_plain(stack.pop());
                            put_result(stack.last_mut(), res);
                        }
                        (true, false) | (false, true) => put_result(stack.last_mut(), res),
                        (false, false) => match res {
                            FastResult::Num(n) => push_num(stack, n),
                            FastResult::Bool(b) => push_bool(stack, b),
                        },
                    }
                }
                Instr::LoadElem { global: false, slot, n: 1 } => {
                    let len = stack.len();
                    let Some(&Value::Num(index)) = stack.last() else { break Fast::Step };
                    let Value::Array(array) = &stack[base + slot as usize] else { break Fast::Step };
                    let Some(&Value::Num(elem)) = element_1d(array, index) else { break Fast::Step };
                    set_num(&mut stack[len - 1], elem);
                }
                Instr::LoadElem { global: true, slot, n: 1 } => {
                    let len = stack.len();
                    let Some(&Value::Num(index)) = stack.last() else { break Fast::Step };
                    let Some(Value::Array(array)) = self.storage.globals.get(slot) else { break Fast::Step };
                    let Some(&Value::Num(elem)) = element_1d(array, index) else { break Fast::Step };
                    set_num(&mut stack[len - 1], elem);
                }
                Instr::StoreElem { global: false, slot, n: 1 } => {
                    let len = stack.len();
                    let (Value::Num(index), Value::Num(value)) = (&stack[len - 2], &stack[len - 1]) else {
                        break Fast::Step;
                    };
                    let (index, value) = (*index, *value);
                    let Value::Array(array) = &mut stack[base + slot as usize] else { break Fast::Step };
                    let Some(Value::Num(elem)) = element_1d_mut(array, index) else { break Fast::Step };
                    *elem = value;
                    drop_plain(stack.pop());
                    drop_plain(stack.pop());
                }
                Instr::StoreElem { global: true, slot, n: 1 } => {
                    let len = stack.len();
                    let (Value::Num(index), Value::Num(value)) = (&stack[len - 2], &stack[len - 1]) else {
                        break Fast::Step;
                    };
                    let (index, value) = (*index, *value);
                    let Some(Value::Array(array)) = self.storage.globals.get_mut(slot) else {
                        break Fast::Step;
                    };
                    let Some(Value::Num(elem)) = element_1d_mut(array, index) else { break Fast::Step };
                    *elem = value;
                    drop_plain(stack.pop());
                    drop_plain(stack.pop());
                }
                Instr::Jump(target) => {
                    pc = target;
                    continue;
                }
                Instr::FellOffEnd => {
                    self.frame_mut().pc = pc;
                    // A PROC's end outside an ERROR handler is a plain return.
                    if !code.is_func && self.frame().active.is_none() && self.return_plain(None).is_ok() {
                        resume_top_frame!();
                    }
                    continue_in_top_frame!(self.fell_off_end());
                }
                Instr::Return => {
                    self.frame_mut().pc = pc;
                    if self.return_plain(None).is_ok() {
                        resume_top_frame!();
                    }
                    continue_in_top_frame!(Ok(self.return_from(None)));
                }
                Instr::ReturnValue => {
                    if let Some(&Value::Num(n)) = stack.last() {
                        if self.return_num(n) {
                            resume_top_frame!();
                        }
                    }
                    let stack = &mut self.storage.stack;
                    let value = stack.pop().unwrap_or(Value::Absent);
                    self.frame_mut().pc = pc;
                    match self.return_plain(Some(value)) {
                        Ok(()) => resume_top_frame!(),
                        Err(value) => continue_in_top_frame!(Ok(self.return_from(value))),
                    }
                }
                Instr::PlaceLocal(slot) => {
                    // `PlaceLocal; PlaceField(f); LoadPlace` reads a component of a
                    // record in a local slot: done at once when the budget allows all
                    // three, without building a place.
                    if let Value::Record(record) = &stack[base + slot as usize] {
                        if let (true, Some(&Instr::PlaceField(field)), Some(&Instr::LoadPlace)) =
                            (left >= 2, code.instrs.get(pc as usize + 1), code.instrs.get(pc as usize + 2))
                        {
                            if let Some(value) = record.fields.get(field as usize) {
                                let value = value.clone();
                                stack.push(value);
                                left -= 2;
                                pc += 3;
                                continue;
                            }
                        }
                    }
                    let place = match &stack[base + slot as usize] {
                        Value::Ref(place) if place.path.is_empty() => place.root,
                        Value::Ref(_) | Value::Absent => break Fast::Step,
                        _ => Root::Stack((base + slot as usize) as u32),
                    };
                    let place = self.pooled_root(place);
                    self.storage.stack.push(Value::Ref(place));
                }
                Instr::PlaceGlobal(idx) => {
                    let place = self.pooled_root(Root::Global(idx));
                    self.storage.stack.push(Value::Ref(place));
                }
                Instr::KernelStore { kernel, skip } => {
                    let kernel = &code.kernels[kernel as usize];
                    let globals = &mut self.storage.globals;
                    let stored = super::kernel::eval(kernel, stack, base, globals.values())
                        .and_then(|results| super::kernel::store(kernel.target?, &results, stack, base, globals));
                    if stored.is_some() {
                        pc = skip;
                        continue;
                    }
                    // Otherwise the general code that follows does the statement.
                }
                Instr::KernelReturn { kernel } => {
                    let kernel = &code.kernels[kernel as usize];
                    if let Some(value) = super::kernel::value(kernel, stack, base, self.storage.globals.values()) {
                        if self.return_num(value) {
                            resume_top_frame!();
                        }
                    }
                }
                Instr::KernelBranch { kernel, on_false, skip } => {
                    let kernel = &code.kernels[kernel as usize];
                    if let Some(truth) = super::kernel::condition(kernel, stack, base, self.storage.globals.values()) {
                        pc = if truth { skip } else { on_false };
                        continue;
                    }
                }
                Instr::Call(site_index) => {
                    let site = &code.sites[site_index as usize];
                    let Callee::Builtin(id) = site.callee else {
                        // A routine: entered here, and the loop starts again in its frame.
                        match self.enter_plain(&code, site_index, pc) {
                            Some((callee_base, true)) => {
                                (base, pc) = (callee_base, 0);
                                continue;
                            }
                            Some((_, false)) => resume_top_frame!(),
                            None => {}
                        }
                        self.frame_mut().pc = pc;
                        continue_in_top_frame!(self.call(&code, site_index, host));
                    };
                    if site.args.iter().any(|a| matches!(a, ArgSpec::Conditional { .. })) {
                        break Fast::Step;
                    }
                    let at = stack.len() - site.n_pushed as usize;
                    // A pure function reads its arguments where they lie; anything
                    // unusual takes the general path below.
                    if let Some(pure) = self.builtins.pure_form(id).filter(|_| only_trailing_absent(site)) {
                        if let Some(value) = pure(&stack[at..]) {
                            stack.truncate(at);
                            stack.push(value);
                            pc += 1;
                            continue;
                        }
                    }
                    let mut args = std::mem::take(&mut self.arg_scratch);
                    clear_values(&mut args);
                    // Moved as one block; the few arguments not pushed are inserted
                    // after (moving values one by one through temporaries costs a
                    // store-forwarding stall each, measured with perf).
                    args.extend(stack.drain(at..));
                    if site.n_pushed as usize != site.args.len() {
                        for (i, spec) in site.args.iter().enumerate() {
                            match spec {
                                ArgSpec::Switch => args.insert(i, Value::SwitchOn),
                                ArgSpec::Absent | ArgSpec::Conditional { .. } => args.insert(i, Value::Absent),
                                ArgSpec::Value | ArgSpec::Place => {}
                            }
                        }
                    }
                    self.frame_mut().pc = pc;
                    let outcome = self.run_builtin(id, &args, host);
                    self.remember_repeated(&outcome, id, &args);
                    self.arg_scratch = args;
                    match outcome {
                        Ok((result, None, crate::builtins::StopKind::None)) => {
                            if let Some(value) = result {
                                self.storage.stack.push(value);
                            }
                            let watched = self.resources.interrupts.active() || self.held_after_call;
                            if self.resources.spy.is_active() || watched {
                                // SpyStart, an interrupt ordered, or a wait for the robot
                                // owed (StartMove in a trap restarts the move the routine
                                // it interrupted waits for): from the next instruction on,
                                // the run looks at every statement (the log, interrupts to
                                // take, the wait to resume), which the fast loop skips.
                                self.frame_mut().pc = pc + 1;
                                break Fast::Called(Ok(None));
                            }
                        }
                        other => break Fast::Called(self.after_builtin(other)),
                    }
                }
                Instr::JumpIfFalse(target) => match stack.last() {
                    Some(Value::Bool(b)) => {
                        let b = *b;
                        drop_plain(stack.pop());
                        pc = if b { pc + 1 } else { target };
                        continue;
                    }
                    _ => break Fast::Step,
                },
                Instr::ForCheck { var, exit } => {
                    let slots = base + var as usize;
                    let (Value::Num(v), Value::Num(to), Value::Num(step)) =
                        (&stack[slots], &stack[slots + 1], &stack[slots + 2])
                    else {
                        break Fast::Step;
                    };
                    pc = if super::instr::for_passed(*v, *to, *step) { exit } else { pc + 1 };
                    continue;
                }
                Instr::ForNext { var, check } => {
                    let slots = base + var as usize;
                    let (Value::Num(v), Value::Num(step)) = (&stack[slots], &stack[slots + 2]) else {
                        break Fast::Step;
                    };
                    // In place: assigning a whole `Value` ran the general drop code
                    // on the old num.
                    let next = super::instr::for_next(*v, *step);
                    set_num(&mut stack[slots], next);
                    pc = check;
                    continue;
                }
                // Listed, not `_`: a new instruction must be given an arm above or
                // be added here (and its declaration's `fast` fact agree, tested below).
                step_only!() | Instr::LoadElem { .. } | Instr::StoreElem { .. } => break Fast::Step,
            }
            pc += 1;
        };
        self.steps += budget - left;
        *remaining = left;
        if !matches!(outcome, Fast::Called(_)) {
            self.frame_mut().pc = pc;
        }
        outcome
    }

    /// `BinOp` on operands other than nums; `None` when an operand needs `Vm::step`.
    /// Kept out of line: inlined, it made the fast loop's other instructions slower
    /// (callgrind, bench/interp varcall).
    #[inline(never)]
    fn binop_general(
        &mut self,
        op: rapid_syntax::ast::BinaryOp,
        lhs: crate::ir::Operand,
        rhs: crate::ir::Operand,
        consts: &[Value],
        base: usize,
    ) -> Option<Result<(), super::storage::Fault>> {
        let stack = &mut self.storage.stack;
        if !plain_operand(lhs, stack, base) || !plain_operand(rhs, stack, base) {
            return None;
        }
        let rhs = take_operand(rhs, stack, base, consts);
        let lhs = take_operand(lhs, stack, base, consts);
        Some(crate::ops::binary(op, lhs, rhs, self.types).map(|value| stack.push(value)))
    }
}

/// Empties the argument scratch vector of the last built-in call. The plain values are
/// forgotten and a string only loses a reference, inline: `clear` ran the general
/// drop code per value (about 70 instructions a call, callgrind on bench/interp
/// strings and strops).
#[inline(always)]
fn clear_values(values: &mut Vec<Value>) {
    while let Some(value) = values.pop() {
        match value {
            Value::Num(_) | Value::Dnum(_) | Value::Bool(_) | Value::Absent | Value::SwitchOn => {
                std::mem::forget(value)
            }
            Value::Str(text) => drop(text),
            other => drop(other),
        }
    }
}

/// Whether `BinOp` may take `operand` as it is: a local slot holding neither a
/// reference nor an absent optional parameter (those need `Vm::load_local`).
#[inline(always)]
fn plain_operand(operand: crate::ir::Operand, stack: &[Value], base: usize) -> bool {
    match operand {
        crate::ir::Operand::Local(slot) => {
            !matches!(stack.get(base + slot as usize), None | Some(Value::Ref(_) | Value::Absent))
        }
        crate::ir::Operand::Stack | crate::ir::Operand::Const(_) => true,
    }
}

/// The value of a plain operand (popped from the stack, or a copy).
#[inline(always)]
fn take_operand(operand: crate::ir::Operand, stack: &mut Vec<Value>, base: usize, consts: &[Value]) -> Value {
    match operand {
        crate::ir::Operand::Stack => stack.pop(),
        crate::ir::Operand::Local(slot) => stack.get(base + slot as usize).cloned(),
        crate::ir::Operand::Const(i) => consts.get(i as usize).cloned(),
    }
    .unwrap_or(Value::Absent)
}

/// The num an operand of `BinOp` names: the stack value `depth` below the top, a
/// local slot (through a reference to a whole num), or a constant. A function marked
/// for inlining: as a closure it was called, about 18 instructions per operand
/// (callgrind, bench/interp fib).
#[inline(always)]
fn num_operand(
    operand: crate::ir::Operand,
    stack: &[Value],
    base: usize,
    globals: &[Value],
    consts: &[Value],
    depth: usize,
) -> Option<f32> {
    match operand {
        crate::ir::Operand::Stack => match stack.get(stack.len().wrapping_sub(depth + 1)) {
            Some(Value::Num(n)) => Some(*n),
            _ => None,
        },
        crate::ir::Operand::Local(slot) => match stack.get(base + slot as usize)? {
            Value::Num(n) => Some(*n),
            // A VAR parameter referring to a whole num in a caller's slot.
            Value::Ref(place) if place.path.is_empty() => match place.root {
                Root::Stack(at) => match stack.get(at as usize)? {
                    Value::Num(n) => Some(*n),
                    _ => None,
                },
                Root::Global(idx) => match globals.get(idx as usize) {
                    Some(&Value::Num(n)) => Some(n),
                    _ => None,
                },
            },
            _ => None,
        },
        crate::ir::Operand::Const(i) => match consts.get(i as usize)? {
            Value::Num(n) => Some(*n),
            _ => None,
        },
    }
}

/// The string an operand names: the stack value `depth` below the top, a local slot
/// holding a string itself (not a reference), or a constant.
#[inline(always)]
fn str_at<'a>(
    operand: crate::ir::Operand,
    stack: &'a [Value],
    base: usize,
    consts: &'a [Value],
    depth: usize,
) -> Option<&'a str> {
    let value = match operand {
        crate::ir::Operand::Stack => stack.get(stack.len().wrapping_sub(depth + 1)),
        crate::ir::Operand::Local(slot) => stack.get(base + slot as usize),
        crate::ir::Operand::Const(i) => consts.get(i as usize),
    };
    match value {
        Some(Value::Str(s)) => Some(s),
        _ => None,
    }
}

#[inline(always)]
fn is_num(value: Option<&Value>) -> bool {
    matches!(value, Some(Value::Num(_)))
}

#[inline(always)]
fn is_str(operand: crate::ir::Operand, stack: &[Value], base: usize, consts: &[Value], depth: usize) -> bool {
    str_at(operand, stack, base, consts, depth).is_some()
}

/// `BinOp(+, Stack, Stack); Const(string); BinOp(+, Stack, Stack)` at `pc` on two
/// strings: the three joined, when the result certainly fits (then neither addition
/// could have failed). `None`: not that sequence, or too long for this shortcut.
#[inline(always)]
/// Whether every argument of the call is on the stack in parameter order: the
/// optional ones not passed come last (none is a switch inserted after).
fn only_trailing_absent(site: &crate::ir::CallSite) -> bool {
    let pushed = site.n_pushed as usize;
    site.args.get(pushed..).is_some_and(|rest| rest.iter().all(|a| matches!(a, ArgSpec::Absent)))
        && site.args[..pushed].iter().all(|a| matches!(a, ArgSpec::Value))
}

fn concat_with_next(
    code: &crate::ir::Code,
    pc: u32,
    lhs: crate::ir::Operand,
    rhs: crate::ir::Operand,
    stack: &[Value],
) -> Option<Value> {
    use crate::ir::Operand::Stack;
    if lhs != Stack || rhs != Stack {
        return None;
    }
    let (Instr::Const(k), Instr::BinOp { op: rapid_syntax::ast::BinaryOp::Add, lhs: Stack, rhs: Stack }) =
        (*code.instrs.get(pc as usize + 1)?, *code.instrs.get(pc as usize + 2)?)
    else {
        return None;
    };
    let (Value::Str(c), [Value::Str(a), Value::Str(b)]) =
        (code.consts.get(k as usize)?, stack.get(stack.len().checked_sub(2)?..)?)
    else {
        return None;
    };
    let len = a.len() + b.len() + c.len();
    if len > MAX_STRING_CHARS {
        return None;
    }
    let mut buf = [0u8; MAX_STRING_CHARS];
    buf[..a.len()].copy_from_slice(a.as_bytes());
    buf[a.len()..a.len() + b.len()].copy_from_slice(b.as_bytes());
    buf[a.len() + b.len()..len].copy_from_slice(c.as_bytes());
    let joined = std::str::from_utf8(&buf[..len]).ok()?;
    Some(Value::Str(joined.into()))
}

/// `a + b` when the result certainly fits a RAPID string: at most 80 bytes of UTF-8
/// are at most 80 characters. Longer results take the general path, which counts
/// characters and raises ERR_STRTOOLNG.
#[inline(always)]
fn concat(a: &str, b: &str) -> Option<Value> {
    if a.len() + b.len() > MAX_STRING_CHARS {
        return None;
    }
    // Joined on the stack, so the value's own allocation is the only one.
    let mut buf = [0u8; MAX_STRING_CHARS];
    buf[..a.len()].copy_from_slice(a.as_bytes());
    buf[a.len()..a.len() + b.len()].copy_from_slice(b.as_bytes());
    let joined = std::str::from_utf8(&buf[..a.len() + b.len()]).ok()?;
    Some(Value::Str(joined.into()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_fast_loop_falls_back_on_exactly_the_instructions_declared_slow() {
        for instr in Instr::samples() {
            let falls_back = matches!(instr, step_only!());
            assert_eq!(falls_back, !instr.fast_path(), "{instr}: the declaration's `fast` and run_fast disagree");
        }
    }
}
