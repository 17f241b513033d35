//! The record of written globals a controller reads to find what a task changed of
//! the persistents it shares: every way a statement writes a global is recorded
//! (the general code, the fast loop's kernels, through a reference), a write to a
//! local is not, and replacing all globals (PP to Main) counts as writing them all.

use std::collections::BTreeSet;

use rapid_sema::SourceInput;
use rapid_vm::exec::storage::GlobalWrites;
use rapid_vm::{load, Exit, Loaded, RecordingHost, Vm};

const PROGRAM: &str = "MODULE t
  VAR num k := 0;
  VAR num karr{3} := [0, 0, 0];
  VAR num m := 0;
  PERS num n := 0;
  PERS num parr{3} := [0, 0, 0];
  PERS pos p := [0, 0, 0];
  PERS num untouched := 0;
  PROC main()
    VAR num loc := 0;
    loc := loc + 1;
    n := 5;
    parr{2} := 7;
    p.x := 3;
    k := k + 1;
    karr{2} := loc * 2;
    bump m;
    loc := 2;
  ENDPROC
  PROC bump(VAR num x)
    x := x + 10;
  ENDPROC
ENDMODULE";

fn loaded(src: &str) -> Loaded {
    match load(&[SourceInput::from_text("t.mod", src)], "main") {
        Ok(loaded) => loaded,
        Err(err) => panic!("load failed: {err:?}"),
    }
}

fn vm(src: &str) -> Vm {
    loaded(src).vm
}

/// The names (of `names`) whose globals are recorded as written.
fn written(vm: &Vm, names: &[&'static str]) -> BTreeSet<&'static str> {
    let GlobalWrites::Only(list) = vm.global_writes() else { panic!("every global recorded") };
    names.iter().copied().filter(|name| vm.global_by_name(name).is_some_and(|(g, _)| list.contains(&g))).collect()
}

#[test]
fn each_statement_records_the_global_it_writes_and_no_other() {
    let names = ["k", "karr", "m", "n", "parr", "p", "untouched"];
    let mut machine = vm(PROGRAM);
    let mut host = RecordingHost::default();
    // Loading gave every global its value.
    assert_eq!(machine.global_writes(), GlobalWrites::All);
    machine.clear_global_writes();
    // One set of written names per statement, in order: `loc := loc + 1` (a kernel
    // store to a local) writes none, nor does the call of bump itself, nor the last
    // statement (a local again).
    let mut steps = Vec::new();
    loop {
        let exit = machine.run_statement(&mut host);
        steps.push(written(&machine, &names));
        machine.clear_global_writes();
        if exit != Exit::Budget {
            assert_eq!(exit, Exit::Done);
            break;
        }
        assert!(steps.len() < 50, "the program must end");
    }
    let nonempty: Vec<Vec<&str>> =
        steps.iter().filter(|s| !s.is_empty()).map(|s| s.iter().copied().collect()).collect();
    // n (general store), parr{2} (element of a global array), p.x (record field),
    // k (kernel store to a global num), karr{2} (kernel store to an element), m
    // (kernel store through bump's VAR parameter).
    assert_eq!(nonempty, vec![vec!["n"], vec!["parr"], vec!["p"], vec!["k"], vec!["karr"], vec!["m"]]);
    // The values are there: the record is of writes that happened.
    let value = |name: &str| machine.global_by_name(name).and_then(|(g, _)| machine.global(g)).cloned();
    assert_eq!(value("m"), Some(rapid_vm::value::Value::Num(10.0)));
    assert_eq!(value("k"), Some(rapid_vm::value::Value::Num(1.0)));
}

#[test]
fn a_write_stays_recorded_until_cleared_and_each_global_is_listed_once() {
    let mut machine = vm("MODULE t\n  VAR num k := 0;\n  PROC main()\n    FOR i FROM 1 TO 5 DO\n      \
                          k := k + 1;\n    ENDFOR\n  ENDPROC\nENDMODULE");
    let mut host = RecordingHost::default();
    machine.clear_global_writes();
    assert_eq!(machine.global_writes(), GlobalWrites::Only(&[]));
    assert_eq!(machine.run(&mut host, u64::MAX), Exit::Done);
    let Some((k, _)) = machine.global_by_name("k") else { panic!("k") };
    // Five writes of k, one entry (the record stays small however long a task runs).
    assert_eq!(machine.global_writes(), GlobalWrites::Only(&[k]));
    // Bringing in another task's value is no write of this task's.
    machine.clear_global_writes();
    machine.sync_global(k, rapid_vm::value::Value::Num(9.0));
    assert_eq!(machine.global_writes(), GlobalWrites::Only(&[]));
    assert_eq!(machine.global(k), Some(&rapid_vm::value::Value::Num(9.0)));
}

#[test]
fn pp_to_main_counts_as_writing_every_global() {
    let Loaded { vm: mut machine, entry, .. } = loaded(PROGRAM);
    let mut host = RecordingHost::default();
    machine.clear_global_writes();
    assert!(machine.pp_to_main(&mut host, entry).is_ok());
    assert_eq!(machine.global_writes(), GlobalWrites::All);
}
