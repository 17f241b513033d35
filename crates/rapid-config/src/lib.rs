//! rapid-config: ABB's `.cfg` system parameter files (EIO, SYS, MOC, …) as RobotWare
//! writes them into a backup's `SYSPAR` folder.
//!
//! Invariant: no IO. A file arrives as text; [`parse`] never fails (every malformed line
//! becomes a [`CfgError`] with its line, the rest is kept), and the original text is
//! kept so [`CfgFile::with_value`] can re-emit the file with one value changed and
//! every other byte the same. Typed views ([`eio`], [`sys`], [`moc`]) read the parsed
//! instances; their findings are `CfgError`s too.

mod edit;
pub use edit::{find_named, EditError};
pub mod eio;
pub mod moc;
mod parse;
pub mod sys;

pub use parse::parse;

use std::ops::Range;

/// A parsed `.cfg` file.
#[derive(Debug, Clone, Default)]
pub struct CfgFile {
    /// The file's text as given (edits are made against it).
    pub text: String,
    /// The first line, `EIO:CFG_1.0:6:1::`, when there is one.
    pub header: Option<Header>,
    /// The type sections, in file order.
    pub sections: Vec<Section>,
    /// What could not be read.
    pub errors: Vec<CfgError>,
}

/// The header line: `DOMAIN:FORMAT:MAJOR:MINOR::`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Header {
    /// The configuration domain (`EIO`, `SYS`, `MOC`, `PROC`, `SIO`, `MMC`).
    pub domain: String,
    /// The file format (`CFG_1.0`).
    pub format: String,
    /// The version fields after the format, e.g. `["6", "1"]`.
    pub version: Vec<String>,
    pub span: Range<usize>,
}

/// A type section: `#` and then `EIO_SIGNAL:` and its instances. A type line may name
/// the section too, `MMC_MC1 = MMC_PALETTE:` (a named instance list of a type, as
/// RobotWare writes the pendant's instruction palettes in MMC.cfg).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Section {
    /// The type name as written (`EIO_SIGNAL`, `MMC_PALETTE`).
    pub name: String,
    /// The section's own name before `=` (`MMC_MC1`), when the type line gives one.
    pub label: Option<String>,
    pub line: u32,
    /// The span of the type line.
    pub span: Range<usize>,
    pub instances: Vec<Instance>,
}

/// One instance: a logical line of `-Attr value` pairs, possibly spread over physical
/// lines joined by a trailing `\`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Instance {
    /// The line the instance starts on (1-based).
    pub line: u32,
    /// From the first `-` to the end of its last physical line (newline excluded).
    pub span: Range<usize>,
    pub attrs: Vec<Attr>,
}

/// `-Name "value"`, `-Name value` or a bare `-Flag`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Attr {
    /// The attribute name without its dash, as written.
    pub name: String,
    /// The span of `-Name`.
    pub name_span: Range<usize>,
    /// The value; `None` for a flag.
    pub value: Option<AttrValue>,
}

/// An attribute's value.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct AttrValue {
    /// The value without its quotes.
    pub text: String,
    /// Whether it was written in double quotes.
    pub quoted: bool,
    /// The span of the value as written, quotes included.
    pub span: Range<usize>,
}

/// A finding: something the parser or a typed view could not accept.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CfgError {
    /// The line (1-based).
    pub line: u32,
    /// Where in the text (byte offsets).
    pub span: Range<usize>,
    pub message: String,
}

impl CfgFile {
    /// The section of a type, compared without regard to case (RobotWare writes the
    /// type names in upper case; we accept what people type).
    pub fn section(&self, name: &str) -> Option<&Section> {
        self.sections.iter().find(|s| s.name.eq_ignore_ascii_case(name))
    }

    /// The instances of a type, across every section of that name.
    pub fn instances<'a>(&'a self, type_name: &'a str) -> impl Iterator<Item = &'a Instance> + 'a {
        self.sections.iter().filter(move |s| s.name.eq_ignore_ascii_case(type_name)).flat_map(|s| &s.instances)
    }

    /// The domain named by the header (`EIO`), if there is a header.
    pub fn domain(&self) -> Option<&str> {
        self.header.as_ref().map(|h| h.domain.as_str())
    }

    /// The 1-based line of a byte offset.
    pub fn line_of(&self, offset: usize) -> u32 {
        line_of(&self.text, offset)
    }
}

impl Instance {
    /// The attribute of a name, compared without regard to case (`-Name` and `-name`
    /// both occur in files RobotWare wrote); the first when it is repeated.
    pub fn attr(&self, name: &str) -> Option<&Attr> {
        self.attrs.iter().find(|a| a.name.eq_ignore_ascii_case(name))
    }

    /// Every value of an attribute, in order: an attribute RobotWare lets repeat
    /// (`-Task "A" -Task "B"`) gives one value each time it is written.
    pub fn values<'a>(&'a self, name: &'a str) -> impl Iterator<Item = &'a str> + 'a {
        self.attrs
            .iter()
            .filter(move |a| a.name.eq_ignore_ascii_case(name))
            .filter_map(|a| a.value.as_ref().map(|v| v.text.as_str()))
    }

    /// The value of an attribute; `None` when absent or a flag.
    pub fn value(&self, name: &str) -> Option<&str> {
        self.attr(name)?.value.as_ref().map(|v| v.text.as_str())
    }

    /// Whether an attribute is present (a flag, or with a value).
    pub fn has(&self, name: &str) -> bool {
        self.attr(name).is_some()
    }

    /// The `-Name` of the instance (most types identify instances by it).
    pub fn name(&self) -> Option<&str> {
        self.value("Name")
    }
}

/// The 1-based line of a byte offset in `text`.
pub(crate) fn line_of(text: &str, offset: usize) -> u32 {
    let end = offset.min(text.len());
    let newlines = text.as_bytes()[..end].iter().filter(|&&b| b == b'\n').count();
    u32::try_from(newlines).unwrap_or(u32::MAX - 1) + 1
}
