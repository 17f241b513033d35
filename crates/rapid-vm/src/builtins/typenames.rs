//! The task's types by name: what a value built or sent by its type's name needs.
//! Each task's program numbers its types itself, so a record that leaves the task (a
//! RAPID Message Queue message, the controller's RMQ binding) travels by its type's
//! name and is rebuilt with the receiver's numbers, and a value the robot builds by
//! type name (`rapid_robot`'s data) finds its number here. It stays in the core because
//! only the loader knows the program's types (set at load, `lib.rs`).

use rapid_sema::types::TypeId;
use rustc_hash::FxHashMap;

use crate::value::Value;

/// The task's types: names as declared by number, numbers by lower-case name.
#[derive(Debug, Default, Clone)]
pub struct TypeNames {
    pub by_id: FxHashMap<TypeId, String>,
    pub by_name: FxHashMap<String, TypeId>,
    /// The value before anything is assigned of each record and alias type, by
    /// number: the shape a message's literal from outside the tasks is read into.
    pub templates: FxHashMap<TypeId, Value>,
}

impl TypeNames {
    /// From every (id, name) of a program's type table.
    pub fn new<'a>(types: impl Iterator<Item = (TypeId, &'a str)>) -> TypeNames {
        let mut names = TypeNames::default();
        for (id, name) in types {
            names.by_id.insert(id, name.to_owned());
            names.by_name.entry(name.to_ascii_lowercase()).or_insert(id);
        }
        names
    }

    /// The value of type `name` (any letter case) before anything is assigned, as the
    /// task declares the type: `None` for a type it has no template of.
    pub fn template(&self, name: &str) -> Option<Value> {
        self.templates.get(self.by_name.get(&name.to_ascii_lowercase())?).cloned()
    }
}
