//! Fuzz target `lsp`: the language server's loop (`rapid_lsp::serve`) in-process, on
//! an in-memory connection, fed a generated session (`rapid_fuzz::lsp`): documents
//! opened and edited at arbitrary positions (inside multi-byte characters too), every
//! request at arbitrary positions, malformed messages, then shutdown and exit.
//!
//! Asserted: no panic; the loop ends; every request answered exactly once; every
//! diagnostic's range inside the text its document had when it was asked for. The
//! client pulls its diagnostics, so the server checks on this thread (no worker) and
//! a run is deterministic.
#![no_main]

use arbitrary::Unstructured;
use libfuzzer_sys::fuzz_target;
use lsp_server::Connection;

/// No workspace folder: open documents are served as loose files, formatted with
/// the default options.
struct Loose;

impl rapid_lsp::WorkspaceLoader for Loose {
    fn load(&self, _root: &std::path::Path) -> Result<rapid_lsp::Workspace, String> {
        Ok(rapid_lsp::Workspace::default())
    }
}

fuzz_target!(|data: &[u8]| {
    let mut u = Unstructured::new(data);
    let Ok(session) = rapid_fuzz::lsp::session(&mut u) else { return };
    let (server, client) = Connection::memory();
    for message in &session.messages {
        client.sender.send(message.clone()).expect("the server's end is open");
    }
    // Everything is queued: the loop reads it all, then sees the client gone.
    let Connection { sender, receiver } = client;
    drop(sender);
    let _ = rapid_lsp::serve(server, &Loose);
    let answers: Vec<_> = receiver.try_iter().collect();
    rapid_fuzz::lsp::check_answers(&session, &answers);
});
