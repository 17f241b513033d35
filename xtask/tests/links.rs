//! Every relative link of the project's Markdown (the README, the user guide and the
//! references under `docs/`, the benchmark and corpus READMEs) names a file or folder
//! that exists, and every page the guide's `docs/SUMMARY.md` lists exists. Runs on every
//! `cargo test`, so a moved or renamed page cannot leave a dead link behind.

use std::fs;
use std::path::{Path, PathBuf};

/// Markdown files under `dir`, skipping build output and hidden folders.
fn markdown_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = fs::read_dir(dir) else { return };
    for entry in entries.flatten() {
        let path = entry.path();
        let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
        if path.is_dir() && name != "target" && name != "node_modules" && !name.starts_with('.') {
            markdown_files(&path, out);
        } else if name.ends_with(".md") {
            out.push(path);
        }
    }
}

/// The targets of the inline links `[text](target)` of `text`, outside code blocks and
/// code spans.
fn link_targets(text: &str) -> Vec<String> {
    let mut targets = Vec::new();
    let mut in_fence = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            in_fence = !in_fence;
            continue;
        }
        if in_fence {
            continue;
        }
        // Code spans hold examples, not links.
        let prose: String = line.split('`').step_by(2).collect::<Vec<_>>().join(" ");
        let mut rest = prose.as_str();
        while let Some(at) = rest.find("](") {
            let after = &rest[at + 2..];
            let Some(end) = after.find(')') else { break };
            targets.push(after[..end].trim().to_owned());
            rest = &after[end..];
        }
    }
    targets
}

/// Whether `target` is a link to another site or a place in the same page.
fn is_external(target: &str) -> bool {
    target.is_empty() || target.starts_with('#') || target.contains("://") || target.starts_with("mailto:")
}

#[test]
fn relative_links_resolve() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut files = vec![root.join("README.md"), root.join("CONTRIBUTING.md")];
    for dir in ["docs", "bench", "tests", "examples", "fuzz"] {
        markdown_files(&root.join(dir), &mut files);
    }
    files.retain(|f| f.exists());
    assert!(files.len() > 10, "found too few Markdown files: {}", files.len());
    let mut dead = Vec::new();
    for file in &files {
        let text = fs::read_to_string(file).unwrap_or_default();
        let folder = file.parent().unwrap_or(&root);
        for target in link_targets(&text) {
            if is_external(&target) {
                continue;
            }
            let path = target.split('#').next().unwrap_or("");
            // A link may carry a title after the path: `(path "title")`.
            let path = path.split_whitespace().next().unwrap_or("");
            if !folder.join(path).exists() {
                let shown = file.strip_prefix(&root).unwrap_or(file).display().to_string();
                dead.push(format!("{shown}: `{target}` does not exist"));
            }
        }
    }
    assert!(dead.is_empty(), "dead links:\n{}", dead.join("\n"));
}

#[test]
fn the_guide_lists_existing_pages() {
    let docs = Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs");
    let summary = fs::read_to_string(docs.join("SUMMARY.md")).expect("docs/SUMMARY.md");
    let pages = link_targets(&summary);
    assert!(pages.len() >= 10, "SUMMARY.md lists too few pages: {}", pages.len());
    for page in pages {
        assert!(docs.join(&page).is_file(), "SUMMARY.md lists `{page}`, which does not exist");
    }
}

#[test]
fn link_targets_skip_code() {
    let text = "see [a](x.md) and `[b](y.md)`\n```\n[c](z.md)\n```\n[d](w.md#part)";
    assert_eq!(link_targets(text), vec!["x.md", "w.md#part"]);
}
