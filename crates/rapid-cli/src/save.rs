//! Writing a module file back safely: the file is re-read and must still be what was
//! loaded; the new text is encoded as the file was (UTF-8 with or without BOM, or
//! Latin-1) and written atomically (a temporary file beside it, fsync, rename over
//! it, fsync of the folder: [`rapid_controller::host_std::atomic::write_atomic`]), so a crash or a kill
//! at any moment leaves the old or the new file, never half a file.

use std::collections::HashSet;
use std::fs;
use std::path::Path;

use anyhow::{bail, Context};
use rapid_sema::SourceInput;
use rapid_syntax::source::{decode, Encoding};

/// `--save-pers`: writes each changed persistent's value into its module file (Save
/// Module). Every file is tried even when one fails, so one unwritable module does
/// not cost the others their values; the failures are reported together.
///
/// `written` holds the module files saved so far by the other tasks of the system: a
/// shared module (`-Shared`) is in every task's file list, its persistents one object,
/// so it is written once, by the first task that changed one of them (the others
/// would find it changed on disk).
pub(crate) fn save_persistents(
    loaded: &rapid_vm::Loaded,
    files: &[SourceInput],
    written: &mut HashSet<String>,
) -> anyhow::Result<()> {
    save_persistents_where(loaded, files, &|_| true, written)
}

/// [`save_persistents`] of the persistents `keep` names by their index in
/// `loaded.persistents` (`rapid serve` saves those that changed since boot).
pub(crate) fn save_persistents_where(
    loaded: &rapid_vm::Loaded,
    files: &[SourceInput],
    keep: &dyn Fn(usize) -> bool,
    written: &mut HashSet<String>,
) -> anyhow::Result<()> {
    let mut failures = Vec::new();
    for (file, input) in files.iter().enumerate() {
        if written.contains(&input.path) {
            continue;
        }
        let sites: Vec<_> = loaded
            .persistents
            .iter()
            .enumerate()
            .filter(|(idx, s)| s.file == file && keep(*idx))
            .map(|(_, s)| s)
            .filter_map(|s| loaded.vm.global(s.global).map(|v| (s, v)))
            .collect();
        let Some(new_text) = rapid_vm::persist::rewrite(&input.text, &sites) else { continue };
        match write_module(Path::new(&input.path), &input.text, &new_text) {
            Ok(()) => {
                written.insert(input.path.clone());
            }
            Err(e) => failures.push(format!("{e:#}")),
        }
    }
    match failures.len() {
        0 => Ok(()),
        _ => bail!("{}", failures.join("\nerror: ")),
    }
}

/// Replaces the module at `path`, loaded as `loaded_text`, with `new_text`.
pub(crate) fn write_module(path: &Path, loaded_text: &str, new_text: &str) -> anyhow::Result<()> {
    let shown = path.display();
    let bytes = fs::read(path).with_context(|| format!("cannot re-read `{shown}` to save persistents"))?;
    let had_bom = bytes.starts_with(&[0xEF, 0xBB, 0xBF]);
    let source = decode(bytes).map_err(|_| anyhow::anyhow!("`{shown}` cannot be saved: it is not a text module"))?;
    if source.text != loaded_text {
        bail!("`{shown}` changed on disk while the program ran; persistents not saved");
    }
    let encoded = match source.encoding {
        Encoding::Utf8 => {
            let mut out = if had_bom { vec![0xEF, 0xBB, 0xBF] } else { Vec::new() };
            out.extend_from_slice(new_text.as_bytes());
            out
        }
        Encoding::Latin1 => new_text
            .chars()
            .map(|c| u8::try_from(u32::from(c)).map_err(|_| anyhow::anyhow!("a value of `{shown}` is not Latin-1")))
            .collect::<anyhow::Result<Vec<u8>>>()?,
        Encoding::Utf16 => bail!("`{shown}` is UTF-16; saving persistents into it is not supported"),
    };
    rapid_controller::host_std::atomic::write_atomic(path, &encoded)
        .with_context(|| format!("cannot save persistents into `{shown}`"))
}

/// Writes a file the run produces (a log) atomically, like a module.
pub(crate) fn write_new(path: &Path, bytes: &[u8]) -> anyhow::Result<()> {
    rapid_controller::host_std::atomic::write_atomic(path, bytes)
        .with_context(|| format!("cannot write `{}`", path.display()))
}

/// [`write_new`] with the content streamed by `fill`.
pub(crate) fn write_new_with(
    path: &Path,
    fill: impl FnOnce(&mut dyn std::io::Write) -> std::io::Result<()>,
) -> anyhow::Result<()> {
    rapid_controller::host_std::atomic::write_atomic_with(path, fill)
        .with_context(|| format!("cannot write `{}`", path.display()))
}
