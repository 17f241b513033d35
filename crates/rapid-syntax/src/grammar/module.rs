//! Files and modules: `%%%` headers, `MODULE name (attrs) ... ENDMODULE`, and the
//! module-level items (§1.1.3).

use super::ITEM_START;
use crate::ast::{Item, Module, ModuleAttr, SourceFile};
use crate::error::SyntaxErrorKind;
use crate::parser::{Parse, Parser};
use crate::span::Span;
use crate::token::{Placeholder, TokenKind as T, TokenSet};

const MODULE_ITEM_RECOVERY: TokenSet = ITEM_START.union(TokenSet::new(&[T::Endmodule, T::Module, T::Placeholder]));

impl Parser<'_, '_, '_> {
    pub(crate) fn source_file(mut self) -> Parse {
        let mut file = SourceFile::default();
        let mut reported_outside = false;
        loop {
            match self.nth(0) {
                T::Eof => break,
                T::Header => {
                    let span = self.bump().span;
                    file.header.get_or_insert(span);
                }
                T::Module => {
                    let module = self.module();
                    file.modules.push(module);
                    reported_outside = false;
                }
                _ => {
                    let span = self.current().span;
                    if !reported_outside {
                        let what = if file.modules.is_empty() { "before MODULE" } else { "after ENDMODULE" };
                        self.error(
                            SyntaxErrorKind::OutsideModule,
                            span,
                            format!("program text {what}: everything must be inside MODULE ... ENDMODULE"),
                        );
                        reported_outside = true;
                    }
                    self.bump();
                    self.recover_until(TokenSet::new(&[T::Module]));
                }
            }
        }
        if file.modules.is_empty() && self.error_count() == 0 {
            self.error(SyntaxErrorKind::OutsideModule, Span::default(), "the file holds no MODULE".into());
        }
        self.finish(file)
    }

    fn module(&mut self) -> Module {
        let start = self.bump().span;
        let name = self.name();
        let attrs = if self.at(T::LParen) { self.module_attributes() } else { Vec::new() };
        let mut items = Vec::new();
        loop {
            match self.nth(0) {
                T::Endmodule => {
                    self.bump();
                    break;
                }
                T::Eof | T::Module => {
                    self.error(SyntaxErrorKind::UnclosedBlock, start, "MODULE has no ENDMODULE".into());
                    break;
                }
                T::Placeholder => items.push(self.item_placeholder()),
                kind if ITEM_START.contains(kind) => {
                    if let Some(item) = self.item() {
                        items.push(item);
                    }
                }
                _ => {
                    self.error_expected("a declaration or ENDMODULE");
                    self.bump();
                    self.recover_until(MODULE_ITEM_RECOVERY);
                }
            }
        }
        let arena = std::mem::take(&mut self.arena);
        Module { name, attrs, items, arena, span: self.span_from(start.start) }
    }

    fn item_placeholder(&mut self) -> Item {
        let token = self.bump();
        match Placeholder::from_text(token.span.text(self.text)) {
            Some(ph @ (Placeholder::Tdn | Placeholder::Ddn | Placeholder::Rdn)) => Item::Placeholder(ph, token.span),
            _ => {
                self.error(
                    SyntaxErrorKind::UnexpectedToken,
                    token.span,
                    "only <TDN>, <DDN> or <RDN> may stand for a module item".into(),
                );
                Item::Placeholder(Placeholder::Ddn, token.span)
            }
        }
    }

    /// `LOCAL`/`TASK` prefixed or plain type, data and routine declarations.
    fn item(&mut self) -> Option<Item> {
        let start = self.current().span.start;
        let mut local = None;
        let mut task = None;
        if self.at(T::Local) {
            local = Some(self.bump().span);
        } else if self.at(T::Task) {
            task = Some(self.bump().span);
        }
        match self.nth(0) {
            T::Record | T::Alias => {
                if let Some(span) = task {
                    self.error(
                        SyntaxErrorKind::UnexpectedToken,
                        span,
                        "TASK applies only to PERS and VAR declarations".into(),
                    );
                }
                Some(Item::Type(self.type_def(start, local.is_some())))
            }
            T::Var | T::Pers | T::Const => Some(Item::Data(self.data_decl(start, local, task))),
            T::Proc | T::Func | T::Trap => {
                if let Some(span) = task {
                    self.error(
                        SyntaxErrorKind::UnexpectedToken,
                        span,
                        "TASK applies only to PERS and VAR declarations".into(),
                    );
                }
                Some(Item::Routine(self.routine(start, local.is_some())))
            }
            _ => {
                self.error_expected("a declaration after LOCAL or TASK");
                self.recover_until(MODULE_ITEM_RECOVERY);
                None
            }
        }
    }

    /// `( SYSMODULE, NOVIEW, ... )` with the manual's ordering rule.
    fn module_attributes(&mut self) -> Vec<(ModuleAttr, Span)> {
        self.bump();
        let mut attrs: Vec<(ModuleAttr, Span)> = Vec::new();
        loop {
            let token = self.current();
            let attr = match token.kind {
                T::Sysmodule => ModuleAttr::Sysmodule,
                T::Noview => ModuleAttr::Noview,
                T::Nostepin => ModuleAttr::Nostepin,
                T::Viewonly => ModuleAttr::Viewonly,
                T::Readonly => ModuleAttr::Readonly,
                _ => {
                    self.error_expected("a module attribute (SYSMODULE, NOVIEW, NOSTEPIN, VIEWONLY or READONLY)");
                    self.recover_until(TokenSet::new(&[T::RParen]).union(MODULE_ITEM_RECOVERY));
                    self.eat(T::RParen);
                    return attrs;
                }
            };
            self.bump();
            self.check_attribute(&attrs, attr, token.span);
            attrs.push((attr, token.span));
            if !self.eat(T::Comma) {
                break;
            }
        }
        self.expect(T::RParen);
        attrs
    }

    fn check_attribute(&mut self, before: &[(ModuleAttr, Span)], attr: ModuleAttr, span: Span) {
        let text = span.text(self.text).to_ascii_uppercase();
        if before.iter().any(|(a, _)| *a == attr) {
            self.error(
                SyntaxErrorKind::DuplicateModuleAttribute,
                span,
                format!("module attribute {text} is given twice"),
            );
        } else if before.iter().any(|(a, _)| *a > attr) {
            self.error(SyntaxErrorKind::ModuleAttributeOrder, span, format!("module attribute {text} is out of order: the order is SYSMODULE, NOVIEW, NOSTEPIN, VIEWONLY, READONLY"));
        } else if attr > ModuleAttr::Noview && before.iter().any(|(a, _)| *a == ModuleAttr::Noview) {
            self.error(
                SyntaxErrorKind::ModuleAttributeOrder,
                span,
                format!("NOVIEW may stand alone or with SYSMODULE only, not with {text}"),
            );
        }
    }
}
