//! The data of an RMQ message, free of any task's type numbering: each task's
//! program numbers its types itself, so a record travels by its type's name and is
//! rebuilt with the receiver's numbers.

use rapid_vm::ext::{Array, Record, TypeNames, Value};

/// A value on its way between tasks.
#[derive(Debug, Clone, PartialEq)]
pub enum Datum {
    Num(f32),
    Dnum(f64),
    Bool(bool),
    Str(String),
    /// A record by its type's name (as declared).
    Record(String, Vec<Datum>),
    Array([u32; 3], Vec<Datum>),
}

/// A datum as RAPID literal text (ValToStr's syntax): what an RWS client reads of a
/// message a task sent it.
pub fn literal(datum: &Datum) -> String {
    use rapid_vm::ext::{aggregate_to_text, bool_to_text, dnum_to_text, num_to_text, string_to_literal};
    match datum {
        Datum::Num(n) => num_to_text(*n),
        Datum::Dnum(d) => dnum_to_text(*d),
        Datum::Bool(b) => bool_to_text(*b).to_owned(),
        Datum::Str(s) => string_to_literal(s),
        Datum::Record(_, parts) | Datum::Array(_, parts) => {
            aggregate_to_text(&parts.iter().map(literal).collect::<Vec<_>>())
        }
    }
}

/// The RAPID type name of a value (an array's is its elements'), as declared, and its
/// array sizes (all 0 for a scalar). Aliases are not seen: a value declared `errnum`
/// is a `num` here.
// uncertain: the controller may send an alias type's own name in the message header.
pub(super) fn type_of(value: &Value, names: &TypeNames) -> Option<(String, [u32; 3])> {
    match value {
        Value::Num(_) => Some(("num".into(), [0; 3])),
        Value::Dnum(_) => Some(("dnum".into(), [0; 3])),
        Value::Bool(_) => Some(("bool".into(), [0; 3])),
        Value::Str(_) => Some(("string".into(), [0; 3])),
        Value::Record(record) => Some((names.by_id.get(&record.ty)?.clone(), [0; 3])),
        Value::Array(array) => {
            let (name, _) = type_of(array.elems.first()?, names)?;
            Some((name, array.dims))
        }
        _ => None,
    }
}

/// The datum of a value; `None` for data that cannot travel (non-value data).
pub(super) fn to_datum(value: &Value, names: &TypeNames) -> Option<Datum> {
    Some(match value {
        Value::Num(n) => Datum::Num(*n),
        Value::Dnum(d) => Datum::Dnum(*d),
        Value::Bool(b) => Datum::Bool(*b),
        Value::Str(s) => Datum::Str(s.to_string()),
        Value::Record(record) => {
            let fields = record.fields.iter().map(|f| to_datum(f, names)).collect::<Option<Vec<_>>>()?;
            Datum::Record(names.by_id.get(&record.ty)?.clone(), fields)
        }
        Value::Array(array) => {
            let elems = array.elems.iter().map(|e| to_datum(e, names)).collect::<Option<Vec<_>>>()?;
            Datum::Array(array.dims, elems)
        }
        _ => return None,
    })
}

/// The value of a datum in the receiving task; `None` when the task has no type of a
/// record's name.
pub(super) fn to_value(datum: &Datum, names: &TypeNames) -> Option<Value> {
    Some(match datum {
        Datum::Num(n) => Value::Num(*n),
        Datum::Dnum(d) => Value::Dnum(*d),
        Datum::Bool(b) => Value::Bool(*b),
        Datum::Str(s) => Value::Str(s.as_str().into()),
        Datum::Record(name, fields) => {
            let ty = *names.by_name.get(&name.to_ascii_lowercase())?;
            let fields = fields.iter().map(|f| to_value(f, names)).collect::<Option<Vec<_>>>()?;
            Value::Record(std::rc::Rc::new(Record { ty, fields }))
        }
        Datum::Array(dims, elems) => {
            let elems = elems.iter().map(|e| to_value(e, names)).collect::<Option<Vec<_>>>()?;
            Value::Array(Box::new(Array { dims: *dims, elems }))
        }
    })
}

/// The bytes the datum takes in a message: 4 per num, 8 per dnum, 1 per bool, a
/// string's characters.
// uncertain: the controller's message encoding is not public; this is what RmqMaxMsgSize
// is compared with.
pub(super) fn size(datum: &Datum) -> usize {
    match datum {
        Datum::Num(_) => 4,
        Datum::Dnum(_) => 8,
        Datum::Bool(_) => 1,
        Datum::Str(s) => s.chars().count(),
        Datum::Record(_, fields) => fields.iter().map(size).sum(),
        Datum::Array(_, elems) => elems.iter().map(size).sum(),
    }
}
