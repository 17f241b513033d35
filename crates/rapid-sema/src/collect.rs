//! Declaring everything before bodies are checked: built-in types, data and routines
//! from the catalogue, then each module's types, data and routine signatures, with
//! the duplicate rules of §1.1.5 and §1.2.2.

use rapid_lib::catalogue::EntryKind;
use rapid_lib::LoadedCatalogue;
use rapid_syntax::ast::{DataDecl, DeclScope, Item, Module, Name, Param, Routine, Storage, TypeDefKind};
use rapid_syntax::{Interner, Span, Symbol};
use rustc_hash::FxHashMap;

use crate::checker::Checker;
use crate::codes::Code;
use crate::symbols::{DataInfo, DataKind, DeclOrigin, Def, Origin, ParamInfo, RoutineInfo, ANY_RANK};
use crate::types::{self, Atomic, Field, TypeId, TypeInfo, TypeKind};

/// One user module and the file it came from.
#[derive(Clone, Copy)]
pub(crate) struct ModuleRef<'m> {
    pub(crate) file: usize,
    pub(crate) module: &'m Module,
}

/// Where a declaration is being made.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Level {
    Builtin,
    /// Module index; `local` for LOCAL declarations.
    Module {
        local: bool,
    },
}

impl Checker<'_> {
    // ---- built-ins ---------------------------------------------------------------

    /// Declares the catalogue. Entries of software options the system lacks
    /// (`system_options`, `None`: unknown, all present) are not declared: their names
    /// are remembered, for E0217 where the task uses them.
    pub(crate) fn load_builtins(
        &mut self,
        cat: &LoadedCatalogue,
        system_options: Option<&[String]>,
        interner: &mut Interner,
    ) {
        let present = |entry: &rapid_lib::LoadedEntry| crate::options::has_option(system_options, entry.option);
        let mut semi_bases = Vec::new();
        for entry in &cat.entries {
            if !present(entry) {
                self.unknowns.note_absent(cat, entry, interner);
                continue;
            }
            let kind = match entry.entry.kind {
                EntryKind::AtomicValue => TypeKind::Atomic(match entry.entry.text {
                    "num" => Atomic::Num,
                    "dnum" => Atomic::Dnum,
                    "bool" => Atomic::Bool,
                    _ => Atomic::String,
                }),
                EntryKind::NonValue => TypeKind::NonValue,
                EntryKind::SemiValue => TypeKind::Pending,
                // An option type whose components are not public accepts any value
                // and any use, like an unresolved type; a component read is E0305.
                EntryKind::Opaque => TypeKind::Error,
                _ => continue,
            };
            let mut words = entry.entry.text.split_whitespace();
            let name = words.next().unwrap_or("");
            let ty = self.types.add(TypeInfo { display: name.into(), kind, span: Span::default() });
            if let (EntryKind::Opaque, Some(option)) = (entry.entry.kind, entry.option) {
                self.unknowns.opaque.insert(ty, option);
            }
            self.scopes.builtins.insert(interner.intern(name), Def::Type(ty));
            if let Some(base) = words.next() {
                semi_bases.push((ty, interner.intern(base)));
            }
        }
        let items: Vec<&Item> = cat.entries.iter().filter(|e| present(e)).filter_map(|e| cat.item(e)).collect();
        self.declare_types(&items, Level::Builtin, cat.text.as_str());
        for (ty, base) in semi_bases {
            let base = match self.scopes.builtins.get(&base) {
                Some(Def::Type(base)) => *base,
                _ => types::ERROR,
            };
            self.types.set_kind(ty, TypeKind::SemiValue(base));
        }
        self.resolve_types(&items, Level::Builtin, cat.text.as_str());
        self.find_core_types(interner);
        for entry in cat.entries.iter().filter(|e| present(e)) {
            let Some(item) = cat.item(entry) else { continue };
            let rapid_lib::BuiltinItem::Parsed(item_idx) = entry.item else { continue };
            let origin = DeclOrigin::Builtin(item_idx);
            match item {
                Item::Data(decl) => {
                    let read_only = entry.entry.kind == EntryKind::ReadOnlyData;
                    self.declare_data(decl, Level::Builtin, read_only, &cat.module.arena, cat.text.as_str(), origin);
                }
                Item::Routine(routine) => {
                    let builtin = Some((entry.chapter, entry.entry.flags));
                    self.declare_routine(routine, Level::Builtin, builtin, cat.text.as_str(), origin)
                }
                _ => {}
            }
        }
    }

    /// Declares the configured data (signals of `EIO.cfg`) as predefined VAR data. A
    /// name the catalogue already has keeps its catalogue meaning; a type name the
    /// catalogue lacks is skipped (the caller passes only built-in types).
    // uncertain: on a controller a signal named like predefined data is refused by the
    // configuration; here the catalogue's meaning wins.
    pub(crate) fn declare_predefined(&mut self, extra: &[crate::PredefinedData], interner: &mut Interner) {
        for data in extra {
            let Some(Def::Type(ty)) = self.scopes.builtins.get(&interner.intern(&data.type_name)).copied() else {
                continue;
            };
            let sym = interner.intern(&data.name);
            if self.scopes.builtins.contains_key(&sym) {
                continue;
            }
            self.datas.push(DataInfo {
                display: data.name.clone(),
                ty,
                rank: 0,
                dims: [0; 3],
                kind: DataKind::Var,
                const_value: None,
                optional: false,
                origin: DeclOrigin::CONFIGURED,
                system_global: false,
            });
            self.scopes.builtins.insert(sym, Def::Data(self.datas.len() as u32 - 1));
        }
    }

    fn find_core_types(&mut self, interner: &mut Interner) {
        let mut find = |name: &str| match self.scopes.builtins.get(&interner.intern(name)) {
            Some(Def::Type(ty)) => *ty,
            _ => types::ERROR,
        };
        self.core = crate::types::CoreTypes {
            num: find("num"),
            dnum: find("dnum"),
            bool_: find("bool"),
            string: find("string"),
            pos: find("pos"),
            orient: find("orient"),
            errnum: find("errnum"),
            intnum: find("intnum"),
        };
    }

    // ---- user modules --------------------------------------------------------------

    /// Declares every module's types, data and routines, then resolves them.
    pub(crate) fn declare_modules(&mut self, modules: &[ModuleRef<'_>]) {
        self.scopes.module_locals = vec![FxHashMap::default(); modules.len()];
        self.module_files = modules.iter().map(|m| m.file).collect();
        self.check_module_names(modules);
        let mut seen: Vec<FxHashMap<Symbol, Span>> = vec![FxHashMap::default(); modules.len()];
        for (idx, m) in modules.iter().enumerate() {
            self.enter(m.file, idx);
            for item in &m.module.items {
                if let Some((name, local)) = item_name(item) {
                    self.check_duplicate(&mut seen[idx], name, local);
                }
            }
            let items: Vec<&Item> = m.module.items.iter().collect();
            self.declare_types(&items, Level::Module { local: false }, &self.files[m.file].text);
        }
        for (idx, m) in modules.iter().enumerate() {
            self.enter(m.file, idx);
            let items: Vec<&Item> = m.module.items.iter().collect();
            self.resolve_types(&items, Level::Module { local: false }, &self.files[m.file].text);
        }
        for (idx, m) in modules.iter().enumerate() {
            self.enter(m.file, idx);
            for (item_idx, item) in m.module.items.iter().enumerate() {
                let origin = DeclOrigin::Module { module: idx, item: item_idx };
                match item {
                    Item::Data(decl) => {
                        let level = Level::Module { local: decl.scope == DeclScope::Local };
                        self.declare_data(decl, level, false, &m.module.arena, &self.files[m.file].text, origin);
                    }
                    Item::Routine(routine) => self.declare_routine(
                        routine,
                        Level::Module { local: routine.local },
                        None,
                        &self.files[m.file].text,
                        origin,
                    ),
                    _ => {}
                }
            }
        }
    }

    fn check_module_names(&mut self, modules: &[ModuleRef<'_>]) {
        let mut names: FxHashMap<Symbol, usize> = FxHashMap::default();
        for (idx, m) in modules.iter().enumerate() {
            let name = m.module.name;
            if name.is_placeholder {
                continue;
            }
            if let Some(&first) = names.get(&name.sym) {
                self.enter(m.file, idx);
                let first_path = self.files[modules[first].file].path.clone();
                let text = self.text(name.span);
                self.diag(
                    Code::DuplicateModule,
                    name.span,
                    format!("module `{text}` is already in this task (in {first_path})"),
                );
            } else {
                names.insert(name.sym, idx);
            }
        }
    }

    /// Two module-level items of one name in one module are an error (§1.1.5).
    fn check_duplicate(&mut self, seen: &mut FxHashMap<Symbol, Span>, name: Name, _local: bool) {
        if name.is_placeholder {
            return;
        }
        if seen.insert(name.sym, name.span).is_some() {
            let text = self.text(name.span);
            self.diag(Code::DuplicateDeclaration, name.span, format!("`{text}` is declared twice in this module"));
        }
    }

    /// Registers a name at its level; global names may not repeat across modules.
    fn register(&mut self, name: Name, level: Level, def: Def) {
        if name.is_placeholder {
            return;
        }
        match level {
            Level::Builtin => {
                self.scopes.builtins.insert(name.sym, def);
            }
            Level::Module { local: true } => {
                self.scopes.module_locals[self.module].entry(name.sym).or_insert(def);
            }
            Level::Module { local: false } => {
                let origin = Origin { module: self.module, span: name.span, def };
                match self.scopes.globals.get(&name.sym).copied() {
                    None => {
                        self.scopes.globals.insert(name.sym, origin);
                    }
                    Some(first) if first.module == self.module => {}
                    Some(first) if self.same_persistent(first.def, def) => {}
                    Some(first) => {
                        let text = self.text(name.span);
                        let other = self.files.get(first_file(self, first)).map_or(String::new(), |f| f.path.clone());
                        self.diag(
                            Code::AmbiguousGlobal,
                            name.span,
                            format!("global `{text}` is also declared in another module of the task ({other})"),
                        );
                    }
                }
            }
        }
    }

    /// A global PERS may be declared in several modules when type and shape agree;
    /// they denote one persistent.
    fn same_persistent(&self, first: Def, second: Def) -> bool {
        match (first, second) {
            (Def::Data(a), Def::Data(b)) => {
                let (a, b) = (self.data(a), self.data(b));
                a.kind == DataKind::Pers && b.kind == DataKind::Pers && self.types.same(a.ty, b.ty) && a.rank == b.rank
            }
            _ => false,
        }
    }

    // ---- types ---------------------------------------------------------------------

    fn declare_types(&mut self, items: &[&Item], level: Level, text: &str) {
        for item in items {
            let Item::Type(def) = item else { continue };
            let name = def.name();
            let display = name.span.text(text).to_string();
            let ty = self.types.add(TypeInfo { display, kind: TypeKind::Pending, span: name.span });
            let level = match level {
                Level::Builtin => Level::Builtin,
                Level::Module { .. } => Level::Module { local: def.local },
            };
            self.register(name, level, Def::Type(ty));
        }
    }

    fn resolve_types(&mut self, items: &[&Item], level: Level, text: &str) {
        let mut records = Vec::new();
        for item in items {
            let Item::Type(def) = item else { continue };
            let Some(Def::Type(ty)) = self.lookup_decl(def.name().sym, level) else { continue };
            if self.types.info(ty).span != def.name().span && level != Level::Builtin {
                continue;
            }
            match &def.kind {
                TypeDefKind::Alias { base, .. } => {
                    let base_ty = self.resolve_type_name(*base, level == Level::Builtin);
                    if level != Level::Builtin && matches!(self.types.info(base_ty).kind, TypeKind::Alias(_)) {
                        let (b, n) = (self.text(base.span), self.text(def.name().span));
                        self.diag(
                            Code::AliasOfAlias,
                            base.span,
                            format!("ALIAS `{n}` is defined upon `{b}`, which is itself an alias type"),
                        );
                    }
                    self.types.set_kind(ty, TypeKind::Alias(base_ty));
                }
                TypeDefKind::Record { components, .. } => {
                    let fields = components
                        .iter()
                        .map(|c| Field {
                            name: c.name.sym,
                            display: c.name.span.text(text).to_string(),
                            ty: self.resolve_type_name(c.ty, level == Level::Builtin),
                        })
                        .collect();
                    self.types.set_kind(ty, TypeKind::Record(fields));
                    records.push((ty, def.name().span));
                }
            }
        }
        if level != Level::Builtin {
            for (ty, span) in records {
                if self.record_contains(ty) {
                    let name = self.types.name(ty).to_string();
                    self.diag(Code::RecursiveRecord, span, format!("RECORD `{name}` contains itself"));
                }
            }
        }
    }

    /// Whether record `outer` contains itself, directly or through other records: a
    /// walk over the records it reaches, each visited once.
    fn record_contains(&self, outer: TypeId) -> bool {
        let mut visited: Vec<TypeId> = Vec::new();
        let mut pending: Vec<TypeId> =
            self.types.record_fields(outer).map_or(Vec::new(), |f| f.iter().map(|f| f.ty).collect());
        while let Some(next) = pending.pop() {
            let canon = self.types.canonical(next);
            if canon == outer {
                return true;
            }
            if visited.contains(&canon) {
                continue;
            }
            visited.push(canon);
            if let Some(fields) = self.types.record_fields(canon) {
                pending.extend(fields.iter().map(|f| f.ty));
            }
        }
        false
    }

    fn lookup_decl(&self, sym: Symbol, level: Level) -> Option<Def> {
        match level {
            Level::Builtin => self.scopes.builtins.get(&sym).copied(),
            Level::Module { .. } => self.scopes.lookup_module_level(self.module, sym),
        }
    }

    /// A data type by name: undefined (E0204) and non-type names (E0211) give `ERROR`.
    pub(crate) fn resolve_type_name(&mut self, name: Name, builtin: bool) -> TypeId {
        if name.is_placeholder {
            return types::ERROR;
        }
        if name.sym == self.known.switch {
            return types::SWITCH;
        }
        if name.sym == self.known.anytype && builtin {
            return types::ANY;
        }
        let def = if builtin { self.scopes.builtins.get(&name.sym).copied() } else { self.lookup(name.sym) };
        match def {
            Some(Def::Type(ty)) => ty,
            Some(_) if !builtin => {
                let text = self.text(name.span);
                self.diag(Code::NotAType, name.span, format!("`{text}` is not a data type"));
                types::ERROR
            }
            _ if !builtin => {
                let text = self.text(name.span);
                let note = crate::options::note_for(text);
                let message = format!("undefined data type `{text}`{note}");
                self.undefined(Code::UndefinedType, name.span, name.sym, message);
                types::ERROR
            }
            _ => types::ERROR,
        }
    }

    // ---- data and routines ------------------------------------------------------------

    fn declare_data(
        &mut self,
        decl: &DataDecl,
        level: Level,
        read_only: bool,
        arena: &rapid_syntax::ast::Arena,
        text: &str,
        origin: DeclOrigin,
    ) {
        let builtin = level == Level::Builtin;
        let ty = self.resolve_type_name(decl.ty, builtin);
        let system_global = !builtin && decl.scope == DeclScope::Global;
        let info = DataInfo { origin, system_global, ..self.data_info(decl, ty, read_only, !builtin, arena, text) };
        self.datas.push(info);
        let idx = self.datas.len() as u32 - 1;
        self.register(decl.name, level, Def::Data(idx));
    }

    /// What the data table records about a declaration; the value of a num CONST is
    /// evaluated when `evaluate_const` (built-ins need no values).
    pub(crate) fn data_info(
        &self,
        decl: &DataDecl,
        ty: TypeId,
        read_only: bool,
        evaluate_const: bool,
        arena: &rapid_syntax::ast::Arena,
        text: &str,
    ) -> DataInfo {
        let kind = match (read_only, decl.storage) {
            (true, _) => DataKind::ReadOnly,
            (_, Storage::Var) => DataKind::Var,
            (_, Storage::Pers) => DataKind::Pers,
            (_, Storage::Const) => DataKind::Const,
        };
        let const_value = match (kind, decl.init) {
            (DataKind::Const, Some(init)) if decl.dims.is_empty() && evaluate_const => self.const_num(arena, init),
            _ => None,
        };
        DataInfo {
            display: decl.name.span.text(text).to_string(),
            ty,
            rank: decl.dims.len().min(3) as u8,
            dims: [0; 3],
            kind,
            const_value,
            optional: false,
            origin: DeclOrigin::Routine,
            system_global: false,
        }
    }

    fn declare_routine(
        &mut self,
        routine: &Routine,
        level: Level,
        builtin_entry: Option<(&'static str, rapid_lib::catalogue::RoutineFlags)>,
        text: &str,
        origin: DeclOrigin,
    ) {
        let builtin = level == Level::Builtin;
        let ret = routine.ret_ty.map(|ty| self.resolve_type_name(ty, builtin));
        let mut has_placeholders = false;
        let mut params = Vec::with_capacity(routine.params.len());
        for param in &routine.params {
            if param.placeholder.is_some() {
                has_placeholders = true;
                continue;
            }
            params.push(self.param_info(param, builtin, text));
        }
        let groups = crate::symbols::group_ranges(&params);
        let info = RoutineInfo {
            display: routine.name.span.text(text).to_string(),
            kind: routine.kind,
            ret,
            params: params.into(),
            groups,
            chapter: builtin_entry.map(|(chapter, _)| chapter),
            flags: builtin_entry.map(|(_, flags)| flags).unwrap_or_default(),
            has_placeholders,
            origin,
        };
        self.routines.push(info);
        let idx = self.routines.len() as u32 - 1;
        self.register(routine.name, level, Def::Routine(idx));
    }

    pub(crate) fn param_info(&mut self, param: &Param, builtin: bool, text: &str) -> ParamInfo {
        let ty = self.resolve_type_name(param.ty, builtin);
        let rank = if ty == types::ANY && param.rank > 0 { ANY_RANK } else { param.rank };
        ParamInfo {
            name: param.name.sym,
            display: param.name.span.text(text).to_string(),
            ty,
            rank,
            mode: param.mode,
            optional: param.optional,
            group: param.group,
        }
    }
}

fn first_file(ck: &Checker<'_>, origin: Origin) -> usize {
    let _ = origin.span;
    ck.module_files.get(origin.module).copied().unwrap_or(0)
}

/// The name an item declares and whether it is LOCAL.
fn item_name(item: &Item) -> Option<(Name, bool)> {
    match item {
        Item::Type(def) => Some((def.name(), def.local)),
        Item::Data(decl) => Some((decl.name, decl.scope == DeclScope::Local)),
        Item::Routine(routine) => Some((routine.name, routine.local)),
        Item::Placeholder(..) => None,
    }
}
