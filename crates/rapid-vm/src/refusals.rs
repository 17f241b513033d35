//! Programs that check but cannot run here, refused at load before anything runs:
//! a task that needs code only an encrypted module defines, and module data of a
//! software option's type whose components are not public (no value of it can be
//! made faithfully). Option instructions are refused where their calls are compiled
//! (`builtins::option_refusal`).

use rapid_lib::catalogue::options::ALL_OPTIONS;
use rapid_lib::catalogue::EntryKind;
use rapid_sema::symbols::DeclOrigin;
use rapid_sema::types::{TypeKind, ERROR};
use rapid_sema::{Code, Diagnostic, Program, SourceInput};
use rapid_syntax::Span;

use crate::compile::CompileError;

/// Names only an encrypted module can define (W0218) mean the task needs that module's
/// code, which cannot be read: it cannot run here. One refusal, at the first such
/// name, naming them all and the encrypted modules.
pub(crate) fn needs_encrypted(files: &[SourceInput], diagnostics: &[Diagnostic]) -> Option<CompileError> {
    let uses: Vec<&Diagnostic> = diagnostics.iter().filter(|d| d.code == Code::UndefinedBesideEncrypted).collect();
    let first = uses.first()?;
    let name_of = |d: &Diagnostic| {
        let text = files[d.file].text.get(d.span.start as usize..d.span.end as usize).unwrap_or("");
        format!("`{}`", text.split('(').next().unwrap_or("").trim())
    };
    let mut names: Vec<String> = uses.iter().map(|d| name_of(d)).collect();
    names.dedup();
    let modules: Vec<String> =
        files.iter().filter(|f| f.unreadable.is_some()).map(|f| format!("`{}`", f.path)).collect();
    let message = format!(
        "the task cannot run: it needs code from the encrypted module {}, which cannot be read ({} defined in no \
         readable module)",
        modules.join(", "),
        names.join(", ")
    );
    Some(CompileError { file: first.file, span: first.span, message })
}

/// Module data whose type is an opaque option type (`rapid_lib` `opaque`): one
/// refusal each, at the start of its module's file.
pub(crate) fn opaque_data(prog: &Program) -> Vec<CompileError> {
    prog.datas
        .iter()
        .filter_map(|data| {
            let DeclOrigin::Module { module, .. } = data.origin else { return None };
            let ty = prog.types.canonical(data.ty);
            if ty == ERROR || !matches!(prog.types.info(ty).kind, TypeKind::Error) {
                return None;
            }
            let type_name = &prog.types.info(ty).display;
            let option = ALL_OPTIONS.iter().find(|option| {
                option.entries.iter().any(|e| e.kind == EntryKind::Opaque && e.text.eq_ignore_ascii_case(type_name))
            })?;
            let file = prog.module_files.get(module).copied().unwrap_or(0);
            let message = format!(
                "`{}` is data of `{type_name}`, a type of option {} whose components are not public: \
                 `rapid run` cannot give it a value",
                data.display, option.name
            );
            Some(CompileError { file, span: Span::default(), message })
        })
        .collect()
}
