//! The registry of built-in implementations. Each family file registers its built-ins
//! in one table beside their code (`pub static FAMILY: Family`), under the name the
//! catalogue declares them by (`crates/rapid-lib/src/catalogue/`); `CORE_FAMILIES` in
//! `builtins/mod.rs` lists the language's families, and an embedder adds its own
//! through an [`Extension`] (`crate::embed`). What the compiler must know about how a
//! built-in takes its arguments is in its catalogue entry (`RoutineFlags`); what
//! `rapid run` does with it is here: the Rust function a call runs, its pure form for
//! the fast loop, or the instructions the compiler makes of it.
//!
//! A set of built-ins ([`Builtins`]) is built once from the families: their tables
//! are concatenated (a built-in's id is its position) and indexed by lower-case name,
//! so a call site finds its built-in once, when it is compiled; running a call
//! indexes by id in the same set.
//!
//! A catalogue routine that is in no family is listed in `not_yet.rs` with the reason;
//! a program calling it is refused at load ("not supported by `rapid run` yet").
//! [`out_of_step`] holds the three in step for a full set. Routines of software
//! options (catalogue `options/`) are in no family: a call is refused at load naming
//! the option.

use rustc_hash::FxHashMap;

use super::pure::PureFn;
use super::{BuiltinFn, BuiltinId, Ctx, Resources};
use crate::embed::{Extension, TaskHooks};
use crate::error::RapidError;
use crate::value::Value;

/// One family's registrations, with the file that implements them (for the docs).
pub struct Family {
    pub file: &'static str,
    pub builtins: &'static [Builtin],
}

/// How `rapid run` runs one built-in.
#[derive(Clone, Copy)]
pub struct Builtin {
    /// The name as the catalogue spells it.
    pub name: &'static str,
    /// What a call runs (arguments in parameter order, see [`BuiltinFn`]).
    pub run: BuiltinFn,
    /// A pure form the fast loop may call on the arguments where they lie (`pure.rs`).
    pub pure: Option<PureFn>,
    /// The compiler's own form of the call (`compile/call.rs`), in place of `run` or
    /// (Break outside a loop, ArgName) beside it.
    pub compiled: Option<Compiled>,
}

/// Built-ins the compiler turns into instructions of its own.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Compiled {
    /// `Present(p)`: whether an optional parameter of the routine was passed.
    Present,
    /// `CallByVar Name, Number`: a late-bound call.
    CallByVar,
    /// `Type(Data)`: the data's type name, known when compiling.
    Type,
    /// `WaitUntil`: a loop that evaluates the condition at every poll.
    WaitUntil,
    /// `Continue`: a jump to the next pass of the innermost loop.
    Continue,
    /// `Break`: inside a loop a jump out of it; outside one, a call of `run`.
    Break,
    /// `ArgName`: a call of `run` whose first argument is not evaluated; the call site
    /// records the data object it names.
    ArgName,
}

/// A built-in that runs as the Rust function `run`.
pub const fn native(name: &'static str, run: BuiltinFn) -> Builtin {
    Builtin { name, run, pure: None, compiled: None }
}

/// A built-in the compiler always turns into instructions of its own.
pub const fn compiled(name: &'static str, how: Compiled) -> Builtin {
    Builtin { name, run: compiled_only, pure: None, compiled: Some(how) }
}

impl Builtin {
    /// With a pure form for the fast loop; it must give what `run` gives whenever it
    /// answers (see `pure.rs`).
    pub const fn with_pure(self, pure: PureFn) -> Builtin {
        Builtin { pure: Some(pure), ..self }
    }

    /// With a form of its own in the compiler, `run` serving where that form says.
    pub const fn compiled_as(self, how: Compiled) -> Builtin {
        Builtin { compiled: Some(how), ..self }
    }
}

/// `run` of a built-in that is always compiled into instructions: never called.
fn compiled_only(_: &mut Ctx<'_>, _: &[Value]) -> Result<Option<Value>, RapidError> {
    Err(RapidError::fatal("internal error: a built-in compiled into instructions was called"))
}

/// A set of built-ins a task runs with: the language's own families (`CORE_FAMILIES`
/// in `builtins/mod.rs`) followed by those of the embedder's [`Extension`]s, indexed
/// by lower-case name. The compiler resolves a call site against the set it is given
/// and the VM runs the call by id in the same set, so a set is built once per
/// controller (or per program) and shared (`Arc`) by its tasks; it never changes
/// after it is built (no global mutable state: two embedders in one process may run
/// different sets side by side).
pub struct Builtins {
    builtins: Vec<Builtin>,
    by_name: FxHashMap<String, BuiltinId>,
    /// The family file of each built-in, for the docs.
    files: Vec<&'static str>,
    /// The hooks of the extensions, in the order they were given.
    hooks: Vec<&'static dyn TaskHooks>,
    /// The extensions' constructors of per-task state.
    inits: Vec<fn(&mut Resources)>,
}

