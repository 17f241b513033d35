//! Searching data by type and name (§1.17 "搜索符号"): SetDataSearch, GetNextSym,
//! SetAllDataVal and the `datapos` a found object comes with (GetDataVal and SetDataVal
//! take it as `\Block`).
//!
//! The task's module-level data, in declaration order, is listed when the program is
//! loaded ([`catalog::task_symbols`]) and again whenever a module is loaded or
//! unloaded. SetDataSearch picks the matching ones at once;
//! GetNextSym hands them out one by one. A `datapos` holds `OpaqueState::Handle(m + 1)`
//! for the module `m` that declares the object.
//!
//! Routine data has no names at run time in our VM, so `\InRout` is refused with a
//! clear message, and `\Recursive` (which would go on into routines) finds nothing more.

pub(crate) mod catalog;
mod pattern;

use pattern::Pattern;

use super::{native, present, Ctx, Family, NamedData};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::{OpaqueState, Value};

type Res = Result<Option<Value>, RapidError>;

pub(super) static FAMILY: Family = Family {
    file: file!(),
    builtins: &[
        native("SetDataSearch", set_data_search),
        native("GetNextSym", get_next_sym),
        native("SetAllDataVal", set_all_data_val),
    ],
};

/// How a datum is stored.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SymKind {
    Var,
    Pers,
    Const,
}

/// One module-level data object of the task.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SymData {
    /// The name as declared.
    pub name: String,
    /// Index into the task's module names.
    pub module: u32,
    /// The declared type's name (an alias's own name, not its base type's).
    pub ty: String,
    pub kind: SymKind,
    /// Declared LOCAL.
    pub local: bool,
    /// Its slot in the VM's globals.
    pub global: u32,
    /// 0 for a scalar, else the number of dimensions.
    pub rank: u8,
}

/// The task's data by module, and the search SetDataSearch started.
#[derive(Debug, Default)]
pub struct SymSearchState {
    modules: Vec<String>,
    data: Vec<SymData>,
    /// The objects still to be handed out by GetNextSym (indices into `data`), and
    /// how many were handed out.
    search: Option<(Vec<usize>, usize)>,
}

impl SymSearchState {
    pub fn new(modules: Vec<String>, data: Vec<SymData>) -> Self {
        SymSearchState { modules, data, search: None }
    }

    /// The task's module names, by index.
    pub fn modules(&self) -> &[String] {
        &self.modules
    }

    /// The task's module-level data, in declaration order.
    pub fn data(&self) -> &[SymData] {
        &self.data
    }

    /// Takes `fresh`, the catalogue made again after modules were loaded or unloaded
    /// (this one when it could not be made), keeping only the data of modules `live`
    /// names (an unloaded module's stand-in is no module of the task). A search under
    /// way goes on over the objects it had left that still exist.
    pub(crate) fn refresh(&mut self, fresh: Option<SymSearchState>, live: &[String]) {
        let mut fresh = fresh.unwrap_or_else(|| SymSearchState::new(self.modules.clone(), self.data.clone()));
        let modules = &fresh.modules;
        fresh
            .data
            .retain(|d| modules.get(d.module as usize).is_some_and(|m| live.iter().any(|l| l.eq_ignore_ascii_case(m))));
        if let Some((left, handed)) = self.search.take() {
            let left = left
                .iter()
                .filter_map(|&i| self.data.get(i).map(|d| d.global))
                .filter_map(|global| fresh.data.iter().position(|d| d.global == global))
                .collect();
            fresh.search = Some((left, handed));
        }
        *self = fresh;
    }

    /// Forgets the current search (PP to Main).
    // uncertain: whether the controller keeps a search across PP to Main is not
    // public; a new run starts without one here.
    pub(crate) fn end_search(&mut self) {
        self.search = None;
    }

    /// The object named `name` as seen from the module a datapos names: that module's
    /// own data first, then any global data of the task.
    pub(crate) fn in_block(&self, block: u32, name: &str) -> Option<NamedData> {
        let module = block.checked_sub(1)?;
        let own = self.data.iter().find(|d| d.module == module && d.name.eq_ignore_ascii_case(name));
        let found = own.or_else(|| self.data.iter().find(|d| !d.local && d.name.eq_ignore_ascii_case(name)))?;
        Some(NamedData { global: found.global, constant: found.kind == SymKind::Const })
    }

    fn module_index(&self, name: &str) -> Option<u32> {
        self.modules.iter().position(|m| m.eq_ignore_ascii_case(name)).map(|i| i as u32)
    }
}

/// What a search accepts besides the type and the name pattern.
struct Filter {
    kinds: Option<Vec<SymKind>>,
    module: Option<Option<u32>>,
    local: Option<bool>,
}

impl Filter {
    fn accepts(&self, d: &SymData) -> bool {
        self.kinds.as_ref().is_none_or(|kinds| kinds.contains(&d.kind))
            && self.module.is_none_or(|m| m == Some(d.module))
            && self.local.is_none_or(|local| local == d.local)
    }
}

/// The `\Object` pattern, if one was passed.
fn object_pattern(ctx: &Ctx<'_>, arg: Option<&Value>) -> Result<Option<Pattern>, RapidError> {
    let Some(arg) = arg.filter(|a| present(Some(a))) else { return Ok(None) };
    let text = ctx.string(arg)?;
    // uncertain: the manual names no error for a malformed pattern; ERR_ARGVALERR is
    // the controller's error for an argument value it cannot use.
    Pattern::parse(&text)
        .map(Some)
        .map_err(|fault| ctx.error(Err::ArgValue, format!("`{text}` is not a data name pattern: {}", fault.0)))
}

