//! The RWS load client of `bench/serve/run.sh`: CLIENTS connections each log in with
//! HTTP Digest and then poll a signal and the execution state, one request at a time
//! on a keep-alive connection, for SECONDS; SUBSCRIBERS websockets (`robapi2_subscription`)
//! are subscribed to a signal meanwhile. It prints the requests per second, the p50
//! and p99 latency, the failed requests, and per subscriber the events told, lost
//! (a gap in the counting signal's values) and reordered (a value not above the last).
//!
//! `rws-load URL SECONDS CLIENTS SUBSCRIBERS POLLED_SIGNAL [COUNTED_SIGNAL]`; without
//! COUNTED_SIGNAL the subscribers listen to the polled one and events are not checked
//! (a server with no program to count, like the Python stub). Exits 1 when a request
//! failed, an event was lost or reordered, or a counted signal told nothing.
//!
//! HTTP/1.1 is written by hand here (GET and POST with Content-Length answers, or
//! chunked ones): a bench client must be lean and see each request's own latency.

use std::time::{Duration, Instant};

use futures_util::StreamExt;
use md5::{Digest, Md5};
use tokio::io::{AsyncBufReadExt, AsyncReadExt, AsyncWriteExt, BufReader};
use tokio::net::TcpStream;

const USER: (&str, &str) = ("Default User", "robotics");
/// A request not answered in this time counts as failed (and its connection is dropped).
const REQUEST_TIMEOUT: Duration = Duration::from_secs(5);
/// Clients connect spread over this time, as a crowd arriving rather than one burst.
const RAMP: Duration = Duration::from_secs(1);

/// One keep-alive connection with a session cookie.
struct Conn {
    host: String,
    stream: BufReader<TcpStream>,
    cookie: String,
}

/// An answer: status, the headers we need, the body.
struct Answer {
    status: u16,
    www_authenticate: Option<String>,
    set_cookie: Vec<String>,
    location: Option<String>,
    body: Vec<u8>,
}

impl Conn {
    async fn open(host: &str) -> std::io::Result<Conn> {
        let stream = TcpStream::connect(host).await?;
        stream.set_nodelay(true)?;
        Ok(Conn { host: host.to_owned(), stream: BufReader::new(stream), cookie: String::new() })
    }

    async fn send(&mut self, method: &str, path: &str, extra: &str, body: &str) -> std::io::Result<Answer> {
        let cookie = if self.cookie.is_empty() { String::new() } else { format!("Cookie: {}\r\n", self.cookie) };
        let head = format!(
            "{method} {path} HTTP/1.1\r\nHost: {}\r\n{cookie}{extra}Content-Type: application/x-www-form-urlencoded\r\n\
             Content-Length: {}\r\n\r\n{body}",
            self.host,
            body.len()
        );
        self.stream.get_mut().write_all(head.as_bytes()).await?;
        self.read_answer().await
    }

    async fn read_answer(&mut self) -> std::io::Result<Answer> {
        let mut line = String::new();
        self.stream.read_line(&mut line).await?;
        let status = line.split(' ').nth(1).and_then(|s| s.parse().ok()).ok_or_else(|| bad("no status line"))?;
        let mut answer =
            Answer { status, www_authenticate: None, set_cookie: Vec::new(), location: None, body: Vec::new() };
        let (mut length, mut chunked) = (0usize, false);
        loop {
            line.clear();
            if self.stream.read_line(&mut line).await? == 0 {
                return Err(bad("the connection closed in the head"));
            }
            let text = line.trim_end();
            if text.is_empty() {
                break;
            }
            let Some((key, value)) = text.split_once(':') else { continue };
            let value = value.trim().to_owned();
            match key.trim().to_ascii_lowercase().as_str() {
                "content-length" => length = value.parse().map_err(|_| bad("a bad length"))?,
                "transfer-encoding" => chunked = value.eq_ignore_ascii_case("chunked"),
                "www-authenticate" => answer.www_authenticate = Some(value),
                "set-cookie" => answer.set_cookie.push(value),
                "location" => answer.location = Some(value),
                _ => {}
            }
        }
        if chunked {
            loop {
                line.clear();
                self.stream.read_line(&mut line).await?;
                let size = usize::from_str_radix(line.trim(), 16).map_err(|_| bad("a bad chunk"))?;
                let mut chunk = vec![0u8; size + 2];
                self.stream.read_exact(&mut chunk).await?;
                if size == 0 {
                    break;
                }
                answer.body.extend_from_slice(&chunk[..size]);
            }
        } else {
            answer.body.resize(length, 0);
            self.stream.read_exact(&mut answer.body).await?;
        }
        Ok(answer)
    }

