//! End-to-end tests of the `rapid` binary: exit code, stdout and stderr.
//!
//! Committed fixtures live in `tests/cli/fixtures/`; inputs that cannot be committed (an
//! empty folder, binary junk, a 10 MB line) are written to a scratch folder at run time.
//! Commands run inside the folder with relative paths so snapshots do not hold
//! machine-specific paths.

use std::fs;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use insta_cmd::assert_cmd_snapshot;

use crate::fixture::{rapid_cmd, scratch_in, Scratch};

/// A fresh, empty scratch folder for one test.
fn scratch(name: &str) -> Scratch {
    scratch_in("check", name)
}

fn fixtures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/cli/fixtures")
}

fn rapid(args: &[&str]) -> Command {
    rapid_cmd(&fixtures(), args)
}

#[test]
fn version() {
    let out = rapid(&["--version"]).output().unwrap();
    assert!(out.status.success());
    assert_eq!(String::from_utf8(out.stdout).unwrap(), format!("rapid {}\n", env!("CARGO_PKG_VERSION")));
}

#[test]
fn clean_file() {
    assert_cmd_snapshot!(rapid(&["check", "clean.mod"]));
}

#[test]
fn file_with_syntax_errors() {
    assert_cmd_snapshot!(rapid(&["check", "syntax_errors.mod"]));
}

#[test]
fn file_with_semantic_errors() {
    assert_cmd_snapshot!(rapid(&["check", "semantic_errors.mod"]));
}

#[test]
fn warnings_alone_exit_zero() {
    assert_cmd_snapshot!(rapid(&["check", "warnings_only.mod"]));
}

#[test]
fn syntax_only_flag() {
    // The semantic errors of the file are not looked for.
    assert_cmd_snapshot!(rapid(&["check", "--syntax-only", "semantic_errors.mod", "syntax_errors.mod"]));
}

#[test]
fn json_format() {
    assert_cmd_snapshot!(rapid(&["check", "--format", "json", "missing_entry/Program.pgf", "syntax_errors.mod"]));
}

#[test]
fn json_format_clean() {
    assert_cmd_snapshot!(rapid(&["check", "--format", "json", "clean.mod"]));
}

#[test]
fn missing_path() {
    assert_cmd_snapshot!(rapid(&["check", "clean.mod", "nosuch.mod"]));
}

#[test]
fn unknown_extension() {
    assert_cmd_snapshot!(rapid(&["check", "notes.txt"]));
}