impl Builtins {
    /// The language's families and then each extension's, in order. The first
    /// registration of a name wins (the core's before any extension's); the catalogue
    /// tests (`registry::out_of_step`) refuse a second.
    pub fn new(extensions: &[&'static Extension]) -> Builtins {
        let mut set = Builtins {
            builtins: Vec::new(),
            by_name: FxHashMap::default(),
            files: Vec::new(),
            hooks: Vec::new(),
            inits: Vec::new(),
        };
        for family in super::CORE_FAMILIES {
            set.add(family);
        }
        for extension in extensions {
            for family in extension.families {
                set.add(family);
            }
            set.hooks.extend(extension.hooks);
            set.inits.extend(extension.init);
        }
        set
    }

    fn add(&mut self, family: &Family) {
        for builtin in family.builtins {
            let id = BuiltinId(self.builtins.len() as u16);
            self.by_name.entry(builtin.name.to_ascii_lowercase()).or_insert(id);
            self.builtins.push(*builtin);
            self.files.push(family.file);
        }
    }

    /// The built-in named `name` (any letter case), if this set runs it. The compiler
    /// asks once per call site; running the call goes by the id.
    pub fn lookup(&self, name: &str) -> Option<BuiltinId> {
        self.by_name.get(name.to_ascii_lowercase().as_str()).copied()
    }

    /// The registration of built-in `id`.
    #[inline]
    pub fn get(&self, id: BuiltinId) -> &Builtin {
        &self.builtins[id.0 as usize]
    }

    /// What a call of built-in `id` runs.
    #[inline]
    pub fn function(&self, id: BuiltinId) -> BuiltinFn {
        self.builtins[id.0 as usize].run
    }

    /// The pure form of built-in `id`, if it has one (`pure.rs`).
    #[inline]
    pub fn pure_form(&self, id: BuiltinId) -> Option<PureFn> {
        self.builtins[id.0 as usize].pure
    }

    pub fn name(&self, id: BuiltinId) -> &'static str {
        self.builtins[id.0 as usize].name
    }

    /// Every registration with the file of its family, in registry order.
    pub fn registered(&self) -> impl Iterator<Item = (&Builtin, &'static str)> {
        self.builtins.iter().zip(self.files.iter().copied())
    }

    /// The hooks the core loop calls (see [`TaskHooks`]).
    #[inline]
    pub fn hooks(&self) -> &[&'static dyn TaskHooks] {
        &self.hooks
    }

    /// Gives a new task's resources the extensions' state.
    pub(crate) fn init_task(&self, resources: &mut Resources) {
        for init in &self.inits {
            init(resources);
        }
    }
}

/// What stands out of step between `set` and the catalogue: a catalogue routine
/// (not of a software option) neither run by `set` nor listed in `not_yet.rs` (or
/// both), a `not_yet.rs` entry the catalogue lacks, a registration of no catalogue
/// routine or spelled otherwise, a name registered twice. Empty when they agree.
/// Run on the full set where an embedder assembles it (the controller's): the core
/// alone leaves the robot's routines unregistered.
pub fn out_of_step(set: &Builtins) -> Vec<String> {
    let routines = catalogue_routines();
    let mut wrong = Vec::new();
    for name in routines.values() {
        match (set.lookup(name).is_some(), super::not_yet::reason(name)) {
            (true, Some(_)) => wrong.push(format!("{name}: registered and listed in not_yet.rs")),
            (false, None) => wrong.push(format!("{name}: neither registered nor listed in not_yet.rs")),
            (false, Some(reason)) if reason.trim().is_empty() => {
                wrong.push(format!("{name}: listed in not_yet.rs without a reason"))
            }
            _ => {}
        }
    }
    for &(name, _) in super::not_yet::NOT_YET {
        if !routines.contains_key(&name.to_ascii_lowercase()) {
            wrong.push(format!("{name}: in not_yet.rs but not in the catalogue"));
        }
    }
    let mut seen = std::collections::BTreeMap::new();
    for (builtin, file) in set.registered() {
        let key = builtin.name.to_ascii_lowercase();
        match routines.get(&key) {
            None => wrong.push(format!("{} ({file}): no catalogue entry", builtin.name)),
            Some(spelled) if spelled != builtin.name => {
                wrong.push(format!("{} ({file}): the catalogue spells it {spelled}", builtin.name))
            }
            Some(_) => {}
        }
        if let Some(first) = seen.insert(key, file) {
            wrong.push(format!("{} registered twice ({first}, {file})", builtin.name));
        }
    }
    wrong
}

/// Every routine the catalogue declares, except those of software options (none
/// runs: a call is refused at load with the option's name): lower-case name → name
/// as spelled.
fn catalogue_routines() -> std::collections::BTreeMap<String, String> {
    use rapid_lib::catalogue::EntryKind;
    use rapid_syntax::ast::Item;
    let mut interner = rapid_syntax::Interner::default();
    let cat = rapid_lib::load(&mut interner);
    let mut out = std::collections::BTreeMap::new();
    for loaded in &cat.entries {
        if loaded.entry.kind != EntryKind::Routine || loaded.option.is_some() {
            continue;
        }
        if let Some(Item::Routine(routine)) = cat.item(loaded) {
            let name = routine.name.span.text(&cat.text).to_string();
            out.insert(name.to_ascii_lowercase(), name);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::Builtins;

    // That the full set is in step with the catalogue is tested where the full set is
    // assembled (`rapid_controller::builtin_set`): the core and the robot alone
    // leave the controller's bindings (files ...) unregistered.

    #[test]
    fn the_core_set_runs_no_routine_an_extension_brings() {
        let core = Builtins::new(&[]);
        assert!(core.lookup("TPWrite").is_some());
        assert!(core.lookup("MoveL").is_none(), "MoveL is the robot's");
    }
}