    /// Logs in with Digest: the challenge, then the answer; keeps the session cookie.
    async fn login(&mut self, path: &str) -> std::io::Result<()> {
        let challenge = self.send("GET", path, "", "").await?;
        let www = challenge.www_authenticate.ok_or_else(|| bad("no challenge"))?;
        let auth = digest(&www, "GET", path).ok_or_else(|| bad("not a digest challenge"))?;
        let answer = self.send("GET", path, &format!("Authorization: {auth}\r\n"), "").await?;
        if answer.status != 200 {
            return Err(bad("the login was refused"));
        }
        let cookie = answer
            .set_cookie
            .iter()
            .find_map(|c| c.strip_prefix("ABBCX="))
            .and_then(|c| c.split(';').next())
            .ok_or_else(|| bad("no ABBCX cookie"))?;
        self.cookie = format!("ABBCX={cookie}");
        Ok(())
    }
}

fn bad(what: &str) -> std::io::Error {
    std::io::Error::new(std::io::ErrorKind::InvalidData, what.to_owned())
}

fn md5_hex(text: &str) -> String {
    Md5::digest(text.as_bytes()).iter().map(|b| format!("{b:02x}")).collect()
}

/// The `Authorization` value answering a Digest challenge (MD5, qop=auth).
fn digest(challenge: &str, method: &str, uri: &str) -> Option<String> {
    let field = |name: &str| -> Option<String> {
        let at = challenge.find(&format!("{name}=\""))? + name.len() + 2;
        Some(challenge[at..].split('"').next()?.to_owned())
    };
    let (nonce, realm) = (field("nonce")?, field("realm")?);
    let ha1 = md5_hex(&format!("{}:{realm}:{}", USER.0, USER.1));
    let ha2 = md5_hex(&format!("{method}:{uri}"));
    let response = md5_hex(&format!("{ha1}:{nonce}:00000001:0a4f1:auth:{ha2}"));
    Some(format!(
        "Digest username=\"{}\", realm=\"{realm}\", nonce=\"{nonce}\", uri=\"{uri}\", response=\"{response}\", \
         qop=auth, nc=00000001, cnonce=\"0a4f1\", algorithm=MD5, opaque=\"799d5\"",
        USER.0
    ))
}

/// What one polling client measured.
#[derive(Default)]
struct Polled {
    latencies_us: Vec<u32>,
    failed: u64,
    first_failure: Option<String>,
}

