//! `/fileservice`: the controller's file devices (`$HOME`, `$TEMP`, `$RAMDISK`,
//! `$BACKUP`: the folders RAPID opens as `HOME:` and so on, under the controller root)
//! read, written, listed, deleted, and folders made (`?action=create`).
//!
//! Sandboxed: a path is a device and then plain names; `..`, `.`, absolute parts,
//! backslashes, drive letters and symbolic links (anywhere on the way) are refused,
//! so nothing outside the device's folder is ever reached. Writes go to a temporary
//! file renamed over the target, so a reader never sees half a file.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use axum::http::{Method, StatusCode};

use super::{not_found, Req, Res};
use crate::elog::timestamp;
use crate::model::{Item, Reply, RwsError};
use crate::App;

/// The devices, as RAPID and the file system name them.
const DEVICES: [&str; 4] = ["HOME", "TEMP", "RAMDISK", "BACKUP"];

/// A device named by `$HOME`, `HOME`, `home:`… (its folder's name).
pub(super) fn device_name(text: &str) -> Option<&'static str> {
    let bare = text.trim_start_matches('$').trim_end_matches(':');
    DEVICES.iter().copied().find(|d| d.eq_ignore_ascii_case(bare))
}

pub(super) async fn route(app: &Arc<App>, req: &Req) -> Res {
    let root = app
        .file_root
        .clone()
        .ok_or_else(|| RwsError::unsupported("this system has no file devices (no controller root)"))?;
    let rest = &req.segs[1..];
    if rest.is_empty() {
        if !req.is(Method::GET) {
            return Err(not_found(req));
        }
        let items = DEVICES.iter().map(|d| Item::new("fs-device", &format!("${d}"))).collect();
        return Ok(Reply::Items { base: "/fileservice/".into(), items });
    }
    let path = resolve(&root, rest)?;
    let body = req.body.clone();
    let method = req.method.clone();
    let action = req.action().map(str::to_owned);
    let new_name = req.field("fs-newname").map(str::to_owned);
    let base = format!("/fileservice/{}/", rest.join("/"));
    // File-system work off the async threads.
    let outcome = tokio::task::spawn_blocking(move || match (method, action.as_deref()) {
        (Method::GET, None) => get(&path, base),
        (Method::PUT, None) => put(&path, &body),
        (Method::DELETE, None) => delete(&path),
        (Method::POST, Some("create")) => create(&path, new_name.as_deref()),
        _ => Err(RwsError::not_found("no such file-service operation")),
    })
    .await;
    outcome.map_err(|_| RwsError::busy("the file operation failed"))?
}

/// The host path of `segs` (a device, then names), checked.
pub(super) fn resolve(root: &Path, segs: &[String]) -> Result<PathBuf, RwsError> {
    let refused = |why: &str| RwsError::new(StatusCode::FORBIDDEN, crate::model::CODE_BAD_REQUEST, why);
    let device = device_name(&segs[0])
        .ok_or_else(|| RwsError::not_found(format!("`{}` is no device ($HOME, $TEMP, $RAMDISK, $BACKUP)", segs[0])))?;
    let device_dir = root.join(device);
    std::fs::create_dir_all(&device_dir).map_err(|e| RwsError::busy(format!("the device folder: {e}")))?;
    let mut path = device_dir;
    for name in &segs[1..] {
        let plain = !name.is_empty()
            && name != "."
            && name != ".."
            && !name.contains(['/', '\\', ':', '\0'])
            && !Path::new(name).is_absolute();
        if !plain {
            return Err(refused(&format!("`{name}`: a path leaving the device is refused")));
        }
        path.push(name);
        if std::fs::symlink_metadata(&path).is_ok_and(|m| m.file_type().is_symlink()) {
            return Err(refused(&format!("`{name}` is a link: links are refused")));
        }
    }
    Ok(path)
}

