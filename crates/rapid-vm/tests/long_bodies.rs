//! Routine bodies compiled in the checker's stream, item by item as the parser hands them over:
//! a body past the pipeline threshold (1 MiB) is parsed on a second thread while it is
//! compiled, and must run exactly as a short one does — declarations, labels and GOTO,
//! an ERROR handler with RETRY, the handlers' order.

use rapid_sema::{Options, SourceInput};
use rapid_syntax::items::PIPELINE_THRESHOLD;
use rapid_vm::{compile, load, Exit, RecordingHost};

/// `main` with `count` increments of `n`, a division by zero handled by RETRY, a GOTO
/// over a line, and BACKWARD/ERROR/UNDO handlers.
fn program(count: usize) -> String {
    let mut text = String::from("MODULE t\nPROC main()\n  VAR num n := 0;\n  VAR num d := 0;\n");
    for _ in 0..count {
        text.push_str("  n := n + 1;\n");
    }
    text.push_str(concat!(
        "  TPWrite \"n \" \\Num:=n;\n",
        "  n := n / d;\n",
        "  TPWrite \"after \" \\Num:=n;\n",
        "  GOTO done;\n",
        "  TPWrite \"skipped\";\n",
        "  done:\n",
        "  TPWrite \"end\";\n",
        "BACKWARD\n",
        "  TPWrite \"backward\";\n",
        "ERROR (ERR_DIVZERO)\n",
        "  TPWrite \"handled\";\n",
        "  d := 2;\n",
        "  RETRY;\n",
        "UNDO\n",
        "  TPWrite \"undo\";\n",
        "ENDPROC\nENDMODULE\n",
    ));
    text
}

fn output(text: &str) -> Vec<String> {
    let mut vm = match load(&[SourceInput::from_text("t.mod", text)], "main") {
        Ok(loaded) => loaded.vm,
        Err(err) => panic!("load failed: {err:?}"),
    };
    let mut host = RecordingHost::default();
    assert_eq!(vm.run(&mut host, u64::MAX), Exit::Done);
    host.lines
}

#[test]
fn a_body_parsed_alongside_its_compilation_runs_as_written() {
    // 14 bytes a line: enough lines to pass the threshold.
    let count = PIPELINE_THRESHOLD as usize / 14 + 1000;
    let text = program(count);
    assert!(text.len() > PIPELINE_THRESHOLD as usize);
    // Worked by hand: n counts to `count`; n / 0 goes to the handler, which makes d 2 and
    // retries the division; GOTO skips one line; BACKWARD and UNDO never run forward.
    let expected = vec![format!("n {count}"), "handled".to_string(), format!("after {}", count / 2), "end".to_string()];
    assert_eq!(output(&text), expected);
}

#[test]
fn a_short_body_runs_the_same() {
    assert_eq!(output(&program(3)), vec!["n 3", "handled", "after 1.5", "end"]);
}

/// The code compiled while the checker goes through a body (each body parsed once, by
/// the checker, and compiled item by item with what the checker resolved in the item)
/// compiles every `n := n + 1` of `main` alike. (The compiler no longer compiles a
/// whole tree of its own to compare with: the stream is the only way code is made.)
#[test]
fn each_like_statement_of_a_streamed_body_compiles_alike() {
    streamed_statements_agree(5);
}

/// The same for a body the parser hands over in batches sharing one arena: what the
/// checker resolved in one item is not taken for another's, so every increment still
/// compiles to the same instructions.
#[test]
fn each_like_statement_of_a_long_batched_body_compiles_alike() {
    streamed_statements_agree(PIPELINE_THRESHOLD as usize / 14 + 1000);
}

/// Compiles `program(count)` in the stream and checks that its `count` increments
/// compile to one and the same instruction sequence.
fn streamed_statements_agree(count: usize) {
    let text = program(count);
    let files = [SourceInput::from_text("t.mod", &text)];
    let builtins = rapid_vm::builtins::Builtins::core();
    let mut sink = compile::StreamCompiler::new(&builtins, &files);
    let analysis = rapid_sema::analyze_with(&files, &Options::default(), Some(&mut sink as _));
    let streamed = sink.finish();
    // The program's one routine.
    assert_eq!(streamed.len(), 1);
    let prog = analysis.program.expect("the program checks");
    let outline = rapid_syntax::parse_outline(&text, &mut prog.interner.clone());
    let modules: Vec<compile::ModuleSource<'_>> =
        outline.file.modules.iter().map(|module| compile::ModuleSource { file: 0, text: &text, module }).collect();
    let code =
        compile::compile(&prog, &modules, &builtins, streamed).unwrap_or_else(|e| panic!("compile failed: {e:?}"));
    let main = code.routines.iter().flatten().next().expect("main is compiled");
    assert!(format!("{:?}", main.instrs).contains("FellOffEnd"));
    // The instructions of each statement, by what they do: a constant by its value,
    // a kernel without its number and length (each statement has its own).
    let mut alike: std::collections::HashMap<String, usize> = std::collections::HashMap::new();
    for stmt in &main.stmts {
        let instrs = &main.instrs[stmt.start as usize..stmt.end as usize];
        *alike.entry(shape(&format!("{instrs:?}"), &main.consts)).or_default() += 1;
    }
    let most = alike.iter().max_by_key(|(_, &n)| n).map(|(shape, &n)| (shape.clone(), n));
    let (shape, n) = most.expect("main has statements");
    assert_eq!(n, count, "the most common statement, {shape}");
    assert_eq!(shape, "[KernelStore, BinOp { op: Add, lhs: Local(0), rhs: Const(Num(1.0)) }, StoreLocal(0)]");
}

/// `instrs` (their debug text) with each `Const(i)` written as the constant's value and
/// kernels' numbers left out.
fn shape(instrs: &str, consts: &[rapid_vm::value::Value]) -> String {
    let mut out = String::new();
    let mut rest = instrs;
    loop {
        let constant = rest.find("Const(");
        let kernel = rest.find("KernelStore {");
        let at = match (constant, kernel) {
            (Some(c), Some(k)) => c.min(k),
            (Some(at), None) | (None, Some(at)) => at,
            (None, None) => break,
        };
        out.push_str(&rest[..at]);
        let tail = &rest[at..];
        if Some(at) == constant {
            let digits: String = tail["Const(".len()..].chars().take_while(char::is_ascii_digit).collect();
            match digits.parse::<usize>().ok().and_then(|i| consts.get(i)) {
                Some(value) => out.push_str(&format!("Const({value:?}")),
                None => out.push_str(&format!("Const({digits}")),
            }
            rest = &tail["Const(".len() + digits.len()..];
        } else {
            out.push_str("KernelStore");
            rest = tail.split_once('}').map_or("", |(_, after)| after);
        }
    }
    out.push_str(rest);
    out
}
