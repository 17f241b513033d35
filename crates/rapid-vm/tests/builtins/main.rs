//! The pure built-in families in process, as tables of RAPID expression → value: each
//! row is compiled into a one-statement program (`r := EXPR;` for a module variable `r`
//! of the result's type), run on the VM, and `r` is read back. No binary, no files.
//!
//! Expected values are worked out by hand from the definitions and examples of ABB's
//! technical reference as gathered in `shared/reference/semantics.md` (§2.3 NumToStr,
//! §3.1 string functions, §3.2 arithmetic, math and bits), never taken from what the
//! interpreter printed. A table reports every row that differs, not just the first.
//!
//! One family: `cargo test -p rapid-vm --test builtins -- strings::`.

mod eval;

mod bits;
mod math;
mod strings;
