//! Signature help: the routine call around the cursor (a function's parentheses, or a
//! procedure call statement, `MoveL p10, v100, …;`) and which parameter the argument
//! under the cursor fills. Optional arguments are written `\Name`; the others fill
//! the required parameters in order, alternatives (`A | B`) sharing one place.

use lsp_types::{
    Documentation, MarkupContent, MarkupKind, ParameterInformation, ParameterLabel, Position, SignatureHelp,
    SignatureInformation,
};
use rapid_syntax::token::TokenKind;

use super::{Target, TaskIndex};
use crate::builtins::Builtin;
use crate::index::{fold, FileIndex, Kind};

/// How far back a call's start is looked for.
const MAX_LOOKBACK: usize = 4000;

/// A call around the cursor.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Call {
    /// The routine's name token (index into `FileIndex::tokens`).
    pub(crate) name: usize,
    /// The first token of the arguments.
    pub(crate) args: usize,
}

/// One parameter as a signature shows it.
#[derive(Debug, Clone)]
pub(crate) struct SigParam {
    pub(crate) label: String,
    pub(crate) name: String,
    pub(crate) ty: String,
    pub(crate) optional: bool,
    pub(crate) switch: bool,
    pub(crate) group: u16,
}

/// A routine's signature, from the catalogue or from a user declaration.
#[derive(Debug, Clone)]
pub(crate) struct Signature {
    pub(crate) name: String,
    pub(crate) is_func: bool,
    pub(crate) params: Vec<SigParam>,
    pub(crate) doc: Option<String>,
}

impl Signature {
    pub(crate) fn of_builtin(b: &Builtin) -> Signature {
        let params = b
            .params
            .iter()
            .map(|p| SigParam {
                label: Builtin::param_label(p),
                name: p.name.clone(),
                ty: p.ty.clone(),
                optional: p.optional,
                switch: p.switch,
                group: p.group,
            })
            .collect();
        Signature { name: b.name.clone(), is_func: b.is_func, params, doc: Some(b.doc.to_owned()) }
    }

    pub(crate) fn of_user(ti: &TaskIndex, file: usize, routine: usize) -> Signature {
        let decl = ti.decl(file, routine);
        let text = ti.text(file);
        let params = ti.files[file]
            .decls
            .iter()
            .filter(|d| d.routine == Some(routine) && d.kind == Kind::Param)
            .enumerate()
            .map(|(at, d)| SigParam {
                label: d.span.text(text).split_whitespace().collect::<Vec<_>>().join(" "),
                name: d.name.clone(),
                ty: d.ty.clone().unwrap_or_default(),
                optional: d.optional,
                switch: d.ty.as_deref().is_some_and(|t| t.eq_ignore_ascii_case("switch")),
                group: at as u16,
            })
            .collect();
        Signature { name: decl.name.clone(), is_func: decl.kind == Kind::Func, params, doc: None }
    }

    /// The signature of the routine `target` denotes, if it is one.
    pub(crate) fn of(ti: &TaskIndex, target: Target<'_>) -> Option<Signature> {
        match target {
            Target::Builtin(b) if !b.params.is_empty() || b.kind == rapid_lib::catalogue::EntryKind::Routine => {
                Some(Signature::of_builtin(b))
            }
            Target::User { file, decl } if ti.decl(file, decl).kind.is_routine() => {
                Some(Signature::of_user(ti, file, decl))
            }
            _ => None,
        }
    }

    /// The first parameter of each required place, in order.
    fn required_places(&self) -> Vec<usize> {
        let mut places: Vec<usize> = Vec::new();
        for (at, p) in self.params.iter().enumerate() {
            let same_group = places.last().is_some_and(|&last| self.params[last].group == p.group);
            if !p.optional && !same_group {
                places.push(at);
            }
        }
        places
    }
}

/// The call whose arguments hold `offset`.
pub(crate) fn call_at(index: &FileIndex, offset: u32) -> Option<Call> {
    let tokens = &index.tokens;
    let end = tokens.partition_point(|t| t.span.end <= offset);
    // The first statement of a body follows the routine's header, not a `;`.
    let body = index.body_start(offset).map_or(0, |start| tokens.partition_point(|t| t.span.start < start));
    let first = end.saturating_sub(MAX_LOOKBACK).max(body);
    let mut depth = 0u32;
    for j in (first..end).rev() {
        if j == body && depth == 0 && body > 0 && statement_call(tokens, j, end) {
            return Some(Call { name: j, args: j + 1 });
        }
        match tokens[j].kind {
            TokenKind::RParen | TokenKind::RBracket | TokenKind::RBrace => depth += 1,
            TokenKind::LParen if depth == 0 && j > 0 && tokens[j - 1].kind == TokenKind::Ident => {
                return Some(Call { name: j - 1, args: j + 1 });
            }
            // A parenthesised expression: the call, if any, is further out.
            TokenKind::LParen if depth == 0 => {}
            TokenKind::LParen | TokenKind::LBracket | TokenKind::LBrace => depth = depth.saturating_sub(1),
            kind if depth == 0 && starts_statement_after(kind) => {
                let name = j + 1;
                return statement_call(tokens, name, end).then_some(Call { name, args: name + 1 });
            }
            _ => {}
        }
    }
    None
}

