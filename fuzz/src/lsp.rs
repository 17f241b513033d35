//! What the `lsp` fuzz target is made of: a session of Language Server Protocol
//! messages built from the fuzzer's bytes, a mirror of the documents the server
//! holds, and the checks its answers must pass.
//!
//! A session is: `initialize` (a client that pulls diagnostics, so the server checks
//! on this thread and the run is deterministic), `initialized`, then generated
//! messages (documents opened, changed at arbitrary positions, saved and closed;
//! every request the server offers at arbitrary positions; messages with parameters
//! of the wrong shape, unknown methods, stray responses, and messages the fuzzer
//! writes as raw JSON-RPC bytes), then `shutdown` and `exit`.
//!
//! The mirror applies each change as the protocol says: positions count UTF-16
//! units, a line past the end is the text's end, a character past a line's end is
//! the line's end (before its break). A position inside a character (the middle of a
//! surrogate pair) is not defined by the protocol; it is taken as the end of that
//! character, as `rapid-lsp` takes it.

use arbitrary::{Result, Unstructured};
use lsp_server::{Message, Notification, Request, RequestId, Response};
use serde_json::{json, Value};

/// The documents a session works on (a `.sys` module among them, and a name that
/// needs percent-encoding).
pub const URIS: &[&str] = &["file:///fuzz/a.mod", "file:///fuzz/b.sys", "file:///fuzz/%C3%A4.mod"];

/// Pieces of text edits insert: RAPID words, line breaks and multi-byte characters.
const INSERTS: &[&str] = &[
    "",
    "\n",
    "\r\n",
    "ä",
    "€",
    "😀",
    " ",
    "x",
    ";",
    ":=",
    "(",
    ")",
    "\"",
    "!",
    "\\",
    ".",
    ",",
    "MODULE m\n",
    "ENDMODULE\n",
    "PROC p()\n",
    "ENDPROC\n",
    "FUNC num f()\nRETURN 1;\nENDFUNC\n",
    "VAR num n := 1;\n",
    "PERS pos p := [1,2,3];\n",
    "RECORD r\nnum a;\nENDRECORD\n",
    "n := n + 1;\n",
    "IF n > 1 THEN\n",
    "ENDIF\n",
    "TPWrite \"a\";\n",
    "p;\n",
    "%\"p\"%;\n",
    "ERROR\nRETRY;\n",
    "n",
    "p",
    "f(",
    "ABS(",
    "\\Dec",
];

/// The messages of one session, and the ids of the requests among them (each must
/// be answered once).
#[derive(Debug, Default)]
pub struct Session {
    pub messages: Vec<Message>,
    pub requests: Vec<RequestId>,
    /// For each diagnostics request, the text its document has when it is asked.
    pub expect: Vec<(RequestId, String)>,
    next_id: i32,
    docs: Vec<Option<String>>,
}

impl Session {
    fn request(&mut self, method: &str, params: Value) -> RequestId {
        self.next_id += 1;
        let id = RequestId::from(self.next_id);
        self.messages.push(Message::Request(Request::new(id.clone(), method.to_owned(), params)));
        self.requests.push(id.clone());
        id
    }

    fn notify(&mut self, method: &str, params: Value) {
        self.messages.push(Message::Notification(Notification::new(method.to_owned(), params)));
    }
}

/// A whole session from the fuzzer's bytes.
pub fn session(u: &mut Unstructured) -> Result<Session> {
    let mut s = Session { docs: vec![None; URIS.len()], ..Session::default() };
    let capabilities = json!({"textDocument": {"diagnostic": {}, "completion": {"completionItem": {"snippetSupport": u.arbitrary::<bool>()?}}}});
    s.request("initialize", json!({"processId": null, "rootUri": null, "capabilities": capabilities}));
    s.notify("initialized", json!({}));
    for _ in 0..u.int_in_range(1..=24u8)? {
        if u.is_empty() {
            break;
        }
        step(u, &mut s)?;
    }
    s.request("shutdown", Value::Null);
    s.notify("exit", Value::Null);
    Ok(s)
}

