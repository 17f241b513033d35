//! The instruction sets, each declared once. `for_each_instr!` lists every
//! instruction of [`crate::ir::Instr`] and `for_each_kernel_op!` every operation of
//! [`crate::ir::KernelOp`]; each hands its list to a macro that expands it: into the
//! enum (`define_ops!`, here), into the disassembler (`crate::disas`) and into the
//! facts the executors are checked against (`Instr::fast_path`, tested in
//! `exec/fast.rs`). The shape follows pulley's `for_each_op!` (wasmtime).
//!
//! One line per instruction:
//!
//! ```text
//! /// Doc line.
//! Name(operand: Kind, …) | Name { operand: Kind, … } | Name  => "mnemonic", fast: bool;
//! ```
//!
//! Operands are named in both forms (a tuple variant's names are used by the
//! disassembler only). An operand's `Kind` is a single identifier: a plain type, or
//! one of the aliases below that say what a number designates, so the listing can
//! print what it points at (a constant's value, a call's callee, a local's name).
//! `fast` says whether `Vm::run_fast` has an arm for the instruction (it may still
//! hand some operands to `Vm::step`); every instruction without one goes to `step`.
//!
//! Why the kernel operations are a second instance of the same macro rather than
//! instructions of the one set: they run in a different machine (f32 registers, no
//! value stack, no errors: a kernel that cannot run gives way to the statement's
//! general code), they are held per kernel, not per routine, and `exec/kernel.rs` is
//! their only executor. Sharing the declaration's shape still gives them the same
//! enum expansion and disassembler.

/// A local slot of the running frame (parameters first).
pub type Slot = u32;
/// A module-level data object (global) of the task.
pub type Global = u32;
/// An entry of the routine's constant pool.
pub type Konst = u32;
/// An instruction offset in the same routine.
pub type Target = u32;
/// An entry of the routine's packed constant aggregates (`crate::packed`).
pub type Packed = u32;
/// An entry of the routine's call-site table.
pub type Site = u32;
/// An entry of the routine's kernel table.
pub type KernelIdx = u32;
/// A routine of the task (the index compiled routines are held by).
pub type RoutineIdx = u32;
/// A component of a record (0-based).
pub type FieldIdx = u16;
/// How many values an instruction pops or gathers.
pub type Count = u32;

