//! The disassembler: one instruction per line with its operands named (`Display` for
//! `Instr` and `KernelOp`), and a routine's listing with its slots, constants, call
//! sites, kernels and the source line each statement starts at (`rapid dump-ir`).
//! Generated from the instruction declarations (`crate::instrs`), so a new
//! instruction is listed without a line written here.
//!
//! Listing format (`list`):
//!
//! ```text
//! PROC main (file 0, 0 params, 2 locals)
//!   slot 0: x
//!   line 3
//!      0* const k=0  ; k: 1
//!      1* store_local slot=0  ; slot: x
//! ```
//!
//! A routine's head gives its kind, name, file (index among the task's files) and slot
//! counts, then the names of its parameters and data by slot. An instruction line is
//! its offset, `*` when the fast loop has an arm for it, the mnemonic, `name=value` for
//! each operand, and after `;` what operands point at (`name: what`): a constant's
//! value, a local's or global's name, a call's callee with how many arguments it
//! pushed, a kernel's operations. `line N` heads the first instruction of a statement
//! on source line N; `ERROR:`, `UNDO:` and `BACKWARD:` head the handlers.

use std::fmt::{self, Write};

use rapid_sema::types::TypeId;
use rapid_syntax::ast::{BinaryOp, UnaryOp};
use rapid_syntax::LineIndex;

use crate::instrs::{for_each_instr, for_each_kernel_op};
use crate::ir::{Callee, Code, Instr, KernelOp, KernelOperand, KernelTarget, Operand};
use crate::value::Value;

/// How an operand's value is written in a listing.
pub(crate) trait OperandText {
    fn text(&self, out: &mut String);
}

/// A value of each operand type, for tests that build every instruction.
#[cfg(test)]
pub(crate) trait Sample {
    fn sample() -> Self;
}

macro_rules! plain_operands {
    ($($ty:ty = $sample:expr),*) => {$(
        impl OperandText for $ty {
            fn text(&self, out: &mut String) {
                let _ = write!(out, "{self}");
            }
        }
        #[cfg(test)]
        impl Sample for $ty {
            fn sample() -> Self {
                $sample
            }
        }
    )*};
}

plain_operands!(u8 = 1, u16 = 1, u32 = 1, f32 = 1.5, bool = true);

impl OperandText for BinaryOp {
    fn text(&self, out: &mut String) {
        out.push_str(BinaryOp::text(*self));
    }
}

#[cfg(test)]
impl Sample for BinaryOp {
    fn sample() -> Self {
        BinaryOp::Add
    }
}

impl OperandText for UnaryOp {
    fn text(&self, out: &mut String) {
        out.push_str(match self {
            UnaryOp::Neg => "-",
            UnaryOp::Plus => "+",
            UnaryOp::Not => "NOT",
        });
    }
}

#[cfg(test)]
impl Sample for UnaryOp {
    fn sample() -> Self {
        UnaryOp::Neg
    }
}

impl OperandText for Operand {
    fn text(&self, out: &mut String) {
        let _ = match self {
            Operand::Stack => write!(out, "stack"),
            Operand::Local(slot) => write!(out, "local:{slot}"),
            Operand::Const(k) => write!(out, "const:{k}"),
        };
    }
}

#[cfg(test)]
impl Sample for Operand {
    fn sample() -> Self {
        Operand::Stack
    }
}

impl OperandText for KernelOperand {
    fn text(&self, out: &mut String) {
        let _ = match self {
            KernelOperand::Local(slot) => write!(out, "local:{slot}"),
            KernelOperand::Global(global) => write!(out, "global:{global}"),
            KernelOperand::Const(value) => write!(out, "{value}"),
        };
    }
}

#[cfg(test)]
impl Sample for KernelOperand {
    fn sample() -> Self {
        KernelOperand::Const(1.0)
    }
}

impl OperandText for TypeId {
    fn text(&self, out: &mut String) {
        let _ = write!(out, "{self:?}");
    }
}

#[cfg(test)]
impl Sample for TypeId {
    fn sample() -> Self {
        rapid_sema::types::ANY
    }
}

