//! Routine bodies compiled from an outline, item by item as the parser hands them over:
//! a body past the pipeline threshold (1 MiB) is parsed on a second thread while it is
//! compiled, and must run exactly as a short one does — declarations, labels and GOTO,
//! an ERROR handler with RETRY, the handlers' order.

use rapid_sema::{analyze, Options, SourceInput};
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

/// The code compiled from an outline (each body parsed as it is compiled) is the code
/// compiled from the whole tree.
#[test]
fn outline_and_tree_compile_to_the_same_code() {
    let text = program(5);
    let files = [SourceInput::from_text("t.mod", &text)];
    let analysis = analyze(&files, &Options::default());
    let mut prog = analysis.program.expect("the program checks");
    let (_, catalogue) = rapid_sema::catalogue();
    let mut compiled = Vec::new();
    for outline in [false, true] {
        let parse = if outline {
            rapid_syntax::parse_outline(&text, &mut prog.interner)
        } else {
            rapid_syntax::parse(&text, &mut prog.interner)
        };
        let modules: Vec<compile::ModuleSource<'_>> =
            parse.file.modules.iter().map(|module| compile::ModuleSource { file: 0, text: &text, module }).collect();
        let mut interner = prog.interner.clone();
        let code = compile::compile(
            &prog,
            &modules,
            &rapid_vm::builtins::Builtins::core(),
            &catalogue.module,
            &catalogue.text,
            &mut interner,
            compile::Streamed::default(),
        )
        .unwrap_or_else(|e| panic!("compile failed: {e:?}"));
        compiled.push(format!("{:?}", code.routines));
    }
    assert!(compiled[0].contains("FellOffEnd"));
    assert_eq!(compiled[0], compiled[1]);
}

/// The code compiled while the checker goes through the bodies (each body parsed
/// once, by the checker) is the code compiled from the whole tree afterwards.
#[test]
fn streamed_and_tree_compile_to_the_same_code() {
    streamed_and_tree_agree(5);
}

/// The same for a body the parser hands over in batches sharing one arena: what the
/// checker resolved in one item is not taken for another's.
#[test]
fn a_long_streamed_body_compiles_to_the_code_of_its_tree() {
    streamed_and_tree_agree(PIPELINE_THRESHOLD as usize / 14 + 1000);
}

fn streamed_and_tree_agree(lines: usize) {
    let text = program(lines);
    let files = [SourceInput::from_text("t.mod", &text)];
    let builtins = rapid_vm::builtins::Builtins::core();
    let (_, catalogue) = rapid_sema::catalogue();
    let mut compiled = Vec::new();
    for streaming in [false, true] {
        let mut sink = compile::StreamCompiler::new(&builtins, &files);
        let analysis = rapid_sema::analyze_with(&files, &Options::default(), streaming.then_some(&mut sink as _));
        let streamed = sink.finish();
        // The program's one routine, or none when nothing was streamed.
        assert_eq!(streamed.len(), usize::from(streaming));
        let mut prog = analysis.program.expect("the program checks");
        let parse = rapid_syntax::parse(&text, &mut prog.interner);
        let modules: Vec<compile::ModuleSource<'_>> =
            parse.file.modules.iter().map(|module| compile::ModuleSource { file: 0, text: &text, module }).collect();
        let mut interner = prog.interner.clone();
        let code =
            compile::compile(&prog, &modules, &builtins, &catalogue.module, &catalogue.text, &mut interner, streamed)
                .unwrap_or_else(|e| panic!("compile failed: {e:?}"));
        compiled.push(format!("{:?}", code.routines));
    }
    assert!(compiled[0].contains("FellOffEnd"));
    assert_eq!(compiled[0], compiled[1]);
}
