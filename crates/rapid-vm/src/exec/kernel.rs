//! Runs kernels (`ir::Kernel`): num expressions and conditions evaluated in f32
//! registers on the Rust stack. Every value read must be a plain num (or a reference
//! to a whole num) and every operation must succeed as the fast loop's num arithmetic
//! does; anything else answers `None`, and the statement's general code, which
//! follows the kernel instruction, runs instead and raises any error itself.
//!
//! Why: each `Value` the stack machine pushes is 24 bytes assembled in a temporary,
//! and the copies cost a store-forwarding stall apiece (perf on bench/interp/arith);
//! a kernel moves bare f32s.

use super::num::{element_1d, element_1d_mut, fast_num_op, FastResult};
use super::storage::Globals;
use crate::ir::{Kernel, KernelOp, KernelOperand, KernelTarget, KERNEL_DEPTH};
use crate::value::{Root, Value};

/// What a kernel left: its top value and, for an element target, the index below it.
/// Only these two leave the registers (copying the whole register file out would
/// stall on the narrow stores that just wrote it).
pub(super) struct Results {
    top: f32,
    below_top: Option<f32>,
}

/// Evaluates `kernel` against the frame at `base` of `stack` and the globals.
///
/// The top value lives in `top` (a register), the ones below it in `regs`: the common
/// kernel is a chain of `BinaryWith` operations on one value, which then never goes
/// through memory (cut bench/interp arith by about a fifth, callgrind).
#[inline(always)]
pub(super) fn eval(kernel: &Kernel, stack: &[Value], base: usize, globals: &[Value]) -> Option<Results> {
    // Value k of the `depth` values (1 = deepest) is in `regs[k]` for k < depth, the
    // top in `top`; `regs[0]` takes the undefined top spilled by the first push.
    let mut regs = [0f32; KERNEL_DEPTH];
    let mut depth = 0usize;
    let mut top = 0f32;
    macro_rules! push {
        ($value:expr) => {{
            let value = $value;
            *regs.get_mut(depth)? = top;
            depth += 1;
            top = value;
        }};
    }
    use rapid_syntax::ast::BinaryOp as B;
    for op in &kernel.ops {
        match *op {
            KernelOp::Local(slot) => push!(local_num(stack, globals, base + slot as usize)?),
            KernelOp::Global(idx) => match globals.get(idx as usize) {
                Some(&Value::Num(n)) => push!(n),
                _ => return None,
            },
            KernelOp::Const(n) => push!(n),
            KernelOp::Elem { global, slot } => {
                if depth == 0 {
                    return None;
                }
                let array = if global { globals.get(slot as usize) } else { stack.get(base + slot as usize) };
                let Some(Value::Array(array)) = array else { return None };
                let Some(&Value::Num(elem)) = element_1d(array, top) else { return None };
                top = elem;
            }
            KernelOp::ElemAt { global, slot, index, offset } => {
                let at = local_num(stack, globals, base + index as usize)? + offset;
                let array = if global { globals.get(slot as usize) } else { stack.get(base + slot as usize) };
                let Some(Value::Array(array)) = array else { return None };
                let Some(&Value::Num(elem)) = element_1d(array, at) else { return None };
                push!(elem);
            }
            KernelOp::Neg => {
                if depth == 0 {
                    return None;
                }
                top = -top;
            }
            KernelOp::Not => {
                if depth == 0 {
                    return None;
                }
                top = if top == 0.0 { 1.0 } else { 0.0 };
            }
            KernelOp::Binary(op) => {
                if depth < 2 {
                    return None;
                }
                depth -= 1;
                top = binary(op, *regs.get(depth)?, top)?;
            }
            KernelOp::AddConst(c) => top = with_top(depth, top, c, B::Add)?,
            KernelOp::SubConst(c) => top = with_top(depth, top, c, B::Sub)?,
            KernelOp::MulConst(c) => top = with_top(depth, top, c, B::Mul)?,
            KernelOp::ModConst(c) => top = with_top(depth, top, c, B::Mod)?,
            KernelOp::LtConst(c) => top = with_top(depth, top, c, B::Lt)?,
            KernelOp::GtConst(c) => top = with_top(depth, top, c, B::Gt)?,
            KernelOp::AddLocal(slot) => {
                let b = local_num(stack, globals, base + slot as usize)?;
                top = with_top(depth, top, b, B::Add)?;
            }
            KernelOp::BinaryWith(op, operand) => {
                if depth == 0 {
                    return None;
                }
                let b = match operand {
                    KernelOperand::Local(slot) => local_num(stack, globals, base + slot as usize)?,
                    KernelOperand::Global(idx) => match globals.get(idx as usize) {
                        Some(&Value::Num(n)) => n,
                        _ => return None,
                    },
                    KernelOperand::Const(n) => n,
                };
                top = binary(op, top, b)?;
            }
        }
    }
    if depth == 0 {
        return None;
    }
    let below_top = if depth >= 2 { Some(*regs.get(depth - 1)?) } else { None };
    Some(Results { top, below_top })
}