/// One generated message (or a few: a change often comes with a request after it).
fn step(u: &mut Unstructured, s: &mut Session) -> Result<()> {
    let doc = u.choose_index(URIS.len())?;
    let uri = URIS[doc];
    let position = position(u, s.docs[doc].as_deref())?;
    let at = json!({"textDocument": {"uri": uri}, "position": position});
    match u.int_in_range(0..=23u8)? {
        0..=2 => {
            let text = initial_text(u)?;
            s.notify(
                "textDocument/didOpen",
                json!({"textDocument": {"uri": uri, "languageId": "rapid", "version": 1, "text": text}}),
            );
            s.docs[doc] = Some(text);
        }
        3..=7 => change(u, s, doc)?,
        8 => {
            s.notify("textDocument/didClose", json!({"textDocument": {"uri": uri}}));
            s.docs[doc] = None;
        }
        9 => s.notify("textDocument/didSave", json!({"textDocument": {"uri": uri}})),
        10 => {
            s.request("textDocument/hover", at);
        }
        11 => {
            s.request("textDocument/completion", at);
        }
        12 => {
            s.request("textDocument/definition", at);
        }
        13 => {
            let mut p = at;
            p["context"] = json!({"includeDeclaration": u.arbitrary::<bool>()?});
            s.request("textDocument/references", p);
        }
        14 => {
            let mut p = at;
            p["newName"] = json!(u.choose(&["m", "n2", "ä", "", "1x", "PROC", "a b", "😀"])?);
            s.request("textDocument/rename", p);
        }
        15 => {
            s.request("textDocument/signatureHelp", at);
        }
        16 => {
            s.request(
                "textDocument/formatting",
                json!({"textDocument": {"uri": uri}, "options": {"tabSize": 2, "insertSpaces": true}}),
            );
        }
        17 => {
            let method = u.choose(&[
                "textDocument/semanticTokens/full",
                "textDocument/documentSymbol",
                "textDocument/foldingRange",
            ])?;
            s.request(method, json!({"textDocument": {"uri": uri}}));
        }
        18 => {
            let range = json!({"start": position, "end": self::position(u, s.docs[doc].as_deref())?});
            let diagnostic = json!({"range": range, "message": "x", "code": u.choose(&["E0101", "W0001", ""])?});
            s.request(
                "textDocument/codeAction",
                json!({"textDocument": {"uri": uri}, "range": range, "context": {"diagnostics": [diagnostic]}}),
            );
        }
        19 => {
            s.request("workspace/symbol", json!({"query": u.choose(&["", "m", "p", "ä"])?}));
        }
        20 | 21 => {
            let id = s.request("textDocument/diagnostic", json!({"textDocument": {"uri": uri}}));
            if let Some(text) = &s.docs[doc] {
                s.expect.push((id, text.clone()));
            }
        }
        _ => malformed(u, s, &at)?,
    }
    Ok(())
}

/// A document's first text: a generated program (so that navigation finds names),
/// or a few pieces.
fn initial_text(u: &mut Unstructured) -> Result<String> {
    if u.ratio(1u8, 2)? {
        let program = crate::program::generate(u)?;
        return Ok(program.modules.into_iter().next().unwrap_or_default());
    }
    let mut text = String::new();
    for _ in 0..u.int_in_range(0..=12u8)? {
        text.push_str(u.choose(INSERTS)?);
    }
    Ok(text)
}

/// A position in (or just past) `text`: any line up to two past the last, any
/// character up to three past its line's end, so inside multi-byte characters too.
fn position(u: &mut Unstructured, text: Option<&str>) -> Result<Value> {
    let text = text.unwrap_or("");
    let lines: Vec<&str> = text.split('\n').collect();
    let line = u.int_in_range(0..=lines.len() as u32 + 1)?;
    let units = lines.get(line as usize).map_or(0, |l| l.encode_utf16().count() as u32);
    let character = u.int_in_range(0..=units + 3)?;
    Ok(json!({"line": line, "character": character}))
}

