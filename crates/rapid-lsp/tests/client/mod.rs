//! A minimal LSP client for the protocol tests: the server runs on a thread behind
//! `Connection::memory()`; the client sends JSON-RPC messages and waits (bounded) for
//! the answers and notifications it expects.

#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::thread;
use std::time::Duration;

use lsp_server::{Connection, Message, Notification, Request, RequestId};
use rapid_lsp::{Task, Workspace, WorkspaceLoader};
use rapid_sema::{Options, PredefinedData, SourceInput};
use serde_json::{json, Value};

/// How long any one answer may take before the test fails.
const PATIENCE: Duration = Duration::from_secs(20);

/// A scratch folder of module files.
pub(crate) struct Folder {
    pub(crate) root: PathBuf,
}

impl Folder {
    pub(crate) fn new(name: &str, files: &[(&str, &str)]) -> Folder {
        static NEXT: AtomicUsize = AtomicUsize::new(0);
        let unique = NEXT.fetch_add(1, Ordering::Relaxed);
        let root = std::env::temp_dir().join(format!("rapid-lsp-tests-{}-{name}-{unique}", std::process::id()));
        let _ = std::fs::remove_dir_all(&root);
        std::fs::create_dir_all(&root).unwrap();
        for (file, text) in files {
            let path = root.join(file);
            std::fs::create_dir_all(path.parent().unwrap()).unwrap();
            std::fs::write(path, text).unwrap();
        }
        Folder { root }
    }

    pub(crate) fn uri(&self, file: &str) -> String {
        format!("file://{}", self.root.join(file).display())
    }

    /// The folder's modules as `rapid check FOLDER` would read them.
    pub(crate) fn inputs(&self) -> Vec<SourceInput> {
        read_folder(&self.root)
    }
}

impl Drop for Folder {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.root);
    }
}

pub(crate) fn read_folder(root: &Path) -> Vec<SourceInput> {
    let mut paths: Vec<PathBuf> = std::fs::read_dir(root)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e.eq_ignore_ascii_case("mod")))
        .collect();
    paths.sort();
    paths.iter().map(|p| SourceInput::from_bytes(p.display().to_string(), std::fs::read(p).unwrap())).collect()
}

/// The test loader: a folder's `.mod` files are one task; `signals` are configured.
pub(crate) struct TestLoader {
    pub(crate) signals: Vec<(String, String)>,
}

impl WorkspaceLoader for TestLoader {
    fn load(&self, root: &Path) -> Result<Workspace, String> {
        let predefined =
            self.signals.iter().map(|(n, t)| PredefinedData { name: n.clone(), type_name: t.clone() }).collect();
        let task =
            Task { name: None, modules: read_folder(root), options: Options { predefined, ..Options::default() } };
        Ok(Workspace { tasks: vec![task], ..Workspace::default() })
    }
}

pub(crate) struct Client {
    conn: Connection,
    server: Option<thread::JoinHandle<()>>,
    next_id: i32,
    pub(crate) capabilities: Value,
    /// Notifications received while waiting for something else.
    pending: Vec<Notification>,
}

pub(crate) fn at(uri: &str, line: u32, character: u32) -> Value {
    json!({"textDocument": {"uri": uri}, "position": {"line": line, "character": character}})
}

impl Client {
    pub(crate) fn start(folder: &Folder, capabilities: Value) -> Client {
        Client::start_with(folder, capabilities, Vec::new())
    }

    pub(crate) fn start_with(folder: &Folder, capabilities: Value, signals: Vec<(String, String)>) -> Client {
        Client::start_loader(folder, capabilities, TestLoader { signals })
    }

    /// Starts the server with its own loader.
    pub(crate) fn start_loader(
        folder: &Folder,
        capabilities: Value,
        loader: impl WorkspaceLoader + Send + 'static,
    ) -> Client {
        let (server_end, client_end) = Connection::memory();
        let server = thread::spawn(move || {
            rapid_lsp::serve(server_end, &loader).unwrap();
        });
        let mut client = Client {
            conn: client_end,
            server: Some(server),
            next_id: 0,
            capabilities: Value::Null,
            pending: Vec::new(),
        };
        let root = format!("file://{}", folder.root.display());
        let result = client.request("initialize", json!({"capabilities": capabilities, "rootUri": root}));
        client.capabilities = result["capabilities"].clone();
        client.notify("initialized", json!({}));
        client
    }

    pub(crate) fn notify(&self, method: &str, params: Value) {
        self.conn.sender.send(Message::Notification(Notification::new(method.to_owned(), params))).unwrap();
    }

    fn send(&mut self, method: &str, params: Value) -> RequestId {
        self.next_id += 1;
        let id = RequestId::from(self.next_id);
        self.conn.sender.send(Message::Request(Request::new(id.clone(), method.to_owned(), params))).unwrap();
        id
    }

    fn wait_response(&mut self, id: RequestId) -> lsp_server::Response {
        loop {
            match self.conn.receiver.recv_timeout(PATIENCE).expect("the server answers in time") {
                Message::Response(r) if r.id == id => return r,
                Message::Notification(n) => self.pending.push(n),
                _ => {}
            }
        }
    }

    /// Sends a request and returns its result (failing the test on an error).
    pub(crate) fn request(&mut self, method: &str, params: Value) -> Value {
        let id = self.send(method, params);
        let response = self.wait_response(id);
        assert!(response.error.is_none(), "{method} failed: {:?}", response.error);
        response.result.unwrap_or(Value::Null)
    }

    /// Sends a request that must fail and returns the error's message.
    pub(crate) fn request_error(&mut self, method: &str, params: Value) -> String {
        let id = self.send(method, params);
        self.wait_response(id).error.expect("the request fails").message
    }

    pub(crate) fn open(&self, uri: &str, text: &str) {
        self.notify(
            "textDocument/didOpen",
            json!({"textDocument": {"uri": uri, "languageId": "rapid", "version": 1, "text": text}}),
        );
    }

    pub(crate) fn change(&self, uri: &str, version: i32, range: Value, text: &str) {
        self.notify(
            "textDocument/didChange",
            json!({"textDocument": {"uri": uri, "version": version}, "contentChanges": [{"range": range, "text": text}]}),
        );
    }

    /// The next diagnostics published for `uri`.
    pub(crate) fn diagnostics_for(&mut self, uri: &str) -> Vec<Value> {
        self.published(uri, |_| true)
    }

    /// The diagnostics published for `uri` at document version `version`.
    pub(crate) fn diagnostics_for_version(&mut self, uri: &str, version: i32) -> Vec<Value> {
        self.published(uri, |p| p["version"] == version)
    }

    /// The first publication for `uri` that `wanted` accepts, in the order they were
    /// sent; others are kept for later calls.
    fn published(&mut self, uri: &str, wanted: impl Fn(&Value) -> bool) -> Vec<Value> {
        let matches = |n: &Notification| {
            n.method == "textDocument/publishDiagnostics" && n.params["uri"] == uri && wanted(&n.params)
        };
        loop {
            if let Some(at) = self.pending.iter().position(matches) {
                let n = self.pending.remove(at);
                return n.params["diagnostics"].as_array().cloned().unwrap_or_default();
            }
            match self.conn.receiver.recv_timeout(PATIENCE).expect("the server publishes in time") {
                Message::Notification(n) => self.pending.push(n),
                _ => continue,
            }
        }
    }

    pub(crate) fn shutdown(mut self) {
        self.request("shutdown", Value::Null);
        self.notify("exit", Value::Null);
        if let Some(server) = self.server.take() {
            server.join().unwrap();
        }
    }
}