/// Calls `$macro` with every instruction of `Instr`, after the tokens in brackets.
macro_rules! for_each_instr {
    ($macro:ident [$($extra:tt)*]) => {
        $macro! {
            [$($extra)*]
            /// Push constant `k` of the pool.
            Const(k: Konst) => "const", fast: true;
            /// Push packed constant aggregate `k`, built anew (a record or an array
            /// whose leaves are all literals, `crate::packed`).
            Aggregate(k: Packed) => "aggregate", fast: false;
            /// Push the value of local `slot` (through it when it holds a reference).
            LoadLocal(slot: Slot) => "load_local", fast: true;
            /// Pop a value into local `slot` (through it when it holds a reference).
            StoreLocal(slot: Slot) => "store_local", fast: true;
            /// Push the value of global `global`.
            LoadGlobal(global: Global) => "load_global", fast: true;
            /// Pop a value into global `global`.
            StoreGlobal(global: Global) => "store_global", fast: false;
            /// Push the place of local `slot` (the referenced place for a reference).
            PlaceLocal(slot: Slot) => "place_local", fast: true;
            /// Push the place of global `global`.
            PlaceGlobal(global: Global) => "place_global", fast: true;
            /// Replace the place on top with its component `field`.
            PlaceField(field: FieldIdx) => "place_field", fast: false;
            /// Pop `n` indices and a place; push the element's place (bounds checked).
            PlaceIndex(n: u8) => "place_index", fast: false;
            /// Pop a place, push its value.
            LoadPlace => "load_place", fast: false;
            /// Pop a value and a place; store the value there.
            StorePlace => "store_place", fast: false;
            /// Pop `n` indices; push that element of the array in local `slot` (through
            /// a reference) or global `slot`.
            LoadElem { global: bool, slot: Slot, n: u8 } => "load_elem", fast: true;
            /// Pop a value and `n` indices; store the value in that element.
            StoreElem { global: bool, slot: Slot, n: u8 } => "store_elem", fast: true;
            /// Pop a record, push its component `field`.
            Field(field: FieldIdx) => "field", fast: true;
            /// Pop `n` indices and an array, push the element.
            Index(n: u8) => "index", fast: false;
            /// Pop a value, push `op value`.
            Unary(op: UnaryOp) => "unary", fast: false;
            /// Pop two values, push `lhs op rhs`.
            Binary(op: BinaryOp) => "binary", fast: true;
            /// A binary operator whose operands may come straight from a local slot or the
            /// constant pool instead of the stack (the right one popped first).
            BinOp { op: BinaryOp, lhs: Operand, rhs: Operand } => "bin_op", fast: true;
            /// Pop `n` values, push a record of type `ty`.
            MakeRecord(ty: TypeId, n: u16) => "make_record", fast: true;
            /// Pop `n` values (elements or rows), push an array.
            MakeArray(n: Count) => "make_array", fast: false;
            /// Continue at `target`.
            Jump(target: Target) => "jump", fast: true;
            /// Pop a bool; jump to `target` when it is FALSE.
            JumpIfFalse(target: Target) => "jump_if_false", fast: true;
            /// Pop a value and drop it.
            Pop => "pop", fast: false;
            /// Call the routine or built-in described by call site `site`.
            Call(site: Site) => "call", fast: true;
            /// Pop a string naming a procedure; call it with call site `site`'s arguments.
            LateCall(site: Site) => "late_call", fast: false;
            /// A call of a function defined nowhere in the task: raise ERR_REFUNKFUN
            /// (constant `name` names it). The controller links late, so only executing
            /// it fails.
            UnknownFunc(name: Konst) => "unknown_func", fast: false;
            /// End a PROC or TRAP.
            Return => "return", fast: true;
            /// Pop the value a FUNC returns.
            ReturnValue => "return_value", fast: true;
            /// Pop an error number and raise it.
            Raise => "raise", fast: false;
            /// Raise the current error again in the caller (bare RAISE in an ERROR handler).
            ReRaise => "re_raise", fast: false;
            /// RETRY: run the statement that failed again.
            Retry => "retry", fast: false;
            /// TRYNEXT: go on after the statement that failed.
            TryNext => "try_next", fast: false;
            /// EXIT: end the program.
            Exit => "exit", fast: false;
            /// A RETURN written in an UNDO handler: ignored, with an event-log warning
            /// (manual §1.13; `exec/undo.rs`).
            UndoReturn => "undo_return", fast: false;
            /// FOR: pop FROM, TO and STEP (or none for the default) into slots var,
            /// var+1, var+2.
            ForInit { var: Slot, has_step: bool } => "for_init", fast: false;
            /// FOR: jump to `exit` when the loop variable has passed TO.
            ForCheck { var: Slot, exit: Target } => "for_check", fast: true;
            /// FOR: add STEP to the variable and jump back to `check`.
            ForNext { var: Slot, check: Target } => "for_next", fast: true;
            /// Push whether optional parameter `slot` was passed.
            Present(slot: Slot) => "present", fast: false;
            /// Executing a placeholder raises ERR_EXECPHR.
            Placeholder => "placeholder", fast: false;
            /// Pop a number and a name; push the name followed by the number (CallByVar).
            NameWithNumber => "name_with_number", fast: false;
            /// Push the controller's time in seconds (a dnum).
            PushTime => "push_time", fast: false;
            /// Pop a number of seconds and wait that long (the run hands control back).
            WaitPop => "wait_pop", fast: false;
            /// Raise the predefined error WaitUntil's timeout raises (ERR_WAIT_MAXTIME).
            RaiseWaitTimeout => "raise_wait_timeout", fast: false;
            /// CONNECT: pop the intnum's place; give it a new interrupt whose trap is
            /// routine `trap` (ERR_ALRDYCNT when it is connected already).
            Connect(trap: RoutineIdx) => "connect", fast: false;
            /// Pop signal data, push the signal's value; data no AliasIO connected raises
            /// ERR_NO_ALIASIO_DEF (manual §1.9). Constant `name` names the data (for the
            /// message).
            ReadSignal(name: Konst) => "read_signal", fast: false;
            /// The routine ran off its end without RETURN (in a FUNC: ERR_FNCNORET).
            FellOffEnd => "fell_off_end", fast: true;
            /// Evaluate kernel `kernel` and store its result at its target, then continue
            /// at `skip`. When the kernel cannot run (an operand is not a plain num, or an
            /// error would arise) nothing happens and execution continues with the next
            /// instruction: the statement's general code, which follows and does it all
            /// again (a kernel only reads, so starting over is safe).
            KernelStore { kernel: KernelIdx, skip: Target } => "kernel_store", fast: true;
            /// `RETURN` of a num: evaluate kernel `kernel` and return its result from the
            /// FUNC; when the kernel or the plain return cannot run, the next instruction
            /// (the statement's general code).
            KernelReturn { kernel: KernelIdx } => "kernel_return", fast: true;
            /// Evaluate condition kernel `kernel`: FALSE jumps to `on_false`, TRUE
            /// continues at `skip`; when it cannot run, the next instruction (the
            /// condition's general code).
            KernelBranch { kernel: KernelIdx, on_false: Target, skip: Target } => "kernel_branch", fast: true;
        }
    };
}

