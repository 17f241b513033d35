//! The file devices' sandbox end to end: paths that try to leave their device (`..`,
//! absolute host paths, symbolic links pointing outside) are refused with the RAPID
//! error and never followed; the default controller root; a VM without a root.

use std::fs;
use std::path::Path;
use std::process::{Command, Output};

use crate::fixture::{scratch_in, Scratch};

/// A fresh, empty scratch folder for one test.
fn temp_dir(name: &str) -> Scratch {
    scratch_in("files", name)
}

fn run(module: &Path, home: Option<&Path>) -> Output {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_rapid"));
    cmd.arg("run");
    if let Some(home) = home {
        cmd.arg("--home").arg(home);
    }
    cmd.arg(module).output().expect("run rapid")
}

/// A program that tries to write `path` and prints the error it gets.
fn writer(path: &str) -> String {
    format!(
        "MODULE w\nPROC main()\n  VAR iodev f;\n  Open \"{path}\", f \\Write;\n  Write f, \"escaped\";\n  Close f;\n  TPWrite \"written\";\nERROR\n  IF ERRNO = ERR_FILEOPEN TPWrite \"ERR_FILEOPEN\";\nENDPROC\nENDMODULE\n"
    )
}

#[test]
fn dot_dot_and_absolute_paths_are_refused() {
    let dir = temp_dir("dotdot");
    let home = dir.join("home");
    let module = dir.join("w.mod");
    let target = dir.join("escaped.txt");
    for path in ["HOME:/../../escaped.txt", "HOME:../escaped.txt", "TEMP:/x/../../../escaped.txt"] {
        fs::write(&module, writer(path)).unwrap();
        let out = run(&module, Some(&home));
        assert_eq!(String::from_utf8_lossy(&out.stdout), "ERR_FILEOPEN\n", "{path}");
        assert!(!target.exists(), "{path} wrote outside the root");
        assert!(!home.join("escaped.txt").exists(), "{path} wrote beside the devices");
    }
    let absolute = dir.join("absolute.txt");
    fs::write(&module, writer(absolute.to_str().unwrap())).unwrap();
    let out = run(&module, Some(&home));
    assert_eq!(String::from_utf8_lossy(&out.stdout), "ERR_FILEOPEN\n");
    assert!(!absolute.exists());
}

#[cfg(unix)]
#[test]
fn links_pointing_outside_are_not_followed() {
    let dir = temp_dir("links");
    let home = dir.join("home");
    let outside = dir.join("outside");
    fs::create_dir_all(home.join("HOME")).unwrap();
    fs::create_dir_all(&outside).unwrap();
    fs::write(outside.join("secret.txt"), "secret\n").unwrap();
    std::os::unix::fs::symlink(&outside, home.join("HOME").join("out")).unwrap();
    std::os::unix::fs::symlink(outside.join("new.txt"), home.join("HOME").join("dangling")).unwrap();
    let module = dir.join("w.mod");
    for path in ["HOME:/out/new.txt", "HOME:/dangling", "HOME:/out/secret.txt"] {
        fs::write(&module, writer(path)).unwrap();
        let out = run(&module, Some(&home));
        assert_eq!(String::from_utf8_lossy(&out.stdout), "ERR_FILEOPEN\n", "{path}");
    }
    assert!(!outside.join("new.txt").exists());
    assert_eq!(fs::read_to_string(outside.join("secret.txt")).unwrap(), "secret\n");
    // Reading through the link and listing it are refused too.
    let reader = "MODULE r\nPROC main()\n  VAR dir d;\n  TPWrite \"\" \\Bool:=IsFile(\"HOME:/out/secret.txt\");\nERROR\n  IF ERRNO = ERR_FILEACC TPWrite \"ERR_FILEACC\";\nENDPROC\nENDMODULE\n";
    fs::write(&module, reader).unwrap();
    let out = run(&module, Some(&home));
    assert_eq!(String::from_utf8_lossy(&out.stdout), "ERR_FILEACC\n");
}

#[cfg(unix)]
#[test]
fn a_fifo_in_the_root_is_not_opened() {
    let dir = temp_dir("fifo");
    let home = dir.join("home");
    fs::create_dir_all(home.join("HOME")).unwrap();
    let made = Command::new("mkfifo").arg(home.join("HOME").join("pipe")).status();
    if !made.is_ok_and(|s| s.success()) {
        return; // No mkfifo on this host: nothing to check.
    }
    let module = dir.join("w.mod");
    fs::write(&module, writer("HOME:/pipe")).unwrap();
    let out = run(&module, Some(&home));
    assert_eq!(String::from_utf8_lossy(&out.stdout), "ERR_FILEOPEN\n");
}

#[test]
fn the_default_root_is_beside_the_program() {
    let dir = temp_dir("default");
    let module = dir.join("w.mod");
    fs::write(&module, writer("TEMP:/note.txt")).unwrap();
    let out = run(&module, None);
    assert_eq!(String::from_utf8_lossy(&out.stdout), "written\n");
    let written = dir.join("rapid-controller").join("TEMP").join("note.txt");
    assert_eq!(fs::read_to_string(written).unwrap(), "escaped\n");
}

#[test]
fn a_vm_without_a_root_raises_an_error() {
    let text = writer("HOME:/a.txt").replace("IF ERRNO = ERR_FILEOPEN TPWrite \"ERR_FILEOPEN\";", "RAISE;");
    let input = rapid_sema::SourceInput { path: "w.mod".into(), text: text.into(), unreadable: None };
    let mut loaded = rapid_controller::builtin_set::load(&[input], "main").map_err(|e| format!("{e:?}")).unwrap();
    let mut host = rapid_vm::RecordingHost::default();
    match loaded.vm.run(&mut host, 1_000_000) {
        rapid_vm::Exit::Unhandled(unhandled) => {
            assert_eq!(unhandled.error.name, "ERR_FILEOPEN");
            assert!(unhandled.error.message.contains("no controller root"), "{}", unhandled.error.message);
        }
        other => panic!("expected an unhandled error, got {other:?}"),
    }
}