/// The objects of type `ty` matching `pattern` and `filter`, in declaration order.
fn select(state: &SymSearchState, ty: &str, pattern: Option<&Pattern>, filter: &Filter) -> Vec<usize> {
    state
        .data
        .iter()
        .enumerate()
        .filter(|(_, d)| d.ty.eq_ignore_ascii_case(ty))
        .filter(|(_, d)| pattern.is_none_or(|p| p.matches(&d.name)))
        .filter(|(_, d)| filter.accepts(d))
        .map(|(i, _)| i)
        .collect()
}

/// `SetDataSearch Type [\TypeMod] [\Object] [\PersSym] [\VarSym] [\ConstSym]
/// [\InTask]|[\InMod] [\InRout] [\GlobalSym]|[\LocalSym]`: starts a search for data
/// of a type. Without a storage switch every VAR, PERS and CONST is accepted; without
/// `\InMod` the whole task is searched; `\GlobalSym` skips LOCAL data, `\LocalSym`
/// skips the rest.
// uncertain: \TypeMod (the module a LOCAL type is declared in) does not narrow the
// search: the type's name does, and our task's type names are unique.
fn set_data_search(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let ty = ctx.string(&args[0])?;
    let pattern = object_pattern(ctx, args.get(2))?;
    if present(args.get(8)) {
        return Err(RapidError::fatal("SetDataSearch \\InRout: routine data has no names at run time in `rapid run`"));
    }
    let kinds = [(3, SymKind::Pers), (4, SymKind::Var), (5, SymKind::Const)]
        .iter()
        .filter(|(i, _)| present(args.get(*i)))
        .map(|&(_, k)| k)
        .collect::<Vec<_>>();
    // uncertain: an \InMod naming no loaded module finds nothing (no error is named).
    let module = match args.get(7).filter(|a| present(Some(a))) {
        Some(arg) => Some(ctx.resources.symsearch.module_index(&ctx.string(arg)?)),
        None => None,
    };
    let local = if present(args.get(9)) {
        Some(false)
    } else if present(args.get(10)) {
        Some(true)
    } else {
        None
    };
    let filter = Filter { kinds: (!kinds.is_empty()).then_some(kinds), module, local };
    let state = &mut ctx.resources.symsearch;
    let hits = select(state, &ty, pattern.as_ref(), &filter);
    state.search = Some((hits, 0));
    Ok(None)
}

/// `GetNextSym(Object Block [\Recursive])`: the next object of the search in Object
/// (its name) and Block (where it is declared); FALSE when there is none left.
// uncertain: without a SetDataSearch first, GetNextSym returns FALSE (no error named).
fn get_next_sym(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let state = &mut ctx.resources.symsearch;
    let Some((hits, handed)) = state.search.as_mut() else { return Ok(Some(Value::Bool(false))) };
    let Some(&index) = hits.get(*handed) else { return Ok(Some(Value::Bool(false))) };
    *handed += 1;
    let found = &state.data[index];
    let (name, block) = (found.name.clone(), found.module + 1);
    ctx.store(&args[0], Value::Str(name.as_str().into()))?;
    let Value::Opaque(mut shell) = ctx.value(&args[1])? else {
        return Err(ctx.error(Err::ArgValue, "GetNextSym needs a datapos for Block"));
    };
    shell.state = OpaqueState::Handle(block);
    ctx.store(&args[1], Value::Opaque(shell))?;
    Ok(Some(Value::Bool(true)))
}

crate::builtins::signature::layout! {
    static SET_ALL_DATA_VAL: SetAllDataValArgs = "SetAllDataVal" { object: "Object", value: "Value" }
}

/// `SetAllDataVal Type [\TypeMod] [\Object] [\Hidden] Value`: sets every VAR and PERS
/// of the type (whose name matches Object) to Value; ERR_SYMBOL_TYPE if Value is not of
/// that type.
// uncertain: constants are skipped (they cannot be set), and so are arrays of the type
// (Value is one value of the type). \Hidden concerns routine data hidden by the call
// chain, which this search never reaches, so it changes nothing here.
fn set_all_data_val(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let at = *SET_ALL_DATA_VAL;
    let ty = ctx.string(&args[0])?;
    let pattern = object_pattern(ctx, args.get(at.object))?;
    let value = ctx.value(&args[at.value])?;
    let filter = Filter { kinds: Some(vec![SymKind::Var, SymKind::Pers]), module: None, local: None };
    let hits = select(&ctx.resources.symsearch, &ty, pattern.as_ref(), &filter);
    let mut targets = Vec::with_capacity(hits.len());
    for index in hits {
        let datum = &ctx.resources.symsearch.data[index];
        if datum.rank > 0 {
            continue;
        }
        let slot = datum.global;
        let current = ctx.storage.globals.get(slot).ok_or_else(|| RapidError::fatal("a data slot is missing"))?;
        if !super::symbols::same_type(current, &value) {
            let message = format!("`{}` is of type {ty}, the Value is not", datum.name);
            return Err(ctx.error(Err::SymbolType, message));
        }
        targets.push(slot);
    }
    for slot in targets {
        if let Some(target) = ctx.storage.globals.get_mut(slot) {
            *target = value.clone();
        }
    }
    Ok(None)
}
