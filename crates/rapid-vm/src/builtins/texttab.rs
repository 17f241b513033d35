//! User text tables (§1.17): TextTabInstall, TextTabGet, TextGet and TextTabFreeToUse.
//!
//! A text table is a text resource file on a file device (`HOME:/text_file.eng`). Its
//! format, as we read it:
//!
//! ```text
//! # a comment line
//! my_texts::
//! 1:
//! the text of index 1
//! 2:
//! the text of index 2
//! ```
//!
//! The line `NAME::` starts a table (the text resource name); a line `N:` gives the
//! index of the text on the next line. Lines starting with `#`, and blank lines between
//! entries, are skipped. Installed tables belong to the controller, not to one run of
//! the program, so PP to Main does not remove them (the manual installs them from the
//! START/POWER_ON event routines, guarded by TextTabFreeToUse).

use rustc_hash::FxHashMap;

use super::{native, present, Ctx, Family};
use crate::errnames::Err;
use crate::error::RapidError;
use crate::value::{Value, MAX_STRING_CHARS};

type Res = Result<Option<Value>, RapidError>;

pub(super) static FAMILY: Family = Family {
    file: file!(),
    builtins: &[
        native("TextTabInstall", text_tab_install),
        native("TextTabGet", text_tab_get),
        native("TextGet", text_get),
        native("TextTabFreeToUse", text_tab_free_to_use),
    ],
};

/// The installed text tables; a table's number is its position plus one.
#[derive(Default)]
pub struct TextTabState {
    tables: Vec<TextTable>,
}

/// One installed text resource.
#[derive(Debug, Clone, PartialEq, Eq)]
struct TextTable {
    name: String,
    texts: FxHashMap<u32, String>,
}

impl TextTabState {
    /// The number of the table named `name` (any letter case).
    fn number_of(&self, name: &str) -> Option<usize> {
        self.tables.iter().position(|t| t.name.eq_ignore_ascii_case(name)).map(|i| i + 1)
    }
}

// ---- the file format ---------------------------------------------------------------------------

/// What is wrong with a text table file, and on which line (1-based).
#[derive(Debug, Clone, PartialEq, Eq)]
struct FormatFault {
    line: usize,
    what: &'static str,
}

/// The `NAME` of a `NAME::` line.
fn table_header(line: &str) -> Option<&str> {
    let name = line.strip_suffix("::")?.trim();
    (!name.is_empty() && !name.contains(char::is_whitespace)).then_some(name)
}

/// The `N` of an `N:` line.
fn index_line(line: &str) -> Option<u32> {
    let digits = line.strip_suffix(':')?.trim();
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    digits.parse().ok()
}

/// Reads the tables of one file (bytes are Latin-1 characters).
// uncertain: ABB's manual points to a separate description of the text file format
// that is not public; this is the `NAME::` / `N:` / text layout of ABB's examples as
// we know it. A text is exactly the one line after its index line (even when that line
// looks like an index), and texts longer than a RAPID string are cut to 80 characters.
fn parse_tables(bytes: &[u8]) -> Result<Vec<TextTable>, FormatFault> {
    let text: String = bytes.iter().map(|&b| char::from(b)).collect();
    let mut tables: Vec<TextTable> = Vec::new();
    let mut lines = text.lines().map(|l| l.strip_suffix('\r').unwrap_or(l)).enumerate();
    while let Some((no, line)) = lines.next() {
        let trimmed = line.trim();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            continue;
        }
        if let Some(name) = table_header(trimmed) {
            tables.push(TextTable { name: name.to_string(), texts: FxHashMap::default() });
            continue;
        }
        let Some(index) = index_line(trimmed) else {
            return Err(FormatFault { line: no + 1, what: "expected `NAME::` or an index line `N:`" });
        };
        let Some(table) = tables.last_mut() else {
            return Err(FormatFault { line: no + 1, what: "an index comes before the `NAME::` line" });
        };
        let entry = lines.next().map_or("", |(_, l)| l);
        table.texts.insert(index, entry.chars().take(MAX_STRING_CHARS).collect());
    }
    if tables.is_empty() {
        return Err(FormatFault { line: 1, what: "no `NAME::` line names the text table" });
    }
    Ok(tables)
}

// ---- the built-ins -------------------------------------------------------------------------------

/// `TextTabInstall File`: installs the text tables of a file. A file that cannot be
/// opened raises ERR_FILEOPEN (manual); a table already installed stays as it is.
// uncertain: installing a name that is already installed is silently skipped (the
// manual guards every install with TextTabFreeToUse and names no error for it).
fn text_tab_install(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let file = ctx.string(&args[0])?;
    let resolved = ctx.resolve_path(&file).map_err(|fault| ctx.error(Err::FileOpen, fault.message()))?;
    let bytes = ctx
        .resources
        .devices
        .file_system()
        .read(&resolved.path)
        .map_err(|e| ctx.error(Err::FileOpen, format!("the text table file `{file}` cannot be opened: {e}")))?;
    // uncertain: a badly formed file stops the program (the controller reports it in
    // the event log); the manual names no RAPID error for it.
    let tables = parse_tables(&bytes)
        .map_err(|fault| RapidError::fatal(format!("text table file `{file}`, line {}: {}", fault.line, fault.what)))?;
    let state = &mut ctx.resources.texttab;
    for table in tables {
        if state.number_of(&table.name).is_none() {
            state.tables.push(table);
        }
    }
    Ok(None)
}