/// What an operand of kind `$kind` points at in `$cx`, pushed on `$notes` after
/// the operand's name.
macro_rules! note {
    ($kind:ident, $op:ident, $cx:expr, $notes:expr) => {
        if let Some(text) = note!(@text $kind, $op, $cx) {
            $notes.push(format!(concat!(stringify!($op), ": {}"), text));
        }
    };
    (@text Konst, $op:ident, $cx:expr) => { Some(const_text($cx.code.consts.get($op as usize))) };
    (@text Packed, $op:ident, $cx:expr) => { Some(const_text($cx.code.aggregates.value($op).as_ref())) };
    (@text Slot, $op:ident, $cx:expr) => { local_name($cx.code, $op).map(str::to_owned) };
    (@text Site, $op:ident, $cx:expr) => { Some(site_text($cx, $op)) };
    (@text KernelIdx, $op:ident, $cx:expr) => { Some(kernel_text($cx, $op)) };
    (@text RoutineIdx, $op:ident, $cx:expr) => { Some(routine_name($cx, $op)) };
    (@text Global, $op:ident, $cx:expr) => { $cx.globals.get($op as usize).cloned() };
    (@text Operand, $op:ident, $cx:expr) => {
        match $op {
            Operand::Stack => None,
            Operand::Local(slot) => local_name($cx.code, slot).map(str::to_owned),
            Operand::Const(k) => Some(const_text($cx.code.consts.get(k as usize))),
        }
    };
    (@text KernelOperand, $op:ident, $cx:expr) => {
        match $op {
            KernelOperand::Local(slot) => local_name($cx.code, slot).map(str::to_owned),
            KernelOperand::Global(global) => $cx.globals.get(global as usize).cloned(),
            KernelOperand::Const(_) => None,
        }
    };
    (@text $other:ident, $op:ident, $cx:expr) => { None::<String> };
}

/// What a listing needs beyond the instruction: the routine holding it and the
/// task's other routines (by the index calls name them with).
#[derive(Clone, Copy)]
pub struct Context<'a> {
    pub code: &'a Code,
    pub routines: &'a [Option<Code>],
    /// The task's data by global index (empty when not known).
    pub globals: &'a [String],
    /// The built-ins the task's call sites name by id.
    pub builtins: &'a crate::builtins::Builtins,
}

/// Expands a declaration into `Display` (the instruction alone) and `notes` (what its
/// operands point at in its routine).
macro_rules! impl_disas {
    (
        [$enum:ident]
        $(
            $(#[$doc:meta])*
            $name:ident
                $( ( $($tuple_op:ident : $tuple_ty:ident),* ) )?
                $( { $($field_op:ident : $field_ty:ident),* } )?
                => $mnemonic:literal, fast: $fast:literal;
        )*
    ) => {
        impl fmt::Display for $enum {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                let mut out = String::from(self.mnemonic());
                match self {
                    $(
                        $enum::$name $( ( $($tuple_op),* ) )? $( { $($field_op),* } )? => {
                            $($(
                                out.push_str(concat!(" ", stringify!($tuple_op), "="));
                                OperandText::text($tuple_op, &mut out);
                            )*)?
                            $($(
                                out.push_str(concat!(" ", stringify!($field_op), "="));
                                OperandText::text($field_op, &mut out);
                            )*)?
                        }
                    )*
                }
                f.write_str(&out)
            }
        }

        impl $enum {
            /// What the operands point at in `cx`, in operand order, each after the
            /// operand's name.
            #[allow(unused_variables)]
            pub(crate) fn notes(&self, cx: &Context<'_>) -> Vec<String> {
                let mut notes = Vec::new();
                match *self {
                    $(
                        $enum::$name $( ( $($tuple_op),* ) )? $( { $($field_op),* } )? => {
                            $($( note!($tuple_ty, $tuple_op, cx, notes); )*)?
                            $($( note!($field_ty, $field_op, cx, notes); )*)?
                        }
                    )*
                }
                notes
            }
        }
    };
}

for_each_instr!(impl_disas[Instr]);
for_each_kernel_op!(impl_disas[KernelOp]);

