//! A routine compiled item by item in source order: its declarations, statements and
//! handler keywords, as the checker hands them over while the parser works through the
//! routine's text (`rapid_syntax::for_each_body_item`, which parses a long body on a
//! second thread; `stream.rs`). No whole body's tree is held, which for a CAM program
//! is millions of moves.

use rapid_sema::types::TypeId;
use rapid_syntax::ast::{Arena, BodyItem, DataDecl, ExprId, Routine, RoutineKind, Section};

use super::{numeric_like, CompileError, RoutineCompiler};
use crate::ir::{Code, Handler, Instr};

impl RoutineCompiler<'_> {
    /// What the routine's head says: its name, kind and return type.
    /// `ret` is the return type the checker resolved.
    pub(super) fn header(&mut self, routine: &Routine, ret: Option<TypeId>) {
        self.st.code.name = routine.name.span.text(self.text).to_string();
        self.st.code.span = routine.span;
        self.st.code.is_func = routine.kind == RoutineKind::Func;
        self.st.code.is_trap = routine.kind == RoutineKind::Trap;
        self.st.ret_ty = ret.filter(|&ty| ty != rapid_sema::types::ERROR);
        self.st.code.ret_like = self.st.ret_ty.and_then(|ty| numeric_like(self.prog.types, ty, 0));
    }

    pub(super) fn body_item(&mut self, item: &BodyItem, arena: &Arena, errors: &mut Vec<CompileError>) {
        match item {
            BodyItem::Decl(decl) => self.decl(decl, arena, errors),
            BodyItem::Stmt(stmt) => self.stmt_list(arena, std::slice::from_ref(stmt), errors),
            BodyItem::Section { section, error_numbers, .. } => self.enter_section(*section, error_numbers, arena),
            BodyItem::End => {}
        }
    }

    fn decl(&mut self, decl: &DataDecl, arena: &Arena, errors: &mut Vec<CompileError>) {
        if let Err(e) = self.routine_data(decl, arena) {
            errors.push(e);
        }
    }

    /// Ends the part being compiled and starts handler `section` here.
    fn enter_section(&mut self, section: Section, error_numbers: &[ExprId], arena: &Arena) {
        self.close_section();
        let here = self.st.code.here();
        match section {
            Section::Error => {
                let numbers = error_numbers.iter().filter_map(|&n| self.handler_number(arena, n)).collect();
                self.st.code.error_handler = Some(Handler { pc: here, numbers });
            }
            Section::Undo => self.st.code.undo_handler = Some(here),
            // Backward execution is driven by a debugger, not by forward runs; the
            // handler is compiled so its errors show, and kept for that API.
            Section::Backward => self.st.code.backward_handler = Some(here),
            Section::Body => {}
        }
        self.st.section = section;
    }

    /// What ends the part being compiled when execution runs off it: the body and the
    /// ERROR handler fall off the routine's end, UNDO and BACKWARD return.
    fn close_section(&mut self) {
        match self.st.section {
            Section::Body | Section::Error => self.st.code.emit(Instr::FellOffEnd),
            Section::Undo | Section::Backward => self.st.code.emit(Instr::Return),
        };
    }

    pub(super) fn finish_routine(&mut self, mut errors: Vec<CompileError>) -> Result<Code, Vec<CompileError>> {
        self.close_section();
        self.resolve_gotos(&mut errors);
        self.finish_locals();
        self.st.code.shrink_to_fit();
        if errors.is_empty() {
            Ok(std::mem::take(&mut self.st.code))
        } else {
            Err(errors)
        }
    }
}