async fn poll_client(host: String, until: Instant, signal: String, delay: Duration) -> Polled {
    tokio::time::sleep(delay).await;
    let mut polled = Polled::default();
    let paths = [format!("/rw/iosystem/signals/{signal}?json=1"), "/rw/rapid/execution?json=1".to_owned()];
    let mut conn: Option<Conn> = None;
    let mut turn = 0usize;
    while Instant::now() < until {
        if conn.is_none() {
            let opened = tokio::time::timeout(REQUEST_TIMEOUT, async {
                let mut c = Conn::open(&host).await.map_err(|e| format!("connect: {e}"))?;
                c.login("/rw/panel/ctrlstate?json=1").await.map_err(|e| format!("login: {e}"))?;
                Ok::<Conn, String>(c)
            })
            .await
            .unwrap_or_else(|_| Err("login: no answer in time".to_owned()));
            match opened {
                Ok(c) => conn = Some(c),
                Err(e) => fail(&mut polled, e),
            }
            if conn.is_none() {
                tokio::time::sleep(Duration::from_millis(50)).await;
                continue;
            }
        }
        let Some(c) = conn.as_mut() else { continue };
        let path = &paths[turn % 2];
        turn += 1;
        let sent = Instant::now();
        let answer = tokio::time::timeout(REQUEST_TIMEOUT, c.send("GET", path, "", ""))
            .await
            .unwrap_or_else(|_| Err(bad("no answer in time")));
        match answer {
            Ok(a) if a.status == 200 && a.body.windows(9).any(|w| w == b"_embedded") => {
                polled.latencies_us.push(sent.elapsed().as_micros().min(u32::MAX as u128) as u32);
            }
            Ok(a) => fail(&mut polled, format!("GET {path}: {} {}", a.status, String::from_utf8_lossy(&a.body))),
            Err(e) => {
                fail(&mut polled, format!("GET {path}: {e}"));
                conn = None;
            }
        }
    }
    polled
}

fn fail(polled: &mut Polled, why: String) {
    polled.failed += 1;
    polled.first_failure.get_or_insert(why);
}

/// What one subscriber was told.
#[derive(Default)]
struct Told {
    events: u64,
    lost: u64,
    reordered: u64,
    closed_by_server: bool,
    error: Option<String>,
}

async fn subscriber(host: String, until: Instant, signal: String, counted: bool) -> Told {
    let mut told = Told::default();
    if let Err(e) = listen(&host, until, &signal, counted, &mut told).await {
        told.error = Some(e.to_string());
    }
    told
}

async fn listen(host: &str, until: Instant, signal: &str, counted: bool, told: &mut Told) -> std::io::Result<()> {
    use tokio_tungstenite::tungstenite::client::IntoClientRequest;
    use tokio_tungstenite::tungstenite::http::HeaderValue;
    let timed = |what: &'static str| move |_| bad(what);
    let mut conn =
        tokio::time::timeout(REQUEST_TIMEOUT, Conn::open(host)).await.map_err(timed("connect: no answer"))??;
    tokio::time::timeout(REQUEST_TIMEOUT, conn.login("/rw/panel/ctrlstate?json=1"))
        .await
        .map_err(timed("login: no answer"))??;
    let form = format!("resources=1&1=/rw/iosystem/signals/{signal};state&1-p=1");
    let created = tokio::time::timeout(REQUEST_TIMEOUT, conn.send("POST", "/subscription", "", &form))
        .await
        .map_err(timed("subscription: no answer"))??;
    let location = created.location.filter(|_| created.status == 201).ok_or_else(|| bad("no subscription"))?;
    let path = &location[location.find("/poll/").ok_or_else(|| bad("no poll address"))?..];
    let mut request = format!("ws://{host}{path}").into_client_request().map_err(|e| bad(&e.to_string()))?;
    let headers = request.headers_mut();
    headers.insert("Cookie", HeaderValue::from_str(&conn.cookie).map_err(|_| bad("cookie"))?);
    headers.insert("Sec-WebSocket-Protocol", HeaderValue::from_static("robapi2_subscription"));
    let tcp = TcpStream::connect(host).await?;
    let (mut socket, _) = tokio::time::timeout(REQUEST_TIMEOUT, tokio_tungstenite::client_async(request, tcp))
        .await
        .map_err(timed("websocket: no answer"))?
        .map_err(|e| bad(&e.to_string()))?;
    let mut last: Option<u64> = None;
    loop {
        let left = until.saturating_duration_since(Instant::now());
        let message = match tokio::time::timeout(left, socket.next()).await {
            Err(_) => return Ok(()),
            Ok(None) => return Ok(()),
            Ok(Some(m)) => m.map_err(|e| bad(&e.to_string()))?,
        };
        if message.is_close() {
            told.closed_by_server = true;
            return Ok(());
        }
        let Ok(text) = message.to_text() else { continue };
        for value in text.split("<span class=\"lvalue\">").skip(1).filter_map(|s| s.split('<').next()) {
            told.events += 1;
            let Some(v) = value.parse::<f64>().ok().map(|v| v as u64).filter(|_| counted) else { continue };
            if let Some(prev) = last {
                let expected = if prev >= 65535 { 1 } else { prev + 1 };
                if v != expected {
                    if v > prev || (prev >= 65000 && v < 1000) {
                        told.lost += 1;
                    } else {
                        told.reordered += 1;
                    }
                }
            }
            last = Some(v);
        }
    }
}

