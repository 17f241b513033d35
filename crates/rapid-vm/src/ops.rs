//! The operators of §1.3.1 on values: num and dnum arithmetic (num results are
//! rounded to single precision), DIV and MOD on integers, pos vector algebra,
//! orient (quaternion) products, string concatenation, comparisons and logic.

use rapid_syntax::ast::{BinaryOp, UnaryOp};

use crate::errnames::Err;
use crate::value::{string_len, Record, Value, MAX_STRING_CHARS};

/// Why an operation failed: a RAPID error and a message.
pub type OpError = (Err, String);

/// The record layout of pos and orient, known to the operators.
#[derive(Debug, Clone, Copy)]
pub struct OpTypes {
    pub pos: rapid_sema::types::TypeId,
    pub orient: rapid_sema::types::TypeId,
}

pub fn unary(op: UnaryOp, v: Value, types: OpTypes) -> Result<Value, OpError> {
    Ok(match (op, v) {
        (UnaryOp::Not, Value::Bool(b)) => Value::Bool(!b),
        (UnaryOp::Neg, Value::Num(n)) => Value::Num(-n),
        (UnaryOp::Neg, Value::Dnum(n)) => Value::Dnum(-n),
        (UnaryOp::Neg, Value::Record(r)) if r.ty == types.pos => map_pos(&r, |x| -x),
        (UnaryOp::Plus, v @ (Value::Num(_) | Value::Dnum(_) | Value::Record(_))) => v,
        (op, v) => return Err(type_fault(&format!("{op:?}"), &v, None)),
    })
}

pub fn binary(op: BinaryOp, a: Value, b: Value, types: OpTypes) -> Result<Value, OpError> {
    use BinaryOp as B;
    match op {
        B::Eq => return Ok(Value::Bool(a == b)),
        B::Ne => return Ok(Value::Bool(a != b)),
        B::And | B::Or | B::Xor => {
            let (Value::Bool(x), Value::Bool(y)) = (&a, &b) else { return Err(type_fault(op.text(), &a, Some(&b))) };
            return Ok(Value::Bool(match op {
                B::And => *x && *y,
                B::Or => *x || *y,
                _ => x != y,
            }));
        }
        _ => {}
    }
    match (&a, &b) {
        (Value::Num(x), Value::Num(y)) => finite(num_op(op, *x, *y)?),
        (Value::Num(_) | Value::Dnum(_), Value::Num(_) | Value::Dnum(_)) => {
            finite(dnum_op(op, a.as_f64().unwrap_or(0.0), b.as_f64().unwrap_or(0.0))?)
        }
        (Value::Str(x), Value::Str(y)) if op == B::Add => concat(x, y),
        (Value::Record(x), Value::Record(y)) if x.ty == types.pos && y.ty == types.pos => pos_op(op, x, y),
        (Value::Record(x), Value::Record(y)) if x.ty == types.orient && y.ty == types.orient && op == B::Mul => {
            Ok(quat_mul(x, y))
        }
        (Value::Record(p), Value::Num(_) | Value::Dnum(_)) if p.ty == types.pos && matches!(op, B::Mul | B::Div) => {
            let k = b.as_f64().unwrap_or(0.0) as f32;
            if op == B::Div && k == 0.0 {
                return Err((Err::DivZero, "division of a pos by zero".into()));
            }
            Ok(map_pos(p, |x| if op == B::Mul { x * k } else { x / k }))
        }
        (Value::Num(_) | Value::Dnum(_), Value::Record(p)) if p.ty == types.pos && op == B::Mul => {
            let k = a.as_f64().unwrap_or(0.0) as f32;
            Ok(map_pos(p, |x| k * x))
        }
        _ => Err(type_fault(op.text(), &a, Some(&b))),
    }
}

/// Arithmetic that overflows the number type is an error, not an infinity (`(?)`:
/// the controller's errno for it is not public; ERR_NUM_LIMIT is the closest name).
fn finite(value: Value) -> Result<Value, OpError> {
    match value {
        Value::Num(n) if !n.is_finite() => Err((Err::NumLimit, "the result is outside the range of num".into())),
        Value::Dnum(d) if !d.is_finite() => Err((Err::NumLimit, "the result is outside the range of dnum".into())),
        other => Ok(other),
    }
}

fn type_fault(op: &str, a: &Value, b: Option<&Value>) -> OpError {
    let message = match b {
        Some(b) => format!("operator {op} cannot take {} and {}", kind(a), kind(b)),
        None => format!("operator {op} cannot take {}", kind(a)),
    };
    (Err::ArgValue, message)
}

fn kind(v: &Value) -> &'static str {
    match v {
        Value::Num(_) => "a num",
        Value::Dnum(_) => "a dnum",
        Value::Bool(_) => "a bool",
        Value::Str(_) => "a string",
        Value::Record(_) => "a record",
        Value::Array(_) => "an array",
        Value::Opaque(_) => "non-value data",
        Value::Absent => "an absent optional argument",
        Value::SwitchOn => "a switch",
        Value::Ref(_) => "a reference",
    }
}

