//! The fast loop: the instructions of hot code that need nothing but nums, bools,
//! jumps and one-dimensional num arrays run here without leaving the loop; anything
//! else is handed back to `Vm::step`.

use super::{Value, Vm};
use crate::ir::Instr;
use crate::value::Root;

impl Vm {
    /// Runs the top frame's instructions that need nothing but num arithmetic,
    /// jumps and loads/stores of nums, without leaving the loop. Returns `false`
    /// when the budget ran out; `true` when the instruction at pc (already counted)
    /// needs `step`.
    pub(super) fn run_fast(&mut self, remaining: &mut u64) -> bool {
        let (code, base, mut pc) = {
            let frame = self.frame();
            (frame.code.clone(), frame.base as usize, frame.pc)
        };
        let stack = &mut self.storage.stack;
        let budget = *remaining;
        let mut left = budget;
        let needs_step = loop {
            if left == 0 {
                break false;
            }
            left -= 1;
            let Some(&instr) = code.instrs.get(pc as usize) else { break true };
            match instr {
                Instr::Const(i) => match &code.consts[i as usize] {
                    Value::Num(n) => stack.push(Value::Num(*n)),
                    Value::Bool(b) => stack.push(Value::Bool(*b)),
                    _ => break true,
                },
                Instr::LoadLocal(slot) => match &stack[base + slot as usize] {
                    Value::Num(n) => stack.push(Value::Num(*n)),
                    Value::Bool(b) => stack.push(Value::Bool(*b)),
                    // A VAR parameter referring to a whole num in a caller's slot.
                    Value::Ref(place) if place.path.is_empty() => match place.root {
                        Root::Stack(at) => match stack[at as usize] {
                            Value::Num(n) => stack.push(Value::Num(n)),
                            _ => break true,
                        },
                        Root::Global(idx) => match self.storage.globals.get(idx as usize) {
                            Some(&Value::Num(n)) => stack.push(Value::Num(n)),
                            _ => break true,
                        },
                    },
                    _ => break true,
                },
                Instr::StoreLocal(slot) => {
                    let mut at = base + slot as usize;
                    if let Value::Ref(place) = &stack[at] {
                        match (place.path.is_empty(), place.root) {
                            (true, Root::Stack(target)) => at = target as usize,
                            // A VAR parameter referring to a whole module-level num.
                            (true, Root::Global(idx)) => {
                                let (Some(&Value::Num(n)), Some(Value::Num(x))) =
                                    (stack.last(), self.storage.globals.get_mut(idx as usize))
                                else {
                                    break true;
                                };
                                *x = n;
                                drop_plain(stack.pop());
                                pc += 1;
                                continue;
                            }
                            _ => break true,
                        }
                    }
                    match (stack.last(), &stack[at]) {
                        (Some(&Value::Num(n)), Value::Num(_)) => {
                            drop_plain(stack.pop());
                            set_num(&mut stack[at], n);
                        }
                        (Some(&Value::Bool(b)), Value::Bool(_)) => {
                            drop_plain(stack.pop());
                            stack[at] = Value::Bool(b);
                        }
                        _ => break true,
                    }
                }
                Instr::LoadGlobal(idx) => match self.storage.globals.get(idx as usize) {
                    Some(Value::Num(n)) => stack.push(Value::Num(*n)),
                    _ => break true,
                },
                Instr::Binary(op) => {
                    let len = stack.len();
                    let (Value::Num(a), Value::Num(b)) = (&stack[len - 2], &stack[len - 1]) else { break true };
                    let (a, b) = (*a, *b);
                    let Some(res) = fast_num_op(op, a, b) else { break true };
                    drop_plain(stack.pop());
                    put_result(stack.last_mut(), res);
                }
                Instr::BinOp { op, lhs, rhs } => {
                    let globals = &self.storage.globals;
                    let num_at = |operand: crate::ir::Operand, stack: &Vec<Value>, depth: usize| match operand {
                        crate::ir::Operand::Stack => match stack.get(stack.len().wrapping_sub(depth + 1)) {
                            Some(Value::Num(n)) => Some(*n),
                            _ => None,
                        },
                        crate::ir::Operand::Local(slot) => match &stack[base + slot as usize] {
                            Value::Num(n) => Some(*n),
                            // A VAR parameter referring to a whole num in a caller's slot.
                            Value::Ref(place) if place.path.is_empty() => match place.root {
                                Root::Stack(at) => match stack[at as usize] {
                                    Value::Num(n) => Some(n),
                                    _ => None,
                                },
                                Root::Global(idx) => match globals.get(idx as usize) {
                                    Some(&Value::Num(n)) => Some(n),
                                    _ => None,
                                },
                            },
                            _ => None,
                        },
                        crate::ir::Operand::Const(i) => match code.consts[i as usize] {
                            Value::Num(n) => Some(n),
                            _ => None,
                        },
                    };
                    let rhs_on_stack = rhs == crate::ir::Operand::Stack;
                    let lhs_depth = usize::from(rhs_on_stack);
                    let (Some(a), Some(b)) = (num_at(lhs, stack, lhs_depth), num_at(rhs, stack, 0)) else { break true };
                    let Some(res) = fast_num_op(op, a, b) else { break true };
                    // The result takes the place of the deepest stack operand, written
                    // in place; with no stack operand it is pushed.
                    match (lhs == crate::ir::Operand::Stack, rhs_on_stack) {
                        (true, true) => {
                            drop_plain(stack.pop());
                            put_result(stack.last_mut(), res);
                        }
                        (true, false) | (false, true) => put_result(stack.last_mut(), res),
                        (false, false) => stack.push(res.into_value()),
                    }
                }
                Instr::LoadElem { global: false, slot, n: 1 } => {
                    let len = stack.len();
                    let Some(&Value::Num(index)) = stack.last() else { break true };
                    let Value::Array(array) = &stack[base + slot as usize] else { break true };
                    let Some(&Value::Num(elem)) = element_1d(array, index) else { break true };
                    stack[len - 1] = Value::Num(elem);
                }
                Instr::LoadElem { global: true, slot, n: 1 } => {
                    let len = stack.len();
                    let Some(&Value::Num(index)) = stack.last() else { break true };
                    let Some(Value::Array(array)) = self.storage.globals.get(slot as usize) else { break true };
                    let Some(&Value::Num(elem)) = element_1d(array, index) else { break true };
                    stack[len - 1] = Value::Num(elem);
                }
                Instr::StoreElem { global: false, slot, n: 1 } => {
                    let len = stack.len();
                    let (Value::Num(index), Value::Num(value)) = (&stack[len - 2], &stack[len - 1]) else { break true };
                    let (index, value) = (*index, *value);
                    let Value::Array(array) = &mut stack[base + slot as usize] else { break true };
                    let Some(Value::Num(elem)) = element_1d_mut(array, index) else { break true };
                    *elem = value;
                    drop_plain(stack.pop());
                    drop_plain(stack.pop());
                }
                Instr::StoreElem { global: true, slot, n: 1 } => {
                    let len = stack.len();
                    let (Value::Num(index), Value::Num(value)) = (&stack[len - 2], &stack[len - 1]) else { break true };
                    let (index, value) = (*index, *value);
                    let Some(Value::Array(array)) = self.storage.globals.get_mut(slot as usize) else { break true };
                    let Some(Value::Num(elem)) = element_1d_mut(array, index) else { break true };
                    *elem = value;
                    drop_plain(stack.pop());
                    drop_plain(stack.pop());
                }
                Instr::Jump(target) => {
                    pc = target;
                    continue;
                }
                Instr::JumpIfFalse(target) => match stack.last() {
                    Some(Value::Bool(b)) => {
                        let b = *b;
                        drop_plain(stack.pop());
                        pc = if b { pc + 1 } else { target };
                        continue;
                    }
                    _ => break true,
                },
                Instr::ForCheck { var, exit } => {
                    let slots = base + var as usize;
                    let (Value::Num(v), Value::Num(to), Value::Num(step)) =
                        (&stack[slots], &stack[slots + 1], &stack[slots + 2])
                    else {
                        break true;
                    };
                    let done = if *step >= 0.0 { v > to } else { v < to };
                    pc = if done { exit } else { pc + 1 };
                    continue;
                }
                Instr::ForNext { var, check } => {
                    let slots = base + var as usize;
                    let (Value::Num(v), Value::Num(step)) = (&stack[slots], &stack[slots + 2]) else { break true };
                    stack[slots] = Value::Num(v + step);
                    pc = check;
                    continue;
                }
                _ => break true,
            }
            pc += 1;
        };
        self.steps += budget - left;
        *remaining = left;
        self.frame_mut().pc = pc;
        needs_step
    }
}

