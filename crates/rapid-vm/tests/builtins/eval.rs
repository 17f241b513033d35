//! The table tests' one helper: compile a RAPID expression into a program, run it, and
//! read its value back (or the name of the error that stopped it).

use rapid_sema::SourceInput;
use rapid_vm::value::Value;
use rapid_vm::{load, Exit, RecordingHost};

/// At most this many instructions per row: every row is one statement.
const BUDGET: u64 = 100_000;

/// What a row expects `EXPR` to give.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Expect {
    /// A num (or byte), equal within 1e-6 relative (num is a single-precision float).
    Num(f32),
    Str(&'static str),
    Bool(bool),
    /// The run stops with an unhandled error: (the expression's type, the error's name).
    Error(&'static str, &'static str),
}

/// The RAPID type a result of `expect` is stored in.
fn result_type(expect: Expect) -> &'static str {
    match expect {
        Expect::Num(_) => "num",
        Expect::Str(_) => "string",
        Expect::Bool(_) => "bool",
        Expect::Error(ty, _) => ty,
    }
}

/// Runs `r := EXPR;` with `r` a module variable of type `ty`: the value of `r`, or
/// `Err` with the name of the unhandled error or why the program did not run.
pub(crate) fn eval(ty: &str, expr: &str) -> Result<Value, String> {
    let src = format!("MODULE t\n  VAR {ty} r;\n  PROC main()\n    r := {expr};\n  ENDPROC\nENDMODULE\n");
    let loaded = load(&[SourceInput::from_text("t.mod", &src)], "main").map_err(|e| format!("not loaded: {e:?}"))?;
    let mut vm = loaded.vm;
    let mut host = RecordingHost::default();
    match vm.run(&mut host, BUDGET) {
        Exit::Done => {}
        Exit::Unhandled(u) => return Err(u.error.name.to_string()),
        other => return Err(format!("the run ended with {other:?}")),
    }
    let (global, _) = vm.global_by_name("r").ok_or("no variable r")?;
    vm.global(global).cloned().ok_or_else(|| "r has no value".to_owned())
}

/// Whether `got` is what `expect` says.
fn matches(expect: Expect, got: &Result<Value, String>) -> bool {
    match (expect, got) {
        (Expect::Num(want), Ok(Value::Num(n))) => (n - want).abs() <= 1e-6 * want.abs().max(1.0),
        (Expect::Str(want), Ok(Value::Str(s))) => &**s == want,
        (Expect::Bool(want), Ok(Value::Bool(b))) => *b == want,
        (Expect::Error(_, want), Err(name)) => name == want,
        _ => false,
    }
}

/// Evaluates every row of `table` and fails naming each row that differs.
pub(crate) fn check(table: &[(&str, Expect)]) {
    let wrong: Vec<String> = table
        .iter()
        .filter_map(|&(expr, expect)| {
            let got = eval(result_type(expect), expr);
            (!matches(expect, &got)).then(|| format!("{expr}: expected {expect:?}, got {got:?}"))
        })
        .collect();
    assert!(wrong.is_empty(), "{} of {} rows differ:\n{}", wrong.len(), table.len(), wrong.join("\n"));
}