/// Writes a store kernel's result to its target; `None` (nothing written) when the
/// target is not a plain num slot or the element index is out of range. A global
/// target is recorded as written ([`Globals::get_mut`]).
#[inline]
pub(super) fn store(
    target: KernelTarget,
    results: &Results,
    stack: &mut [Value],
    base: usize,
    globals: &mut Globals,
) -> Option<()> {
    let value = results.top;
    let slot = match target {
        KernelTarget::Local(slot) => {
            let at = base + slot as usize;
            match stack.get(at)? {
                Value::Num(_) => stack.get_mut(at)?,
                Value::Ref(place) if place.path.is_empty() => match place.root {
                    Root::Stack(to) => stack.get_mut(to as usize)?,
                    Root::Global(idx) => globals.get_mut(idx)?,
                },
                _ => return None,
            }
        }
        KernelTarget::Global(idx) => globals.get_mut(idx)?,
        KernelTarget::Elem { global, slot } => {
            let array = if global { globals.get_mut(slot)? } else { stack.get_mut(base + slot as usize)? };
            let Value::Array(array) = array else { return None };
            element_1d_mut(array, results.below_top?)?
        }
    };
    let Value::Num(x) = slot else { return None };
    *x = value;
    Some(())
}

/// The truth of a condition kernel, `None` when it cannot run. The commonest
/// condition, a local compared with a constant (`n < 2`), is answered without the
/// loop over the ops, whose dispatch cost about as much as the rest of the
/// comparison (perf on bench/interp fib).
#[inline(always)]
pub(super) fn condition(kernel: &Kernel, stack: &[Value], base: usize, globals: &[Value]) -> Option<bool> {
    use rapid_syntax::ast::BinaryOp as B;
    match kernel.ops[..] {
        [KernelOp::Local(slot), KernelOp::LtConst(c)] => {
            Some(binary(B::Lt, local_num(stack, globals, base + slot as usize)?, c)? != 0.0)
        }
        [KernelOp::Local(slot), KernelOp::GtConst(c)] => {
            Some(binary(B::Gt, local_num(stack, globals, base + slot as usize)?, c)? != 0.0)
        }
        _ => truth(&eval(kernel, stack, base, globals)?),
    }
}

/// The value of a kernel, `None` when it cannot run. A bare local (`RETURN n`) is
/// read without setting up the registers, which cost more than the read itself.
#[inline(always)]
pub(super) fn value(kernel: &Kernel, stack: &[Value], base: usize, globals: &[Value]) -> Option<f32> {
    match kernel.ops[..] {
        [KernelOp::Local(slot)] => local_num(stack, globals, base + slot as usize),
        _ => Some(eval(kernel, stack, base, globals)?.top),
    }
}

/// The condition a branch kernel computed.
#[inline]
fn truth(results: &Results) -> Option<bool> {
    Some(results.top != 0.0)
}

/// `top op b` for a specialised operation: `binary` with the operator known at
/// compile time (inlined, its dispatch folds away).
#[inline(always)]
fn with_top(depth: usize, top: f32, b: f32, op: rapid_syntax::ast::BinaryOp) -> Option<f32> {
    if depth == 0 {
        return None;
    }
    binary(op, top, b)
}

/// A num in a local slot, or behind a reference to a whole num.
#[inline(always)]
fn local_num(stack: &[Value], globals: &[Value], at: usize) -> Option<f32> {
    match stack.get(at)? {
        Value::Num(n) => Some(*n),
        Value::Ref(place) if place.path.is_empty() => match place.root {
            Root::Stack(to) => match stack.get(to as usize)? {
                Value::Num(n) => Some(*n),
                _ => None,
            },
            Root::Global(idx) => match globals.get(idx as usize)? {
                Value::Num(n) => Some(*n),
                _ => None,
            },
        },
        _ => None,
    }
}

/// num arithmetic and comparisons exactly as the fast loop does them (bools are 1 and
/// 0); AND, OR, XOR on bools.
#[inline(always)]
fn binary(op: rapid_syntax::ast::BinaryOp, a: f32, b: f32) -> Option<f32> {
    use rapid_syntax::ast::BinaryOp as B;
    let bit = |x: bool| if x { 1.0 } else { 0.0 };
    match op {
        B::And => Some(bit(a != 0.0 && b != 0.0)),
        B::Or => Some(bit(a != 0.0 || b != 0.0)),
        B::Xor => Some(bit((a != 0.0) != (b != 0.0))),
        _ => match fast_num_op(op, a, b)? {
            FastResult::Num(n) => Some(n),
            FastResult::Bool(x) => Some(bit(x)),
        },
    }
}
