//! The semantics of instructions that both executors (`Vm::step` and the fast loop,
//! `fast.rs`) run the same way: one function each, inlined into both. The fast loop's
//! other arms are specialisations (nums and bools in place) that hand every other
//! case to `step`, so `step` alone holds those instructions' general semantics.

use rapid_sema::types::TypeId;

use super::Value;

/// `MakeRecord`: the top `n` values become a record of type `ty`.
#[inline(always)]
pub(super) fn make_record(stack: &mut Vec<Value>, ty: TypeId, n: u16) {
    let at = stack.len() - n as usize;
    let fields = stack.split_off(at);
    stack.push(Value::Record(std::rc::Rc::new(crate::value::Record { ty, fields })));
}

/// `Aggregate`: packed constant aggregate `k` of `code`, built anew.
#[inline(always)]
pub(super) fn aggregate(code: &crate::ir::Code, k: u32) -> Result<Value, super::RapidError> {
    code.aggregates.value(k).ok_or_else(|| super::RapidError::fatal("a constant aggregate is missing from its routine"))
}

/// `ForCheck`: whether a FOR loop's variable `v` has passed `to`, counting by `step`
/// (up when it is 0 or more), which ends the loop.
#[inline(always)]
pub(super) fn for_passed<T: PartialOrd + Default>(v: T, to: T, step: T) -> bool {
    if step >= T::default() {
        v > to
    } else {
        v < to
    }
}

/// `ForNext`: the loop variable's next value (a num: f32 arithmetic).
#[inline(always)]
pub(super) fn for_next(v: f32, step: f32) -> f32 {
    v + step
}
