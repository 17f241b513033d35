//! The checker against the shared test corpus under `tests/check/`:
//! - `ok/`: realistic modules that must check with no diagnostic at all;
//! - `programs/`: folders of modules checked together as one task, also clean;
//! - `err/`: faulty inputs whose diagnostics, as a set of (code, line), must equal
//!   the `! expect: CODE line N` comments at the top of the file (or the lines of a
//!   `NAME.expect` sidecar for inputs that cannot hold comments).

use std::collections::BTreeSet;
use std::fs;
use std::path::{Path, PathBuf};

use rapid_sema::{check, Diagnostic, Options, SourceInput};
use rapid_syntax::LineIndex;

fn corpus_dir(sub: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/check").join(sub)
}

fn is_module_file(path: &Path) -> bool {
    let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase();
    matches!(ext.as_str(), "mod" | "modx" | "sys" | "sysx" | "prg")
}

fn sorted_entries(dir: &Path) -> Vec<PathBuf> {
    let mut entries: Vec<PathBuf> =
        fs::read_dir(dir).map(|rd| rd.filter_map(|e| e.ok()).map(|e| e.path()).collect()).unwrap_or_default();
    entries.sort();
    entries
}

fn load(path: &Path) -> SourceInput {
    let bytes = fs::read(path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    SourceInput::from_bytes(path.display().to_string(), bytes)
}

fn render(inputs: &[SourceInput], diags: &[Diagnostic]) -> String {
    diags
        .iter()
        .map(|d| {
            let input = &inputs[d.file];
            let line = LineIndex::new(&input.text).line_col(&input.text, d.span.start).line;
            format!("  {}:{line}: {} {}", input.path, d.code.as_str(), d.message)
        })
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn realistic_modules_check_clean() {
    let files: Vec<PathBuf> = sorted_entries(&corpus_dir("ok")).into_iter().filter(|p| is_module_file(p)).collect();
    assert!(files.len() >= 40, "expected at least 40 realistic modules, found {}", files.len());
    let mut failures = Vec::new();
    for path in &files {
        let inputs = vec![load(path)];
        let diags = check(&inputs, &Options::default());
        if !diags.is_empty() {
            failures.push(render(&inputs, &diags));
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} modules do not check clean:\n{}",
        failures.len(),
        files.len(),
        failures.join("\n")
    );
}

#[test]
fn program_folders_check_clean() {
    let mut failures = Vec::new();
    let folders: Vec<PathBuf> = sorted_entries(&corpus_dir("programs")).into_iter().filter(|p| p.is_dir()).collect();
    assert!(folders.len() >= 3);
    for folder in &folders {
        let mut inputs = Vec::new();
        for path in sorted_entries(folder) {
            let is_pgf_module = path.extension().is_some_and(|e| e.eq_ignore_ascii_case("pgf"))
                && fs::read_to_string(&path)
                    .is_ok_and(|t| t.lines().any(|l| l.trim_start().to_ascii_uppercase().starts_with("MODULE")));
            if is_module_file(&path) || is_pgf_module {
                inputs.push(load(&path));
            }
        }
        let diags = check(&inputs, &Options::default());
        if !diags.is_empty() {
            failures.push(render(&inputs, &diags));
        }
    }
    assert!(failures.is_empty(), "program folders that do not check clean:\n{}", failures.join("\n"));
}

/// `(code, line)` pairs a fixture expects.
fn expectations(path: &Path, input: &SourceInput) -> BTreeSet<(String, u32)> {
    let sidecar = path.with_extension("expect");
    let text = if sidecar.exists() { fs::read_to_string(&sidecar).unwrap_or_default() } else { input.text.to_string() };
    let mut expected = BTreeSet::new();
    for line in text.lines() {
        let line = line.trim();
        let body = line.strip_prefix("! expect:").unwrap_or(line);
        if !sidecar.exists() && !line.starts_with("! expect:") {
            continue;
        }
        let words: Vec<&str> = body.split_whitespace().collect();
        if let [code, "line", n] = words.as_slice() {
            expected.insert((code.to_string(), n.parse().unwrap_or(0)));
        }
    }
    expected
}

#[test]
fn faulty_inputs_report_exactly_their_codes_and_lines() {
    let files: Vec<PathBuf> = sorted_entries(&corpus_dir("err")).into_iter().filter(|p| is_module_file(p)).collect();
    assert!(files.len() >= 80, "expected at least 80 faulty inputs, found {}", files.len());
    let mut failures = Vec::new();
    for path in &files {
        let inputs = vec![load(path)];
        let expected = expectations(path, &inputs[0]);
        let diags = check(&inputs, &Options::default());
        let index = LineIndex::new(&inputs[0].text);
        let actual: BTreeSet<(String, u32)> = diags
            .iter()
            .map(|d| (d.code.as_str().to_string(), index.line_col(&inputs[0].text, d.span.start).line))
            .collect();
        if actual != expected {
            let missing: Vec<_> = expected.difference(&actual).collect();
            let extra: Vec<_> = actual.difference(&expected).collect();
            let name = path.file_name().unwrap_or_default().to_string_lossy();
            failures.push(format!("{name}: missing {missing:?}, unexpected {extra:?}\n{}", render(&inputs, &diags)));
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} faulty inputs differ:\n{}",
        failures.len(),
        files.len(),
        failures.join("\n")
    );
}