/// num arithmetic in single precision; integer-only DIV and MOD (§1.3.1 note iii).
fn num_op(op: BinaryOp, x: f32, y: f32) -> Result<Value, OpError> {
    use BinaryOp as B;
    Ok(match op {
        B::Add => Value::Num(x + y),
        B::Sub => Value::Num(x - y),
        B::Mul => Value::Num(x * y),
        B::Div if y == 0.0 => return Err((Err::DivZero, "division by zero".into())),
        B::Div => Value::Num(x / y),
        B::IntDiv | B::Mod => Value::Num(int_div_mod(op, f64::from(x), f64::from(y))? as f32),
        B::Lt => Value::Bool(x < y),
        B::Le => Value::Bool(x <= y),
        B::Gt => Value::Bool(x > y),
        B::Ge => Value::Bool(x >= y),
        _ => return Err((Err::ArgValue, format!("operator {} cannot take two nums", op.text()))),
    })
}

/// dnum arithmetic (a num operand is widened, the result is a dnum).
fn dnum_op(op: BinaryOp, x: f64, y: f64) -> Result<Value, OpError> {
    use BinaryOp as B;
    Ok(match op {
        B::Add => Value::Dnum(x + y),
        B::Sub => Value::Dnum(x - y),
        B::Mul => Value::Dnum(x * y),
        B::Div if y == 0.0 => return Err((Err::DivZero, "division by zero".into())),
        B::Div => Value::Dnum(x / y),
        B::IntDiv | B::Mod => Value::Dnum(int_div_mod(op, x, y)?),
        B::Lt => Value::Bool(x < y),
        B::Le => Value::Bool(x <= y),
        B::Gt => Value::Bool(x > y),
        B::Ge => Value::Bool(x >= y),
        _ => return Err((Err::ArgValue, format!("operator {} cannot take two dnums", op.text()))),
    })
}

/// DIV truncates toward zero and MOD keeps the dividend's sign: 14 DIV 4 = 3,
/// 14 MOD 4 = 2 (§1.3.1). Both need integer operands.
fn int_div_mod(op: BinaryOp, x: f64, y: f64) -> Result<f64, OpError> {
    if x.fract() != 0.0 || y.fract() != 0.0 {
        let word = op.text();
        return Err((Err::IntNotValue, format!("{word} needs integer operands, got {x} and {y}")));
    }
    if y == 0.0 {
        return Err((Err::DivZero, "division by zero".into()));
    }
    Ok(if op == BinaryOp::IntDiv { (x / y).trunc() } else { x % y })
}

fn concat(x: &str, y: &str) -> Result<Value, OpError> {
    let len = string_len(x) + string_len(y);
    if len > MAX_STRING_CHARS {
        return Err((
            Err::StringTooLong,
            format!("the joined string would have {len} characters; at most {MAX_STRING_CHARS} fit"),
        ));
    }
    let mut s = String::with_capacity(x.len() + y.len());
    s.push_str(x);
    s.push_str(y);
    Ok(Value::Str(s.into()))
}

fn pos_components(r: &Record) -> [f32; 3] {
    let get = |i: usize| match r.fields.get(i) {
        Some(Value::Num(v)) => *v,
        _ => 0.0,
    };
    [get(0), get(1), get(2)]
}

fn make_like(r: &Record, comps: &[f32]) -> Value {
    Value::Record(std::rc::Rc::new(Record { ty: r.ty, fields: comps.iter().map(|&c| Value::Num(c)).collect() }))
}

fn map_pos(r: &Record, f: impl Fn(f32) -> f32) -> Value {
    let c = pos_components(r);
    make_like(r, &[f(c[0]), f(c[1]), f(c[2])])
}

fn pos_op(op: BinaryOp, a: &Record, b: &Record) -> Result<Value, OpError> {
    let (x, y) = (pos_components(a), pos_components(b));
    Ok(match op {
        BinaryOp::Add => make_like(a, &[x[0] + y[0], x[1] + y[1], x[2] + y[2]]),
        BinaryOp::Sub => make_like(a, &[x[0] - y[0], x[1] - y[1], x[2] - y[2]]),
        // The vector (cross) product.
        BinaryOp::Mul => {
            make_like(a, &[x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]])
        }
        _ => return Err((Err::ArgValue, format!("operator {} cannot take two pos", op.text()))),
    })
}

/// The Hamilton product of two quaternions [q1, q2, q3, q4] = q1 + q2 i + q3 j + q4 k:
/// the rotation of `b` followed by... composed as RAPID's orient * orient.
fn quat_mul(a: &Record, b: &Record) -> Value {
    let get = |r: &Record, i: usize| match r.fields.get(i) {
        Some(Value::Num(v)) => *v,
        _ => 0.0,
    };
    let (a1, a2, a3, a4) = (get(a, 0), get(a, 1), get(a, 2), get(a, 3));
    let (b1, b2, b3, b4) = (get(b, 0), get(b, 1), get(b, 2), get(b, 3));
    make_like(
        a,
        &[
            a1 * b1 - a2 * b2 - a3 * b3 - a4 * b4,
            a1 * b2 + a2 * b1 + a3 * b4 - a4 * b3,
            a1 * b3 - a2 * b4 + a3 * b1 + a4 * b2,
            a1 * b4 + a2 * b3 - a3 * b2 + a4 * b1,
        ],
    )
}
