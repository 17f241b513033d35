//! Diagnostics for code-scanning services: one SARIF 2.1.0 log (OASIS, "Static
//! Analysis Results Interchange Format"), as GitHub code scanning and other CI
//! dashboards read it.
//!
//! The log has one run. Its tool lists every diagnostic code as a rule (`rapid codes`:
//! the code as `id`, its name, its one-line summary as short description and help,
//! its severity as the default level), so a dashboard can explain a code it has not
//! seen in a result yet. Each diagnostic is a result naming its rule (`ruleId` and
//! `ruleIndex`), its level, its message and one physical location: the file as a
//! relative URI reference (as given on the command line, `/`-separated) or a `file:`
//! URI for an absolute path, and a region of 1-based lines and columns. Columns count
//! characters (`columnKind: unicodeCodePoints`), as in the other formats; the end is
//! the position just past the span. Where a check of several tasks names the tasks,
//! they are in the result's property bag as `tasks`.
//!
//! `crates/rapid-cli/tests/cli/sarif.rs` validates this output against the official
//! SARIF 2.1.0 JSON schema.

use std::io::{self, Write};

use rapid_sema::{Code, Severity};
use serde::Serialize;

use crate::render::{severity_name, Files, Reported};

/// Where the schema of the format lives (GitHub's documentation names this address).
const SCHEMA: &str = "https://json.schemastore.org/sarif-2.1.0.json";

#[derive(Debug, Serialize)]
struct Log<'a> {
    #[serde(rename = "$schema")]
    schema: &'static str,
    version: &'static str,
    runs: [Run<'a>; 1],
}

#[derive(Debug, Serialize)]
#[serde(rename_all = "camelCase")]
struct Run<'a> {
    tool: Tool,
    column_kind: &'static str,
    results: Vec<SarifResult<'a>>,
}

#[derive(Debug, Serialize)]
struct Tool {
    driver: Driver,
}

#[derive(Debug, Serialize)]
#[serde(rename_all = "camelCase")]
struct Driver {
    name: &'static str,
    version: &'static str,
    rules: Vec<Rule>,
}

#[derive(Debug, Serialize)]
#[serde(rename_all = "camelCase")]
struct Rule {
    id: &'static str,
    name: &'static str,
    short_description: Text<&'static str>,
    help: Text<String>,
    default_configuration: Configuration,
}

#[derive(Debug, Serialize)]
struct Text<T> {
    text: T,
}

#[derive(Debug, Serialize)]
struct Configuration {
    level: &'static str,
}

#[derive(Debug, Serialize)]
#[serde(rename_all = "camelCase")]
struct SarifResult<'a> {
    rule_id: &'static str,
    rule_index: usize,
    level: &'static str,
    message: Text<&'a str>,
    locations: [Location; 1],
    #[serde(skip_serializing_if = "Option::is_none")]
    properties: Option<Properties<'a>>,
}

#[derive(Debug, Serialize)]
#[serde(rename_all = "camelCase")]
struct Location {
    physical_location: PhysicalLocation,
}

#[derive(Debug, Serialize)]
#[serde(rename_all = "camelCase")]
struct PhysicalLocation {
    artifact_location: ArtifactLocation,
    region: Region,
}

#[derive(Debug, Serialize)]
struct ArtifactLocation {
    uri: String,
}

#[derive(Debug, Serialize)]
#[serde(rename_all = "camelCase")]
struct Region {
    start_line: u32,
    start_column: u32,
    end_line: u32,
    end_column: u32,
}

#[derive(Debug, Serialize)]
struct Properties<'a> {
    tasks: &'a [String],
}

/// Writes the diagnostics as one pretty-printed SARIF log and a newline.
pub(crate) fn render(out: &mut dyn Write, files: &Files<'_>, reported: &[Reported]) -> io::Result<()> {
    let results = reported.iter().map(|it| result(files, it)).collect();
    let driver = Driver {
        name: "rapid",
        version: env!("CARGO_PKG_VERSION"),
        rules: Code::ALL.iter().map(|&code| rule(code)).collect(),
    };
    let log = Log {
        schema: SCHEMA,
        version: "2.1.0",
        runs: [Run { tool: Tool { driver }, column_kind: "unicodeCodePoints", results }],
    };
    serde_json::to_writer_pretty(&mut *out, &log)?;
    writeln!(out)
}

fn rule(code: Code) -> Rule {
    Rule {
        id: code.as_str(),
        name: code.name(),
        short_description: Text { text: code.summary() },
        help: Text { text: format!("{} {}: {}.", code.as_str(), severity_name(code.severity()), code.summary()) },
        default_configuration: Configuration { level: level(code.severity()) },
    }
}

