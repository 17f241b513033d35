//! Formats every module under `tests/` (the checker's fixtures, the multi-module
//! programs, the backups and the conformance corpus) in memory and asserts, for each
//! file the formatter accepts: the output checks to the same diagnostic codes, as many
//! of each (spans may move), with no syntax error; it holds every comment of the input,
//! in order; and formatting it again changes nothing. No file is refused as unsafe;
//! files with syntax errors are refused and left alone.

use std::fs;
use std::path::{Path, PathBuf};

use rapid_fmt::{format, Config, Refusal};
use rapid_sema::{check, Options, SourceInput};
use rapid_syntax::lexer::Lexer;
use rapid_syntax::source::{decode, Encoding};
use rapid_syntax::token::TokenKind;

fn module_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = fs::read_dir(dir).unwrap().flatten().map(|e| e.path()).collect();
    entries.sort();
    for path in entries {
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase();
        if path.is_dir() {
            module_files(&path, out);
        } else if matches!(ext.as_str(), "mod" | "modx" | "sys" | "sysx" | "prg") {
            out.push(path);
        }
    }
}

fn codes(text: &str) -> Vec<&'static str> {
    let diags = check(&[SourceInput::from_text("m.mod", text)], &Options::default());
    let mut codes: Vec<_> = diags.iter().map(|d| d.code.as_str()).collect();
    codes.sort_unstable();
    codes
}

fn comments(text: &str) -> Vec<&str> {
    let mut lexer = Lexer::new(text);
    while lexer.next_token().kind != TokenKind::Eof {}
    lexer.comments.iter().map(|c| c.text(text)).collect()
}

/// What went wrong with one file, if anything; `Ok(true)` when it was formatted.
fn format_one(text: &str, config: &Config) -> Result<bool, String> {
    let out = match format(text, config) {
        Ok(out) => out,
        Err(Refusal::SyntaxErrors(_)) => return Ok(false),
        Err(Refusal::Unsafe { offset, message }) => return Err(format!("unsafe at byte {offset}: {message}")),
    };
    let (before, after) = (codes(text), codes(&out));
    if before != after {
        return Err(format!("diagnostics changed: {before:?} -> {after:?}"));
    }
    if after.iter().any(|code| code.starts_with("E01")) {
        return Err(format!("the output has syntax errors: {after:?}"));
    }
    if comments(text) != comments(&out) {
        return Err("comments changed".into());
    }
    match format(&out, config) {
        Ok(again) if again == out => Ok(true),
        Ok(_) => Err("formatting twice changed the output again".into()),
        Err(refusal) => Err(format!("the output was refused: {refusal:?}")),
    }
}

fn run_corpus(config: &Config) -> usize {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests");
    let mut files = Vec::new();
    module_files(&root, &mut files);
    let mut problems = Vec::new();
    let mut formatted = 0;
    for path in &files {
        let Ok(source) = decode(fs::read(path).unwrap()) else { continue };
        if source.encoding == Encoding::Utf16 {
            continue;
        }
        match format_one(&source.text, config) {
            Ok(true) => formatted += 1,
            Ok(false) => {}
            Err(problem) => problems.push(format!("{}: {problem}", path.display())),
        }
    }
    assert!(problems.is_empty(), "{} of {} files:\n{}", problems.len(), files.len(), problems.join("\n"));
    formatted
}

#[test]
fn every_module_of_the_corpus_formats_safely() {
    let formatted = run_corpus(&Config::default());
    // tests/ holds over 700 modules; most have no syntax error.
    assert!(formatted > 500, "only {formatted} files were formatted");
}

#[test]
fn the_corpus_formats_safely_when_everything_wraps() {
    // A narrow width wraps nearly every statement with commas.
    let config = Config { max_width: 30, indent_width: 2, aggregate_spaces: true, max_blank_lines: 0 };
    assert!(run_corpus(&config) > 500);
}
