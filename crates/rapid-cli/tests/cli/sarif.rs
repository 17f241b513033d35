//! `rapid check --format sarif` writes one SARIF 2.1.0 log that the official OASIS
//! schema (vendored in `tests/cli/sarif_schema/`, with its licence note) accepts: for a
//! clean module, for the error fixtures checked as one task, and for a backup of several
//! tasks (results naming their tasks). The log says what the JSON format says: the same
//! diagnostics in the same order, with the same codes, severities and positions.

use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::Value;

fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Runs `rapid check --format FORMAT PATH` from the repository root; returns the
/// parsed output and the exit code.
fn check(format: &str, path: &str) -> (Value, i32) {
    let output = Command::new(env!("CARGO_BIN_EXE_rapid"))
        .current_dir(repo_root())
        .args(["check", "--format", format, path])
        .output()
        .expect("rapid runs");
    let stdout = String::from_utf8(output.stdout).expect("UTF-8 output");
    let value = serde_json::from_str(&stdout).unwrap_or_else(|err| panic!("{format} output is JSON: {err}\n{stdout}"));
    (value, output.status.code().unwrap_or(-1))
}

fn validator() -> jsonschema::Validator {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/cli/sarif_schema/sarif-schema-2.1.0.json");
    let schema: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    jsonschema::validator_for(&schema).expect("the SARIF schema compiles")
}

fn assert_valid(log: &Value) {
    let validator = validator();
    let errors: Vec<String> = validator.iter_errors(log).map(|e| format!("{e} at {}", e.instance_path())).collect();
    assert!(errors.is_empty(), "SARIF log breaks the 2.1.0 schema:\n{}", errors.join("\n"));
}

/// The SARIF results must be the JSON diagnostics, one for one and in order.
fn assert_matches_json(path: &str) -> Value {
    let (log, sarif_exit) = check("sarif", path);
    let (json, json_exit) = check("json", path);
    assert_eq!(sarif_exit, json_exit, "{path}: the format does not change the exit status");
    assert_valid(&log);
    let results = log["runs"][0]["results"].as_array().unwrap();
    let diagnostics = json.as_array().unwrap();
    assert_eq!(results.len(), diagnostics.len(), "{path}");
    for (result, diag) in results.iter().zip(diagnostics) {
        assert_eq!(result["ruleId"], diag["code"]);
        assert_eq!(result["level"], diag["severity"]);
        assert_eq!(result["message"]["text"], diag["message"]);
        let location = &result["locations"][0]["physicalLocation"];
        let file = diag["file"].as_str().unwrap().replace('\\', "/");
        let uri = location["artifactLocation"]["uri"].as_str().unwrap();
        assert!(uri == file || uri == format!("file://{file}"), "{uri} names {file}");
        let region = &location["region"];
        assert_eq!(region["startLine"], diag["line"]);
        assert_eq!(region["startColumn"], diag["column"]);
        assert_eq!(region["endLine"], diag["end_line"]);
        assert_eq!(region["endColumn"], diag["end_column"]);
        assert_eq!(result.get("properties").map(|p| &p["tasks"]), diag.get("tasks"));
        let rules = log["runs"][0]["tool"]["driver"]["rules"].as_array().unwrap();
        let index = result["ruleIndex"].as_u64().unwrap() as usize;
        assert_eq!(rules[index]["id"], result["ruleId"]);
    }
    log
}

#[test]
fn clean_module_gives_a_valid_log_without_results() {
    let log = assert_matches_json("tests/check/ok/cell_state_machine.mod");
    assert!(log["runs"][0]["results"].as_array().unwrap().is_empty());
    // Every code is a rule, with its help text, even when no result uses it.
    let rules = log["runs"][0]["tool"]["driver"]["rules"].as_array().unwrap();
    let e0201 = rules.iter().find(|rule| rule["id"] == "E0201").expect("E0201 is a rule");
    assert_eq!(e0201["help"]["text"], "E0201 error: a name that is not declared data in scope.");
    assert_eq!(e0201["defaultConfiguration"]["level"], "error");
}

#[test]
fn error_fixtures_give_a_valid_log() {
    let log = assert_matches_json("tests/check/err");
    let results = log["runs"][0]["results"].as_array().unwrap();
    assert!(results.iter().any(|r| r["level"] == "error"));
    assert!(results.iter().any(|r| r["level"] == "warning"));
}

#[test]
fn a_backup_gives_a_valid_log() {
    let log = assert_matches_json("tests/check/backups/palletizer");
    assert_eq!(log["version"], "2.1.0");
}

#[test]
fn several_tasks_are_named_in_the_property_bag() {
    // Two tasks load one library whose line 3 writes `missing`, declared nowhere: one
    // report names both tasks.
    let dir = std::env::temp_dir().join(format!("rapid-sarif-tasks-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let lib = "MODULE Lib(SYSMODULE)\n  PROC lib_log()\n    missing := 1;\n  ENDPROC\nENDMODULE\n";
    std::fs::write(dir.join("Lib.sys"), lib).unwrap();
    std::fs::write(dir.join("A.mod"), "MODULE A\n  PROC main()\n    lib_log;\n  ENDPROC\nENDMODULE\n").unwrap();
    std::fs::write(dir.join("B.mod"), "MODULE B\n  PROC main()\n    lib_log;\n  ENDPROC\nENDMODULE\n").unwrap();
    let manifest = "[[task]]\nname = \"T_A\"\nmodules = [\"A.mod\", \"Lib.sys\"]\n\n\
                    [[task]]\nname = \"T_B\"\nmodules = [\"B.mod\", \"Lib.sys\"]\n";
    std::fs::write(dir.join("rapid.toml"), manifest).unwrap();
    let log = assert_matches_json(dir.join("rapid.toml").to_str().unwrap());
    let _ = std::fs::remove_dir_all(&dir);
    let results = log["runs"][0]["results"].as_array().unwrap();
    assert_eq!(results.len(), 1, "{results:?}");
    assert_eq!(results[0]["ruleId"], "E0201");
    assert_eq!(results[0]["properties"]["tasks"], serde_json::json!(["T_A", "T_B"]));
    let uri = results[0]["locations"][0]["physicalLocation"]["artifactLocation"]["uri"].as_str().unwrap();
    assert!(uri.starts_with("file:///") && uri.ends_with("/Lib.sys"), "{uri}");
}

#[test]
fn the_schema_refuses_a_broken_log() {
    // The validator is not a yes-machine: a result without its message is refused.
    let (mut log, _) = check("sarif", "tests/check/err/E0101_1_at_sign.mod");
    assert_valid(&log);
    log["runs"][0]["results"][0].as_object_mut().unwrap().remove("message");
    assert!(!validator().is_valid(&log));
}