/// Whether the statement starting at token `name` is a procedure call whose
/// arguments reach the cursor (before token `end`): a name not followed by `:=`, `.`,
/// `{` or `:` (an assignment or a label).
fn statement_call(tokens: &[rapid_syntax::token::Token], name: usize, end: usize) -> bool {
    tokens.get(name).is_some_and(|t| t.kind == TokenKind::Ident)
        && tokens.get(name + 1).is_none_or(|t| {
            !matches!(t.kind, TokenKind::Assign | TokenKind::Dot | TokenKind::LBrace | TokenKind::Colon)
        })
        && name < end
}

/// Tokens after which a statement starts.
fn starts_statement_after(kind: TokenKind) -> bool {
    matches!(
        kind,
        TokenKind::Semi
            | TokenKind::Then
            | TokenKind::Else
            | TokenKind::Do
            | TokenKind::Error
            | TokenKind::Backward
            | TokenKind::Undo
            | TokenKind::Colon
    )
}

/// Which parameter the argument at `offset` fills: the index into `sig.params`.
pub(crate) fn active_param(index: &FileIndex, text: &str, call: &Call, offset: u32, sig: &Signature) -> Option<usize> {
    let tokens = &index.tokens;
    let mut depth = 0u32;
    let mut required_done = 0usize;
    let mut optional: Option<String> = None;
    let mut after_backslash = false;
    for token in tokens[call.args..].iter().take_while(|t| t.span.end <= offset) {
        match token.kind {
            TokenKind::LParen | TokenKind::LBracket | TokenKind::LBrace => depth += 1,
            TokenKind::RParen | TokenKind::RBracket | TokenKind::RBrace => depth = depth.saturating_sub(1),
            TokenKind::Comma if depth == 0 && optional.take().is_none() => required_done += 1,
            TokenKind::Backslash if depth == 0 => {
                // An optional argument ends the required one before it, if any.
                after_backslash = true;
                continue;
            }
            // A name typed in part may spell a reserved word so far (`\Not` of NotInSet).
            kind if after_backslash && (kind == TokenKind::Ident || kind.is_keyword()) => {
                optional = Some(fold(token.span.text(text)));
            }
            _ => {}
        }
        after_backslash = false;
    }
    if let Some(name) = optional {
        // The name may be typed only in part: the first optional parameter it begins.
        let exact = sig.params.iter().position(|p| fold(&p.name) == name);
        return exact.or_else(|| sig.params.iter().position(|p| p.optional && fold(&p.name).starts_with(&name)));
    }
    sig.required_places().get(required_done).copied()
}

pub(crate) fn help(ti: &TaskIndex, file: usize, pos: Position) -> Option<SignatureHelp> {
    let index = &ti.files[file];
    let offset = ti.offset(file, pos);
    let call = call_at(index, offset)?;
    let name = index.tokens[call.name];
    let key = fold(name.span.text(ti.text(file)));
    let sig = Signature::of(ti, ti.lookup(file, name.span.start, &key)?)?;
    let active = active_param(index, ti.text(file), &call, offset, &sig);
    Some(SignatureHelp {
        signatures: vec![information(&sig)],
        active_signature: Some(0),
        active_parameter: active.map(|a| a as u32),
    })
}

/// The signature as one label with each parameter's place in it (UTF-16 offsets).
fn information(sig: &Signature) -> SignatureInformation {
    let mut label = format!("{}{}(", if sig.is_func { "FUNC " } else { "PROC " }, sig.name);
    let mut parameters = Vec::new();
    for (at, p) in sig.params.iter().enumerate() {
        if at > 0 {
            let alternative = sig.params[at - 1].group == p.group;
            label.push_str(if alternative { " | " } else { ", " });
        }
        let start = label.encode_utf16().count() as u32;
        label.push_str(&p.label);
        let end = label.encode_utf16().count() as u32;
        parameters
            .push(ParameterInformation { label: ParameterLabel::LabelOffsets([start, end]), documentation: None });
    }
    label.push(')');
    SignatureInformation {
        label,
        documentation: sig
            .doc
            .clone()
            .map(|value| Documentation::MarkupContent(MarkupContent { kind: MarkupKind::Markdown, value })),
        parameters: Some(parameters),
        active_parameter: None,
    }
}
