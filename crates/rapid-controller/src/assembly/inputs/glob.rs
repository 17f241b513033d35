//! The file patterns of a manifest's `modules` list: `*` (any characters but `/`),
//! `?` (one character), and `**` as a whole component (any number of folders, none
//! included). Matching is on names as the file system spells them, so `*.MOD` does not
//! match `a.mod` on a case-sensitive disk. A pattern matches files only.

use std::fs;
use std::path::{Path, PathBuf};

/// At most this many folders are visited for one pattern, so `**` under a huge tree
/// (or a loop of symbolic links) cannot hang the reader.
const MAX_FOLDERS: usize = 10_000;

/// True when `text` holds a pattern character.
pub(crate) fn is_pattern(text: &str) -> bool {
    text.contains(['*', '?'])
}

/// The files under `base` that `pattern` (components separated by `/`) matches, sorted.
pub(crate) fn files(base: &Path, pattern: &str) -> Vec<PathBuf> {
    let parts: Vec<&str> = pattern.split('/').filter(|p| !p.is_empty() && *p != ".").collect();
    let start = if pattern.starts_with('/') { PathBuf::from("/") } else { base.to_path_buf() };
    let mut found = Vec::new();
    let mut budget = MAX_FOLDERS;
    walk(&start, &parts, &mut found, &mut budget);
    found.sort();
    found.dedup();
    found
}

fn walk(dir: &Path, parts: &[&str], found: &mut Vec<PathBuf>, budget: &mut usize) {
    let Some((&part, rest)) = parts.split_first() else { return };
    if *budget == 0 {
        return;
    }
    *budget -= 1;
    if part == "**" {
        // None of the folders: the rest matches here.
        walk(dir, rest, found, budget);
        for sub in subfolders(dir) {
            walk(&sub, parts, found, budget);
        }
        return;
    }
    if !is_pattern(part) {
        let next = dir.join(part);
        if rest.is_empty() {
            if next.is_file() {
                found.push(next);
            }
        } else if next.is_dir() {
            walk(&next, rest, found, budget);
        }
        return;
    }
    let Ok(entries) = fs::read_dir(dir) else { return };
    let mut names: Vec<(String, PathBuf)> = entries
        .filter_map(Result::ok)
        .filter_map(|e| Some((e.file_name().to_str()?.to_owned(), e.path())))
        .filter(|(name, _)| matches(part, name))
        .collect();
    names.sort();
    for (_, path) in names {
        if rest.is_empty() {
            if path.is_file() {
                found.push(path);
            }
        } else if path.is_dir() {
            walk(&path, rest, found, budget);
        }
    }
}

/// The folders in `dir`, sorted; symbolic links to folders are not followed (a link
/// loop would otherwise be walked until the budget runs out).
fn subfolders(dir: &Path) -> Vec<PathBuf> {
    let Ok(entries) = fs::read_dir(dir) else { return Vec::new() };
    let mut subs: Vec<PathBuf> =
        entries.filter_map(Result::ok).filter(|e| e.file_type().is_ok_and(|t| t.is_dir())).map(|e| e.path()).collect();
    subs.sort();
    subs
}

/// Whether one component pattern (`*`, `?`, literal characters) matches `name`.
/// Iterative with one backtrack point, so it takes at most `pattern × name` steps.
pub(crate) fn matches(pattern: &str, name: &str) -> bool {
    let pat: Vec<char> = pattern.chars().collect();
    let txt: Vec<char> = name.chars().collect();
    let (mut p, mut t) = (0, 0);
    let mut star: Option<(usize, usize)> = None;
    while t < txt.len() {
        match pat.get(p) {
            Some('*') => {
                star = Some((p, t));
                p += 1;
            }
            Some(&c) if c == '?' || c == txt[t] => {
                p += 1;
                t += 1;
            }
            _ => match star {
                Some((sp, st)) => {
                    p = sp + 1;
                    t = st + 1;
                    star = Some((sp, st + 1));
                }
                None => return false,
            },
        }
    }
    pat[p..].iter().all(|&c| c == '*')
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn component_patterns() {
        assert!(matches("*.mod", "Robot.mod"));
        assert!(matches("*", "x"));
        assert!(matches("R?bot.*", "Robot.sys"));
        assert!(matches("*a*b", "xxaxxb"));
        assert!(!matches("*.mod", "Robot.sys"));
        assert!(!matches("*.mod", "Robot.mod.bak"));
        assert!(!matches("?", ""));
        assert!(matches("**", ""));
    }

    #[test]
    fn walks_folders() {
        let dir = std::env::temp_dir().join(format!("rapid-glob-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(dir.join("src/lib/deep")).unwrap();
        for file in ["src/A.mod", "src/b.sys", "src/lib/C.mod", "src/lib/deep/D.mod", "notes.txt"] {
            fs::write(dir.join(file), "").unwrap();
        }
        let names = |pattern: &str| -> Vec<String> {
            files(&dir, pattern)
                .iter()
                .map(|p| p.strip_prefix(&dir).unwrap().to_string_lossy().replace('\\', "/"))
                .collect()
        };
        assert_eq!(names("src/*.mod"), ["src/A.mod"]);
        assert_eq!(names("src/*"), ["src/A.mod", "src/b.sys"]);
        assert_eq!(names("src/**/*.mod"), ["src/A.mod", "src/lib/C.mod", "src/lib/deep/D.mod"]);
        assert_eq!(names("*/lib/*.mod"), ["src/lib/C.mod"]);
        assert!(names("src/*.prg").is_empty());
        let _ = fs::remove_dir_all(&dir);
    }
}
