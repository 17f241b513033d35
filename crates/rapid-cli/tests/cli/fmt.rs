//! `rapid fmt` on files in a scratch folder: `--check` names the files that would
//! change and exits 1, writing nothing; formatting writes them in their own encoding
//! (Latin-1, UTF-8 with a BOM) and line ends (CRLF); a file with a syntax error is left
//! byte for byte as it was and reported; `rapid.toml` `[fmt]` applies; `-` formats
//! stdin to stdout. Every expected text is worked out by hand from docs/fmt.md.

use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use crate::fixture::{rapid_in as rapid, scratch_in, stdout, Scratch};

fn scratch(name: &str) -> Scratch {
    scratch_in("fmt", name)
}

const MESSY: &str = "module m\nproc main()\nmovel p,v10,fine,tool0;\nendproc\nendmodule\n";
const NEAT: &str = "MODULE m\n    PROC main()\n        MoveL p, v10, fine, tool0;\n    ENDPROC\nENDMODULE\n";

#[test]
fn check_names_changed_files_and_writes_nothing() {
    let dir = scratch("check");
    fs::write(dir.join("a.mod"), MESSY).unwrap();
    fs::write(dir.join("b.mod"), NEAT).unwrap();
    let output = rapid(&dir, &["fmt", "--check", "."]);
    assert_eq!(output.status.code(), Some(1));
    assert_eq!(stdout(&output), "./a.mod\n");
    assert_eq!(fs::read_to_string(dir.join("a.mod")).unwrap(), MESSY);

    let output = rapid(&dir, &["fmt", "a.mod", "b.mod"]);
    assert_eq!(output.status.code(), Some(0), "{output:?}");
    assert_eq!(fs::read_to_string(dir.join("a.mod")).unwrap(), NEAT);
    assert_eq!(rapid(&dir, &["fmt", "--check", "."]).status.code(), Some(0));
    let _ = fs::remove_dir_all(&dir);
}

#[test]
fn encoding_and_line_ends_are_kept() {
    let dir = scratch("encoding");
    // Latin-1: the comment's `é` is one byte 0xE9, and must stay so.
    let latin1 = b"MODULE m\r\n! caf\xE9\r\nVAR num a;\r\nENDMODULE\r\n".to_vec();
    fs::write(dir.join("latin1.mod"), &latin1).unwrap();
    let bom = "\u{feff}MODULE m\nVAR string s:=\"\u{e4}\";\nENDMODULE\n";
    fs::write(dir.join("bom.mod"), bom).unwrap();
    let output = rapid(&dir, &["fmt", "latin1.mod", "bom.mod"]);
    assert_eq!(output.status.code(), Some(0), "{output:?}");
    assert_eq!(
        fs::read(dir.join("latin1.mod")).unwrap(),
        b"MODULE m\r\n    ! caf\xE9\r\n    VAR num a;\r\nENDMODULE\r\n"
    );
    let expected_bom = "\u{feff}MODULE m\n    VAR string s:=\"\u{e4}\";\nENDMODULE\n";
    assert_eq!(fs::read(dir.join("bom.mod")).unwrap(), expected_bom.as_bytes());
    let _ = fs::remove_dir_all(&dir);
}

#[test]
fn a_file_with_syntax_errors_is_left_alone() {
    let dir = scratch("refused");
    let broken = "module m\nproc main()\n  x := ;\nendproc\nendmodule\n";
    fs::write(dir.join("broken.mod"), broken).unwrap();
    fs::write(dir.join("ok.mod"), MESSY).unwrap();
    let output = rapid(&dir, &["fmt", "broken.mod", "ok.mod"]);
    assert_eq!(output.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("broken.mod: not formatted: 1 syntax error(s) (first at 3:"), "{stderr}");
    assert_eq!(fs::read_to_string(dir.join("broken.mod")).unwrap(), broken);
    // The other file is formatted all the same.
    assert_eq!(fs::read_to_string(dir.join("ok.mod")).unwrap(), NEAT);
    let _ = fs::remove_dir_all(&dir);
}