/// `TextTabGet(TableName)`: the number of an installed table; ERR_TXTNOEXIST if none
/// has that name.
fn text_tab_get(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let name = ctx.string(&args[0])?;
    match ctx.resources.texttab.number_of(&name) {
        Some(number) => Ok(Some(Value::Num(number as f32))),
        None => Err(ctx.error(Err::TextNotExist, format!("no text table named `{name}` is installed"))),
    }
}

/// `TextGet(Table Index [\Arg1] [\Arg2])`: the text at Index of table number Table,
/// with `{1}` and `{2}` replaced by the optional arguments. ERR_TXTNOEXIST if the table
/// or the index does not exist.
fn text_get(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let table = ctx.num(&args[0])?;
    let index = ctx.num(&args[1])?;
    let text = lookup_text(&ctx.resources.texttab, table, index).map(str::to_string);
    let Some(mut text) = text else {
        return Err(ctx.error(Err::TextNotExist, format!("text table {table} has no text with index {index}")));
    };
    // uncertain: the `{1}`/`{2}` replacement is from our reference notes only
    // (semantics.md §3.1); without the arguments the placeholders stay as they are.
    for (placeholder, arg) in [("{1}", args.get(2)), ("{2}", args.get(3))] {
        if let Some(arg) = arg.filter(|a| present(Some(a))) {
            let value = ctx.string(arg)?;
            text = text.replace(placeholder, &value);
        }
    }
    if text.chars().count() > MAX_STRING_CHARS {
        return Err(ctx.error(Err::StringTooLong, "the text with its arguments is longer than 80 characters"));
    }
    Ok(Some(Value::Str(text.as_str().into())))
}

/// The text of table number `table` at `index`, if both exist (numbers are integers).
fn lookup_text(state: &TextTabState, table: f64, index: f64) -> Option<&str> {
    if table.fract() != 0.0 || index.fract() != 0.0 || table < 1.0 || index < 0.0 || index > f64::from(u32::MAX) {
        return None;
    }
    let table = state.tables.get(table as usize - 1)?;
    table.texts.get(&(index as u32)).map(String::as_str)
}

/// `TextTabFreeToUse(TableName)`: TRUE while no table of that name is installed.
fn text_tab_free_to_use(ctx: &mut Ctx<'_>, args: &[Value]) -> Res {
    let name = ctx.string(&args[0])?;
    Ok(Some(Value::Bool(ctx.resources.texttab.number_of(&name).is_none())))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_tables_indices_and_comments() {
        let file = b"# comment\r\nmy_tab::\r\n# texts\r\n1:\r\nfirst text\r\n\r\n2:\r\n3:\r\n";
        let tables = parse_tables(file).expect("well formed");
        assert_eq!(tables.len(), 1);
        assert_eq!(tables[0].name, "my_tab");
        assert_eq!(tables[0].texts.get(&1).map(String::as_str), Some("first text"));
        // The line after an index is its text, even when it looks like an index.
        assert_eq!(tables[0].texts.get(&2).map(String::as_str), Some("3:"));
    }

    #[test]
    fn latin1_and_long_texts() {
        let mut file = b"t::\n0:\n\xe5\xe4\xf6 ".to_vec();
        file.extend(std::iter::repeat_n(b'x', 100));
        let tables = parse_tables(&file).expect("well formed");
        let text = &tables[0].texts[&0];
        assert!(text.starts_with("åäö "));
        assert_eq!(text.chars().count(), MAX_STRING_CHARS);
    }

    #[test]
    fn format_faults_name_their_line() {
        assert_eq!(parse_tables(b"1:\nx\n").unwrap_err().line, 1);
        assert_eq!(parse_tables(b"t::\n1:\nx\nstray\n").unwrap_err().line, 4);
        assert_eq!(parse_tables(b"# only a comment\n").unwrap_err().line, 1);
    }

    #[test]
    fn lookup_needs_integral_existing_numbers() {
        let mut texts = FxHashMap::default();
        texts.insert(1, "one".to_string());
        let state = TextTabState { tables: vec![TextTable { name: "t".into(), texts }] };
        assert_eq!(lookup_text(&state, 1.0, 1.0), Some("one"));
        assert_eq!(lookup_text(&state, 1.0, 2.0), None);
        assert_eq!(lookup_text(&state, 2.0, 1.0), None);
        assert_eq!(lookup_text(&state, 0.0, 1.0), None);
        assert_eq!(lookup_text(&state, 1.5, 1.0), None);
        assert_eq!(state.number_of("T"), Some(1));
    }
}
