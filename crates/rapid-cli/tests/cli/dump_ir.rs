//! `rapid dump-ir PATH` prints the compiled form of every routine and runs nothing.
//!
//! The expected listing is worked out by hand from the compiler's rules
//! (`compile/stmt.rs`, `compile/expr.rs`, `compile/call.rs`, `compile/body.rs`):
//! - routine data without an initial value emits no code; `s` is slot 0;
//! - `s := "ab" + s` to a local: the value, then `store_local`. The value is a binary
//!   operator whose right operand is a local (read in place, `rhs=local:0`) and whose
//!   left is a string literal (not a leaf: pushed by `const`, `lhs=stack`);
//! - FOR pushes FROM and TO (no STEP), takes the loop variable's three slots (1, 2, 3),
//!   then `for_init`, `for_check` (its exit patched to the instruction after
//!   `for_next`), the body, and `for_next` back to `for_check`;
//! - `TPWrite s` pushes its one argument (an IN string) and calls the built-in;
//! - the body ends with `fell_off_end`.
//!
//! Constants are numbered in the order they are made: "ab", 1, 3. Every instruction
//! but `for_init` has a fast-loop arm (`*`), as declared in rapid-vm's `instrs.rs`.
//! Statements head their first instruction with their line: 4, 5 and 6. Since TPWrite
//! would print `ab` three times, a stdout that is the listing alone shows nothing ran.

use crate::fixture::{rapid_in, scratch_in, stderr, stdout, write_files};

const DEMO: &str = "\
MODULE Demo
  PROC main()
    VAR string s;
    s := \"ab\" + s;
    FOR i FROM 1 TO 3 DO
      TPWrite s;
    ENDFOR
  ENDPROC
ENDMODULE
";

const LISTING: &str = "\
PROC main (file 0, 0 params, 4 locals)
  slot 0: s
  line 4
     0* const k=0  ; k: \"ab\"
     1* bin_op op=+ lhs=stack rhs=local:0  ; rhs: s
     2* store_local slot=0  ; slot: s
  line 5
     3* const k=1  ; k: 1
     4* const k=2  ; k: 3
     5  for_init var=1 has_step=false
     6* for_check var=1 exit=10
  line 6
     7* load_local slot=0  ; slot: s
     8* call site=0  ; site: builtin TPWrite (1 pushed)
     9* for_next var=1 check=6
    10* fell_off_end
";

#[test]
fn dump_ir_lists_each_routine_without_running_it() {
    let dir = scratch_in("dump_ir", "lists");
    write_files(dir.path(), &[("demo.mod", DEMO)]);
    let out = rapid_in(dir.path(), &["dump-ir", "demo.mod"]);
    assert!(out.status.success(), "stderr: {}", stderr(&out));
    assert_eq!(stdout(&out), LISTING);
}

#[test]
fn dump_ir_of_a_program_with_errors_lists_nothing_and_fails() {
    let dir = scratch_in("dump_ir", "errors");
    write_files(dir.path(), &[("bad.mod", "MODULE Bad\n  PROC main()\n    nothing := 1;\n  ENDPROC\nENDMODULE\n")]);
    let out = rapid_in(dir.path(), &["dump-ir", "bad.mod"]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(stdout(&out), "");
    assert!(stderr(&out).contains("undefined data `nothing`"), "stderr: {}", stderr(&out));
}
