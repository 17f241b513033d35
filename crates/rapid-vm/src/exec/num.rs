//! Nums and bools on the value stack as the fast loop and kernels handle them: bare
//! f32/bool results written in place, pushes that never assemble a whole `Value` in
//! a temporary, the fast loop's num arithmetic, and one-dimensional array elements.

use super::Value;

/// The result of a fast num operation. Kept apart from `Value` so that a result can be
/// written into an existing num slot as a bare f32: building a whole `Value` in a
/// temporary and copying it costs a store-forwarding stall on every operation
/// (measured with perf on bench/interp/arith).
#[derive(Clone, Copy)]
pub(super) enum FastResult {
    Num(f32),
    Bool(bool),
}

impl FastResult {
    #[inline(always)]
    pub(super) fn into_value(self) -> Value {
        match self {
            FastResult::Num(n) => Value::Num(n),
            FastResult::Bool(b) => Value::Bool(b),
        }
    }
}

/// Overwrites a stack slot that holds a num or bool operand with a result.
#[inline(always)]
pub(super) fn put_result(slot: Option<&mut Value>, res: FastResult) {
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

/// Pushes a num. The constant is copied in whole and then its number written: a
/// `Value::Num(n)` assembled in a temporary by narrow stores and copied with wide
/// loads stalled on store forwarding at every push (perf on bench/interp fib: about a
/// third of the fast loop's time).
#[inline(always)]
pub(super) fn push_num(stack: &mut Vec<Value>, n: f32) {
    const ZERO: Value = Value::Num(0.0);
    stack.push(ZERO);
    if let Some(Value::Num(x)) = stack.last_mut() {
        *x = n;
    }
}

/// Writes a num into a slot holding a plain value (num, dnum, bool, absent, switch),
/// which needs no drop code.
#[inline(always)]
pub(super) fn put_num(slot: &mut Value, n: f32) {
    const ZERO: Value = Value::Num(0.0);
    if !matches!(slot, Value::Num(_)) {
        std::mem::forget(std::mem::replace(slot, ZERO));
    }
    set_num(slot, n);
}

/// Pushes a bool, as `push_num` does.
#[inline(always)]
pub(super) fn push_bool(stack: &mut Vec<Value>, b: bool) {
    const FALSE: Value = Value::Bool(false);
    stack.push(FALSE);
    if let Some(Value::Bool(x)) = stack.last_mut() {
        *x = b;
    }
}

/// Writes a num into a slot that already holds a num.
#[inline(always)]
pub(super) fn set_num(slot: &mut Value, n: f32) {
    if let Value::Num(x) = slot {
        *x = n;
    }
}

/// num arithmetic and comparisons the fast loop does itself; `None` sends the
/// instruction to the general path (errors, non-integer DIV/MOD, AND/OR).
#[inline(always)]
pub(super) fn fast_num_op(op: rapid_syntax::ast::BinaryOp, a: f32, b: f32) -> Option<FastResult> {
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
pub(super) fn drop_plain(value: Option<Value>) {
    std::mem::forget(value);
}

/// Element `index` (1-based) of a one-dimensional array, when in bounds.
#[inline(always)]
pub(super) fn element_1d(array: &crate::value::Array, index: f32) -> Option<&Value> {
    let i = index as usize;
    if array.dims[1] != 0 || i as f32 != index || i == 0 || i > array.dims[0] as usize {
        return None;
    }
    array.elems.get(i - 1)
}

#[inline(always)]
pub(super) fn element_1d_mut(array: &mut crate::value::Array, index: f32) -> Option<&mut Value> {
    let i = index as usize;
    if array.dims[1] != 0 || i as f32 != index || i == 0 || i > array.dims[0] as usize {
        return None;
    }
    array.elems.get_mut(i - 1)
}