/// The result of a fast num operation. Kept apart from `Value` so that a result can be
/// written into an existing num slot as a bare f32: building a whole `Value` in a
/// temporary and copying it costs a store-forwarding stall on every operation
/// (measured with perf on bench/interp/arith).
#[derive(Clone, Copy)]
enum FastResult {
    Num(f32),
    Bool(bool),
}

impl FastResult {
    #[inline(always)]
    fn into_value(self) -> Value {
        match self {
            FastResult::Num(n) => Value::Num(n),
            FastResult::Bool(b) => Value::Bool(b),
        }
    }
}

/// Overwrites a stack slot that holds a num or bool operand with a result.
#[inline(always)]
fn put_result(slot: Option<&mut Value>, res: FastResult) {
    let Some(slot) = slot else { return };
    match (res, &mut *slot) {
        (FastResult::Num(n), Value::Num(x)) => *x = n,
        (FastResult::Bool(b), Value::Bool(x)) => *x = b,
        (res, slot) => {
            // The old value is a num or bool: nothing to free.
            std::mem::forget(std::mem::replace(slot, res.into_value()));
        }
    }
}

/// Writes a num into a slot that already holds a num.
#[inline(always)]
fn set_num(slot: &mut Value, n: f32) {
    if let Value::Num(x) = slot {
        *x = n;
    }
}