#[test]
fn the_manifest_fmt_table_applies() {
    let dir = scratch("manifest");
    fs::write(dir.join("rapid.toml"), "[fmt]\nindent_width = 2\n").unwrap();
    fs::create_dir_all(dir.join("src")).unwrap();
    fs::write(dir.join("src/a.mod"), MESSY).unwrap();
    let output = rapid(&dir, &["fmt", "src"]);
    assert_eq!(output.status.code(), Some(0), "{output:?}");
    let expected = "MODULE m\n  PROC main()\n    MoveL p, v10, fine, tool0;\n  ENDPROC\nENDMODULE\n";
    assert_eq!(fs::read_to_string(dir.join("src/a.mod")).unwrap(), expected);
    let _ = fs::remove_dir_all(&dir);
}

#[test]
fn stdin_is_formatted_to_stdout() {
    let dir = scratch("stdin");
    let mut child = Command::new(env!("CARGO_BIN_EXE_rapid"))
        .current_dir(&dir)
        .args(["fmt", "-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    child.stdin.take().unwrap().write_all(MESSY.as_bytes()).unwrap();
    let output = child.wait_with_output().unwrap();
    assert_eq!(output.status.code(), Some(0));
    assert_eq!(stdout(&output), NEAT);
    let _ = fs::remove_dir_all(&dir);
}

/// Copies a folder tree.
fn copy_tree(from: &Path, to: &Path) {
    fs::create_dir_all(to).unwrap();
    for entry in fs::read_dir(from).unwrap().flatten() {
        let path = entry.path();
        let target = to.join(entry.file_name());
        if path.is_dir() {
            copy_tree(&path, &target);
        } else {
            fs::copy(&path, &target).unwrap();
        }
    }
}

/// Every folder under `dir` (itself included), for `rapid fmt` to take their modules.
fn folders(dir: &Path, out: &mut Vec<PathBuf>) {
    out.push(dir.to_path_buf());
    for entry in fs::read_dir(dir).unwrap().flatten() {
        if entry.path().is_dir() {
            folders(&entry.path(), out);
        }
    }
}

/// The diagnostic codes `rapid check --format json` reports, sorted.
fn check_codes(dir: &Path, target: &str) -> Vec<String> {
    let output = rapid(dir, &["check", "--format", "json", target]);
    assert!(output.status.code().is_some_and(|c| c < 2), "{target}: {output:?}");
    let diags: serde_json::Value = serde_json::from_slice(&output.stdout).expect("JSON diagnostics");
    let mut codes: Vec<String> =
        diags.as_array().unwrap().iter().map(|d| d["code"].as_str().unwrap().to_owned()).collect();
    codes.sort();
    codes
}

#[test]
fn programs_and_backups_check_the_same_after_formatting() {
    // Whole programs of several modules (and their .pgf) and backups of several tasks:
    // `rapid check` finds the same codes, as many of each, before and after.
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/check");
    let dir = scratch("programs");
    let mut n_checked = 0;
    for group in ["programs", "backups"] {
        for entry in fs::read_dir(root.join(group)).unwrap().flatten() {
            if !entry.path().is_dir() {
                continue;
            }
            let copy = dir.join(group).join(entry.file_name());
            copy_tree(&entry.path(), &copy);
            // A program is checked through its .pgf (as RobotWare loads it), a backup whole.
            let pgf = fs::read_dir(&copy)
                .unwrap()
                .flatten()
                .map(|e| e.path())
                .find(|p| p.extension().is_some_and(|x| x == "pgf"));
            let target = pgf.unwrap_or_else(|| copy.clone()).to_str().unwrap().to_owned();
            let before = check_codes(&dir, &target);
            let mut all = Vec::new();
            folders(&copy, &mut all);
            let args: Vec<&str> = std::iter::once("fmt").chain(all.iter().map(|p| p.to_str().unwrap())).collect();
            let formatted = rapid(&dir, &args);
            assert_eq!(formatted.status.code(), Some(0), "{}: {formatted:?}", entry.path().display());
            assert_eq!(check_codes(&dir, &target), before, "{}", entry.path().display());
            let mut again = vec!["fmt", "--check"];
            again.extend(all.iter().map(|p| p.to_str().unwrap()));
            assert_eq!(rapid(&dir, &again).status.code(), Some(0), "{}: not idempotent", entry.path().display());
            n_checked += 1;
        }
    }
    assert!(n_checked >= 7, "only {n_checked} programs and backups");
    let _ = fs::remove_dir_all(&dir);
}