/// The listing of one routine. `source` is the text of the file it was compiled from,
/// when known: each statement is then headed by the line it starts at.
pub fn list(cx: &Context<'_>, source: Option<&str>) -> String {
    let code = cx.code;
    let mut out = String::new();
    let kind = match (code.is_trap, code.is_func) {
        (true, _) => "TRAP",
        (false, true) => "FUNC",
        (false, false) => "PROC",
    };
    let _ =
        writeln!(out, "{kind} {} (file {}, {} params, {} locals)", code.name, code.file, code.n_params, code.n_locals);
    let mut named: Vec<&(String, u32)> = code.local_names.iter().collect();
    named.sort_by_key(|(_, slot)| *slot);
    for (name, slot) in named {
        let _ = writeln!(out, "  slot {slot}: {name}");
    }
    let lines = source.map(LineIndex::new);
    let mut last_line = None;
    for (pc, instr) in code.instrs.iter().enumerate() {
        let pc = pc as u32;
        if let Some(handler) = handler_at(code, pc) {
            let _ = writeln!(out, "  {handler}:");
        }
        // The line of the innermost statement starting here, when it differs from
        // the line of the one before.
        let line = code.stmts.iter().rev().find(|s| s.start == pc).map(|s| s.span.start);
        if let (Some(lines), Some(start)) = (&lines, line) {
            let line = lines.line_of(start) + 1;
            if last_line != Some(line) {
                let _ = writeln!(out, "  line {line}");
                last_line = Some(line);
            }
        }
        let fast = if instr.fast_path() { '*' } else { ' ' };
        let _ = write!(out, "  {pc:4}{fast} {instr}");
        let notes = instr.notes(cx);
        if !notes.is_empty() {
            let _ = write!(out, "  ; {}", notes.join(", "));
        }
        out.push('\n');
    }
    out
}

/// The handler that starts at `pc`, if one does.
fn handler_at(code: &Code, pc: u32) -> Option<&'static str> {
    if code.error_handler.as_ref().is_some_and(|h| h.pc == pc) {
        return Some("ERROR");
    }
    if code.undo_handler == Some(pc) {
        return Some("UNDO");
    }
    if code.backward_handler == Some(pc) {
        return Some("BACKWARD");
    }
    None
}

fn const_text(value: Option<&Value>) -> String {
    match value {
        Some(Value::Num(n)) => crate::format::num_to_text(*n),
        Some(Value::Dnum(n)) => crate::format::dnum_to_text(*n),
        Some(Value::Bool(b)) => crate::format::bool_to_text(*b).to_owned(),
        Some(Value::Str(s)) => crate::format::string_to_literal(s),
        // A packed constant aggregate, written as its literal.
        Some(Value::Record(r)) => crate::format::aggregate_to_text(&parts_text(&r.fields)),
        Some(Value::Array(a)) => crate::format::aggregate_to_text(&parts_text(&a.elems)),
        Some(_) => "<aggregate>".to_owned(),
        None => "<missing>".to_owned(),
    }
}

fn parts_text(parts: &[Value]) -> Vec<String> {
    parts.iter().map(|part| const_text(Some(part))).collect()
}

fn local_name(code: &Code, slot: u32) -> Option<&str> {
    code.local_names.iter().find(|(_, s)| *s == slot).map(|(name, _)| name.as_str())
}

fn routine_name(cx: &Context<'_>, idx: u32) -> String {
    match cx.routines.get(idx as usize) {
        Some(Some(code)) => code.name.clone(),
        _ => format!("routine {idx}"),
    }
}

fn site_text(cx: &Context<'_>, site: u32) -> String {
    let Some(site) = cx.code.sites.get(site as usize) else { return "<missing>".to_owned() };
    let callee = match site.callee {
        Callee::Routine(idx) => routine_name(cx, idx),
        Callee::Builtin(id) => format!("builtin {}", cx.builtins.name(id)),
        Callee::Late => "late".to_owned(),
    };
    format!("{callee} ({} pushed)", site.n_pushed)
}