/// num arithmetic and comparisons the fast loop does itself; `None` sends the
/// instruction to the general path (errors, non-integer DIV/MOD, AND/OR).
#[inline(always)]
fn fast_num_op(op: rapid_syntax::ast::BinaryOp, a: f32, b: f32) -> Option<FastResult> {
    use rapid_syntax::ast::BinaryOp as B;
    let finite = |x: f32| x.is_finite().then_some(FastResult::Num(x));
    Some(match op {
        B::Add => finite(a + b)?,
        B::Sub => finite(a - b)?,
        B::Mul => finite(a * b)?,
        B::Div if b != 0.0 => finite(a / b)?,
        B::Mod | B::IntDiv => {
            // Integer operands (exactly representable as i64) take integer arithmetic:
            // MOD keeps the dividend's sign and DIV truncates, as RAPID's do.
            // num holds integers exactly only up to 2^24, so i32 covers every case where
            // the operands are integers at all; larger magnitudes take the general path.
            let (x, y) = (a as i32, b as i32);
            if y == 0 || x as f32 != a || y as f32 != b || x == i32::MIN {
                return None;
            }
            FastResult::Num(if op == B::Mod { (x % y) as f32 } else { (x / y) as f32 })
        }
        B::Lt => FastResult::Bool(a < b),
        B::Le => FastResult::Bool(a <= b),
        B::Gt => FastResult::Bool(a > b),
        B::Ge => FastResult::Bool(a >= b),
        B::Eq => FastResult::Bool(a == b),
        B::Ne => FastResult::Bool(a != b),
        _ => return None,
    })
}

/// Discards a value the fast loop knows to be a num or bool (nothing to free), without
/// running the general drop code.
#[inline(always)]
fn drop_plain(value: Option<Value>) {
    std::mem::forget(value);
}

/// Element `index` (1-based) of a one-dimensional array, when in bounds.
#[inline(always)]
fn element_1d(array: &crate::value::Array, index: f32) -> Option<&Value> {
    let i = index as usize;
    if array.dims[1] != 0 || i as f32 != index || i == 0 || i > array.dims[0] as usize {
        return None;
    }
    array.elems.get(i - 1)
}

#[inline(always)]
fn element_1d_mut(array: &mut crate::value::Array, index: f32) -> Option<&mut Value> {
    let i = index as usize;
    if array.dims[1] != 0 || i as f32 != index || i == 0 || i > array.dims[0] as usize {
        return None;
    }
    array.elems.get_mut(i - 1)
}