/// A `didChange`: one to three ranged edits (or the whole text), mirrored.
fn change(u: &mut Unstructured, s: &mut Session, doc: usize) -> Result<()> {
    let mut text = s.docs[doc].clone();
    let mut changes = Vec::new();
    for _ in 0..u.int_in_range(1..=3u8)? {
        let mut insert = String::new();
        for _ in 0..u.int_in_range(0..=3u8)? {
            insert.push_str(u.choose(INSERTS)?);
        }
        if u.ratio(1u8, 10)? {
            changes.push(json!({"text": insert}));
            text = text.map(|_| insert);
            continue;
        }
        let start = position(u, text.as_deref())?;
        // The end mostly after the start; sometimes before it (the server then
        // takes an empty range at the start).
        let end = position(u, text.as_deref())?;
        if let Some(t) = &mut text {
            let (a, b) = (offset(t, &start), offset(t, &end));
            t.replace_range(a..b.max(a), &insert);
        }
        changes.push(json!({"range": {"start": start, "end": end}, "text": insert}));
    }
    s.notify(
        "textDocument/didChange",
        json!({"textDocument": {"uri": URIS[doc], "version": 2}, "contentChanges": changes}),
    );
    s.docs[doc] = text;
    Ok(())
}

/// The byte offset of an LSP position in `text` (the protocol's rule, see the
/// module's doc).
pub fn offset(text: &str, position: &Value) -> usize {
    let line = position["line"].as_u64().unwrap_or(0) as usize;
    let character = position["character"].as_u64().unwrap_or(0) as usize;
    let mut start = 0;
    for _ in 0..line {
        match text[start..].find('\n') {
            Some(nl) => start += nl + 1,
            None => return text.len(),
        }
    }
    let line_text = &text[start..];
    let line_end = line_text.find('\n').map_or(line_text.len(), |nl| match line_text[..nl].ends_with('\r') {
        true => nl - 1,
        false => nl,
    });
    let mut units = 0;
    for (at, c) in line_text[..line_end].char_indices() {
        if units >= character {
            return start + at;
        }
        units += c.len_utf16();
    }
    start + line_end
}

/// Messages a client should not send: parameters of the wrong shape, an unknown
/// method, a response nobody asked for, a change to a document never opened, and
/// raw bytes read as a JSON-RPC message (when they read as one).
fn malformed(u: &mut Unstructured, s: &mut Session, at: &Value) -> Result<()> {
    let junk = [
        json!(null),
        json!(1),
        json!("x"),
        json!([1, 2]),
        json!({"textDocument": 5}),
        json!({"position": at["position"]}),
    ];
    let params = u.choose(&junk)?.clone();
    match u.int_in_range(0..=5u8)? {
        0 => {
            let method = u.choose(&[
                "textDocument/hover",
                "textDocument/rename",
                "textDocument/diagnostic",
                "textDocument/formatting",
                "workspace/symbol",
            ])?;
            s.request(method, params);
        }
        1 => {
            s.request(u.choose(&["$/cancelRequest", "textDocument/unknown", "", "initialize"])?, params);
        }
        2 => {
            let method =
                u.choose(&["textDocument/didOpen", "textDocument/didChange", "textDocument/didClose", "$/unknown"])?;
            s.notify(method, params);
        }
        3 => s.messages.push(Message::Response(Response::new_ok(RequestId::from(9999), params))),
        4 => {
            let change = json!({"range": {"start": at["position"], "end": at["position"]}, "text": "x"});
            s.notify(
                "textDocument/didChange",
                json!({"textDocument": {"uri": "file:///fuzz/never.mod", "version": 1}, "contentChanges": [change]}),
            );
        }
        _ => {
            let len = u.int_in_range(0..=96usize)?;
            let body = u.bytes(len.min(u.len()))?;
            let mut framed = format!("Content-Length: {}\r\n\r\n", body.len()).into_bytes();
            framed.extend_from_slice(body);
            if let Ok(Some(message)) = Message::read(&mut framed.as_slice()) {
                // Requests the fuzzer wrote are answered too; a numeric id could be one
                // of ours (a client's mistake whose answers cannot be told apart).
                match &message {
                    Message::Request(r) if serde_json::to_value(&r.id).is_ok_and(|v| v.is_number()) => return Ok(()),
                    Message::Request(r) if s.requests.contains(&r.id) || r.method == "shutdown" => return Ok(()),
                    Message::Request(r) => s.requests.push(r.id.clone()),
                    Message::Notification(n) if n.method == "exit" => return Ok(()),
                    _ => {}
                }
                s.messages.push(message);
            }
        }
    }
    Ok(())
}