fn kernel_text(cx: &Context<'_>, kernel: u32) -> String {
    let Some(kernel) = cx.code.kernels.get(kernel as usize) else { return "<missing>".to_owned() };
    let op_text = |op: &KernelOp| match op.notes(cx).as_slice() {
        [] => op.to_string(),
        notes => format!("{op} ({})", notes.join(", ")),
    };
    let ops: Vec<String> = kernel.ops.iter().map(op_text).collect();
    let target = match kernel.target {
        None => String::new(),
        Some(KernelTarget::Local(slot)) => format!(" -> local:{slot}"),
        Some(KernelTarget::Global(global)) => match cx.globals.get(global as usize) {
            Some(name) => format!(" -> global:{global} ({name})"),
            None => format!(" -> global:{global}"),
        },
        Some(KernelTarget::Elem { global, slot }) => format!(" -> elem global={global} slot={slot}"),
    };
    format!("[{}]{target}", ops.join("; "))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_instruction_prints_its_mnemonic_and_named_operands() {
        let instr = Instr::BinOp { op: BinaryOp::Mod, lhs: Operand::Local(2), rhs: Operand::Const(0) };
        assert_eq!(instr.to_string(), "bin_op op=MOD lhs=local:2 rhs=const:0");
        assert_eq!(Instr::ForCheck { var: 3, exit: 9 }.to_string(), "for_check var=3 exit=9");
        assert_eq!(Instr::Return.to_string(), "return");
        assert_eq!(KernelOp::AddConst(2.5).to_string(), "add_const value=2.5");
    }

    /// Each instruction of a set has a mnemonic of its own, which starts its line.
    fn check_mnemonics<T: fmt::Display>(samples: &[T], mnemonic: impl Fn(&T) -> &'static str, all: &[&str]) {
        assert_eq!(samples.len(), all.len());
        for (instr, expected) in samples.iter().zip(all) {
            assert_eq!(mnemonic(instr), *expected);
            assert!(instr.to_string().starts_with(expected));
        }
        let mut sorted = all.to_vec();
        sorted.sort_unstable();
        sorted.dedup();
        assert_eq!(sorted.len(), all.len(), "two instructions share a mnemonic");
    }

    #[test]
    fn every_instruction_has_its_own_mnemonic() {
        check_mnemonics(&Instr::samples(), Instr::mnemonic, Instr::MNEMONICS);
        check_mnemonics(&KernelOp::samples(), KernelOp::mnemonic, KernelOp::MNEMONICS);
    }

    #[test]
    fn a_listing_names_the_routine_kind_handlers_callees_and_kernels() {
        let callee = Code { name: "helper".to_owned(), ..Code::default() };
        let mut code = Code { name: "f".to_owned(), is_func: true, n_params: 1, n_locals: 1, ..Code::default() };
        code.local_names.push(("n".to_owned(), 0));
        let site =
            crate::ir::CallSite { callee: Callee::Routine(0), args: Vec::new(), n_pushed: 0, late_args: Vec::new() };
        code.sites.push(site);
        code.kernels.push(crate::ir::Kernel { ops: vec![KernelOp::Local(0), KernelOp::AddConst(1.0)], target: None });
        code.emit(Instr::KernelReturn { kernel: 0 });
        code.emit(Instr::Call(0));
        code.emit(Instr::Pop);
        code.error_handler = Some(crate::ir::Handler { pc: 2, numbers: Vec::new() });
        let routines = [Some(callee)];
        let expected = "\
FUNC f (file 0, 1 params, 1 locals)
  slot 0: n
     0* kernel_return kernel=0  ; kernel: [local slot=0 (slot: n); add_const value=1]
     1* call site=0  ; site: helper (0 pushed)
  ERROR:
     2  pop
";
        assert_eq!(
            list(
                &Context {
                    code: &code,
                    routines: &routines,
                    globals: &[],
                    builtins: &crate::builtins::Builtins::core()
                },
                None
            ),
            expected
        );
    }

    #[test]
    fn globals_are_named_when_the_task_is_known() {
        let mut code = Code { name: "main".to_owned(), ..Code::default() };
        code.emit(Instr::LoadGlobal(1));
        code.emit(Instr::StoreGlobal(0));
        let globals = ["a".to_owned(), "b".to_owned()];
        let cx =
            Context { code: &code, routines: &[], globals: &globals, builtins: &crate::builtins::Builtins::core() };
        let expected = "\
PROC main (file 0, 0 params, 0 locals)
     0* load_global global=1  ; global: b
     1  store_global global=0  ; global: a
";
        assert_eq!(list(&cx, None), expected);
    }

    #[test]
    fn a_listing_heads_statements_with_their_line_and_names_what_operands_point_at() {
        let mut code = Code { name: "main".to_owned(), n_locals: 1, ..Code::default() };
        code.local_names.push(("x".to_owned(), 0));
        let k = code.constant(Value::Num(7.0));
        code.emit(Instr::Const(k));
        code.emit(Instr::StoreLocal(0));
        code.emit(Instr::Return);
        let span = |start| rapid_syntax::Span { start, end: start + 1 };
        code.stmts.push(crate::ir::StmtRange { start: 0, end: 2, span: span(4), depth: 0, calls: None });
        code.stmts.push(crate::ir::StmtRange { start: 2, end: 3, span: span(12), depth: 0, calls: None });
        let text = "one\nx := 7;\nRETURN;\n";
        let expected = "\
PROC main (file 0, 0 params, 1 locals)
  slot 0: x
  line 2
     0* const k=0  ; k: 7
     1* store_local slot=0  ; slot: x
  line 3
     2* return
";
        let routines = [];
        assert_eq!(
            list(
                &Context {
                    code: &code,
                    routines: &routines,
                    globals: &[],
                    builtins: &crate::builtins::Builtins::core()
                },
                Some(text)
            ),
            expected
        );
    }
}
