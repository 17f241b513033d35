//! `rapid fmt [--check] PATH...` and `rapid fmt -`: lays out RAPID modules as
//! RobotStudio's editor does (rapid-fmt; docs/fmt.md).
//!
//! Each PATH is a module file or a folder (its module files, not its subfolders, as
//! `rapid check` reads folders). A file is rewritten only when its layout changes, in
//! its own encoding (UTF-8 with or without BOM, or Latin-1) and line ends, atomically
//! (a temporary file beside it, then a rename). A file with syntax errors, an encrypted
//! or UTF-16 file is left as it is and reported on stderr. `--check` writes nothing and
//! prints the files that would change. `-` reads one module from stdin and writes it
//! formatted to stdout (nothing on stdout when it is refused).
//!
//! Exit status: 0 when every file is (or, with `--check`, already was) formatted; 1 when
//! a file would change (`--check`) or was refused; 2 for bad usage or unreadable paths.

#![allow(clippy::print_stderr, clippy::print_stdout)]

use std::io::{self, Read, Write};
use std::path::{Path, PathBuf};

use anyhow::{bail, Context};
use rapid_syntax::source::{decode, Encoding};
use rapid_syntax::LineIndex;

use crate::args::FmtArgs;
use crate::commands::fmt_config::Configs;
use crate::commands::ExitStatus;
use rapid_controller::assembly::inputs::MODULE_EXTENSIONS;

pub(crate) fn run(args: &FmtArgs) -> anyhow::Result<ExitStatus> {
    let stdin_dash = args.paths.iter().any(|p| p.as_os_str() == "-");
    if stdin_dash {
        if args.paths.len() > 1 {
            bail!("`-` (stdin) cannot be given with other paths");
        }
        return stdin(args.check);
    }
    let mut configs = Configs::default();
    let mut status = ExitStatus::Success;
    let mut stdout = io::stdout().lock();
    for path in module_paths(&args.paths)? {
        let config = configs.for_folder(path.parent().unwrap_or(Path::new(".")))?;
        match format_file(&path, &config, args.check)? {
            Outcome::Unchanged => {}
            Outcome::Changed if args.check => {
                writeln!(stdout, "{}", path.display())?;
                status = ExitStatus::Failure;
            }
            Outcome::Changed => {}
            Outcome::Refused(why) => {
                eprintln!("error: {}: not formatted: {why}", path.display());
                status = ExitStatus::Failure;
            }
        }
    }
    stdout.flush()?;
    Ok(status)
}

enum Outcome {
    Unchanged,
    Changed,
    Refused(String),
}

/// The files to format, in the order given (a folder's in name order), each once.
fn module_paths(paths: &[PathBuf]) -> anyhow::Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    for path in paths {
        if path.is_dir() {
            let entries =
                std::fs::read_dir(path).with_context(|| format!("cannot read folder `{}`", path.display()))?;
            let mut found: Vec<PathBuf> = entries.flatten().map(|e| e.path()).filter(|p| is_module(p)).collect();
            found.sort();
            files.extend(found);
        } else if path.is_file() {
            files.push(path.clone());
        } else {
            bail!("`{}` is not a file or folder", path.display());
        }
    }
    let mut seen = rustc_hash::FxHashSet::default();
    files.retain(|p| seen.insert(p.canonicalize().unwrap_or_else(|_| p.clone())));
    Ok(files)
}

fn is_module(path: &Path) -> bool {
    let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
    path.is_file() && MODULE_EXTENSIONS.iter().any(|known| ext.eq_ignore_ascii_case(known))
}

