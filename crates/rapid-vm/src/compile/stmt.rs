//! Statements (§1.4, §1.5): assignment, calls, IF, FOR, WHILE, TEST, GOTO and labels,
//! RETURN, RAISE, RETRY, TRYNEXT, EXIT. Each statement's code range is recorded for
//! error recovery.

use rapid_syntax::ast::{Arena, ExprKind, Section, Stmt, StmtKind};

use super::call::CallOf;
use super::{CompileError, LocalKind, Resolved, RoutineCompiler};
use crate::ir::{CallSite, Callee, Instr, StmtRange};

impl RoutineCompiler<'_> {
    pub(crate) fn stmt_list(&mut self, arena: &Arena, stmts: &[Stmt], errors: &mut Vec<CompileError>) {
        for stmt in stmts {
            if let Err(e) = self.stmt(arena, stmt, errors) {
                errors.push(e);
            }
        }
    }

    fn stmt(&mut self, arena: &Arena, stmt: &Stmt, errors: &mut Vec<CompileError>) -> Result<(), CompileError> {
        let range_idx = self.st.code.stmts.len();
        let start = self.st.code.here();
        let calls = match &stmt.kind {
            StmtKind::Call { name, .. } => match self.callee(CallOf::Stmt(name.span.start)) {
                Some(Resolved::Routine(idx)) if self.prog.routines[idx as usize].chapter.is_none() => Some(idx),
                _ => None,
            },
            _ => None,
        };
        let depth = self.st.stmt_depth;
        self.st.code.stmts.push(StmtRange { start, end: start, span: stmt.span, depth, calls });
        self.st.stmt_depth += 1;
        let res = self.stmt_kind(arena, stmt, errors);
        self.st.stmt_depth -= 1;
        self.st.code.stmts[range_idx].end = self.st.code.here();
        res
    }

    fn stmt_kind(&mut self, arena: &Arena, stmt: &Stmt, errors: &mut Vec<CompileError>) -> Result<(), CompileError> {
        match &stmt.kind {
            StmtKind::Assign { target, value } => self.assign(arena, *target, *value)?,
            StmtKind::Call { name, args } => self.call(arena, *args, stmt.span, CallOf::Stmt(name.span.start))?,
            StmtKind::LateCall { callee, args } => {
                self.expr(arena, *callee, None)?;
                let site = CallSite { callee: Callee::Late, args: Vec::new(), n_pushed: 0, late_args: Vec::new() };
                let site = self.late_site(arena, *args, site)?;
                self.st.code.emit(Instr::LateCall(site));
            }
            StmtKind::If { cond, then, elifs, els } => {
                let mut to_end = Vec::new();
                let mut skip = self.condition(arena, *cond)?;
                self.stmt_list(arena, then, errors);
                for elif in elifs {
                    to_end.push(self.st.code.emit(Instr::Jump(0)));
                    let here = self.st.code.here();
                    self.patch_all(&skip, here);
                    skip = match elif.cond {
                        Some(cond) => self.condition(arena, cond)?,
                        None => {
                            self.st.code.emit(Instr::Placeholder);
                            vec![self.st.code.emit(Instr::JumpIfFalse(0))]
                        }
                    };
                    self.stmt_list(arena, &elif.body, errors);
                }
                if let Some(els) = els {
                    to_end.push(self.st.code.emit(Instr::Jump(0)));
                    let here = self.st.code.here();
                    self.patch_all(&skip, here);
                    self.stmt_list(arena, els, errors);
                } else {
                    let here = self.st.code.here();
                    self.patch_all(&skip, here);
                }
                let end = self.st.code.here();
                for at in to_end {
                    self.st.code.patch(at, end);
                }
            }
            StmtKind::CompactIf { cond, stmt: inner } => {
                let skip = self.condition(arena, *cond)?;
                self.stmt(arena, inner, errors)?;
                let here = self.st.code.here();
                self.patch_all(&skip, here);
            }
            StmtKind::For { from, to, step, body, .. } => {
                let num = self.prog.core.num;
                self.expr(arena, *from, None)?;
                self.expr(arena, *to, None)?;
                if let Some(step) = step {
                    self.expr(arena, *step, None)?;
                }
                let local = self.new_local(num, [0; 3], 0, LocalKind::LoopVar);
                self.new_local(num, [0; 3], 0, LocalKind::Temp);
                self.new_local(num, [0; 3], 0, LocalKind::Temp);
                self.st.code.emit(Instr::ForInit { var: local.slot, has_step: step.is_some() });
                let check = self.st.code.emit(Instr::ForCheck { var: local.slot, exit: 0 });
                self.st.own_data.push(local);
                self.st.loops.push(super::LoopJumps::default());
                self.stmt_list(arena, body, errors);
                let next = self.st.code.emit(Instr::ForNext { var: local.slot, check });
                let exit = self.st.code.here();
                self.st.code.patch(check, exit);
                self.end_loop(next, exit);
            }
            StmtKind::While { cond, body } => {
                let top = self.st.code.here();
                let exit = self.condition(arena, *cond)?;
                self.st.loops.push(super::LoopJumps::default());
                self.stmt_list(arena, body, errors);
                self.st.code.emit(Instr::Jump(top));
                let here = self.st.code.here();
                self.patch_all(&exit, here);
                self.end_loop(top, here);
            }
            StmtKind::Test { subject, cases, default } => {
                let subject_ty = self.static_type(arena, *subject);
                let ty = subject_ty.map_or(self.prog.core.num, |(t, _)| t);
                let tmp = self.new_local(ty, [0; 3], 0, LocalKind::Temp);
                self.expr(arena, *subject, None)?;
                self.st.code.emit(Instr::StoreLocal(tmp.slot));
                let mut to_end = Vec::new();
                for case in cases {
                    let mut to_body = Vec::new();
                    for &value in &case.values {
                        self.st.code.emit(Instr::LoadLocal(tmp.slot));
                        self.expr(arena, value, subject_ty)?;
                        self.st.code.emit(Instr::Binary(rapid_syntax::ast::BinaryOp::Ne));
                        to_body.push(self.st.code.emit(Instr::JumpIfFalse(0)));
                    }
                    let next_case = self.st.code.emit(Instr::Jump(0));
                    let body_start = self.st.code.here();
                    for at in to_body {
                        self.st.code.patch(at, body_start);
                    }
                    self.stmt_list(arena, &case.body, errors);
                    to_end.push(self.st.code.emit(Instr::Jump(0)));
                    let here = self.st.code.here();
                    self.st.code.patch(next_case, here);
                }
                if let Some(default) = default {
                    self.stmt_list(arena, default, errors);
                }
                let end = self.st.code.here();
                for at in to_end {
                    self.st.code.patch(at, end);
                }
            }
            StmtKind::Goto(label) => {
                let at = self.st.code.emit(Instr::Jump(0));
                self.st.gotos.push((at, label.sym, label.span));
            }
            StmtKind::Label(label) => {
                let here = self.st.code.here();
                self.st.labels.insert(label.sym, here);
            }
            // §1.13: a RETURN in the UNDO handler itself is ignored (its value is not
            // evaluated); one in a routine the handler calls returns (`exec/undo.rs`).
            StmtKind::Return(_) if self.st.section == Section::Undo => {
                self.st.code.emit(Instr::UndoReturn);
            }
            StmtKind::Return(value) => match value {
                Some(value) => {
                    self.kernel_return(arena, *value);
                    let ret = self.st.ret_ty;
                    self.expr(arena, *value, ret.map(|t| (t, [0; 3])))?;
                    self.st.code.emit(Instr::ReturnValue);
                }
                None => {
                    self.st.code.emit(Instr::Return);
                }
            },
            StmtKind::Raise(value) => match value {
                Some(value) => {
                    self.expr(arena, *value, None)?;
                    self.st.code.emit(Instr::Raise);
                }
                None => {
                    self.st.code.emit(Instr::ReRaise);
                }
            },
            StmtKind::Retry => {
                self.st.code.emit(Instr::Retry);
            }
            StmtKind::TryNext => {
                self.st.code.emit(Instr::TryNext);
            }
            StmtKind::Exit => {
                self.st.code.emit(Instr::Exit);
            }
            StmtKind::Connect { target, trap } => {
                let found = self.facts.and_then(|facts| facts.procedure(trap.span.start));
                let Some(super::Resolved::Routine(idx)) = found.and_then(|denotes| self.denoted(denotes)) else {
                    return Err(self.error(trap.span, "CONNECT needs a TRAP routine"));
                };
                self.place(arena, *target)?;
                self.st.code.emit(Instr::Connect(idx));
            }
            StmtKind::Placeholder(_) | StmtKind::Error => {
                self.st.code.emit(Instr::Placeholder);
            }
        }
        Ok(())
    }

    /// Code that evaluates condition `cond` and jumps when it is FALSE: a kernel
    /// (when the condition is plain num comparisons) followed by the general code.
    /// Returns the jumps whose target is the FALSE branch, to be patched together.
    fn condition(&mut self, arena: &Arena, cond: rapid_syntax::ast::ExprId) -> Result<Vec<u32>, CompileError> {
        let kernel = self.kernel_branch(arena, cond);
        self.expr(arena, cond, None)?;
        let jump = self.st.code.emit(Instr::JumpIfFalse(0));
        let here = self.st.code.here();
        Ok(match kernel {
            Some(kernel) => {
                self.st.code.patch_skip(kernel, here);
                vec![kernel, jump]
            }
            None => vec![jump],
        })
    }

    /// Points the innermost loop's Continue jumps at `next` (where the next iteration
    /// starts: FOR's step, WHILE's condition) and its Break jumps at `exit`.
    fn end_loop(&mut self, next: u32, exit: u32) {
        let Some(jumps) = self.st.loops.pop() else { return };
        self.patch_all(&jumps.continues, next);
        self.patch_all(&jumps.breaks, exit);
    }

    fn patch_all(&mut self, jumps: &[u32], target: u32) {
        for &at in jumps {
            self.st.code.patch(at, target);
        }
    }

    fn assign(
        &mut self,
        arena: &Arena,
        target: rapid_syntax::ast::ExprId,
        value: rapid_syntax::ast::ExprId,
    ) -> Result<(), CompileError> {
        let kernel = self.kernel_store(arena, target, value);
        self.assign_general(arena, target, value)?;
        if let Some(kernel) = kernel {
            let here = self.st.code.here();
            self.st.code.patch_skip(kernel, here);
        }
        Ok(())
    }

    fn assign_general(
        &mut self,
        arena: &Arena,
        target: rapid_syntax::ast::ExprId,
        value: rapid_syntax::ast::ExprId,
    ) -> Result<(), CompileError> {
        let expect = self.static_type(arena, target);
        match arena.expr(target).kind {
            ExprKind::Name(_) => match self.name(target) {
                Some(Resolved::Local(local)) => {
                    self.expr(arena, value, expect)?;
                    self.st.code.emit(Instr::StoreLocal(local.slot));
                    return Ok(());
                }
                Some(Resolved::Global(idx)) => {
                    self.expr(arena, value, expect)?;
                    self.st.code.emit(Instr::StoreGlobal(idx));
                    return Ok(());
                }
                _ => {}
            },
            ExprKind::Placeholder(_) => {
                self.st.code.emit(Instr::Placeholder);
                return Ok(());
            }
            ExprKind::Index { base, indices } => {
                if let Some((global, slot)) = self.elem_root(arena, base) {
                    let indices = arena.list(indices);
                    for &index in indices {
                        self.expr(arena, index, None)?;
                    }
                    self.expr(arena, value, expect)?;
                    self.st.code.emit(Instr::StoreElem { global, slot, n: indices.len() as u8 });
                    return Ok(());
                }
            }
            _ => {}
        }
        self.place(arena, target)?;
        self.expr(arena, value, expect)?;
        self.st.code.emit(Instr::StorePlace);
        Ok(())
    }
}
