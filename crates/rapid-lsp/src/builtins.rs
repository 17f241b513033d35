//! The catalogue of built-ins (`rapid-lib`) as the editor features see it: by folded
//! name, each entry's declaration text, doc line and parsed parameters.

use std::sync::OnceLock;

use rapid_lib::catalogue::EntryKind;
use rapid_syntax::ast::{Item, ParamMode, TypeDefKind};
use rustc_hash::FxHashMap;

use crate::index::fold;

/// One parameter of a built-in routine.
#[derive(Debug, Clone)]
pub(crate) struct BuiltinParam {
    pub(crate) name: String,
    pub(crate) ty: String,
    pub(crate) optional: bool,
    pub(crate) switch: bool,
    /// `INOUT`/`VAR`/`PERS`, as written before the type.
    pub(crate) mode: &'static str,
    /// The parameter's alternatives group (`A | B` share one).
    pub(crate) group: u16,
}

/// One built-in.
#[derive(Debug, Clone)]
pub(crate) struct Builtin {
    pub(crate) name: String,
    pub(crate) kind: EntryKind,
    /// `PROC`, `FUNC`, `RECORD`… the declaration as the catalogue writes it.
    pub(crate) text: &'static str,
    pub(crate) doc: &'static str,
    pub(crate) chapter: &'static str,
    pub(crate) is_func: bool,
    pub(crate) params: Vec<BuiltinParam>,
    /// A record's components: (name, type).
    pub(crate) components: Vec<(String, String)>,
    /// The data type of predefined data, the return type of a function.
    pub(crate) ty: Option<String>,
}

/// Every built-in, by folded name, built once per process.
pub(crate) fn table() -> &'static FxHashMap<String, Builtin> {
    static TABLE: OnceLock<FxHashMap<String, Builtin>> = OnceLock::new();
    TABLE.get_or_init(build)
}

fn build() -> FxHashMap<String, Builtin> {
    let (_, catalogue) = rapid_sema::catalogue();
    let text = catalogue.text.as_str();
    let mut table = FxHashMap::default();
    for loaded in &catalogue.entries {
        let entry = loaded.entry;
        let mut builtin = Builtin {
            name: String::new(),
            kind: entry.kind,
            text: entry.text.trim(),
            doc: entry.doc,
            chapter: loaded.chapter,
            is_func: false,
            params: Vec::new(),
            components: Vec::new(),
            ty: None,
        };
        match catalogue.item(loaded) {
            None => builtin.name = entry.text.split_whitespace().next().unwrap_or("").to_owned(),
            Some(Item::Routine(routine)) => {
                builtin.name = routine.name.span.text(text).to_owned();
                builtin.is_func = routine.ret_ty.is_some();
                builtin.ty = routine.ret_ty.map(|n| n.span.text(text).to_owned());
                builtin.params = routine
                    .params
                    .iter()
                    .map(|p| BuiltinParam {
                        name: p.name.span.text(text).to_owned(),
                        ty: p.ty.span.text(text).to_owned(),
                        optional: p.optional,
                        switch: p.ty.span.text(text).eq_ignore_ascii_case("switch"),
                        mode: match p.mode {
                            ParamMode::In => "",
                            ParamMode::Inout => "INOUT ",
                            ParamMode::Var => "VAR ",
                            ParamMode::Pers => "PERS ",
                        },
                        group: p.group,
                    })
                    .collect();
            }
            Some(Item::Data(decl)) => {
                builtin.name = decl.name.span.text(text).to_owned();
                builtin.ty = Some(decl.ty.span.text(text).to_owned());
            }
            Some(Item::Type(def)) => {
                builtin.name = def.name().span.text(text).to_owned();
                if let TypeDefKind::Record { components, .. } = &def.kind {
                    builtin.components = components
                        .iter()
                        .map(|c| (c.name.span.text(text).to_owned(), c.ty.span.text(text).to_owned()))
                        .collect();
                }
            }
            Some(Item::Placeholder(..)) => continue,
        }
        table.entry(fold(&builtin.name)).or_insert(builtin);
    }
    table
}

impl Builtin {
    /// The routine's signature on one line, parameters as RAPID writes them:
    /// `MoveL [\Conc] ToPoint [\ID] Speed …` would be the manual's; we show the
    /// declaration (`PROC MoveL(\switch Conc, robtarget ToPoint, …)`).
    pub(crate) fn signature(&self) -> String {
        self.text.lines().map(str::trim).collect::<Vec<_>>().join(" ")
    }

    /// How one parameter is written in a signature label.
    pub(crate) fn param_label(param: &BuiltinParam) -> String {
        let backslash = if param.optional { "\\" } else { "" };
        format!("{backslash}{}{} {}", param.mode, param.ty, param.name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_routines_records_and_data_by_folded_name() {
        let table = table();
        let strfind = &table["strfind"];
        assert!(strfind.is_func);
        assert_eq!(strfind.ty.as_deref(), Some("num"));
        let names: Vec<&str> = strfind.params.iter().map(|p| p.name.as_str()).collect();
        assert_eq!(names, ["Str", "ChPos", "Set", "NotInSet"]);
        assert!(strfind.params[3].optional && strfind.params[3].switch);
        let pos = &table["pos"];
        let comps: Vec<&str> = pos.components.iter().map(|c| c.0.as_str()).collect();
        assert_eq!(comps, ["x", "y", "z"]);
        assert_eq!(table["num"].kind, EntryKind::AtomicValue);
    }
}
