//! The crate dependency rules (issue 19, docs/architecture.md): which workspace crate
//! may depend on which. Two checks keep the graph honest:
//! - every dependency between workspace crates (`[dependencies]`, not dev-dependencies)
//!   is in [`ALLOWED`], and every entry of [`ALLOWED`] is still used — so the list
//!   tracks the code and can only shrink unless someone adds an edge on purpose, in
//!   review;
//! - [`ALLOWED`] itself never points up the layers of [`LAYERS`]: an engine crate never
//!   depends on a front end, the front ends never on the CLI.
//!
//! [`DEBT`] names the edges the design wants gone, allowed until they are paid and
//! then deleted from both lists. None is left: rapid-vm reaching rapid-motion was paid
//! when the robot became the crate rapid-robot, rapid-vm reaching rapid-io when the I/O
//! signals became the crate rapid-signals.

use std::collections::BTreeSet;
use std::fs;
use std::path::Path;

/// The workspace's crates, lowest first: a crate may depend only on crates of a lower
/// layer.
const LAYERS: &[&[&str]] = &[
    &["rapid-limits", "rapid-motion"],
    &["rapid-syntax", "rapid-config", "rapid-io"],
    &["rapid-lib"],
    &["rapid-sema", "rapid-fmt"],
    &["rapid-vm"],
    &["rapid-tasks", "rapid-signals"],
    &["rapid-robot"],
    &["rapid-controller", "rapid-lsp"],
    &["rapid-serve", "rapid-dap"],
    &["rapid-cli"],
];

/// Every allowed dependency between workspace crates: (crate, the crates it uses).
const ALLOWED: &[(&str, &[&str])] = &[
    ("rapid-limits", &[]),
    ("rapid-motion", &[]),
    ("rapid-syntax", &["rapid-limits"]),
    ("rapid-config", &["rapid-limits"]),
    ("rapid-io", &["rapid-limits"]),
    ("rapid-lib", &["rapid-syntax"]),
    ("rapid-sema", &["rapid-limits", "rapid-syntax", "rapid-lib", "rapid-config"]),
    ("rapid-fmt", &["rapid-syntax", "rapid-lib"]),
    ("rapid-vm", &["rapid-limits", "rapid-syntax", "rapid-sema", "rapid-lib"]),
    ("rapid-tasks", &["rapid-vm"]),
    ("rapid-signals", &["rapid-sema", "rapid-vm", "rapid-io"]),
    (
        "rapid-robot",
        &[
            "rapid-limits",
            "rapid-syntax",
            "rapid-sema",
            "rapid-vm",
            "rapid-tasks",
            "rapid-signals",
            "rapid-motion",
            "rapid-io",
        ],
    ),
    (
        "rapid-controller",
        &[
            "rapid-limits",
            "rapid-syntax",
            "rapid-vm",
            "rapid-tasks",
            "rapid-signals",
            "rapid-robot",
            "rapid-sema",
            "rapid-io",
            "rapid-config",
            "rapid-motion",
        ],
    ),
    ("rapid-lsp", &["rapid-syntax", "rapid-sema", "rapid-lib", "rapid-fmt", "rapid-config"]),
    ("rapid-serve", &["rapid-controller", "rapid-vm"]),
    ("rapid-dap", &["rapid-controller", "rapid-vm"]),
    (
        "rapid-cli",
        &[
            "rapid-limits",
            "rapid-syntax",
            "rapid-sema",
            "rapid-vm",
            "rapid-signals",
            "rapid-robot",
            "rapid-io",
            "rapid-controller",
            "rapid-motion",
            "rapid-lsp",
            "rapid-dap",
            "rapid-fmt",
            "rapid-serve",
        ],
    ),
];

/// Allowed today, wanted gone (none left: the interpreter core reaches no controller
/// side).
const DEBT: &[(&str, &str)] = &[];

/// The workspace crates a manifest's `[dependencies]` (and target-specific
/// dependencies) name; dev- and build-dependencies are not part of the graph.
fn workspace_deps(manifest: &str) -> BTreeSet<String> {
    let mut deps = BTreeSet::new();
    let mut in_deps = false;
    for line in manifest.lines().map(str::trim) {
        if line.starts_with('[') {
            in_deps = line == "[dependencies]" || (line.starts_with("[target.") && line.ends_with(".dependencies]"));
            continue;
        }
        if !in_deps {
            continue;
        }
        let name = line.split(['=', '.', ' ']).next().unwrap_or("");
        if name.starts_with("rapid-") {
            deps.insert(name.to_string());
        }
    }
    deps
}

fn layer(name: &str) -> Option<usize> {
    LAYERS.iter().position(|layer| layer.contains(&name))
}

#[test]
fn allowed_edges_point_down_the_layers() {
    let mut problems = Vec::new();
    for (krate, deps) in ALLOWED {
        let Some(own) = layer(krate) else {
            problems.push(format!("{krate} is in no layer"));
            continue;
        };
        for dep in *deps {
            match layer(dep) {
                Some(l) if l < own => {}
                Some(_) => problems.push(format!("{krate} -> {dep} points up or sideways")),
                None => problems.push(format!("{dep} (used by {krate}) is in no layer")),
            }
        }
    }
    for (krate, dep) in DEBT {
        let listed = ALLOWED.iter().any(|(k, deps)| k == krate && deps.contains(dep));
        if !listed {
            problems.push(format!("debt {krate} -> {dep} is paid: delete it from DEBT"));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn crate_dependencies_match_the_allow_list() {
    let crates = Path::new(env!("CARGO_MANIFEST_DIR")).join("../crates");
    let mut seen = BTreeSet::new();
    let mut problems = Vec::new();
    for entry in fs::read_dir(&crates).expect("crates/").flatten() {
        let Ok(manifest) = fs::read_to_string(entry.path().join("Cargo.toml")) else { continue };
        let name = entry.file_name().to_string_lossy().into_owned();
        seen.insert(name.clone());
        let actual = workspace_deps(&manifest);
        let Some((_, allowed)) = ALLOWED.iter().find(|(k, _)| *k == name) else {
            problems.push(format!("crate {name} is not in ALLOWED (and LAYERS): place it in the design"));
            continue;
        };
        let allowed: BTreeSet<String> = allowed.iter().map(|s| s.to_string()).collect();
        for extra in actual.difference(&allowed) {
            problems.push(format!("{name} depends on {extra}, which the rules do not allow"));
        }
        for unused in allowed.difference(&actual) {
            problems
                .push(format!("{name} no longer depends on {unused}: delete it from ALLOWED (the list only shrinks)"));
        }
    }
    for (krate, _) in ALLOWED {
        if !seen.contains(*krate) {
            problems.push(format!("ALLOWED names {krate}, which is not a crate of crates/"));
        }
    }
    assert!(seen.len() >= 10, "found too few crates: {seen:?}");
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn the_manifest_reader_sees_only_runtime_dependencies() {
    let manifest = "[package]\nname = \"x\"\n\n[dependencies]\nrapid-syntax.workspace = true\nrapid-io = { path = \"../rapid-io\" }\nserde = \"1\"\n\n[target.'cfg(unix)'.dependencies]\nrapid-motion = \"*\"\n\n[dev-dependencies]\nrapid-vm.workspace = true\n";
    let found: Vec<String> = workspace_deps(manifest).into_iter().collect();
    assert_eq!(found, ["rapid-io", "rapid-motion", "rapid-syntax"]);
}
