//! A small Chrome DevTools Protocol client for the pendant's browser test: Chromium is
//! started headless with `--remote-debugging-port=0`, the browser's websocket address
//! read from its stderr, and commands sent as JSON over tokio-tungstenite (which this
//! crate's tests use already). One page, in flattened session mode; the `Fetch`
//! domain answers the server's Digest challenge with the test's credentials, as a
//! person would type them into the browser's login box. Every wait is bounded.

use std::collections::HashMap;
use std::path::Path;
use std::process::Stdio;
use std::sync::{Arc, Mutex};
use std::time::Duration;

use futures_util::{SinkExt, StreamExt};
use serde_json::{json, Value};
use tokio::io::AsyncBufReadExt;
use tokio::sync::{mpsc, oneshot};
use tokio_tungstenite::tungstenite::Message;

/// How long one command may take.
const COMMAND_TIMEOUT: Duration = Duration::from_secs(20);

type Pending = Arc<Mutex<HashMap<u64, oneshot::Sender<Result<Value, String>>>>>;

/// A connection to the browser: commands out, answers matched by id, events to
/// the handler.
#[derive(Clone)]
struct Conn {
    out: mpsc::UnboundedSender<String>,
    pending: Pending,
    next: Arc<Mutex<u64>>,
}

impl Conn {
    async fn call(&self, session: Option<&str>, method: &str, params: Value) -> Result<Value, String> {
        let id = {
            let mut next = self.next.lock().map_err(|_| "poisoned")?;
            *next += 1;
            *next
        };
        let mut message = json!({"id": id, "method": method, "params": params});
        if let Some(session) = session {
            message["sessionId"] = json!(session);
        }
        let (tx, rx) = oneshot::channel();
        self.pending.lock().map_err(|_| "poisoned")?.insert(id, tx);
        self.out.send(message.to_string()).map_err(|_| "the browser connection is gone".to_owned())?;
        match tokio::time::timeout(COMMAND_TIMEOUT, rx).await {
            Ok(Ok(answer)) => answer,
            Ok(Err(_)) => Err(format!("{method}: the browser connection closed")),
            Err(_) => Err(format!("{method}: no answer in time")),
        }
    }

    /// Sends without waiting for the answer (from the event handler).
    fn send(&self, session: &str, method: &str, params: Value) {
        let id = match self.next.lock() {
            Ok(mut next) => {
                *next += 1;
                *next
            }
            Err(_) => return,
        };
        let message = json!({"id": id, "method": method, "params": params, "sessionId": session});
        let _ = self.out.send(message.to_string());
    }
}

/// The browser process and its connection.
pub(crate) struct Browser {
    child: tokio::process::Child,
    conn: Conn,
    credentials: Arc<Mutex<(String, String)>>,
}

impl Browser {
    /// Starts Chromium headless with a profile in `profile`.
    pub(crate) async fn launch(program: &str, profile: &Path) -> Result<Browser, String> {
        let mut child = tokio::process::Command::new(program)
            .args([
                "--headless",
                "--no-sandbox",
                "--disable-gpu",
                "--no-first-run",
                "--disable-background-networking",
                "--disable-component-update",
                "--disable-sync",
                "--window-size=1280,800",
                "--remote-debugging-port=0",
                "--remote-allow-origins=*",
            ])
            .arg(format!("--user-data-dir={}", profile.display()))
            .arg("about:blank")
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .kill_on_drop(true)
            .spawn()
            .map_err(|e| format!("cannot start {program}: {e}"))?;
        let stderr = child.stderr.take().ok_or("no stderr")?;
        let mut lines = tokio::io::BufReader::new(stderr).lines();
        let address = tokio::time::timeout(Duration::from_secs(30), async {
            while let Ok(Some(line)) = lines.next_line().await {
                if let Some(at) = line.find("ws://") {
                    return Some(line[at..].trim().to_owned());
                }
            }
            None
        })
        .await
        .ok()
        .flatten()
        .ok_or("chromium did not say where its DevTools listen")?;
        // Keep reading stderr so that the browser never blocks on a full pipe.
        tokio::spawn(async move { while let Ok(Some(_)) = lines.next_line().await {} });
        let (socket, _) = tokio_tungstenite::connect_async(address.as_str())
            .await
            .map_err(|e| format!("cannot reach the DevTools at {address}: {e}"))?;
        let (mut sink, mut stream) = socket.split();
        let (out, mut out_rx) = mpsc::unbounded_channel::<String>();
        tokio::spawn(async move {
            while let Some(text) = out_rx.recv().await {
                if sink.send(Message::Text(text.into())).await.is_err() {
                    return;
                }
            }
        });
        let conn = Conn { out, pending: Arc::default(), next: Arc::new(Mutex::new(0)) };
        let credentials = Arc::new(Mutex::new((String::new(), String::new())));
        let (reader_conn, reader_credentials) = (conn.clone(), credentials.clone());
        tokio::spawn(async move {
            while let Some(Ok(message)) = stream.next().await {
                let Message::Text(text) = message else { continue };
                let Ok(value) = serde_json::from_str::<Value>(&text) else { continue };
                dispatch(&reader_conn, &reader_credentials, value);
            }
        });
        Ok(Browser { child, conn, credentials })
    }

