//! The list of the task's module-level data that the symbol search walks: name, module,
//! declared type, storage class and LOCAL, built when the program is loaded and again
//! when a module is loaded or unloaded (`exec::modules`).

use rapid_sema::symbols::{DataKind, DeclOrigin};
use rapid_sema::Program;
use rapid_syntax::ast::{DeclScope, Item};

use super::{SymData, SymKind, SymSearchState};
use crate::compile::ModuleSource;

/// The module-level data of the task's `modules`, in declaration order.
pub(crate) fn task_symbols(prog: &Program, modules: &[ModuleSource<'_>]) -> SymSearchState {
    let names = modules.iter().map(|m| prog.interner.resolve(m.module.name.sym).to_string()).collect();
    let mut data = Vec::new();
    for (global, info) in prog.datas.iter().enumerate() {
        let DeclOrigin::Module { module, item } = info.origin else { continue };
        let kind = match info.kind {
            DataKind::Var => SymKind::Var,
            DataKind::Pers => SymKind::Pers,
            DataKind::Const => SymKind::Const,
            _ => continue,
        };
        let local = match modules.get(module).and_then(|m| m.module.items.get(item)) {
            Some(Item::Data(decl)) => decl.scope == DeclScope::Local,
            _ => false,
        };
        data.push(SymData {
            name: info.display.clone(),
            module: module as u32,
            ty: prog.types.name(info.ty).to_string(),
            kind,
            local,
            global: global as u32,
            rank: info.rank,
        });
    }
    SymSearchState::new(names, data)
}