fn result<'a>(files: &Files<'_>, Reported { diag, tasks }: &'a Reported) -> SarifResult<'a> {
    let location = files.location(diag);
    let region = Region {
        start_line: location.start.line,
        start_column: location.start.column,
        end_line: location.end.line,
        end_column: location.end.column,
    };
    let artifact_location = ArtifactLocation { uri: path_to_uri(files.path(diag.file)) };
    SarifResult {
        rule_id: diag.code.as_str(),
        // Code::ALL holds every code, so the position is always found.
        rule_index: Code::ALL.iter().position(|&code| code == diag.code).unwrap_or(0),
        level: level(diag.severity()),
        message: Text { text: &diag.message },
        locations: [Location { physical_location: PhysicalLocation { artifact_location, region } }],
        properties: (!tasks.is_empty()).then_some(Properties { tasks }),
    }
}

/// SARIF's names for our two severities.
fn level(severity: Severity) -> &'static str {
    match severity {
        Severity::Error => "error",
        Severity::Warning => "warning",
    }
}

/// A path as a URI reference: `/`-separated, characters outside RFC 3986's unreserved
/// set and path separators percent-encoded (UTF-8); an absolute path becomes a
/// `file:` URI (a Windows drive path `C:\x` becomes `file:///C:/x`).
fn path_to_uri(path: &str) -> String {
    let slashed = path.replace('\\', "/");
    let is_drive = slashed.as_bytes().get(1) == Some(&b':') && slashed.as_bytes()[0].is_ascii_alphabetic();
    let (prefix, rest) = if is_drive {
        ("file:///", slashed.as_str())
    } else if slashed.starts_with('/') {
        ("file://", slashed.as_str())
    } else {
        ("", slashed.as_str())
    };
    let mut uri = String::with_capacity(prefix.len() + rest.len());
    uri.push_str(prefix);
    for (idx, byte) in rest.bytes().enumerate() {
        let keep = byte.is_ascii_alphanumeric()
            || matches!(byte, b'-' | b'.' | b'_' | b'~' | b'/')
            // The drive's colon stays: `file:///C:/x`.
            || (is_drive && idx == 1);
        if keep {
            uri.push(byte as char);
        } else {
            uri.push_str(&format!("%{byte:02X}"));
        }
    }
    uri
}

#[cfg(test)]
mod tests {
    use rapid_sema::{Diagnostic, SourceInput};
    use rapid_syntax::Span;

    use super::*;

    fn render_reported(sources: &[SourceInput], reported: &[Reported]) -> serde_json::Value {
        let table: Vec<&SourceInput> = sources.iter().collect();
        let mut out = Vec::new();
        render(&mut out, &Files::new(&table), reported).unwrap();
        serde_json::from_slice(&out).unwrap()
    }

    #[test]
    fn results_name_their_rule_and_place() {
        let text = "MODULE m\n  x := \"é\";\n  foo;\nENDMODULE\n";
        let foo = text.find("foo").unwrap();
        let diag = Diagnostic::new(0, Code::UndefinedData, Span::new(foo, foo + 3), "undefined data `foo`");
        let log = render_reported(&[SourceInput::from_text("dir/m.mod", text)], &[Reported::from(diag)]);
        assert_eq!(log["version"], "2.1.0");
        let run = &log["runs"][0];
        let rules = run["tool"]["driver"]["rules"].as_array().unwrap();
        assert_eq!(rules.len(), Code::ALL.len());
        let result = &run["results"][0];
        assert_eq!(result["ruleId"], "E0201");
        let index = result["ruleIndex"].as_u64().unwrap() as usize;
        assert_eq!(rules[index]["id"], "E0201");
        assert_eq!(result["level"], "error");
        let location = &result["locations"][0]["physicalLocation"];
        assert_eq!(location["artifactLocation"]["uri"], "dir/m.mod");
        // `foo` is on line 3, columns 3 to 5; the end is just past it.
        assert_eq!(location["region"]["startLine"], 3);
        assert_eq!(location["region"]["startColumn"], 3);
        assert_eq!(location["region"]["endColumn"], 6);
        assert!(result.get("properties").is_none());
    }

    #[test]
    fn tasks_go_into_the_property_bag() {
        let text = "MODULE Lib\n  x := 1;\nENDMODULE\n";
        let x = text.find('x').unwrap();
        let diag = Diagnostic::new(0, Code::UndefinedData, Span::new(x, x + 1), "undefined data `x`");
        let reported = [Reported { diag, tasks: vec!["T_ROB1".to_owned()] }];
        let log = render_reported(&[SourceInput::from_text("Lib.sys", text)], &reported);
        assert_eq!(log["runs"][0]["results"][0]["properties"]["tasks"][0], "T_ROB1");
    }

    #[test]
    fn paths_become_uri_references() {
        assert_eq!(path_to_uri("tests/a b/m.mod"), "tests/a%20b/m.mod");
        assert_eq!(path_to_uri("dir\\Modül.mod"), "dir/Mod%C3%BCl.mod");
        assert_eq!(path_to_uri("/home/u/x#1.mod"), "file:///home/u/x%231.mod");
        assert_eq!(path_to_uri("C:\\cell\\main.mod"), "file:///C:/cell/main.mod");
    }
}
