//! What the unit tests of this crate share: a controller of one task.

use rapid_sema::SourceInput;

use crate::{Controller, TaskSpec};

/// A controller of one NORMAL motion task, T_ROB1, running `program` from `main`.
pub(crate) fn one_task(program: &str) -> Controller {
    let files = [SourceInput::from_text("T_ROB1.mod", program)];
    let loaded = match crate::builtin_set::load_with(&files, "main", &rapid_sema::Options::default()) {
        Ok(loaded) => loaded,
        Err(err) => panic!("the test program does not load: {err:?}"),
    };
    let spec = TaskSpec::normal("T_ROB1", true);
    match Controller::new(vec![(spec, loaded)], None) {
        Ok(controller) => controller,
        Err(message) => panic!("{message}"),
    }
}