fn percentile(sorted: &[u32], p: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let at = ((sorted.len() as f64 - 1.0) * p).round() as usize;
    f64::from(sorted[at]) / 1000.0
}

#[tokio::main(flavor = "multi_thread")]
async fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.len() < 6 {
        eprintln!("usage: rws-load URL SECONDS CLIENTS SUBSCRIBERS POLLED_SIGNAL [COUNTED_SIGNAL]");
        std::process::exit(2);
    }
    let host = args[1].trim_start_matches("http://").trim_end_matches('/').to_owned();
    let seconds: f64 = args[2].parse().unwrap_or(10.0);
    let clients: usize = args[3].parse().unwrap_or(200);
    let subscribers: usize = args[4].parse().unwrap_or(20);
    let polled_signal = args[5].clone();
    let counted = args.get(6).cloned();
    let start = Instant::now();
    let until = start + Duration::from_secs_f64(seconds);
    // Subscribers first, so that they hear the whole run.
    let listen_to = counted.clone().unwrap_or_else(|| polled_signal.clone());
    let subs: Vec<_> = (0..subscribers)
        .map(|_| {
            tokio::spawn(subscriber(
                host.clone(),
                until + Duration::from_millis(500),
                listen_to.clone(),
                counted.is_some(),
            ))
        })
        .collect();
    let polls: Vec<_> = (0..clients)
        .map(|i| {
            let delay = RAMP.mul_f64(i as f64 / clients.max(1) as f64);
            tokio::spawn(poll_client(host.clone(), until, polled_signal.clone(), delay))
        })
        .collect();
    let mut latencies = Vec::new();
    let (mut failed, mut first_failure) = (0u64, None);
    for p in polls {
        if let Ok(p) = p.await {
            latencies.extend(p.latencies_us);
            failed += p.failed;
            first_failure = first_failure.or(p.first_failure);
        }
    }
    let elapsed = start.elapsed().as_secs_f64();
    latencies.sort_unstable();
    let (mut events, mut lost, mut reordered, mut closed, mut silent, mut errors) = (0, 0, 0, 0, 0, Vec::new());
    for s in subs {
        if let Ok(t) = s.await {
            events += t.events;
            lost += t.lost;
            reordered += t.reordered;
            closed += u64::from(t.closed_by_server);
            silent += u64::from(t.events == 0);
            errors.extend(t.error);
        }
    }
    println!(
        "{} requests in {elapsed:.1} s: {:.0} req/s, p50 {:.2} ms, p99 {:.2} ms, failed {failed}",
        latencies.len(),
        latencies.len() as f64 / elapsed,
        percentile(&latencies, 0.5),
        percentile(&latencies, 0.99)
    );
    match &counted {
        Some(_) => println!(
            "{subscribers} subscribers: {events} events ({:.0} each), lost {lost}, reordered {reordered}, \
             closed by the server {closed}, silent {silent}, errors {}",
            events as f64 / subscribers.max(1) as f64,
            errors.len()
        ),
        None => println!("{subscribers} subscribers connected ({} errors); events not checked", errors.len()),
    }
    if let Some(why) = &first_failure {
        println!("first failure: {why}");
    }
    if let Some(why) = errors.first() {
        println!("first subscriber error: {why}");
    }
    let bad_events = counted.is_some() && (lost > 0 || reordered > 0 || closed > 0 || silent > 0 || !errors.is_empty());
    if failed > 0 || bad_events {
        std::process::exit(1);
    }
}
