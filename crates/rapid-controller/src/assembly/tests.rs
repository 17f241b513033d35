//! In-process tests of the one assembly path: PATHs on disk (written by each test in a
//! scratch folder) become a booted controller, or say why they cannot.

use std::fs;
use std::path::PathBuf;

use super::{assemble, AssemblyError, LoadOptions};
use crate::boot::system::BootError;
use crate::{SystemExit, TaskEnd};

/// A fresh scratch folder for test `name`, holding `files` (path, text).
fn scratch(name: &str, files: &[(&str, &str)]) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rapid-assembly-{name}-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    for (path, text) in files {
        let path = dir.join(path);
        fs::create_dir_all(path.parent().expect("a folder")).expect("create the folder");
        fs::write(path, text).expect("write a test file");
    }
    dir
}

const COUNT: &str =
    "MODULE M\n  VAR num n := 41;\n  PROC main()\n    n := n + 1;\n    TPWrite \"n is \" \\Num:=n;\n  ENDPROC\nENDMODULE\n";

#[test]
fn a_module_is_a_system_of_one_task_run_alone() {
    let dir = scratch("alone", &[("m.mod", COUNT)]);
    let assembly = assemble(&[dir.join("m.mod")], &LoadOptions::default());
    let assembled = assembly.outcome.expect("the module assembles");
    assert!(assembled.alone);
    assert_eq!(assembled.controller.tasks.len(), 1);
    assert_eq!(assembled.controller.tasks[0].spec.name, "T_ROB1");
    assert_eq!(assembled.inputs[0].modules.len(), 1);
    let _ = fs::remove_dir_all(dir);
}

#[test]
fn an_operated_module_is_never_alone_and_runs_to_its_end() {
    let dir = scratch("operated", &[("m.mod", COUNT)]);
    let options = LoadOptions { operated: true, ..LoadOptions::default() };
    let mut assembled = assemble(&[dir.join("m.mod")], &options).outcome.expect("assembles");
    assert!(!assembled.alone);
    let mut host = rapid_vm::RecordingHost::default();
    assembled.controller.power_on(&mut host).expect("powers on");
    assert_eq!(assembled.controller.run(&mut host, 10_000), SystemExit::Ended, "the program ends by itself");
    assert!(matches!(assembled.controller.tasks[0].end(), Some(TaskEnd::Done)));
    assert_eq!(host.lines, ["n is 42"]);
    let _ = fs::remove_dir_all(dir);
}

#[test]
fn a_manifest_of_two_tasks_assembles_both_in_order() {
    let manifest = "[[task]]\nname = \"T_ROB1\"\nmodules = [\"a.mod\"]\n\n\
                    [[task]]\nname = \"T_B\"\ntype = \"NORMAL\"\nmotion = false\nmodules = [\"b.mod\"]\n";
    let dir = scratch("manifest", &[("rapid.toml", manifest), ("a.mod", COUNT), ("b.mod", COUNT)]);
    let assembled = assemble(std::slice::from_ref(&dir), &LoadOptions::default()).outcome.expect("assembles");
    let names: Vec<&str> = assembled.controller.tasks.iter().map(|t| t.spec.name.as_str()).collect();
    assert_eq!(names, ["T_ROB1", "T_B"]);
    assert!(!assembled.alone);
    assert!(assembled.inputs[1].modules[0].path.ends_with("b.mod"));
    let _ = fs::remove_dir_all(dir);
}

#[test]
fn why_a_system_cannot_start_is_handed_back() {
    let dir = scratch("refused", &[("p.pgf", "<Program><Module>gone.mod</Module></Program>"), ("m.mod", COUNT)]);
    // A PATH that is not there: a tool failure.
    let missing = assemble(&[dir.join("nothing.mod")], &LoadOptions::default()).outcome;
    assert!(matches!(missing, Err(AssemblyError::Unreadable(_))));
    // A `.pgf` entry naming no file: the inputs' finding (E0130), as check reports it.
    let Err(AssemblyError::Inputs(inputs)) = assemble(&[dir.join("p.pgf")], &LoadOptions::default()).outcome else {
        panic!("a .pgf of a missing module is refused with its finding");
    };
    assert!(inputs.diagnostics.iter().any(|d| d.code == rapid_sema::Code::ProgramFileEntry));
    // No entry routine of that name: the task's load error.
    let options = LoadOptions { entry: Some("nosuch".to_owned()), ..LoadOptions::default() };
    let Err(AssemblyError::Load { task, alone, .. }) = assemble(&[dir.join("m.mod")], &options).outcome else {
        panic!("a missing entry is a load error");
    };
    assert_eq!((task.as_str(), alone), ("T_ROB1", true));
    // A robot model nobody has.
    let options = LoadOptions { robot: Some("IRB 0".to_owned()), ..LoadOptions::default() };
    let outcome = assemble(&[dir.join("m.mod")], &options).outcome;
    assert!(matches!(outcome, Err(AssemblyError::Boot(BootError::UnknownModel(_)))), "{:?}", outcome.err());
    let _ = fs::remove_dir_all(dir);
}

#[test]
fn a_stimulus_without_io_is_refused_naming_the_file() {
    let dir = scratch("stimulus", &[("m.mod", COUNT), ("s.stim", "at 1 set di1 1\n")]);
    let options = LoadOptions { stimulus: Some(dir.join("s.stim")), ..LoadOptions::default() };
    let Err(err) = assemble(&[dir.join("m.mod")], &options).outcome else { panic!("no I/O: refused") };
    let message = err.message();
    assert!(message.contains("s.stim`: a stimulus needs an I/O configuration"), "{message}");
    let _ = fs::remove_dir_all(dir);
}
