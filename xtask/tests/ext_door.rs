//! One door into the interpreter for the extension crates (issue 19,
//! docs/architecture.md): the built-in families defined outside rapid-vm (rapid-tasks, rapid-robot,
//! rapid-signals, rapid-controller's bindings) take what they use of the interpreter
//! from `rapid_vm::ext` only, never from its modules (`rapid_vm::value::Value`,
//! `rapid_vm::builtins::Ctx`…). What they need and ext lacks is added to ext on
//! purpose, in review.
//!
//! [`ALLOWED`] names the files that still reach past ext, each with why; every entry
//! must still be needed, so the list only shrinks. Tests directories (`crates/*/tests`)
//! are not scanned: they drive a `Vm` as an embedder does.

use std::fs;
use std::path::{Path, PathBuf};

/// Where the extension crates' source is, from the workspace root.
const SCANNED: &[&str] = &[
    "crates/rapid-tasks/src",
    "crates/rapid-robot/src",
    "crates/rapid-signals/src",
    "crates/rapid-controller/src/bindings",
];

/// The files that may still name `rapid_vm::` paths other than `rapid_vm::ext`, and why.
const ALLOWED: &[(&str, &str)] = &[
    // The embedder door, not the extension door: `SignalsVm` is implemented for
    // `rapid_vm::Vm`, for the controller that builds a task's I/O.
    ("crates/rapid-signals/src/vm.rs", "embedder door (SignalsVm for Vm)"),
];

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = fs::read_dir(dir) else { return };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|ext| ext == "rs") {
            out.push(path);
        }
    }
}

/// The code of a file without its comment lines (docs may name any path).
fn code(text: &str) -> String {
    text.lines().filter(|line| !line.trim_start().starts_with("//")).collect::<Vec<_>>().join("\n")
}

fn is_ident(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// The leading identifier of `s` (after blanks).
fn first_segment(s: &str) -> &str {
    let s = s.trim_start();
    &s[..s.find(|c: char| !is_ident(c)).unwrap_or(s.len())]
}

/// The items of a `{…}` group that `s` opens, split at its top-level commas.
fn group_items(s: &str) -> Vec<&str> {
    let mut items = Vec::new();
    let (mut depth, mut start) = (0usize, 1usize);
    for (i, c) in s.char_indices() {
        match c {
            '{' => depth += 1,
            '}' | ',' if depth == 1 => {
                items.push(&s[start..i]);
                start = i + 1;
                if c == '}' {
                    break;
                }
            }
            '}' => depth -= 1,
            _ => {}
        }
    }
    items.into_iter().map(str::trim).filter(|item| !item.is_empty()).collect()
}

/// Every way `text` reaches rapid-vm other than through `rapid_vm::ext`: a path
/// (`rapid_vm::value::Value`, in a `use` or inline), an item of a `use rapid_vm::{…}`
/// group, or the crate itself (`use rapid_vm;`, `use rapid_vm as vm;`).
fn direct_paths(text: &str) -> Vec<String> {
    let code = code(text);
    let mut found = Vec::new();
    for (at, _) in code.match_indices("rapid_vm") {
        let before = code[..at].chars().next_back();
        let rest = &code[at + "rapid_vm".len()..];
        if before.is_some_and(is_ident) || rest.starts_with(is_ident) {
            continue;
        }
        let Some(path) = rest.trim_start().strip_prefix("::") else {
            found.push("rapid_vm (the crate itself)".to_string());
            continue;
        };
        let path = path.trim_start();
        let segments = if path.starts_with('{') { group_items(path) } else { vec![path] };
        for segment in segments {
            let name = first_segment(segment);
            if name != "ext" {
                found.push(format!("rapid_vm::{name}"));
            }
        }
    }
    found
}

#[test]
fn extension_crates_enter_the_interpreter_through_ext() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut files = Vec::new();
    for dir in SCANNED {
        rust_files(&root.join(dir), &mut files);
    }
    assert!(files.len() > 40, "found too few files: {}", files.len());
    let mut problems = Vec::new();
    let mut seen = Vec::new();
    for path in &files {
        let shown = path.strip_prefix(&root).unwrap_or(path).to_string_lossy().replace('\\', "/");
        let direct = direct_paths(&fs::read_to_string(path).unwrap_or_default());
        let allowed = ALLOWED.iter().any(|(file, _)| *file == shown);
        if allowed {
            seen.push(shown.clone());
        }
        match (direct.is_empty(), allowed) {
            (false, false) => problems.push(format!(
                "{shown}: reaches rapid-vm past rapid_vm::ext ({}): take it from ext (add it there on purpose)",
                direct.join(", ")
            )),
            (true, true) => problems
                .push(format!("{shown} goes through ext only now: delete it from ALLOWED (the list only shrinks)")),
            _ => {}
        }
    }
    for (file, _) in ALLOWED {
        if !seen.iter().any(|s| s == file) {
            problems.push(format!("ALLOWED names {file}, which is not a scanned file"));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn the_scanner_sees_every_way_past_the_door() {
    let text = "\
//! Docs may name rapid_vm::value::Value.
use rapid_vm::ext::{Ctx, Value};
use rapid_vm::{ext::Err, exec::{storage::Storage, Vm}};
use rapid_vm::{
    ext::RapidError,
    value::Place,
};
use rapid_vm as vm;
fn f(v: rapid_vm::value::Value) -> rapid_vm::ext::Value { my_rapid_vm::x(); rapid_vm_extra::y(); v }
// rapid_vm::builtins::Ctx in a comment
";
    assert_eq!(
        direct_paths(text),
        ["rapid_vm::exec", "rapid_vm::value", "rapid_vm (the crate itself)", "rapid_vm::value"],
    );
    assert!(direct_paths("use rapid_vm::ext::{Ctx, Err};\nrapid_vm::ext::layout! {}\n").is_empty());
}
