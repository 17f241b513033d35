//! Record values between tasks: each task's program numbers its types itself, so a
//! record passed from one task to another has its type renumbered by name.

use rapid_sema::types::TypeId;
use rapid_vm::value::{Array, Record, Value};
use rustc_hash::FxHashMap;

/// How the types of one task's program map to another's; empty when every type both
/// know has the same number (the common case: then values pass as they are).
pub(crate) type TypeMap = FxHashMap<TypeId, TypeId>;

/// The renumbering from `from`'s types to `to`'s, both given by lower-case name.
pub(crate) fn type_map(from: &FxHashMap<String, TypeId>, to: &FxHashMap<String, TypeId>) -> TypeMap {
    from.iter()
        .filter_map(|(name, &id)| {
            let other = *to.get(name)?;
            (other != id).then_some((id, other))
        })
        .collect()
}

/// `value` with its record types renumbered through `map`.
pub(crate) fn renumber(value: &Value, map: &TypeMap) -> Value {
    if map.is_empty() {
        return value.clone();
    }
    match value {
        Value::Record(record) => {
            let ty = map.get(&record.ty).copied().unwrap_or(record.ty);
            let fields = record.fields.iter().map(|f| renumber(f, map)).collect();
            Value::Record(std::rc::Rc::new(Record { ty, fields }))
        }
        Value::Array(array) => {
            let elems = array.elems.iter().map(|e| renumber(e, map)).collect();
            Value::Array(Box::new(Array { dims: array.dims, elems }))
        }
        other => other.clone(),
    }
}

/// Whether two values are equal, cheaply when they share storage (a value the task
/// did not touch still shares its records with the copy the controller kept).
pub(crate) fn same(a: &Value, b: &Value) -> bool {
    match (a, b) {
        (Value::Record(x), Value::Record(y)) => std::rc::Rc::ptr_eq(x, y) || x == y,
        (Value::Array(x), Value::Array(y)) => {
            x.dims == y.dims && x.elems.len() == y.elems.len() && x.elems.iter().zip(&y.elems).all(|(p, q)| same(p, q))
        }
        _ => a == b,
    }
}
