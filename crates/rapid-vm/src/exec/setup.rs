//! What the loader tells a VM after making it: the numbers of the predefined errors,
//! where INTNO lives, which globals are persistents, and module data by name.

use rustc_hash::FxHashMap;

use super::Vm;

impl Vm {
    /// The numbers of the predefined errors (read from the ERR_ constants at load).
    pub fn set_errnos(&mut self, errnos: FxHashMap<&'static str, i32>) {
        self.errnos = errnos;
    }

    /// Where INTNO lives (set when a trap starts).
    pub fn set_intno_global(&mut self, global: Option<u32>) {
        self.intno_global = global;
    }

    /// Marks which globals are persistents.
    pub fn set_pers_globals(&mut self, pers: Vec<bool>) {
        self.pers_globals = pers;
    }

    /// Names module-level data for built-ins that take a data name as text (ErrRaise).
    pub fn set_data_names(&mut self, names: FxHashMap<String, crate::builtins::NamedData>) {
        self.data_by_name = names;
    }
}
