//! Hover: a built-in's declaration and doc line from the catalogue, a user
//! declaration as written (data with its initial value), a configured signal.

use lsp_types::{Hover, HoverContents, MarkupContent, MarkupKind, Position};

use super::{header, signature, Target, TaskIndex};
use crate::index::{fold, Kind};

pub(crate) fn hover(ti: &TaskIndex, file: usize, pos: Position) -> Option<Hover> {
    let offset = ti.offset(file, pos);
    let ident = ti.files[file].ident_at(offset)?;
    let range = ti.range(file, ident.span);
    if ident.after_backslash {
        return optional_argument(ti, file, ident).map(|value| markdown(value, range));
    }
    let text = match ti.resolve(file, ident)? {
        Target::User { file, decl } => user(ti, file, decl),
        Target::Signal(at) => {
            let signal = &ti.task.options.predefined[at];
            format!(
                "```rapid\n{} {}\n```\n\nI/O signal of the system's configuration (EIO.cfg).",
                signal.type_name, signal.name
            )
        }
        Target::BuiltinComponent { record, at } => {
            let (name, ty) = &record.components[at];
            format!("```rapid\n{ty} {name}\n```\n\n*Component of {} (built-in record).*", record.name)
        }
        Target::Builtin(builtin) => {
            format!("```rapid\n{}\n```\n\n{}\n\n*Built-in ({}).*", builtin.signature(), builtin.doc, builtin.chapter)
        }
    };
    Some(markdown(text, range))
}

fn markdown(value: String, range: lsp_types::Range) -> Hover {
    Hover { contents: HoverContents::Markup(MarkupContent { kind: MarkupKind::Markdown, value }), range: Some(range) }
}

/// `\Name` in a call: the optional parameter of the routine called.
fn optional_argument(ti: &TaskIndex, file: usize, ident: &crate::index::Ident) -> Option<String> {
    let index = &ti.files[file];
    let call = signature::call_at(index, ident.span.start)?;
    let name = index.tokens[call.name];
    let target = ti.lookup(file, name.span.start, &fold(name.span.text(ti.text(file))))?;
    let sig = signature::Signature::of(ti, target)?;
    let param = sig.params.iter().find(|p| p.optional && fold(&p.name) == ident.key)?;
    Some(format!("```rapid\n{}\n```\n\n*Optional parameter of {}.*", param.label, sig.name))
}

fn user(ti: &TaskIndex, file: usize, at: usize) -> String {
    let decl = ti.decl(file, at);
    let text = ti.text(file);
    let shown = match decl.kind {
        // A FOR loop variable by its loop's header.
        _ if decl.scope.is_some() => header(text, decl),
        // Data as declared, its initial value included.
        k if k.is_data() || k == Kind::Component || k == Kind::Alias => {
            let full = decl.span.text(text);
            let one_line: String = full.split_whitespace().collect::<Vec<_>>().join(" ");
            one_line.chars().take(400).collect()
        }
        _ => header(text, decl),
    };
    let module = ti.files[file]
        .decls
        .iter()
        .find(|d| d.kind == Kind::Module && d.module == decl.module)
        .map_or(String::new(), |m| m.name.clone());
    let place = match decl.routine {
        Some(routine) => format!("in {} of module {module}", ti.decl(file, routine).name),
        None if decl.kind == Kind::Module => "module".to_owned(),
        None => format!("module {module}"),
    };
    format!("```rapid\n{shown}\n```\n\n*{place}*")
}
