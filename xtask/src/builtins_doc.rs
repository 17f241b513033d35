//! `cargo run -p xtask -- builtins-doc`: writes `docs/builtins.md` from the catalogue
//! (`rapid-lib`), the interpreter's registry (`rapid_vm::builtins`) and the
//! conformance programs. A test fails when the committed copy is stale.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

use rapid_lib::catalogue::options::ALL_OPTIONS;
use rapid_lib::catalogue::{Entry, EntryKind, ALL_CHAPTERS};
use rapid_syntax::ast::{Item, RoutineKind};
use rapid_syntax::Interner;

/// The command that regenerates the file (printed when it is stale).
pub(crate) const COMMAND: &str = "cargo run -p xtask -- builtins-doc";

/// Where the generated file lives, relative to the workspace root.
pub(crate) const PATH: &str = "docs/builtins.md";

/// How many conformance programs a row names before it only counts the rest.
const SHOWN_TESTS: usize = 3;

/// What `rapid run` does with one built-in.
pub(crate) enum Status {
    /// Runs it: the family file that registers it.
    Runs(String),
    /// Refuses it at load, for the reason `builtins/not_yet.rs` gives.
    NotYet(String),
    /// Refuses it at load because it is a routine of a software option `rapid run`
    /// does not simulate: the message, and the option's name.
    Option(String, &'static str),
}

/// One built-in instruction or function.
pub(crate) struct Row {
    pub(crate) name: String,
    pub(crate) chapter: &'static str,
    /// An instruction (PROC), else a function (FUNC).
    pub(crate) instruction: bool,
    pub(crate) status: Status,
    tests: Vec<String>,
}

/// The workspace root.
pub(crate) fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// Every routine the catalogue declares, with its chapter and whether it is an
/// instruction, in catalogue order.
fn catalogue_routines() -> Vec<(String, &'static str, bool)> {
    let mut interner = Interner::default();
    let cat = rapid_lib::load(&mut interner);
    let mut out = Vec::new();
    for loaded in &cat.entries {
        if loaded.entry.kind != EntryKind::Routine {
            continue;
        }
        if let Some(Item::Routine(routine)) = cat.item(loaded) {
            let instruction = routine.kind == RoutineKind::Proc;
            out.push((routine.name.span.text(&cat.text).to_string(), loaded.chapter, instruction));
        }
    }
    out
}

/// The lower-case identifiers of a RAPID text outside comments and string literals.
fn words(text: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for line in text.lines() {
        let mut word = String::new();
        let mut in_string = false;
        for c in line.chars() {
            if in_string {
                // A doubled quote inside a literal closes and reopens it: same effect.
                in_string = c != '"';
                continue;
            }
            if c.is_alphanumeric() || c == '_' {
                word.push(c.to_ascii_lowercase());
                continue;
            }
            if !word.is_empty() {
                out.insert(std::mem::take(&mut word));
            }
            match c {
                '"' => in_string = true,
                '!' => break,
                _ => {}
            }
        }
        if !word.is_empty() {
            out.insert(word);
        }
    }
    out
}

/// Each conformance program's name with the words it uses.
fn conformance_words(root: &Path) -> BTreeMap<String, BTreeSet<String>> {
    let dir = root.join("tests/conformance");
    let mut out = BTreeMap::new();
    let Ok(entries) = fs::read_dir(&dir) else { return out };
    for entry in entries.filter_map(|e| e.ok()) {
        let path = entry.path();
        if path.extension().is_none_or(|e| e != "mod") {
            continue;
        }
        let stem = path.file_stem().unwrap_or_default().to_string_lossy().into_owned();
        out.insert(stem, words(&fs::read_to_string(&path).unwrap_or_default()));
    }
    out
}

/// The family file of each built-in the controller's set registers, by lower-case
/// name: relative to `crates/rapid-vm/src/` for the core's, to `crates/` for an
/// extension's (`rapid-robot/src/moves.rs`, `rapid-controller/src/bindings/files/io.rs`).
fn family_files() -> BTreeMap<String, String> {
    let set = rapid_controller::builtin_set::standard();
    set.registered()
        .map(|(builtin, file)| {
            let file =
                file.strip_prefix("crates/rapid-vm/src/").or_else(|| file.strip_prefix("crates/")).unwrap_or(file);
            let file = file.to_string();
            (builtin.name.to_ascii_lowercase(), file)
        })
        .collect()
}

/// Every catalogue instruction and function with what `rapid run` does with it, by
/// chapter (the catalogue's order of chapter files) and name.
pub(crate) fn rows(root: &Path) -> Vec<Row> {
    let programs = conformance_words(root);
    let families = family_files();
    let order: Vec<&str> = chapters().map(|(name, _)| name).collect();
    let mut rows: Vec<Row> = catalogue_routines()
        .into_iter()
        .map(|(name, chapter, instruction)| {
            let key = name.to_ascii_lowercase();
            let tests = programs.iter().filter(|(_, words)| words.contains(&key)).map(|(p, _)| p.clone()).collect();
            let not_yet = rapid_vm::builtins::not_supported_reason(&name).map(str::to_owned);
            let option = rapid_lib::catalogue::options::of_chapter(chapter)
                .and_then(|option| Some((rapid_vm::builtins::option_refusal(&name, chapter)?, option.name)));
            let status = match (families.get(&key), not_yet, option) {
                (Some(file), _, _) => Status::Runs(file.clone()),
                (None, Some(reason), _) => Status::NotYet(reason),
                (None, None, Some((message, option))) => Status::Option(message, option),
                // The registry's own test refuses this; say so rather than hide it.
                (None, None, None) => Status::NotYet("(neither registered nor listed in not_yet.rs)".to_owned()),
            };
            Row { name, chapter, instruction, status, tests }
        })
        .collect();
    let rank = |chapter: &str| order.iter().position(|c| *c == chapter).unwrap_or(usize::MAX);
    rows.sort_by_key(|r| (rank(r.chapter), r.name.to_ascii_lowercase()));
    rows
}

/// The whole of `docs/builtins.md`.
pub(crate) fn render(root: &Path) -> String {
    let rows = rows(root);
    let mut out = format!(
        "# Built-in instructions and functions of `rapid run`\n\n\
         Generated by `{COMMAND}` (`xtask/src/builtins_doc.rs`); do not edit by hand.\n\n\
         Every instruction and function declared in the catalogue (`crates/rapid-lib/src/catalogue/*.rs`,\n\
         one file per chapter, and `options/*.rs`, one file per software option), crossed with the interpreter's registry (each family's `FAMILY` table in\n\
         `crates/rapid-vm/src/builtins/`, listed in `CORE_FAMILIES`, and the extensions of `crates/rapid-controller/src/builtin_set.rs`:\n\
         the robot's, `crates/rapid-robot/src/`); the routines it does not run yet are in\n\
         `builtins/not_yet.rs` with the reason) and the conformance programs (`tests/conformance/*.mod`):\n\n\
         - **run**: `rapid run` runs it (possibly with some options refused: see `docs/coverage.md`);\n  \
         **implemented in** names the file that registers it (`compile/call.rs`: the compiler turns\n  \
         the call into instructions of its own).\n\
         - **refused at load**: a program that calls it is refused when it is loaded\n  \
         (\"… is not supported by `rapid run` yet\"); the reason follows.\n\
         - **conformance tests**: the programs that name it as a whole word outside comments and\n  \
         string literals (letter case ignored), the first few alphabetically, then how many more.\n  \
         A name that is also a common word (`Type`, `Add`, `Open`) can match a program that only\n  \
         uses the word for data of its own.\n\n"
    );
    out.push_str(&catalogue_summary());
    out.push_str(
        "\n## Built-ins by chapter\n\n| catalogue file | built-ins | run | refused at load |\n|---|---:|---:|---:|\n",
    );
    let mut chapters: Vec<&str> = Vec::new();
    for row in &rows {
        if !chapters.contains(&row.chapter) {
            chapters.push(row.chapter);
        }
    }
    for chapter in &chapters {
        let of: Vec<&Row> = rows.iter().filter(|r| r.chapter == *chapter).collect();
        out.push_str(&summary_line(&format!("`{chapter}.rs`"), &of));
    }
    out.push_str(&summary_line("**all**", &rows.iter().collect::<Vec<_>>()));
    out.push_str(
        "\n## Every built-in\n\n| built-in | catalogue file | `rapid run` | implemented in | conformance tests |\n\
         |---|---|---|---|---|\n",
    );
    for row in &rows {
        let (status, place) = match &row.status {
            Status::Runs(file) => ("run".to_string(), format!("`{file}`")),
            Status::NotYet(reason) | Status::Option(reason, _) => {
                (format!("refused at load: {reason}"), "—".to_string())
            }
        };
        out.push_str(&format!(
            "| {} | `{}.rs` | {status} | {place} | {} |\n",
            row.name,
            row.chapter,
            tests_cell(&row.tests)
        ));
    }
    out
}

/// What each chapter file of the catalogue declares, by kind.
fn catalogue_summary() -> String {
    let mut out = String::from(
        "## The catalogue\n\n| catalogue file | types | data | instructions and functions |\n|---|---:|---:|---:|\n",
    );
    let mut totals = [0usize; 3];
    for (chapter, entries) in chapters() {
        let mut counts = [0usize; 3];
        for entry in entries {
            let column = match entry.kind {
                EntryKind::TypeDecl
                | EntryKind::AtomicValue
                | EntryKind::NonValue
                | EntryKind::SemiValue
                | EntryKind::Opaque => 0,
                EntryKind::Data | EntryKind::ReadOnlyData => 1,
                EntryKind::Routine => 2,
            };
            counts[column] += 1;
            totals[column] += 1;
        }
        out.push_str(&format!("| `{chapter}.rs` | {} | {} | {} |\n", counts[0], counts[1], counts[2]));
    }
    out.push_str(&format!("| **all** | {} | {} | {} |\n", totals[0], totals[1], totals[2]));
    out
}

/// Every chapter of the catalogue, then every software option's, with its entries.
pub(crate) fn chapters() -> impl Iterator<Item = (&'static str, &'static [Entry])> {
    ALL_CHAPTERS.iter().copied().chain(ALL_OPTIONS.iter().map(|option| (option.chapter, option.entries)))
}

fn summary_line(label: &str, rows: &[&Row]) -> String {
    let run = rows.iter().filter(|r| matches!(r.status, Status::Runs(_))).count();
    format!("| {label} | {} | {run} | {} |\n", rows.len(), rows.len() - run)
}

fn tests_cell(tests: &[String]) -> String {
    if tests.is_empty() {
        return "—".to_string();
    }
    let shown: Vec<String> = tests.iter().take(SHOWN_TESTS).map(|t| format!("`{t}`")).collect();
    let mut cell = shown.join(", ");
    if tests.len() > SHOWN_TESTS {
        cell.push_str(&format!(" (+{} more)", tests.len() - SHOWN_TESTS));
    }
    cell
}

/// Writes `docs/builtins.md`, then the generated section of `docs/coverage.md`.
pub(crate) fn write(root: &Path) -> std::io::Result<()> {
    write_atomic(&root.join(PATH), &render(root))?;
    crate::coverage_doc::write(root)
}

/// Writes `text` to `path` through a temporary file, so a failed write leaves the old
/// copy whole.
pub(crate) fn write_atomic(path: &Path, text: &str) -> std::io::Result<()> {
    let tmp = path.with_extension("md.tmp");
    fs::write(&tmp, text)?;
    fs::rename(&tmp, path)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builtins_doc_is_fresh() {
        let root = root();
        let actual = fs::read_to_string(root.join(PATH)).unwrap_or_default();
        assert!(actual == render(&root), "{PATH} is stale: run `{COMMAND}`");
    }

    #[test]
    fn words_skip_comments_and_strings() {
        let found = words("  TPWrite \"StrLen\" + ArgName(x); ! Abs here\n  s := \"a\"\"Dim\"\"b\" + Type(y);");
        let expected: BTreeSet<String> =
            ["tpwrite", "argname", "x", "s", "type", "y"].iter().map(|w| w.to_string()).collect();
        assert_eq!(found, expected);
    }

    #[test]
    fn compiled_built_ins_count_as_run_and_the_rest_give_a_reason() {
        let rows = rows(&root());
        let status = |name: &str| &rows.iter().find(|r| r.name == name).expect("a catalogue routine").status;
        assert!(matches!(status("Present"), Status::Runs(file) if file == "compile/call.rs"));
        assert!(matches!(status("Continue"), Status::Runs(file) if file == "compile/call.rs"));
        assert!(matches!(status("StrLen"), Status::Runs(file) if file == "builtins/strings.rs"));
        assert!(matches!(status("WaitSensor"), Status::NotYet(reason) if !reason.is_empty()));
        assert!(matches!(status("EGMReset"), Status::Option(_, option) if option.contains("EGM")));
        assert!(rows.iter().find(|r| r.name == "MoveL").is_some_and(|r| r.instruction));
        assert!(rows.iter().find(|r| r.name == "StrLen").is_some_and(|r| !r.instruction));
    }
}
