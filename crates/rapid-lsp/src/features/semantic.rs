//! Semantic tokens: every token of a file classified for colouring, names by what
//! they resolve to (a routine, a type, data, a parameter, a built-in), so a
//! misspelled name stays uncoloured.

use lsp_types::{SemanticToken, SemanticTokenModifier, SemanticTokenType, SemanticTokens, SemanticTokensLegend};
use rapid_lib::catalogue::EntryKind;
use rapid_syntax::token::TokenKind;
use rapid_syntax::Span;

use super::{Target, TaskIndex};
use crate::index::Kind;

/// The token types, in legend order.
const TYPES: &[SemanticTokenType] = &[
    SemanticTokenType::NAMESPACE,
    SemanticTokenType::TYPE,
    SemanticTokenType::STRUCT,
    SemanticTokenType::PARAMETER,
    SemanticTokenType::VARIABLE,
    SemanticTokenType::PROPERTY,
    SemanticTokenType::FUNCTION,
    SemanticTokenType::METHOD,
    SemanticTokenType::KEYWORD,
    SemanticTokenType::COMMENT,
    SemanticTokenType::STRING,
    SemanticTokenType::NUMBER,
    SemanticTokenType::EVENT,
];

const NAMESPACE: u32 = 0;
const TYPE: u32 = 1;
const STRUCT: u32 = 2;
const PARAMETER: u32 = 3;
const VARIABLE: u32 = 4;
const PROPERTY: u32 = 5;
const FUNCTION: u32 = 6;
const METHOD: u32 = 7;
const KEYWORD: u32 = 8;
const COMMENT: u32 = 9;
const STRING: u32 = 10;
const NUMBER: u32 = 11;
const EVENT: u32 = 12;

const DECLARATION: u32 = 1;
const READONLY: u32 = 2;
const DEFAULT_LIBRARY: u32 = 4;

pub(crate) fn legend() -> SemanticTokensLegend {
    SemanticTokensLegend {
        token_types: TYPES.to_vec(),
        token_modifiers: vec![
            SemanticTokenModifier::DECLARATION,
            SemanticTokenModifier::READONLY,
            SemanticTokenModifier::DEFAULT_LIBRARY,
        ],
    }
}

fn of_kind(kind: Kind) -> (u32, u32) {
    match kind {
        Kind::Module => (NAMESPACE, 0),
        Kind::Record => (STRUCT, 0),
        Kind::Alias => (TYPE, 0),
        Kind::Component => (PROPERTY, 0),
        Kind::Const => (VARIABLE, READONLY),
        Kind::Var | Kind::Pers | Kind::Local => (VARIABLE, 0),
        Kind::Param => (PARAMETER, 0),
        Kind::Proc => (METHOD, 0),
        Kind::Func => (FUNCTION, 0),
        Kind::Trap => (EVENT, 0),
    }
}

/// Every classified token of `file`, delta-encoded as the protocol wants.
pub(crate) fn tokens(ti: &TaskIndex, file: usize) -> SemanticTokens {
    let index = &ti.files[file];
    let mut found: Vec<(Span, u32, u32)> = Vec::with_capacity(index.tokens.len() + index.comments.len());
    let mut idents = index.idents.iter();
    for token in &index.tokens {
        let class = match token.kind {
            TokenKind::Num => Some((NUMBER, 0)),
            TokenKind::Str => Some((STRING, 0)),
            TokenKind::Ident => idents.next().and_then(|ident| {
                if ident.after_backslash {
                    return Some((PARAMETER, 0));
                }
                match ti.resolve(file, ident)? {
                    Target::User { file: f, decl } => {
                        let decl = ti.decl(f, decl);
                        let (ty, mods) = of_kind(decl.kind);
                        let declared = f == file && decl.name_span == ident.span;
                        Some((ty, mods | if declared { DECLARATION } else { 0 }))
                    }
                    Target::Signal(_) => Some((VARIABLE, 0)),
                    Target::BuiltinComponent { .. } => Some((PROPERTY, DEFAULT_LIBRARY)),
                    Target::Builtin(b) => Some(match b.kind {
                        EntryKind::Routine if b.is_func => (FUNCTION, DEFAULT_LIBRARY),
                        EntryKind::Routine => (METHOD, DEFAULT_LIBRARY),
                        EntryKind::Data => (VARIABLE, DEFAULT_LIBRARY | READONLY),
                        EntryKind::ReadOnlyData => (VARIABLE, DEFAULT_LIBRARY | READONLY),
                        _ => (TYPE, DEFAULT_LIBRARY),
                    }),
                }
            }),
            kind if kind.is_keyword() => Some((KEYWORD, 0)),
            _ => None,
        };
        if let Some((ty, mods)) = class {
            found.push((token.span, ty, mods));
        }
    }
    found.extend(index.comments.iter().map(|&c| (c, COMMENT, 0)));
    found.sort_by_key(|(span, ..)| span.start);
    encode(ti, file, &found)
}

fn encode(ti: &TaskIndex, file: usize, found: &[(Span, u32, u32)]) -> SemanticTokens {
    let mut data = Vec::with_capacity(found.len());
    let (mut line, mut col) = (0u32, 0u32);
    for &(span, ty, mods) in found {
        let range = ti.range(file, span);
        // Tokens never span lines in RAPID; a defensive single-line length anyway.
        let length = if range.end.line == range.start.line { range.end.character - range.start.character } else { 0 };
        if length == 0 {
            continue;
        }
        let delta_line = range.start.line - line;
        let delta_start = if delta_line == 0 { range.start.character - col } else { range.start.character };
        data.push(SemanticToken { delta_line, delta_start, length, token_type: ty, token_modifiers_bitset: mods });
        line = range.start.line;
        col = range.start.character;
    }
    SemanticTokens { result_id: None, data }
}
