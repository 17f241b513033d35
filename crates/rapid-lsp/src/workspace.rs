//! The server's view of the workspace: the tasks the embedder loaded, with the text of
//! every open document laid over the module it is, and each open module that belongs
//! to no task as a task of its own (a loose file).

use std::cell::RefCell;
use std::hash::{Hash, Hasher};
use std::path::{Path, PathBuf};
use std::rc::Rc;

use lsp_types::Uri;
use rapid_sema::{Options, SourceInput};
use rustc_hash::{FxHashMap, FxHasher};

use crate::documents::Documents;
use crate::index::FileIndex;
use crate::{uri, Workspace};

/// One task as the editor sees it now.
#[derive(Debug, Clone)]
pub(crate) struct TaskView {
    /// The task's name in the workspace's system; `None` for a folder or a loose file.
    pub(crate) name: Option<String>,
    /// The modules, with open documents' text.
    pub(crate) files: Vec<SourceInput>,
    /// The URI of each of `files` (the editor's own URI for an open document).
    pub(crate) uris: Vec<Uri>,
    pub(crate) options: Options,
}

impl TaskView {
    pub(crate) fn file_of(&self, uri: &Uri) -> Option<usize> {
        self.uris.iter().position(|u| u == uri)
    }
}

/// What the server holds between messages.
#[derive(Default)]
pub(crate) struct State {
    pub(crate) root: Option<PathBuf>,
    pub(crate) loaded: Workspace,
    pub(crate) docs: Documents,
    /// Each file's index with the hash of the text it was built from.
    indexes: RefCell<FxHashMap<Uri, (u64, Rc<FileIndex>)>>,
}

impl State {
    /// Every task, open documents' text laid over the files read from disk.
    pub(crate) fn tasks(&self) -> Vec<TaskView> {
        let open: FxHashMap<PathBuf, (&Uri, &str)> =
            self.docs.iter().filter_map(|(u, doc)| Some((normal(&uri::to_path(u)?), (u, doc.text.as_str())))).collect();
        let mut claimed: Vec<&Uri> = Vec::new();
        let mut tasks: Vec<TaskView> = Vec::new();
        for task in &self.loaded.tasks {
            let mut view = TaskView {
                name: task.name.clone(),
                files: Vec::with_capacity(task.modules.len()),
                uris: Vec::with_capacity(task.modules.len()),
                options: task.options.clone(),
            };
            for module in &task.modules {
                let path = normal(Path::new(&module.path));
                match open.get(&path) {
                    Some(&(u, text)) => {
                        claimed.push(u);
                        view.files.push(SourceInput::from_text(module.path.clone(), text));
                        view.uris.push(u.clone());
                    }
                    None => {
                        let Some(u) = uri::from_path(&path) else { continue };
                        view.files.push(module.clone());
                        view.uris.push(u);
                    }
                }
            }
            tasks.push(view);
        }
        for (u, doc) in self.docs.iter() {
            if claimed.contains(&u) {
                continue;
            }
            let path = uri::to_path(u).map_or_else(|| u.as_str().to_owned(), |p| p.display().to_string());
            tasks.push(TaskView {
                name: None,
                files: vec![SourceInput::from_text(path, doc.text.clone())],
                uris: vec![u.clone()],
                options: Options::default(),
            });
        }
        tasks
    }

    /// The tasks that hold `uri` (a module several tasks load is in each).
    pub(crate) fn tasks_of(&self, uri: &Uri) -> Vec<TaskView> {
        self.tasks().into_iter().filter(|t| t.file_of(uri).is_some()).collect()
    }

    /// The index of a file's current text, built again only when the text changed.
    pub(crate) fn index(&self, uri: &Uri, text: &str) -> Rc<FileIndex> {
        let mut hasher = FxHasher::default();
        text.hash(&mut hasher);
        let hash = hasher.finish();
        let mut cache = self.indexes.borrow_mut();
        if let Some((known, index)) = cache.get(uri) {
            if *known == hash {
                return index.clone();
            }
        }
        let index = Rc::new(FileIndex::build(text));
        cache.insert(uri.clone(), (hash, index.clone()));
        index
    }
}

/// A path made comparable: absolute paths as given, `.` and `..` parts removed.
fn normal(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for part in path.components() {
        match part {
            std::path::Component::CurDir => {}
            std::path::Component::ParentDir => {
                out.pop();
            }
            other => out.push(other),
        }
    }
    out
}
