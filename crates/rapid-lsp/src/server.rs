//! The protocol loop: initialize, then requests and notifications until shutdown.
//! Requests are answered on this thread from the current text; checking runs on the
//! worker (`analysis::Worker`), started again after each burst of edits.

use std::error::Error;
use std::path::PathBuf;

use lsp_server::{Connection, ErrorCode, Message, Notification, Request, RequestId, Response};
use lsp_types::notification::{self as note, Notification as _};
use lsp_types::request::{self as req, Request as _};
use lsp_types::{
    CodeActionProviderCapability, CompletionOptions, DiagnosticOptions, DiagnosticServerCapabilities,
    DocumentDiagnosticReport, DocumentDiagnosticReportResult, FoldingRangeProviderCapability,
    FullDocumentDiagnosticReport, HoverProviderCapability, InitializeParams, MessageType, OneOf,
    RelatedFullDocumentDiagnosticReport, SemanticTokensFullOptions, SemanticTokensOptions,
    SemanticTokensServerCapabilities, ServerCapabilities, ServerInfo, ShowMessageParams, SignatureHelpOptions,
    TextDocumentSyncCapability, TextDocumentSyncKind, Uri,
};
use serde::de::DeserializeOwned;
use serde::Serialize;

use crate::analysis::{self, Job, Worker};
use crate::features::{actions, complete, folding, format, hover, navigate, semantic, signature, symbols, TaskIndex};
use crate::workspace::State;
use crate::{uri, WorkspaceLoader};

/// What the server offers. Pull diagnostics are offered only to a client that can
/// pull (`pull`); every other client gets them pushed.
pub fn capabilities(pull: bool) -> ServerCapabilities {
    ServerCapabilities {
        text_document_sync: Some(TextDocumentSyncCapability::Kind(TextDocumentSyncKind::INCREMENTAL)),
        hover_provider: Some(HoverProviderCapability::Simple(true)),
        definition_provider: Some(OneOf::Left(true)),
        references_provider: Some(OneOf::Left(true)),
        rename_provider: Some(OneOf::Left(true)),
        document_symbol_provider: Some(OneOf::Left(true)),
        workspace_symbol_provider: Some(OneOf::Left(true)),
        completion_provider: Some(CompletionOptions {
            trigger_characters: Some(vec![".".into(), "\\".into()]),
            ..CompletionOptions::default()
        }),
        signature_help_provider: Some(SignatureHelpOptions {
            trigger_characters: Some(vec!["(".into(), ",".into(), "\\".into(), " ".into()]),
            ..SignatureHelpOptions::default()
        }),
        document_formatting_provider: Some(OneOf::Left(true)),
        folding_range_provider: Some(FoldingRangeProviderCapability::Simple(true)),
        code_action_provider: Some(CodeActionProviderCapability::Simple(true)),
        semantic_tokens_provider: Some(SemanticTokensServerCapabilities::SemanticTokensOptions(
            SemanticTokensOptions {
                legend: semantic::legend(),
                full: Some(SemanticTokensFullOptions::Bool(true)),
                range: None,
                ..SemanticTokensOptions::default()
            },
        )),
        diagnostic_provider: pull.then(|| {
            DiagnosticServerCapabilities::Options(DiagnosticOptions {
                identifier: Some("rapid".into()),
                inter_file_dependencies: true,
                workspace_diagnostics: false,
                ..DiagnosticOptions::default()
            })
        }),
        ..ServerCapabilities::default()
    }
}

/// Serves one client on `connection` until it shuts down and exits.
pub fn serve(connection: Connection, loader: &dyn WorkspaceLoader) -> Result<(), Box<dyn Error + Send + Sync>> {
    let (id, params) = connection.initialize_start()?;
    let params: InitializeParams = serde_json::from_value(params)?;
    let text_caps = params.capabilities.text_document.as_ref();
    let pull = text_caps.is_some_and(|t| t.diagnostic.is_some());
    let snippets =
        text_caps.and_then(|t| t.completion.as_ref()?.completion_item.as_ref()?.snippet_support).unwrap_or(false);
    let result = serde_json::json!({
        "capabilities": capabilities(pull),
        "serverInfo": ServerInfo { name: "rapid-lsp".into(), version: Some(env!("CARGO_PKG_VERSION").into()) },
    });
    connection.initialize_finish(id, result)?;

    let mut server = Server { conn: &connection, loader, state: State::default(), worker: None, snippets };
    server.state.root = workspace_root(&params);
    server.reload();
    if !pull {
        server.worker = Some(Worker::start(connection.sender.clone()));
        server.check();
    }
    let mut dirty = false;
    while let Ok(msg) = connection.receiver.recv() {
        match msg {
            Message::Request(request) => {
                if connection.handle_shutdown(&request)? {
                    break;
                }
                server.request(request);
            }
            Message::Notification(notification) => dirty |= server.notification(notification),
            Message::Response(_) => {}
        }
        // Check once the burst of messages is read: typing sends one change a key.
        if dirty && connection.receiver.is_empty() {
            server.check();
            dirty = false;
        }
    }
    if let Some(worker) = server.worker.take() {
        worker.stop();
    }
    Ok(())
}