/// Checks the server's answers to a whole session: each request answered exactly
/// once, and each diagnostic inside the text its document had.
pub fn check_answers(s: &Session, answers: &[Message]) {
    let mut seen: Vec<&RequestId> = Vec::new();
    for message in answers {
        let Message::Response(response) = message else { continue };
        assert!(s.requests.contains(&response.id), "an answer to no request: {response:?}");
        assert!(!seen.contains(&&response.id), "request {} answered twice", response.id);
        seen.push(&response.id);
        if let Some((_, text)) = s.expect.iter().find(|(id, _)| *id == response.id) {
            check_diagnostics(text, response);
        }
    }
    for id in &s.requests {
        assert!(seen.contains(&id), "request {id} not answered");
    }
}

fn check_diagnostics(text: &str, response: &Response) {
    let Some(result) = &response.result else { panic!("a diagnostics request failed: {response:?}") };
    let lines: Vec<&str> = text.split('\n').collect();
    for item in result["items"].as_array().into_iter().flatten() {
        let range = &item["range"];
        let end = |p: &Value| (p["line"].as_u64().unwrap_or(u64::MAX), p["character"].as_u64().unwrap_or(u64::MAX));
        let (start, stop) = (end(&range["start"]), end(&range["end"]));
        assert!(start <= stop, "an inverted range {range} in {text:?}");
        for (line, character) in [start, stop] {
            let Some(l) = lines.get(line as usize) else { panic!("range {range} past the last line of {text:?}") };
            let units = l.trim_end_matches('\r').encode_utf16().count() as u64;
            assert!(character <= units, "range {range} past the end of line {line} of {text:?}");
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pos(line: u32, character: u32) -> Value {
        json!({"line": line, "character": character})
    }

    #[test]
    fn the_mirror_counts_utf16_and_clamps_as_the_protocol_says() {
        // "a😀b\r\ncd": 😀 is bytes 1..5 and UTF-16 units 1..3; the line break at 6.
        let text = "a😀b\r\ncd";
        assert_eq!(offset(text, &pos(0, 1)), 1);
        assert_eq!(offset(text, &pos(0, 2)), 5, "inside the pair: after the character");
        assert_eq!(offset(text, &pos(0, 3)), 5);
        assert_eq!(offset(text, &pos(0, 4)), 6, "the line's end");
        assert_eq!(offset(text, &pos(0, 40)), 6, "before the CRLF");
        assert_eq!(offset(text, &pos(1, 1)), 9);
        assert_eq!(offset(text, &pos(5, 0)), text.len());
    }

    #[test]
    fn sessions_open_documents_and_ask_for_diagnostics() {
        let bytes: Vec<u8> = (0..8192u32).map(|i| (i.wrapping_mul(2654435761) >> 11) as u8).collect();
        let mut u = Unstructured::new(&bytes);
        let mut requests = 0;
        for _ in 0..20 {
            let Ok(s) = session(&mut u) else { break };
            requests += s.requests.len();
        }
        assert!(requests > 40, "only {requests} requests in 20 sessions");
    }
}
