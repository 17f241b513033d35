//! `docs/diagnostics.md` is generated from the code table; this test fails when the
//! committed copy is stale. Refresh it with `UPDATE_DOCS=1 cargo test -p rapid-sema --test docs_fresh`.

use std::fs;
use std::path::Path;

use rapid_sema::{Code, Severity};

fn render() -> String {
    let mut out = String::from(
        "# Diagnostics of `rapid check`\n\n\
         Generated from `crates/rapid-sema/src/codes.rs` by the `docs_fresh` test; do not edit by hand.\n\
         Codes are stable: a code is never reused or renumbered. `E` codes are errors (exit status 1),\n\
         `W` codes are warnings. Every code has at least one fixture under `tests/check/err/` named after it.\n\
         How `rapid check` shows them (the human layout, `--format json`, the tasks a finding of a check\n\
         of several tasks comes from) is in the user guide's `docs/guide/check.md`.\n\n\
         | code | severity | name | what it reports |\n|---|---|---|---|\n",
    );
    for code in Code::ALL {
        let severity = match code.severity() {
            Severity::Error => "error",
            Severity::Warning => "warning",
        };
        out.push_str(&format!(
            "| {} | {severity} | {} | {} |\n",
            code.as_str(),
            code.name(),
            code.summary().replace('|', "\\|")
        ));
    }
    out
}

#[test]
fn diagnostics_doc_is_fresh() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/diagnostics.md");
    let expected = render();
    if std::env::var_os("UPDATE_DOCS").is_some() {
        fs::write(&path, &expected).expect("write docs/diagnostics.md");
        return;
    }
    let actual = fs::read_to_string(&path).unwrap_or_default();
    assert!(
        actual == expected,
        "docs/diagnostics.md is stale: run `UPDATE_DOCS=1 cargo test -p rapid-sema --test docs_fresh`"
    );
}

#[test]
fn every_code_has_a_fixture() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/check/err");
    let names: Vec<String> = fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    // Codes that need several files, a whole program or a system of tasks are tested in
    // tests/program.rs and the CLI tests instead.
    // W0112 needs 500 warnings in one file: tests/program.rs.
    // E0217 needs the system's options, W0131 and W0218 an encrypted module beside
    // readable ones: tests/program.rs and `tests/check/options/` (CLI tests).
    // W0706 needs 64 MiB of source: tests/program.rs generates it.
    let elsewhere = [
        "E0208", "E0216", "E0130", "E0111", "W0112", "E0701", "W0702", "E0703", "E0704", "E0705", "E0217", "W0131",
        "W0218", "W0706",
    ];
    let missing: Vec<&str> = Code::ALL
        .iter()
        .map(|c| c.as_str())
        .filter(|c| !elsewhere.contains(c) && !names.iter().any(|n| n.starts_with(c)))
        .collect();
    assert!(missing.is_empty(), "codes without a fixture in tests/check/err: {missing:?}");
}