/// The folder the client opened: its first workspace folder, or its root URI.
fn workspace_root(params: &InitializeParams) -> Option<PathBuf> {
    if let Some(folder) = params.workspace_folders.as_ref().and_then(|f| f.first()) {
        return uri::to_path(&folder.uri);
    }
    #[allow(deprecated)]
    params.root_uri.as_ref().and_then(uri::to_path)
}

struct Server<'a> {
    conn: &'a Connection,
    loader: &'a dyn WorkspaceLoader,
    state: State,
    worker: Option<Worker>,
    /// The client inserts snippets (`${1:arg}`).
    snippets: bool,
}

impl Server<'_> {
    /// Reads the workspace again (at start, and when files are saved or change on
    /// disk). A workspace that cannot be read is said once; open modules are then
    /// served as loose files.
    fn reload(&mut self) {
        let Some(root) = self.state.root.clone() else { return };
        match self.loader.load(&root) {
            Ok(workspace) => self.state.loaded = workspace,
            Err(why) => {
                self.state.loaded = crate::Workspace::default();
                let params = ShowMessageParams { typ: MessageType::WARNING, message: why };
                self.notify(note::ShowMessage::METHOD, params);
            }
        }
    }

    /// Hands the current state to the checker (push mode only).
    fn check(&self) {
        if let Some(worker) = &self.worker {
            worker.submit(self.job(None));
        }
    }

    /// The state to check: every task, or those holding `only`. A system is checked
    /// whole for any one document: its findings compare the tasks.
    fn job(&self, only: Option<&Uri>) -> Job {
        let loaded = &self.state.loaded;
        let only = only.filter(|_| loaded.system.is_none());
        let others = match only {
            Some(_) => Vec::new(),
            None => loaded
                .other_files
                .iter()
                .filter_map(|f| Some((uri::from_path(std::path::Path::new(&f.path))?, f.clone())))
                .collect(),
        };
        Job {
            tasks: match only {
                Some(u) => self.state.tasks_of(u),
                None => self.state.tasks(),
            },
            other_findings: if only.is_some() { Vec::new() } else { loaded.other_findings.clone() },
            others,
            system: loaded.system.clone(),
            versions: self.state.docs.iter().map(|(u, d)| (u.clone(), d.version)).collect(),
        }
    }

    fn notify(&self, method: &str, params: impl Serialize) {
        let _ = self.conn.sender.send(Message::Notification(Notification::new(method.to_owned(), params)));
    }

    fn respond(&self, id: RequestId, result: Result<serde_json::Value, String>) {
        let response = match result {
            Ok(value) => Response { id, result: Some(value), error: None },
            Err(why) => Response::new_err(id, ErrorCode::RequestFailed as i32, why),
        };
        let _ = self.conn.sender.send(Message::Response(response));
    }

    /// Handles a notification; true when the text the checker sees changed.
    fn notification(&mut self, n: Notification) -> bool {
        match n.method.as_str() {
            note::DidOpenTextDocument::METHOD => {
                let Ok(p) = params::<lsp_types::DidOpenTextDocumentParams>(n.params) else { return false };
                let doc = p.text_document;
                self.state.docs.open(doc.uri, doc.text, doc.version);
                true
            }
            note::DidChangeTextDocument::METHOD => {
                let Ok(p) = params::<lsp_types::DidChangeTextDocumentParams>(n.params) else { return false };
                self.state.docs.change(&p.text_document.uri, p.text_document.version, p.content_changes);
                true
            }
            note::DidCloseTextDocument::METHOD => {
                let Ok(p) = params::<lsp_types::DidCloseTextDocumentParams>(n.params) else { return false };
                self.state.docs.close(&p.text_document.uri);
                // The module's text is the one on disk again; a loose file leaves the
                // workspace, and the next check publishes it empty.
                self.reload();
                true
            }
            note::DidSaveTextDocument::METHOD | note::DidChangeWatchedFiles::METHOD => {
                self.reload();
                true
            }
            _ => false,
        }
    }

    fn request(&mut self, r: Request) {
        let id = r.id.clone();
        let result = self.answer(r);
        self.respond(id, result);
    }

    fn answer(&mut self, r: Request) -> Result<serde_json::Value, String> {
        let state = &self.state;
        match r.method.as_str() {
            req::HoverRequest::METHOD => {
                let p: lsp_types::HoverParams = params(r.params)?;
                let at = p.text_document_position_params;
                json(in_task(state, &at.text_document.uri, |ti, f| hover::hover(ti, f, at.position)))
            }
            req::GotoDefinition::METHOD => {
                let p: lsp_types::GotoDefinitionParams = params(r.params)?;
                let at = p.text_document_position_params;
                json(in_task(state, &at.text_document.uri, |ti, f| navigate::definition(ti, f, at.position)))
            }
            req::References::METHOD => {
                let p: lsp_types::ReferenceParams = params(r.params)?;
                let at = p.text_document_position;
                let with_decl = p.context.include_declaration;
                json(in_task(state, &at.text_document.uri, |ti, f| {
                    Some(navigate::references(ti, f, at.position, with_decl))
                }))
            }
            req::Completion::METHOD => {
                let p: lsp_types::CompletionParams = params(r.params)?;
                let at = p.text_document_position;
                let snippets = self.snippets;
                json(in_task(state, &at.text_document.uri, |ti, f| {
                    Some(complete::complete(ti, f, at.position, snippets))
                }))
            }
            req::SignatureHelpRequest::METHOD => {
                let p: lsp_types::SignatureHelpParams = params(r.params)?;
                let at = p.text_document_position_params;
                json(in_task(state, &at.text_document.uri, |ti, f| signature::help(ti, f, at.position)))
            }
            req::FoldingRangeRequest::METHOD => {
                let p: lsp_types::FoldingRangeParams = params(r.params)?;
                json(in_task(state, &p.text_document.uri, |ti, f| Some(folding::folding(&ti.files[f], ti.text(f)))))
            }
            req::SemanticTokensFullRequest::METHOD => {
                let p: lsp_types::SemanticTokensParams = params(r.params)?;
                json(in_task(state, &p.text_document.uri, |ti, f| Some(semantic::tokens(ti, f))))
            }
            req::CodeActionRequest::METHOD => {
                let p: lsp_types::CodeActionParams = params(r.params)?;
                let diags = p.context.diagnostics;
                json(in_task(state, &p.text_document.uri, |ti, f| Some(actions::actions(ti, f, &diags))))
            }
            req::Formatting::METHOD => {
                let p: lsp_types::DocumentFormattingParams = params(r.params)?;
                let uri = p.text_document.uri;
                let Some((ti, f)) = TaskIndex::of(state, &uri) else { return Err("this document is not open".into()) };
                let path = uri::to_path(&uri).ok_or("only files can be formatted")?;
                let config = self.loader.fmt_config(&path)?;
                json(Some(format::edits(ti.text(f), &config)?))
            }
            req::Rename::METHOD => {
                let p: lsp_types::RenameParams = params(r.params)?;
                let at = p.text_document_position;
                match TaskIndex::of(state, &at.text_document.uri) {
                    Some((ti, f)) => json(Some(navigate::rename(&ti, f, at.position, &p.new_name)?)),
                    None => Err("this document is not open".into()),
                }
            }
            req::DocumentSymbolRequest::METHOD => {
                let p: lsp_types::DocumentSymbolParams = params(r.params)?;
                json(in_task(state, &p.text_document.uri, |ti, f| Some(symbols::document(&ti.files[f], ti.text(f)))))
            }
            req::WorkspaceSymbolRequest::METHOD => {
                let p: lsp_types::WorkspaceSymbolParams = params(r.params)?;
                let (mut out, mut seen) = (Vec::new(), rustc_hash::FxHashSet::default());
                for task in state.tasks() {
                    symbols::workspace(&TaskIndex::new(state, task), &p.query, &mut out, &mut seen);
                }
                json(Some(out))
            }
            req::DocumentDiagnosticRequest::METHOD => {
                let p: lsp_types::DocumentDiagnosticParams = params(r.params)?;
                let found = analysis::diagnose(&self.job(Some(&p.text_document.uri)));
                let items = found.get(&p.text_document.uri).cloned().unwrap_or_default();
                let report = RelatedFullDocumentDiagnosticReport {
                    related_documents: None,
                    full_document_diagnostic_report: FullDocumentDiagnosticReport { result_id: None, items },
                };
                json(Some(DocumentDiagnosticReportResult::Report(DocumentDiagnosticReport::Full(report))))
            }
            _ => Err(format!("unsupported request {}", r.method)),
        }
    }
}

/// Runs `f` on the task holding `uri` (and the file's number in it).
fn in_task<T>(state: &State, uri: &Uri, f: impl FnOnce(&TaskIndex, usize) -> Option<T>) -> Option<T> {
    let (ti, file) = TaskIndex::of(state, uri)?;
    f(&ti, file)
}

fn params<P: DeserializeOwned>(value: serde_json::Value) -> Result<P, String> {
    serde_json::from_value(value).map_err(|e| format!("invalid parameters: {e}"))
}

fn json<T: Serialize>(value: Option<T>) -> Result<serde_json::Value, String> {
    serde_json::to_value(value).map_err(|e| e.to_string())
}
