//! Modules loaded at run time across PP to Main (§1.17: a module loaded `\Dynamic` is
//! unloaded by PP to Main; one loaded without it stays, its data initialised again like
//! the task's own, §1.2.2 start-up table). A conformance program runs only one cycle, so
//! this needs the API.

use rapid_sema::SourceInput;
use rapid_vm::world::memory::MemoryFs;
use rapid_vm::world::World;
use rapid_vm::{Exit, RecordingHost};

/// Loads with the controller's standard set of built-ins (the file and socket
/// built-ins are the controller's bindings).
fn load(files: &[SourceInput], entry: &str) -> Result<rapid_vm::Loaded, rapid_vm::LoadError> {
    rapid_controller::builtin_set::load_with(files, entry, &rapid_sema::Options::default())
}

/// A world whose disk is `fs`, in memory: the modules the program writes and loads
/// never touch the host's disk.
fn memory_world(fs: MemoryFs) -> World {
    World { files: Box::new(fs), ..World::closed() }
}

const PROGRAM: &str = r#"MODULE t
VAR iodev f;
PERS num runs := 0;
PROC main()
  runs := runs + 1;
  IF runs = 1 THEN
    Open "HOME:/st.mod", f \Write;
    Write f, "MODULE st";
    Write f, "VAR num sv := 5; PERS num sp := 1;";
    Write f, "PROC st_p() sv := sv + 1; sp := sp + 1;";
    Write f, "TPWrite ""sv="" \\Num:=sv; TPWrite ""sp="" \\Num:=sp; ENDPROC";
    Write f, "ENDMODULE";
    Close f;
    Open "HOME:/dy.mod", f \Write;
    Write f, "MODULE dy";
    Write f, "PROC dy_p() TPWrite ""dy""; ENDPROC";
    Write f, "ENDMODULE";
    Close f;
    Load "HOME:/st.mod";
    Load \Dynamic, "HOME:/dy.mod";
  ENDIF
  %"st_p"%;
  TPWrite "dy " \Bool:=ModExist("dy");
  TPWrite "st " \Bool:=ModExist("st");
ENDPROC
ENDMODULE
"#;

#[test]
fn pp_to_main_unloads_dynamic_modules_and_reinitialises_static_ones() {
    let root = std::env::temp_dir().join(format!("rapid-dynload-{}", std::process::id()));
    let loaded = match load(&[SourceInput::from_text("t.mod", PROGRAM)], "main") {
        Ok(loaded) => loaded,
        Err(err) => panic!("load failed: {err:?}"),
    };
    let (mut machine, entry) = (loaded.vm, loaded.entry);
    machine.resources_mut().devices.set_root(&root);
    machine.set_world(memory_world(MemoryFs::new()));
    let mut host = RecordingHost::default();
    assert_eq!(machine.run(&mut host, 100_000), Exit::Done);
    machine.pp_to_main(&mut host, entry).expect("pp to main");
    assert_eq!(machine.run(&mut host, 100_000), Exit::Done);
    let _ = std::fs::remove_dir_all(&root);
    let expected = ["sv=6", "sp=2", "dy TRUE", "st TRUE", "sv=6", "sp=3", "dy FALSE", "st TRUE"];
    assert_eq!(host.lines, expected);
}

#[test]
fn a_module_that_does_not_check_is_refused_with_its_diagnostics() {
    let root = std::env::temp_dir().join(format!("rapid-dynload-syntax-{}", std::process::id()));
    let module = root.join("HOME");
    let fs = MemoryFs::new();
    fs.put(module.join("bad.mod"), b"MODULE bad\nPROC bad_p()\n  x := ;\nENDPROC\nENDMODULE\n");
    let program = "MODULE t\nPROC main()\n  Load \"HOME:/bad.mod\";\nENDPROC\nENDMODULE\n";
    let loaded = match load(&[SourceInput::from_text("t.mod", program)], "main") {
        Ok(loaded) => loaded,
        Err(err) => panic!("load failed: {err:?}"),
    };
    let mut machine = loaded.vm;
    machine.resources_mut().devices.set_root(&root);
    machine.set_world(memory_world(fs));
    let mut host = RecordingHost::default();
    let exit = machine.run(&mut host, 100_000);
    let _ = std::fs::remove_dir_all(&root);
    let Exit::Unhandled(unhandled) = exit else { panic!("expected ERR_SYNTAX, got {exit:?}") };
    assert_eq!(unhandled.error.name, "ERR_SYNTAX");
    assert!(unhandled.error.message.contains("HOME:/bad.mod:3:"), "{}", unhandled.error.message);
}

