//! What the external-axis tests (`external_axes`, `external_paths`) share: the manifest
//! units they configure and how they run `rapid` on a project folder.
// Each test file uses a part of it.
#![allow(dead_code)]

use std::fs;
use std::path::Path;

use crate::fixture::{rapid, Scratch};

/// A linear track TRACK (eax_a, 0 … 3000 mm, 1000 mm/s) and a rotating turntable STN1
/// (eax_b, ±180°, 180 °/s), each reaching full speed in 0.15 s.
pub(crate) const UNITS: &str = r#"
[[unit]]
name = "TRACK"
[[unit.axis]]
logical = 7
type = "linear"
min = 0
max = 3000
speed = 1000

[[unit]]
name = "STN1"
[[unit.axis]]
logical = 8
type = "rotating"
min = -180
max = 180
speed = 180
"#;

/// A 3 m track the robot stands on (eax_a, along the world x axis, 1000 mm/s).
pub(crate) const TRACK: &str =
    "[[unit]]\nname = \"TRACK\"\ncarries_robot = true\n[[unit.axis]]\nlogical = 7\ntype = \"linear\"\n\
                     min = 0\nmax = 3000\nspeed = 1000\n";

/// Writes `dir`'s `rapid.toml`: the one task T_ROB1 running `main.mod`, with `units`.
pub(crate) fn write_manifest(dir: &Path, units: &str) {
    let manifest = format!("[[task]]\nname = \"T_ROB1\"\nmodules = [\"main.mod\"]\n\n{units}");
    fs::write(dir.join("rapid.toml"), manifest).expect("manifest");
}

/// UNITS with STN1's frame at (400, 0, 200) and `extra` lines after its name: a turntable
/// that carries work objects.
pub(crate) fn units_with_table(extra: &str) -> String {
    UNITS.replace("name = \"STN1\"\n", &format!("name = \"STN1\"\nbase = [400, 0, 200]\n{extra}"))
}

/// Fills `dir` with `rapid.toml` (one task with UNITS, `extra` appended) and `main.mod`
/// with `body` as the statements of `main`.
pub(crate) fn project_at(dir: Scratch, decls: &str, body: &str, extra: &str) -> Scratch {
    let manifest = format!("[[task]]\nname = \"T_ROB1\"\nmodules = [\"main.mod\"]\n{UNITS}{extra}");
    fs::write(dir.join("rapid.toml"), manifest).expect("manifest");
    let module = format!(
        "MODULE main\n  VAR clock c;\n  VAR jointtarget jt;\n{decls}  PROC main()\n    ClkStart c;\n{body}  ENDPROC\nENDMODULE\n"
    );
    fs::write(dir.join("main.mod"), module).expect("module");
    dir
}

/// Runs the project: stdout, stderr and the exit code.
pub(crate) fn run(dir: &Path) -> (String, String, Option<i32>) {
    let out = rapid(&["run", "--quiet", dir.to_str().expect("path")]);
    (
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
        out.status.code(),
    )
}
