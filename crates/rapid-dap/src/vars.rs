//! Variable handles: DAP names a scope or an expandable value by a number that is
//! valid while the program stands stopped. The table is emptied when it runs on.

use rapid_controller::api::ValueTree;

/// What a variables reference stands for.
#[derive(Debug, Clone)]
pub(crate) enum Handle {
    /// A frame's parameters and routine data (0: the innermost frame).
    Locals { task: String, frame: usize },
    /// The task's module data other than persistents.
    ModuleData { task: String },
    /// The task's persistents.
    Persistents { task: String },
    /// The I/O system's signals.
    Signals,
    /// A record's components or an array's elements. `path` names the value for
    /// writing it; None for a value an expression computed.
    Tree { tree: ValueTree, path: Option<Place> },
}

/// Where a shown value lives, for writing it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum Place {
    /// Module data or a persistent: `TASK/MODULE/name.comp{2}`.
    Data(String),
    /// A parameter or routine datum of a frame, or a part of it: `name.comp{2}`.
    Local { task: String, frame: usize, path: String },
}

impl Place {
    /// The place of part `name` of the value here.
    pub(crate) fn child(&self, name: &str) -> Place {
        match self {
            Place::Data(path) => Place::Data(child_path(path, name)),
            Place::Local { task, frame, path } => {
                Place::Local { task: task.clone(), frame: *frame, path: child_path(path, name) }
            }
        }
    }
}

/// The handles given out since the program last stood still.
#[derive(Debug, Default)]
pub(crate) struct Handles {
    handles: Vec<Handle>,
}

impl Handles {
    /// A new reference (references start at 1: 0 means "nothing to expand").
    pub(crate) fn add(&mut self, handle: Handle) -> i64 {
        self.handles.push(handle);
        self.handles.len() as i64
    }

    pub(crate) fn get(&self, reference: i64) -> Option<&Handle> {
        usize::try_from(reference).ok().and_then(|r| r.checked_sub(1)).and_then(|r| self.handles.get(r))
    }

    pub(crate) fn clear(&mut self) {
        self.handles.clear();
    }
}

/// The path of part `name` of the value at `path`: an element's name is its indices
/// (`{2,1}`), a component's its name.
pub(crate) fn child_path(path: &str, name: &str) -> String {
    match name.starts_with('{') {
        true => format!("{path}{name}"),
        false => format!("{path}.{name}"),
    }
}

#[cfg(test)]
mod tests {
    use super::{child_path, Handle, Handles, Place};

    #[test]
    fn references_start_at_one_and_are_forgotten() {
        let mut handles = Handles::default();
        assert_eq!(handles.add(Handle::Signals), 1);
        assert!(matches!(handles.get(1), Some(Handle::Signals)));
        assert!(handles.get(0).is_none());
        handles.clear();
        assert!(handles.get(1).is_none());
    }

    #[test]
    fn parts_extend_the_path() {
        assert_eq!(child_path("T/M/p", "trans"), "T/M/p.trans");
        assert_eq!(child_path("T/M/grid", "{2,1}"), "T/M/grid{2,1}");
        let local = Place::Local { task: "T".into(), frame: 1, path: "p".into() };
        assert_eq!(
            local.child("trans").child("x"),
            Place::Local { task: "T".into(), frame: 1, path: "p.trans.x".into() }
        );
        assert_eq!(Place::Data("T/M/g".into()).child("{2}"), Place::Data("T/M/g{2}".into()));
    }
}
