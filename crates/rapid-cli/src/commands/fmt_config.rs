//! The `[fmt]` table of `rapid.toml`: the formatter's options for the modules under
//! the manifest's folder (docs/fmt.md). The nearest `rapid.toml` in a module's folder
//! or above it applies; other tables of the file are the manifest's and are ignored
//! here. A missing table or key keeps the default.

use std::path::{Path, PathBuf};

use anyhow::{bail, Context};
use rustc_hash::FxHashMap;
use serde::Deserialize;

#[derive(Debug, Default, Deserialize)]
struct RawFile {
    fmt: Option<RawFmt>,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFmt {
    indent_width: Option<usize>,
    max_width: Option<usize>,
    max_blank_lines: Option<usize>,
    aggregate_spaces: Option<bool>,
}

/// The configuration of each folder, found once.
#[derive(Debug, Default)]
pub(crate) struct Configs {
    by_folder: FxHashMap<PathBuf, rapid_fmt::Config>,
}

impl Configs {
    /// The configuration for a module in `folder`.
    pub(crate) fn for_folder(&mut self, folder: &Path) -> anyhow::Result<rapid_fmt::Config> {
        let folder = folder.canonicalize().unwrap_or_else(|_| folder.to_path_buf());
        if let Some(config) = self.by_folder.get(&folder) {
            return Ok(config.clone());
        }
        let config = match folder.ancestors().map(|dir| dir.join("rapid.toml")).find(|path| path.is_file()) {
            Some(manifest) => read(&manifest)?,
            None => rapid_fmt::Config::default(),
        };
        self.by_folder.insert(folder, config.clone());
        Ok(config)
    }
}

fn read(path: &Path) -> anyhow::Result<rapid_fmt::Config> {
    let text = std::fs::read_to_string(path).with_context(|| format!("cannot read `{}`", path.display()))?;
    parse(&text).with_context(|| format!("`{}`: bad [fmt] table", path.display()))
}

fn parse(text: &str) -> anyhow::Result<rapid_fmt::Config> {
    let raw: RawFile = toml::from_str(text)?;
    let raw = raw.fmt.unwrap_or_default();
    let default = rapid_fmt::Config::default();
    let config = rapid_fmt::Config {
        indent_width: raw.indent_width.unwrap_or(default.indent_width),
        max_width: raw.max_width.unwrap_or(default.max_width),
        max_blank_lines: raw.max_blank_lines.unwrap_or(default.max_blank_lines),
        aggregate_spaces: raw.aggregate_spaces.unwrap_or(default.aggregate_spaces),
    };
    if !(1..=8).contains(&config.indent_width) {
        bail!("indent_width must be 1 to 8, not {}", config.indent_width);
    }
    if config.max_width != 0 && config.max_width < 20 {
        bail!("max_width must be 0 (never wrap) or at least 20, not {}", config.max_width);
    }
    Ok(config)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_override_defaults_and_other_tables_are_ignored() {
        let config = parse("[system]\nname = \"x\"\n\n[fmt]\nindent_width = 2\naggregate_spaces = true\n").unwrap();
        assert_eq!(config.indent_width, 2);
        assert!(config.aggregate_spaces);
        assert_eq!(config.max_width, 120);
        assert_eq!(parse("").unwrap(), rapid_fmt::Config::default());
    }

    #[test]
    fn bad_values_and_unknown_keys_are_errors() {
        assert!(parse("[fmt]\nindent_width = 0\n").is_err());
        assert!(parse("[fmt]\nmax_width = 5\n").is_err());
        assert!(parse("[fmt]\nindent = 2\n").is_err());
    }
}