fn format_file(path: &Path, config: &rapid_fmt::Config, check: bool) -> anyhow::Result<Outcome> {
    let bytes = std::fs::read(path).with_context(|| format!("cannot read `{}`", path.display()))?;
    let had_bom = bytes.starts_with(&[0xEF, 0xBB, 0xBF]);
    let source = match decode(bytes) {
        Ok(source) if source.encoding == Encoding::Utf16 => {
            return Ok(Outcome::Refused("UTF-16 files are not formatted".into()))
        }
        Ok(source) => source,
        Err(_) => return Ok(Outcome::Refused("an encrypted module cannot be read".into())),
    };
    let formatted = match rapid_fmt::format(&source.text, config) {
        Ok(formatted) => formatted,
        Err(refusal) => return Ok(Outcome::Refused(explain(&source.text, &refusal))),
    };
    if formatted == source.text {
        return Ok(Outcome::Unchanged);
    }
    if !check {
        let written = match source.encoding {
            // UTF-8 is written as it is, without a copy (a CAM module is 150 MB).
            Encoding::Utf8 => {
                rapid_controller::host_std::atomic::write_atomic_with(path, |out| write_utf8(out, &formatted, had_bom))
            }
            _ => rapid_controller::host_std::atomic::write_atomic(path, &encode(&formatted, source.encoding, had_bom)?),
        };
        written.with_context(|| format!("cannot write `{}`", path.display()))?;
    }
    Ok(Outcome::Changed)
}

/// The text in the file's own encoding. The formatter adds only ASCII, so Latin-1
/// text stays Latin-1.
fn encode(text: &str, encoding: Encoding, bom: bool) -> anyhow::Result<Vec<u8>> {
    match encoding {
        Encoding::Utf8 => {
            let mut out = if bom { vec![0xEF, 0xBB, 0xBF] } else { Vec::new() };
            out.extend_from_slice(text.as_bytes());
            Ok(out)
        }
        Encoding::Latin1 => text
            .chars()
            .map(|c| u8::try_from(u32::from(c)).map_err(|_| anyhow::anyhow!("character {c:?} is not Latin-1")))
            .collect(),
        Encoding::Utf16 => bail!("UTF-16 files are not formatted"),
    }
}

fn write_utf8(out: &mut dyn Write, text: &str, bom: bool) -> io::Result<()> {
    if bom {
        out.write_all(&[0xEF, 0xBB, 0xBF])?;
    }
    out.write_all(text.as_bytes())
}

/// Why a text was refused, with the first syntax error's line and column.
fn explain(text: &str, refusal: &rapid_fmt::Refusal) -> String {
    let at = |offset: u32| {
        let pos = LineIndex::new(text).line_col(text, offset);
        format!("{}:{}", pos.line, pos.column)
    };
    match refusal {
        rapid_fmt::Refusal::SyntaxErrors(errors) => {
            let first =
                errors.first().map_or(String::new(), |e| format!(" (first at {}: {})", at(e.span.start), e.message));
            format!("{} syntax error(s){first}; run `rapid check`", errors.len())
        }
        rapid_fmt::Refusal::Unsafe { offset, message } => format!("{} at {}", message, at(*offset)),
    }
}

/// `rapid fmt -`: stdin to stdout (UTF-8, or Latin-1 when the bytes are not UTF-8).
fn stdin(check: bool) -> anyhow::Result<ExitStatus> {
    let mut bytes = Vec::new();
    io::stdin().lock().read_to_end(&mut bytes).context("cannot read stdin")?;
    let had_bom = bytes.starts_with(&[0xEF, 0xBB, 0xBF]);
    let source = match decode(bytes) {
        Ok(source) if source.encoding != Encoding::Utf16 => source,
        _ => {
            eprintln!("error: <stdin>: not formatted: not a readable module (encrypted or UTF-16)");
            return Ok(ExitStatus::Failure);
        }
    };
    let config = Configs::default().for_folder(&std::env::current_dir().unwrap_or_else(|_| PathBuf::from(".")))?;
    let formatted = match rapid_fmt::format(&source.text, &config) {
        Ok(formatted) => formatted,
        Err(refusal) => {
            eprintln!("error: <stdin>: not formatted: {}", explain(&source.text, &refusal));
            return Ok(ExitStatus::Failure);
        }
    };
    if check {
        if formatted == source.text {
            return Ok(ExitStatus::Success);
        }
        println!("<stdin>");
        return Ok(ExitStatus::Failure);
    }
    let mut out = io::stdout().lock();
    match source.encoding {
        Encoding::Utf8 => write_utf8(&mut out, &formatted, had_bom)?,
        _ => out.write_all(&encode(&formatted, source.encoding, had_bom)?)?,
    }
    out.flush()?;
    Ok(ExitStatus::Success)
}