#[test]
fn a_static_call_into_an_erased_module_raises_err_refunkprc() {
    // EraseModule removes one of the task's own modules; a call compiled against it
    // then reaches nothing, which the controller reports as an unknown procedure.
    let main = r#"MODULE m
PROC main()
  helper;
  EraseModule "h";
  helper;
  TPWrite "not reached";
ERROR
  IF ERRNO = ERR_REFUNKPRC TPWrite "ERR_REFUNKPRC";
  RETURN;
ENDPROC
ENDMODULE
"#;
    let helper = "MODULE h\nPROC helper()\n  TPWrite \"helper\";\nENDPROC\nENDMODULE\n";
    let files = [SourceInput::from_text("m.mod", main), SourceInput::from_text("h.mod", helper)];
    let loaded = match load(&files, "main") {
        Ok(loaded) => loaded,
        Err(err) => panic!("load failed: {err:?}"),
    };
    let mut machine = loaded.vm;
    let mut host = RecordingHost::default();
    assert_eq!(machine.run(&mut host, 100_000), Exit::Done);
    assert_eq!(host.lines, ["helper", "ERR_REFUNKPRC"]);
}

#[test]
fn load_measures_a_module_file_against_the_program_memory_of_the_limits_table() {
    // The table's program memory is 64 MiB (64 << 20 = 67,108,864 bytes): a module
    // file of 9 MiB (over the 8 MiB Load refused before) loads; one byte over 64 MiB
    // is refused before it is read with ERR_PRGMEMFULL ("program memory full", Load's
    // error for a module that does not fit), the message naming the figure. ProgMemFree gives
    // the same figure: 67,108,864 DIV 1024 = 65,536 KiB.
    let root = std::env::temp_dir().join(format!("rapid-dynload-memory-{}", std::process::id()));
    let home = root.join("HOME");
    let fs = MemoryFs::new();
    let mut medium = b"MODULE medium\nPROC medium_p()\n  TPWrite \"medium\";\nENDPROC\n".to_vec();
    medium.resize(9 << 20, b' ');
    medium.extend_from_slice(b"\nENDMODULE\n");
    fs.put(home.join("medium.mod"), &medium);
    fs.put(home.join("huge.mod"), &vec![b' '; (64 << 20) + 1]);
    let program = r#"MODULE t
PROC main()
  TPWrite "free KiB " \Num:=ProgMemFree() DIV 1024;
  Load "HOME:/medium.mod";
  %"medium_p"%;
  Load "HOME:/huge.mod";
  TPWrite "not reached";
ERROR
  TPWrite "refused " \Bool:=ERRNO = ERR_PRGMEMFULL;
  RETURN;
ENDPROC
ENDMODULE
"#;
    let loaded = match load(&[SourceInput::from_text("t.mod", program)], "main") {
        Ok(loaded) => loaded,
        Err(err) => panic!("load failed: {err:?}"),
    };
    let mut machine = loaded.vm;
    machine.resources_mut().devices.set_root(&root);
    machine.set_world(memory_world(fs));
    let mut host = RecordingHost::default();
    assert_eq!(machine.run(&mut host, 100_000), Exit::Done);
    let _ = std::fs::remove_dir_all(&root);
    assert_eq!(host.lines, ["free KiB 65536", "medium", "refused TRUE"]);
}
