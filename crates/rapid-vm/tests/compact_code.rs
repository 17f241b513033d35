//! Compact compiled code (issue 23): aggregates of literals become one packed
//! constant each, built anew every time they run, and identical calls share one call
//! site. Both must run exactly as the instructions they replace.

use rapid_sema::{Options, SourceInput};
use rapid_vm::ir::{Code, Instr};
use rapid_vm::{compile_files, load, Exit, RecordingHost};

fn output(text: &str) -> Vec<String> {
    let mut vm = match load(&[SourceInput::from_text("t.mod", text)], "main") {
        Ok(loaded) => loaded.vm,
        Err(err) => panic!("load failed: {err:?}"),
    };
    let mut host = RecordingHost::default();
    assert_eq!(vm.run(&mut host, u64::MAX), Exit::Done);
    host.lines
}

/// The compiled `main` of `text`.
fn main_code(text: &str) -> Code {
    let task = match compile_files(
        &[SourceInput::from_text("t.mod", text)],
        &Options::default(),
        rapid_vm::builtins::Builtins::core(),
    ) {
        Ok(task) => task,
        Err(err) => panic!("compile failed: {err:?}"),
    };
    task.compiled.routines.into_iter().flatten().find(|code| code.name == "main").expect("main is compiled")
}

fn count(code: &Code, pred: impl Fn(&Instr) -> bool) -> usize {
    code.instrs.iter().filter(|instr| pred(instr)).count()
}

const AGGREGATES: &str = r#"MODULE t
  RECORD mixed
    num n;
    dnum d;
    bool b;
    string s;
  ENDRECORD
  VAR robtarget p;
  PROC main()
    VAR num a{2,3};
    VAR mixed m;
    VAR wobjdata w := [FALSE,TRUE,"rob",[[1,2,3],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
    FOR i FROM 1 TO 2 DO
      p := [[1,-2.5,3],[1,0,0,0],[-1,0,1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
      p.trans.x := p.trans.x + i;
      TPWrite "x " \Num:=p.trans.x;
    ENDFOR
    TPWrite "y " \Num:=p.trans.y;
    TPWrite "cf1 " \Num:=p.robconf.cf1;
    a := [[1,2,3],[4,-5,6]];
    TPWrite "a22 " \Num:=a{2,2};
    TPWrite "a13 " \Num:=a{1,3};
    m := [7,-2.25,TRUE,"txt"];
    TPWrite "d " \Dnum:=m.d;
    IF m.b TPWrite m.s;
    TPWrite "mec " + w.ufmec;
    FOR j FROM 1 TO 2 DO
      p := [[j,0,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    ENDFOR
    TPWrite "jx " \Num:=p.trans.x;
    TPWrite "q1 " \Num:=p.rot.q1;
  ENDPROC
ENDMODULE
"#;

#[test]
fn constant_aggregates_run_as_the_records_and_arrays_they_write() {
    // Worked by hand: each pass of the first loop assigns a fresh p (x 1), then adds
    // i; a{2,2} is -5 and a{1,3} 3 (rows in order); the record's components in
    // order; the last loop leaves p.trans.x at j = 2 and the constant orient's q1 1.
    let expected = ["x 2", "x 3", "y -2.5", "cf1 -1", "a22 -5", "a13 3", "d -2.25", "txt", "mec rob", "jx 2", "q1 1"];
    assert_eq!(output(AGGREGATES), expected);
}

#[test]
fn constant_aggregates_are_one_instruction_and_others_are_built() {
    let code = main_code(AGGREGATES);
    // Literal aggregates: w's initial value, the first robtarget, the array, the
    // record; in the last robtarget, `[j,0,0]` is built (j is data) but the three
    // other components are constants.
    assert_eq!(count(&code, |i| matches!(i, Instr::Aggregate(_))), 7);
    assert_eq!(code.aggregates.len(), 7);
    // Built at run time: the pos with j and the robtarget holding it.
    assert_eq!(count(&code, |i| matches!(i, Instr::MakeRecord(..))), 2);
    assert_eq!(count(&code, |i| matches!(i, Instr::MakeArray(_))), 0);
    // No negation is left to run: -2.5, -1, -5 and -2.25 are constants.
    assert_eq!(count(&code, |i| matches!(i, Instr::Unary(_))), 0);
}

#[test]
fn a_negated_data_value_is_still_computed() {
    let text = "MODULE t\nPROC main()\n  VAR num k := 4;\n  TPWrite \"k \" \\Num:=-k;\n  TPWrite \"c \" \\Num:=-(3);\nENDPROC\nENDMODULE\n";
    assert_eq!(output(text), ["k -4", "c -3"]);
    assert_eq!(count(&main_code(text), |i| matches!(i, Instr::Unary(_))), 1);
}

const CALLS: &str = r#"MODULE t
  VAR num a := 1;
  VAR num b := 2;
  PROC show(num x)
    TPWrite ArgName(x);
  ENDPROC
  PROC main()
    show a;
    show b;
    show a;
    TPWrite "one";
    TPWrite "two";
    TPWrite "three" \Num:=3;
  ENDPROC
ENDMODULE
"#;

#[test]
fn identical_calls_share_a_site_and_arg_name_still_names_each_argument() {
    // ArgName names the data each call passed: the shared site of the two `show a`
    // calls records a, the other one b.
    assert_eq!(output(CALLS), ["a", "b", "a", "one", "two", "three3"]);
    let code = main_code(CALLS);
    assert_eq!(count(&code, |i| matches!(i, Instr::Call(_))), 6);
    // show a (twice), show b, TPWrite with one argument (twice), TPWrite \Num.
    assert_eq!(code.sites.len(), 4);
}