/// Calls `$macro` with every operation of `KernelOp`, after the tokens in brackets.
/// `fast` is true throughout: `exec/kernel.rs` is the kernels' only executor.
macro_rules! for_each_kernel_op {
    ($macro:ident [$($extra:tt)*]) => {
        $macro! {
            [$($extra)*]
            /// A num in local `slot` (through a reference to a whole num).
            Local(slot: Slot) => "local", fast: true;
            /// A num in global `global`.
            Global(global: Global) => "global", fast: true;
            /// The num `value`.
            Const(value: f32) => "const", fast: true;
            /// Pop an index; push that element of the one-dimensional num array in local
            /// or global `slot`.
            Elem { global: bool, slot: Slot } => "elem", fast: true;
            /// Push element `index + offset` of the one-dimensional num array in local or
            /// global `slot`, the index read from local slot `index`: `Local(index)`,
            /// `AddConst(offset)` (when not 0) and `Elem` fused at compile time, the
            /// commonest element reads (`a{j}`, `a{j + 1}`) in one dispatch instead of
            /// two or three.
            ElemAt { global: bool, slot: Slot, index: Slot, offset: f32 } => "elem_at", fast: true;
            /// Arithmetic and comparisons on nums; AND, OR, XOR on bools (1 or 0).
            Binary(op: BinaryOp) => "binary", fast: true;
            /// `Binary` whose right operand is read in place instead of pushed: the top
            /// becomes `top op rhs` (a push followed by `Binary`, fused at compile time
            /// to halve the dispatches of typical expressions such as `acc * 7 + j`).
            BinaryWith(op: BinaryOp, rhs: KernelOperand) => "binary_with", fast: true;
            /// `BinaryWith` for the commonest operator and operand pairs, specialised at
            /// compile time so that the executor dispatches once, not three times
            /// (operation, operand kind, operator). Same results as `BinaryWith`:
            /// `top + value`.
            AddConst(value: f32) => "add_const", fast: true;
            /// `top - value`.
            SubConst(value: f32) => "sub_const", fast: true;
            /// `top * value`.
            MulConst(value: f32) => "mul_const", fast: true;
            /// `top MOD value`.
            ModConst(value: f32) => "mod_const", fast: true;
            /// `top + local slot`.
            AddLocal(slot: Slot) => "add_local", fast: true;
            /// `top < value`.
            LtConst(value: f32) => "lt_const", fast: true;
            /// `top > value`.
            GtConst(value: f32) => "gt_const", fast: true;
            /// `-top`.
            Neg => "neg", fast: true;
            /// `NOT top`.
            Not => "not", fast: true;
        }
    };
}

/// Expands a declaration into its enum, with the mnemonic and fast-path facts.
/// The bracket holds the enum's attributes, visibility and name.
macro_rules! define_ops {
    (
        [$(#[$enum_attr:meta])* $vis:vis enum $enum:ident]
        $(
            $(#[$doc:meta])*
            $name:ident
                $( ( $($tuple_op:ident : $tuple_ty:ident),* ) )?
                $( { $($field_op:ident : $field_ty:ident),* } )?
                => $mnemonic:literal, fast: $fast:literal;
        )*
    ) => {
        $(#[$enum_attr])*
        $vis enum $enum {
            $(
                $(#[$doc])*
                $name $( ( $($tuple_ty),* ) )? $( { $($field_op: $field_ty),* } )?,
            )*
        }

        impl $enum {
            /// Every mnemonic, in declaration order.
            pub const MNEMONICS: &'static [&'static str] = &[$($mnemonic),*];

            /// The instruction's name in listings.
            pub fn mnemonic(&self) -> &'static str {
                match self {
                    $( $enum::$name { .. } => $mnemonic, )*
                }
            }

            /// Whether the fast loop has an arm for it (the others always go to the
            /// general executor).
            pub fn fast_path(&self) -> bool {
                match self {
                    $( $enum::$name { .. } => $fast, )*
                }
            }

            /// One instance of every instruction, in declaration order, operands set to
            /// sample values (for tests that go over the whole set).
            #[cfg(test)]
            pub(crate) fn samples() -> Vec<$enum> {
                use $crate::disas::Sample;
                vec![$(
                    $enum::$name
                        $( ( $(<$tuple_ty as Sample>::sample()),* ) )?
                        $( { $($field_op: <$field_ty as Sample>::sample()),* } )?
                ),*]
            }
        }
    };
}

pub(crate) use {define_ops, for_each_instr, for_each_kernel_op};
