//! `rapid run --virtual-io`: programs written for a cell whose I/O configuration is
//! not at hand (a module on its own) connect their signals with `AliasIO "NAME", var`;
//! with this option every such name the configuration lacks becomes a virtual signal
//! of the variable's kind, so the program runs (and a stimulus can drive its inputs).
//! A real controller raises ERR_ALIASIO_DEF instead; this is a simulation aid.
//! The same goes for names the program uses where a signal is wanted and nothing
//! declares (`SetDO doGrip, 1;`: the checker makes them configuration data of the
//! type their place wants, `rapid_sema::Options::virtual_signals`), and for AliasIO
//! names computed at run time (rapid-signals makes those, `IoState::virtual_io`). Each
//! virtual signal is listed once on stderr.

use rapid_io::{IoSystem, SignalDef, SignalKind};
use rapid_sema::SourceInput;

/// The signals `AliasIO "NAME", var` calls name, with the kind of `var` as the modules
/// declare it (`VAR signaldi var`); calls whose variable is not declared so are left
/// out.
pub fn aliased_signals(modules: &[SourceInput]) -> Vec<(String, SignalKind)> {
    let mut found: Vec<(String, SignalKind)> = Vec::new();
    for module in modules {
        let lower = module.text.to_ascii_lowercase();
        for (name, var) in alias_calls(&module.text, &lower) {
            let Some(kind) = declared_kind(&lower, &var.to_ascii_lowercase()) else { continue };
            if !found.iter().any(|(n, _)| n.eq_ignore_ascii_case(&name)) {
                found.push((name, kind));
            }
        }
    }
    found
}

/// `(signal name, variable)` of every `AliasIO "NAME", var` in a module's text.
fn alias_calls(text: &str, lower: &str) -> Vec<(String, String)> {
    let mut calls = Vec::new();
    let mut from = 0;
    while let Some(at) = lower[from..].find("aliasio") {
        let start = from + at;
        from = start + "aliasio".len();
        let before = lower[..start].chars().next_back();
        if before.is_some_and(|c| c.is_ascii_alphanumeric() || c == '_') {
            continue;
        }
        let rest = text[from..].trim_start();
        let Some(quoted) = rest.strip_prefix('"') else { continue };
        let Some(end) = quoted.find('"') else { continue };
        let name = &quoted[..end];
        let Some(after) = quoted[end + 1..].trim_start().strip_prefix(',') else { continue };
        let var: String = after.trim_start().chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect();
        if !name.is_empty() && !var.is_empty() {
            calls.push((name.to_string(), var));
        }
    }
    calls
}

/// The signal kind `var` is declared with (`signaldi var`, …), from lower-case text.
fn declared_kind(lower: &str, var: &str) -> Option<SignalKind> {
    let kinds = [
        ("signaldi", SignalKind::DI),
        ("signaldo", SignalKind::DO),
        ("signalai", SignalKind::AI),
        ("signalao", SignalKind::AO),
        ("signalgi", SignalKind::GI),
        ("signalgo", SignalKind::GO),
    ];
    for (type_name, kind) in kinds {
        let mut from = 0;
        while let Some(at) = lower[from..].find(type_name) {
            let after = &lower[from + at + type_name.len()..];
            from += at + type_name.len();
            let ident: String =
                after.trim_start().chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect();
            if ident == var {
                return Some(kind);
            }
        }
    }
    None
}

/// Adds a virtual signal for each name the system lacks (groups 32 bits wide);
/// answers those it added.
pub fn add_to(system: &mut IoSystem, signals: &[(String, SignalKind)]) -> Result<Vec<(String, SignalKind)>, String> {
    let mut added = Vec::new();
    for (name, kind) in signals {
        if system.id(name).is_some() {
            continue;
        }
        let mut def = SignalDef::new(name, *kind);
        if matches!(kind, SignalKind::GI | SignalKind::GO) {
            // uncertain: a group's width is unknown without its configuration: 32 bits.
            def.group_bits = 32;
        }
        system.add_virtual(def).map_err(|e| format!("virtual signal `{name}`: {e}"))?;
        added.push((name.clone(), *kind));
    }
    Ok(added)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn alias_calls_and_kinds_are_found() {
        let text = "MODULE m\n  VAR signaldo doGrip;\n  VAR signalgi giCode;\n  PROC main()\n    \
                    AliasIO \"DO_Grip\", doGrip;\n    aliasio \"GI_Code\" , giCode;\n    MyAliasIO \"X\", doGrip;\n    \
                    AliasIO \"Unknown\", notDeclared;\n  ENDPROC\nENDMODULE\n";
        let module = SourceInput::from_bytes(String::from("m.mod"), text.as_bytes().to_vec());
        let found = aliased_signals(&[module]);
        assert_eq!(found, [("DO_Grip".to_string(), SignalKind::DO), ("GI_Code".to_string(), SignalKind::GI)]);
    }
}
