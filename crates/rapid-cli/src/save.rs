//! Writing a module file back safely: the file is re-read and must still be what was
//! loaded; the new text is encoded as the file was (UTF-8 with or without BOM, or
//! Latin-1), written beside it and renamed over it, so a crash never leaves half a file.

use std::fs;
use std::io::Write;
use std::path::Path;

use anyhow::{bail, Context};
use rapid_syntax::source::{decode, Encoding};

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
    let dir = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let tmp = dir.join(format!(".{name}.rapid-save.tmp"));
    let mut file = fs::File::create(&tmp).with_context(|| format!("cannot write `{}`", tmp.display()))?;
    file.write_all(&encoded)?;
    file.sync_all()?;
    drop(file);
    fs::rename(&tmp, path).with_context(|| format!("cannot replace `{shown}`"))?;
    Ok(())
}

/// Writes a file the run produces (a log) beside its place and renames it over, so a
/// crash never leaves half a file.
pub(crate) fn write_new(path: &Path, bytes: &[u8]) -> anyhow::Result<()> {
    let dir = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let tmp = dir.join(format!(".{name}.rapid-write.tmp"));
    let mut file = fs::File::create(&tmp).with_context(|| format!("cannot write `{}`", tmp.display()))?;
    file.write_all(bytes)?;
    file.sync_all()?;
    drop(file);
    fs::rename(&tmp, path).with_context(|| format!("cannot write `{}`", path.display()))?;
    Ok(())
}