    /// A new page that logs in with `credentials` when the server asks.
    pub(crate) async fn page(&self, credentials: (&str, &str)) -> Result<Page, String> {
        if let Ok(mut c) = self.credentials.lock() {
            *c = (credentials.0.to_owned(), credentials.1.to_owned());
        }
        let target = self.conn.call(None, "Target.createTarget", json!({"url": "about:blank"})).await?;
        let target_id = target["targetId"].as_str().ok_or("no target id")?.to_owned();
        let attached =
            self.conn.call(None, "Target.attachToTarget", json!({"targetId": target_id, "flatten": true})).await?;
        let session = attached["sessionId"].as_str().ok_or("no session id")?.to_owned();
        let page = Page { conn: self.conn.clone(), session, shots: Mutex::new(Vec::new()) };
        page.call("Page.enable", json!({})).await?;
        page.call("Runtime.enable", json!({})).await?;
        page.call(
            "Emulation.setDeviceMetricsOverride",
            json!({"width": 1280, "height": 800, "deviceScaleFactor": 1, "mobile": false}),
        )
        .await?;
        page.call("Fetch.enable", json!({"handleAuthRequests": true, "patterns": [{"urlPattern": "*"}]})).await?;
        Ok(page)
    }

    pub(crate) async fn close(mut self) {
        let _ = tokio::time::timeout(Duration::from_secs(5), self.conn.call(None, "Browser.close", json!({}))).await;
        if tokio::time::timeout(Duration::from_secs(5), self.child.wait()).await.is_err() {
            let _ = self.child.kill().await;
        }
    }
}

/// An answer goes to its caller; `Fetch` events are answered here: a paused request
/// goes on, a login is given the credentials.
fn dispatch(conn: &Conn, credentials: &Mutex<(String, String)>, value: Value) {
    if let Some(id) = value["id"].as_u64() {
        let waiting = conn.pending.lock().ok().and_then(|mut p| p.remove(&id));
        if let Some(tx) = waiting {
            let answer = match value.get("error") {
                Some(error) => Err(error.to_string()),
                None => Ok(value["result"].clone()),
            };
            let _ = tx.send(answer);
        }
        return;
    }
    let session = value["sessionId"].as_str().unwrap_or_default();
    let request = value["params"]["requestId"].clone();
    match value["method"].as_str() {
        Some("Fetch.requestPaused") => conn.send(session, "Fetch.continueRequest", json!({"requestId": request})),
        Some("Fetch.authRequired") => {
            let (user, password) = credentials.lock().map(|c| c.clone()).unwrap_or_default();
            conn.send(
                session,
                "Fetch.continueWithAuth",
                json!({"requestId": request, "authChallengeResponse": {
                    "response": "ProvideCredentials", "username": user, "password": password}}),
            );
        }
        _ => {}
    }
}

/// One page (tab) of the browser.
pub(crate) struct Page {
    conn: Conn,
    session: String,
    shots: Mutex<Vec<(String, Vec<u8>)>>,
}

impl Page {
    async fn call(&self, method: &str, params: Value) -> Result<Value, String> {
        self.conn.call(Some(&self.session), method, params).await
    }

    pub(crate) async fn navigate(&self, url: &str) -> Result<(), String> {
        let answer = self.call("Page.navigate", json!({"url": url})).await?;
        match answer.get("errorText") {
            Some(error) => Err(format!("{url}: {error}")),
            None => Ok(()),
        }
    }

    /// The value of a JavaScript expression, as a string (awaited when a promise).
    pub(crate) async fn eval(&self, expr: &str) -> Result<String, String> {
        let answer = self
            .call("Runtime.evaluate", json!({"expression": expr, "returnByValue": true, "awaitPromise": true}))
            .await?;
        if let Some(exception) = answer.get("exceptionDetails") {
            return Err(format!("`{expr}` threw: {exception}"));
        }
        let value = &answer["result"]["value"];
        Ok(value.as_str().map_or_else(|| value.to_string(), str::to_owned))
    }

    /// The page's visible text, for a failing step's message.
    pub(crate) async fn body_text(&self) -> String {
        self.eval("document.body ? document.body.innerText : '(no body)'").await.unwrap_or_else(|e| e)
    }

    /// Takes a PNG screenshot named `name`.
    pub(crate) async fn shot(&self, name: &str) -> Result<(), String> {
        let answer = self.call("Page.captureScreenshot", json!({"format": "png"})).await?;
        let data = answer["data"].as_str().ok_or("no screenshot data")?;
        let png = base64_decode(data).ok_or("the screenshot is not base64")?;
        self.shots.lock().map_err(|_| "poisoned")?.push((name.to_owned(), png));
        Ok(())
    }

    pub(crate) fn screenshots(&self) -> Vec<(String, Vec<u8>)> {
        self.shots.lock().map(|s| s.clone()).unwrap_or_default()
    }
}

/// Standard base64 (with padding) to bytes.
fn base64_decode(text: &str) -> Option<Vec<u8>> {
    let value = |c: u8| -> Option<u32> {
        Some(match c {
            b'A'..=b'Z' => c - b'A',
            b'a'..=b'z' => c - b'a' + 26,
            b'0'..=b'9' => c - b'0' + 52,
            b'+' => 62,
            b'/' => 63,
            _ => return None,
        } as u32)
    };
    let bytes: Vec<u8> = text.bytes().filter(|b| !b.is_ascii_whitespace()).collect();
    let mut out = Vec::with_capacity(bytes.len() / 4 * 3);
    for chunk in bytes.chunks(4) {
        let pads = chunk.iter().filter(|&&b| b == b'=').count();
        let mut n = 0u32;
        for &b in chunk {
            n = (n << 6) | if b == b'=' { 0 } else { value(b)? };
        }
        n <<= 6 * (4 - chunk.len()) as u32;
        let three = [(n >> 16) as u8, (n >> 8) as u8, n as u8];
        out.extend_from_slice(&three[..3 - pads.min(2)]);
    }
    Some(out)
}