#[test]
fn no_path_is_a_usage_error() {
    let out = rapid(&["check"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    assert!(String::from_utf8(out.stderr).unwrap().contains("<PATH>"));
}

#[test]
fn empty_folder() {
    let dir = scratch("empty_folder");
    fs::create_dir(dir.join("empty")).unwrap();
    assert_cmd_snapshot!(rapid_cmd(&dir, &["check", "empty"]));
}

#[test]
fn folder_of_modules() {
    // Module files only (any letter case), not subfolders: a.mod and B.SYS, plus the
    // program file and its one readable module.
    assert_cmd_snapshot!(rapid(&["check", "folder", "missing_entry/Program.pgf"]));
}

#[test]
fn program_file_listing_modules() {
    assert_cmd_snapshot!(rapid(&["check", "program/Program.pgf"]));
}

#[test]
fn program_file_holding_a_module() {
    assert_cmd_snapshot!(rapid(&["check", "pgf_module/Legacy.pgf"]));
}

#[test]
fn program_file_with_missing_entry() {
    assert_cmd_snapshot!(rapid(&["check", "missing_entry/Program.pgf"]));
}

#[test]
fn program_file_entries_from_windows() {
    // Backups made on Windows name entries with `\` and in any letter case.
    let dir = scratch("windows_entries");
    fs::create_dir(dir.join("progmod")).unwrap();
    fs::write(dir.join("progmod/Main.mod"), "MODULE Main\nENDMODULE\n").unwrap();
    fs::write(dir.join("Prog.pgf"), "<Program><Module>progmod\\MAIN.MOD</Module></Program>").unwrap();
    let out = rapid_cmd(&dir, &["check", "Prog.pgf"]).output().unwrap();
    assert_eq!(String::from_utf8(out.stdout).unwrap(), "checked 2 files: no problems found\n");
    assert_eq!(out.status.code(), Some(0));
}

#[test]
fn same_file_twice_is_read_once() {
    assert_cmd_snapshot!(rapid(&["check", "program/Program.pgf", "program/Tools.mod", "program"]));
}

#[test]
fn codes_table() {
    let out = rapid(&["codes"]).output().unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.starts_with("code   severity summary\nE0101  error    "));
    assert!(text.contains("\nW0202  warning  "));
}

/// Runs `rapid check` on a generated file and asserts that it ends normally with short
/// output, whatever the checker finds.
fn check_survives(dir: &Path, file: &str) -> String {
    let out = rapid_cmd(dir, &["check", file]).output().unwrap();
    let stdout = String::from_utf8(out.stdout).unwrap();
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert!(matches!(out.status.code(), Some(0 | 1)), "status {:?}, stderr {stderr}", out.status);
    assert!(stderr.is_empty(), "{stderr}");
    let longest = stdout.lines().map(|line| line.chars().count()).max().unwrap_or(0);
    assert!(longest < 300, "a line of {longest} characters");
    assert!(stdout.ends_with(" file\n") || stdout.ends_with(" files\n") || stdout.ends_with("found\n"), "{stdout}");
    stdout
}

#[test]
fn binary_file() {
    let dir = scratch("binary_file");
    // A deterministic jumble of every byte value, NULs and invalid UTF-8 included.
    let mut state: u32 = 0x2545_f491;
    let junk: Vec<u8> = (0..200_000)
        .map(|_| {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            (state >> 24) as u8
        })
        .collect();
    fs::write(dir.join("junk.mod"), &junk).unwrap();
    check_survives(&dir, "junk.mod");
    // A first byte of 0xFC or 0xFE marks an ABB-encrypted module.
    fs::write(dir.join("encrypted.mod"), [&[0xFC][..], &junk].concat()).unwrap();
    check_survives(&dir, "encrypted.mod");
    fs::write(dir.join("utf16.mod"), [&[0xFF, 0xFE][..], &junk].concat()).unwrap();
    check_survives(&dir, "utf16.mod");
}

#[test]
fn very_long_line() {
    let dir = scratch("very_long_line");
    // A 10 MB routine on one line, with an undefined name in the middle.
    let statements = "n := n + 1; ".repeat(400_000);
    let text = format!(
        "MODULE Long\n    VAR num n := 0;\n    PROC main() {statements}nosuch := 1; {statements}ENDPROC\nENDMODULE\n"
    );
    fs::write(dir.join("long.mod"), &text).unwrap();
    let stdout = check_survives(&dir, "long.mod");
    assert!(stdout.contains("--> long.mod:3:4800017\n"), "{stdout}");
    assert!(stdout.contains("n + 1; nosuch := 1; n := n"), "{stdout}");
    assert!(stdout.len() < 2_000, "{} bytes of output", stdout.len());
}

#[test]
fn broken_pipe_is_a_clean_exit() {
    let dir = scratch("broken_pipe");
    // Enough diagnostics to fill a pipe several times over.
    let entries: String = (0..5000).map(|idx| format!("<Module>missing_{idx}.mod</Module>\n")).collect();
    fs::write(dir.join("Many.pgf"), format!("<Program>\n{entries}</Program>\n")).unwrap();
    let mut child =
        rapid_cmd(&dir, &["check", "Many.pgf"]).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn().unwrap();
    let mut first = [0u8; 16];
    child.stdout.take().unwrap().read_exact(&mut first).unwrap();
    let status = child.wait().unwrap();
    let mut stderr = String::new();
    child.stderr.take().unwrap().read_to_string(&mut stderr).unwrap();
    assert_eq!(&first, b"error[E0130]: ca");
    assert_eq!(status.code(), Some(0), "stderr: {stderr}");
    assert!(stderr.is_empty(), "{stderr}");
}
