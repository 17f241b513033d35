//! Programs that check but cannot run here, refused at load before anything runs:
//! a task that needs code only an encrypted module defines, and module data of a
//! software option's type whose components are not public (no value of it can be
//! made faithfully). Option instructions are refused where their calls are compiled
//! (`builtins::option_refusal`); `one_per_option` makes those one refusal per option.

use rapid_lib::catalogue::options::ALL_OPTIONS;
use rapid_lib::catalogue::EntryKind;
use rapid_sema::symbols::DeclOrigin;
use rapid_sema::types::{TypeKind, ERROR};
use rapid_sema::{Code, Diagnostic, Program, SourceInput};
use rapid_syntax::Span;

use crate::builtins::{OPTION_REFUSAL_MIDDLE, OPTION_REFUSAL_TAIL};
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

/// The compiler's refusals with those of option routines merged: one per option, at
/// its first call, naming each of its routines the program calls once, in order.
pub(crate) fn one_per_option(errors: Vec<CompileError>) -> Vec<CompileError> {
    let mut out: Vec<CompileError> = Vec::new();
    // (option, index into `out`, routine names)
    let mut options: Vec<(String, usize, Vec<String>)> = Vec::new();
    for error in errors {
        let Some((name, option)) = option_of_refusal(&error.message) else {
            out.push(error);
            continue;
        };
        match options.iter_mut().find(|(o, _, _)| *o == option) {
            Some((_, _, names)) if names.contains(&name) => {}
            Some((_, _, names)) => names.push(name),
            None => {
                options.push((option, out.len(), vec![name]));
                out.push(error);
            }
        }
    }
    for (option, at, names) in options {
        let verb = if names.len() == 1 { "belongs" } else { "belong" };
        out[at].message = format!("{} {verb} to option {option}{OPTION_REFUSAL_TAIL}", names.join(", "));
    }
    out
}

/// (`` `name` ``, option) of a message `builtins::option_refusal` wrote.
fn option_of_refusal(message: &str) -> Option<(String, String)> {
    let (name, rest) = message.strip_suffix(OPTION_REFUSAL_TAIL)?.split_once(' ')?;
    let option = rest.strip_prefix(OPTION_REFUSAL_MIDDLE)?;
    Some((name.to_owned(), option.to_owned()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn error(line: u32, message: &str) -> CompileError {
        CompileError { file: 0, span: Span { start: line, end: line }, message: message.to_owned() }
    }

    #[test]
    fn option_refusals_become_one_per_option_at_the_first_call() {
        let egm = |name: &str| crate::builtins::option_refusal(name, "options/egm").unwrap_or_default();
        let arc = crate::builtins::option_refusal("ArcL", "options/arc").unwrap_or_default();
        let other = "the built-in `X` is not supported by `rapid run` yet";
        let errors = vec![
            error(1, &egm("EGMReset")),
            error(2, other),
            error(3, &egm("EGMGetId")),
            error(4, &arc),
            error(5, &egm("EGMReset")),
        ];
        let merged: Vec<(u32, String)> =
            one_per_option(errors).into_iter().map(|e| (e.span.start, e.message)).collect();
        assert_eq!(
            merged,
            [
                (
                    1,
                    "`EGMReset`, `EGMGetId` belong to option Externally Guided Motion (EGM), which `rapid run` does \
                     not simulate"
                        .to_owned()
                ),
                (2, other.to_owned()),
                (4, "`ArcL` belongs to option Arc (RobotWare Arc), which `rapid run` does not simulate".to_owned()),
            ]
        );
    }
}
