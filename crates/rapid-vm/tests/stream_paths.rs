//! Every path that loads a program compiles its routines in the checker's stream
//! (`compile::StreamCompiler`), with what the checker resolved: none is compiled
//! afterwards from its text by the compiler's own rules.

use rapid_sema::{Options, SourceInput};
use rapid_vm::compile;

/// Routines `first` and `second` name signals nothing declares, under `--virtual-io`.
const VIRTUAL: &str = "MODULE t
PROC first(signaldo s)
  show doA;
  show doB;
ENDPROC
PROC second()
  show doB;
ENDPROC
PROC show(signaldo s)
  TPWrite ArgName(s);
ENDPROC
ENDMODULE
";

#[test]
fn virtual_signals_are_streamed_by_the_numbers_they_will_have() {
    let files = [SourceInput::from_text("t.mod", VIRTUAL)];
    let builtins = rapid_vm::builtins::Builtins::core();
    let mut sink = compile::StreamCompiler::new(&builtins, &files);
    let options = Options { virtual_signals: true, ..Options::default() };
    let analysis = rapid_sema::analyze_with(&files, &options, Some(&mut sink as _));
    let streamed = sink.finish();
    assert!(!rapid_sema::Program::has_errors(&analysis.diagnostics), "{:?}", analysis.diagnostics);
    // All three routines, the two naming virtual signals among them.
    assert_eq!(streamed.len(), 3);
    let prog = analysis.program.expect("the program checks");
    // doA and doB are declared when `first` ends, in the order it names them: the last
    // two globals.
    let names: Vec<&str> = prog.datas.iter().rev().take(2).map(|d| d.display.as_str()).collect();
    assert_eq!(names, ["doB", "doA"]);
    let listing = rapid_vm::compile_files(&files, &options, builtins.clone()).expect("compiles");
    let first = listing.compiled.routines.iter().flatten().find(|c| c.name == "first").expect("first");
    let do_a = prog.datas.len() as u32 - 2;
    let text = format!("{:?}", first.instrs);
    assert!(text.contains(&format!("PlaceGlobal({do_a})")) || text.contains(&format!("LoadGlobal({do_a})")), "{text}");
    let second = listing.compiled.routines.iter().flatten().find(|c| c.name == "second").expect("second");
    let text = format!("{:?}", second.instrs);
    assert!(text.contains(&format!("Global({})", do_a + 1)), "{text}");
}

/// Module data whose initial values name constants of the module.
const DATA: &str = "MODULE t
CONST num base := 2;
CONST num twice := base * 2;
VAR pos p := [base, twice, 0.5];
PROC main()
  TPWrite \"twice \" \\Num:=twice;
  TPWrite \"y \" \\Num:=p.y;
ENDPROC
ENDMODULE
";

#[test]
fn module_data_initial_values_are_compiled_in_the_stream() {
    let files = [SourceInput::from_text("t.mod", DATA)];
    let builtins = rapid_vm::builtins::Builtins::core();
    let mut sink = compile::StreamCompiler::new(&builtins, &files);
    let analysis = rapid_sema::analyze_with(&files, &Options::default(), Some(&mut sink as _));
    assert!(!rapid_sema::Program::has_errors(&analysis.diagnostics), "{:?}", analysis.diagnostics);
    let streamed = sink.finish();
    assert!(streamed.has_init());
    // Worked by hand: twice = 2 * 2 = 4; p.y = twice = 4.
    let loaded = rapid_vm::load(&files, "main").unwrap_or_else(|e| panic!("load failed: {e:?}"));
    let mut vm = loaded.vm;
    let mut host = rapid_vm::RecordingHost::default();
    assert_eq!(vm.run(&mut host, u64::MAX), rapid_vm::Exit::Done);
    assert_eq!(host.lines, ["twice 4", "y 4"]);
}

/// A global PERS declared in two modules of a task is one persistent, held by the
/// first declaration (`exec/modules.rs`, `pers_slot`): the second declaration's
/// initial value goes to its own slot, never to the first's.
#[test]
fn a_pers_declared_twice_keeps_the_first_declarations_value() {
    let a = "MODULE a\nPERS num shared := 5;\nPROC main()\n  TPWrite \"shared \" \\Num:=shared;\nENDPROC\nENDMODULE\n";
    let b = "MODULE b\nPERS num shared := 9;\nENDMODULE\n";
    let files = [SourceInput::from_text("a.mod", a), SourceInput::from_text("b.mod", b)];
    let loaded = rapid_vm::load(&files, "main").unwrap_or_else(|e| panic!("load failed: {e:?}"));
    let mut vm = loaded.vm;
    let mut host = rapid_vm::RecordingHost::default();
    assert_eq!(vm.run(&mut host, u64::MAX), rapid_vm::Exit::Done);
    assert_eq!(host.lines, ["shared 5"]);
}
