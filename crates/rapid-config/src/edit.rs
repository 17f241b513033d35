//! Changing one value of a parsed file and re-emitting it: every byte outside the
//! changed value stays as it was, so a backup's diff shows exactly the change.

use crate::{CfgFile, Instance};

/// Why a value could not be written.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum EditError {
    /// No such section or instance.
    NoInstance,
    /// The value holds a `"`, which the format cannot quote.
    Unquotable,
}

impl CfgFile {
    /// The file's text with attribute `attr` of instance `instance` of section
    /// `section` set to `value`. An attribute the instance lacks is added at the end
    /// of the instance.
    pub fn with_value(&self, section: usize, instance: usize, attr: &str, value: &str) -> Result<String, EditError> {
        if value.contains('"') {
            return Err(EditError::Unquotable);
        }
        let inst = self.sections.get(section).and_then(|s| s.instances.get(instance)).ok_or(EditError::NoInstance)?;
        let (at, inserted) = match inst.attr(attr) {
            Some(found) => match &found.value {
                Some(old) => (old.span.clone(), format_value(value, old.quoted)),
                // A flag given a value: the value goes after the name.
                None => (found.name_span.end..found.name_span.end, format!(" {}", format_value(value, true))),
            },
            None => {
                let end = inst.span.end;
                (end..end, format!(" -{attr} {}", format_value(value, true)))
            }
        };
        let mut text = String::with_capacity(self.text.len() + inserted.len());
        text.push_str(&self.text[..at.start]);
        text.push_str(&inserted);
        text.push_str(&self.text[at.end..]);
        Ok(text)
    }
}

impl CfgFile {
    /// The file's text with flag `attr` added at the end of an instance; `None` when
    /// the instance has it already.
    pub fn with_flag(&self, section: usize, instance: usize, attr: &str) -> Result<Option<String>, EditError> {
        let inst = self.sections.get(section).and_then(|s| s.instances.get(instance)).ok_or(EditError::NoInstance)?;
        if inst.has(attr) {
            return Ok(None);
        }
        let end = inst.span.end;
        Ok(Some(format!("{} -{attr}{}", &self.text[..end], &self.text[end..])))
    }

    /// The file's text without attribute `attr` of an instance (and the blanks before
    /// it on its line), e.g. a flag switched off. `None` when the instance lacks it.
    pub fn without_attr(&self, section: usize, instance: usize, attr: &str) -> Result<Option<String>, EditError> {
        let inst = self.sections.get(section).and_then(|s| s.instances.get(instance)).ok_or(EditError::NoInstance)?;
        let Some(found) = inst.attr(attr) else { return Ok(None) };
        let end = found.value.as_ref().map_or(found.name_span.end, |v| v.span.end);
        let before = &self.text[..found.name_span.start];
        let start = before.trim_end_matches([' ', '\t']).len();
        // The first item of the instance keeps its indentation.
        let start = if start == 0 || self.text[..start].ends_with('\n') { found.name_span.start } else { start };
        Ok(Some(format!("{}{}", &self.text[..start], &self.text[end..])))
    }
}

/// A value as the file writes it: in quotes when it was quoted, or when it is empty or
/// holds blanks (a bare value ends at the first blank).
fn format_value(value: &str, quoted: bool) -> String {
    if quoted || value.is_empty() || value.chars().any(char::is_whitespace) {
        format!("\"{value}\"")
    } else {
        value.to_owned()
    }
}

/// The index of the instance of `type_name` whose `-Name` is `name` (ignoring case,
/// as RAPID names do): (section index, instance index).
pub fn find_named(file: &CfgFile, type_name: &str, name: &str) -> Option<(usize, usize)> {
    file.sections.iter().enumerate().filter(|(_, s)| s.name.eq_ignore_ascii_case(type_name)).find_map(|(si, s)| {
        s.instances
            .iter()
            .position(|i: &Instance| i.name().is_some_and(|n| n.eq_ignore_ascii_case(name)))
            .map(|ii| (si, ii))
    })
}
