//! The software options a system has, as its backup records them: `system.xml` at
//! the backup's root (`<Option descr="689-1 Externally Guided Motion (EGM)">`, with
//! `<SubOption>`s such as `652-1 BullsEye` under Arc), else BACKINFO/backinfo.txt's
//! `>>PRODUCTS_ID:` section (one product per line). A manifest names them itself
//! (`[system] options`). The checker (`rapid_lib::catalogue::options::find`) tells
//! which of these descriptions name an option the catalogue declares; the others are
//! kept and ignored.

use std::fs;
use std::path::Path;

/// The product descriptions of the backup at `folder`, or `None` when it has neither
/// a system.xml nor a backinfo.txt listing products (nothing says what it has).
pub(crate) fn of_backup(folder: &Path) -> Option<Vec<String>> {
    if let Some(text) = super::backup::child(folder, "system.xml").and_then(|p| fs::read(p).ok()) {
        return Some(from_system_xml(&String::from_utf8_lossy(&text)));
    }
    let backinfo =
        super::backup::child(folder, "BACKINFO").and_then(|dir| super::backup::child(&dir, "backinfo.txt"))?;
    from_backinfo(&String::from_utf8_lossy(&fs::read(backinfo).ok()?))
}

/// Every `descr` of an `<Option>` or `<SubOption>` element, in document order.
// RobotStudio writes the file with and without line breaks; the attribute is the only
// part read, so no XML parser is needed.
pub(crate) fn from_system_xml(text: &str) -> Vec<String> {
    let mut found = Vec::new();
    let mut rest = text;
    while let Some(at) = rest.find("Option descr=\"") {
        rest = &rest[at + "Option descr=\"".len()..];
        let Some(end) = rest.find('"') else { break };
        found.push(unescape(&rest[..end]));
        rest = &rest[end..];
    }
    found
}

/// The lines of the `>>PRODUCTS_ID:` section, trimmed, or `None` without one.
pub(crate) fn from_backinfo(text: &str) -> Option<Vec<String>> {
    let mut lines = text.lines().skip_while(|l| !l.trim().eq_ignore_ascii_case(">>PRODUCTS_ID:"));
    lines.next()?;
    Some(
        lines
            .take_while(|l| !l.trim_start().starts_with(">>"))
            .map(str::trim)
            .filter(|l| !l.is_empty())
            .map(str::to_owned)
            .collect(),
    )
}

/// The five predefined XML entities.
fn unescape(text: &str) -> String {
    text.replace("&lt;", "<").replace("&gt;", ">").replace("&quot;", "\"").replace("&apos;", "'").replace("&amp;", "&")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn system_xml_options_and_sub_options_are_read() {
        let xml = "<SystemProperties><ControlModule>\n<Option descr=\"RobotWare Base\"></Option>\
                   <Option descr=\"633-1 Arc\">\n  <SubOption descr=\"652-1 BullsEye\"/>\n</Option>\
                   <Option descr=\"709-1 DeviceNet Master/Slave\"/><Category descr=\"Options\">x</Category>\
                   </ControlModule></SystemProperties>";
        let found = from_system_xml(xml);
        assert_eq!(found, ["RobotWare Base", "633-1 Arc", "652-1 BullsEye", "709-1 DeviceNet Master/Slave"]);
    }

    #[test]
    fn backinfo_products_are_the_lines_of_their_section() {
        let text = "#\n>>SYSTEM_ID:\ncell\n\n>>PRODUCTS_ID:\nRobotWare Version: 6.13\n\n  623-1 Multitasking\n  \
                    689-1 Externally Guided Motion (EGM)\n\n>>HOME:\nall\n";
        let found = from_backinfo(text).unwrap_or_default();
        assert_eq!(found, ["RobotWare Version: 6.13", "623-1 Multitasking", "689-1 Externally Guided Motion (EGM)"]);
        assert_eq!(from_backinfo(">>SYSTEM_ID:\ncell\n"), None);
    }
}