fn io_error(path: &Path, e: &std::io::Error) -> RwsError {
    let name = path.file_name().map_or_else(String::new, |n| n.to_string_lossy().into_owned());
    match e.kind() {
        std::io::ErrorKind::NotFound => RwsError::not_found(format!("`{name}` does not exist")),
        _ => RwsError::new(StatusCode::INTERNAL_SERVER_ERROR, crate::model::CODE_BAD_REQUEST, format!("`{name}`: {e}")),
    }
}

/// A file's bytes, or a folder's listing.
fn get(path: &Path, base: String) -> Res {
    let meta = std::fs::metadata(path).map_err(|e| io_error(path, &e))?;
    if meta.is_file() {
        return std::fs::read(path).map(Reply::Bytes).map_err(|e| io_error(path, &e));
    }
    let mut entries: Vec<_> = std::fs::read_dir(path)
        .map_err(|e| io_error(path, &e))?
        .filter_map(Result::ok)
        .filter(|e| e.file_type().is_ok_and(|t| !t.is_symlink()))
        .collect();
    entries.sort_by_key(|e| e.file_name());
    let items = entries
        .iter()
        .filter_map(|entry| {
            let meta = entry.metadata().ok()?;
            let name = entry.file_name().to_string_lossy().into_owned();
            let modified = meta.modified().map(timestamp).unwrap_or_default();
            let item = if meta.is_dir() {
                Item::new("fs-dir", &name).with("fs-cdate", modified.clone()).with("fs-mdate", modified)
            } else {
                Item::new("fs-file", &name)
                    .with("fs-cdate", modified.clone())
                    .with("fs-mdate", modified)
                    .with("fs-size", meta.len().to_string())
                    .with("fs-readonly", if meta.permissions().readonly() { "true" } else { "false" })
            };
            Some(item)
        })
        .collect();
    Ok(Reply::Items { base, items })
}

/// Writes a file whole (through a temporary file renamed over it).
fn put(path: &Path, body: &[u8]) -> Res {
    let parent = path.parent().ok_or_else(|| RwsError::bad_request("a file needs a name"))?;
    if !parent.is_dir() {
        return Err(RwsError::not_found("the folder does not exist"));
    }
    if path.is_dir() {
        return Err(RwsError::wrong_state("a folder of that name exists"));
    }
    let name = path.file_name().map_or_else(String::new, |n| n.to_string_lossy().into_owned());
    let temp = parent.join(format!(".{name}.{}.part", crate::auth::random_hex(4)));
    let written = std::fs::write(&temp, body).and_then(|()| std::fs::rename(&temp, path));
    if let Err(e) = written {
        let _ = std::fs::remove_file(&temp);
        return Err(io_error(path, &e));
    }
    Ok(Reply::Created { location: None, body: None })
}

/// Deletes a file or an empty folder.
fn delete(path: &Path) -> Res {
    let meta = std::fs::metadata(path).map_err(|e| io_error(path, &e))?;
    let removed = if meta.is_dir() { std::fs::remove_dir(path) } else { std::fs::remove_file(path) };
    removed.map_err(|e| io_error(path, &e))?;
    Ok(Reply::NoContent)
}

/// Makes folder `fs-newname` in the folder `path`.
fn create(path: &Path, new_name: Option<&str>) -> Res {
    let name = new_name.ok_or_else(|| RwsError::bad_request("the form field `fs-newname` is missing"))?;
    if name.is_empty() || name == "." || name == ".." || name.contains(['/', '\\', ':', '\0']) {
        return Err(RwsError::new(
            StatusCode::FORBIDDEN,
            crate::model::CODE_BAD_REQUEST,
            "a plain folder name is needed",
        ));
    }
    if !path.is_dir() {
        return Err(RwsError::not_found("the folder does not exist"));
    }
    std::fs::create_dir(path.join(name)).map_err(|e| io_error(path, &e))?;
    Ok(Reply::Created { location: None, body: None })
}
