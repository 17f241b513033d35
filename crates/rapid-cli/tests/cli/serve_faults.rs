//! `rapid serve` under faults, over raw sockets (the faults are what a well-behaved
//! HTTP client would never send): no or wrong credentials (401), a malformed request
//! (400), a body over the limit (413), clients that hang up in the middle of a
//! request or of a subscription, and file-service paths that leave the devices
//! (`..`, absolute parts, a symbolic link: 403). Each gets its HTTP error, and the
//! controller keeps running with nothing lost: the program goes on counting, a signal
//! set before the faults keeps its value, a new subscription is told of changes, and
//! Ctrl-C still saves the persistents and exits 0.

use std::io::{Read, Write};
use std::net::TcpStream;
use std::path::Path;
use std::time::Duration;

use crate::fixture::scratch_in;
use crate::serve::{interrupt, start_server, wait_bounded};

const PROGRAM: &str = "MODULE main
  PERS num count := 0;
  PROC main()
    WHILE TRUE DO
      count := count + 1;
      WaitTime 0.05;
    ENDWHILE
  ENDPROC
ENDMODULE
";

const MANIFEST: &str = "[system]\nname = \"faults\"\nio = \"eio.cfg\"\n\n[[task]]\nname = \"T_ROB1\"\n\
                        type = \"NORMAL\"\nmodules = [\"main.mod\"]\nmotion = true\n";

const EIO: &str = "EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n\n      -Name \"di1\" -SignalType \"DI\"\n\n      \
                   -Name \"do1\" -SignalType \"DO\"\n";

/// An HTTP answer: status, head, body.
pub(super) struct Answer {
    pub(super) status: u16,
    pub(super) head: String,
    pub(super) body: String,
}

impl Answer {
    /// The value of header `name` (any letter case).
    fn header(&self, name: &str) -> Option<&str> {
        self.head.lines().find_map(|line| {
            let (key, value) = line.split_once(':')?;
            key.trim().eq_ignore_ascii_case(name).then(|| value.trim())
        })
    }
}

/// Sends `raw` on a fresh connection and reads the answer to its end (the request
/// asks the server to close); at most 10 s.
fn exchange(addr: &str, raw: &[u8]) -> Answer {
    let mut stream = TcpStream::connect(addr).expect("connect");
    stream.set_read_timeout(Some(Duration::from_secs(10))).expect("timeout");
    stream.write_all(raw).expect("send");
    let mut bytes = Vec::new();
    let _ = stream.read_to_end(&mut bytes);
    parse(&bytes)
}

fn parse(bytes: &[u8]) -> Answer {
    let text = String::from_utf8_lossy(bytes).into_owned();
    let (head, body) = text.split_once("\r\n\r\n").unwrap_or((&text, ""));
    let status = head.split(' ').nth(1).and_then(|s| s.parse().ok()).unwrap_or(0);
    Answer { status, head: head.to_owned(), body: body.to_owned() }
}

/// A request with a session cookie (none when empty) and a form body.
pub(super) fn request(addr: &str, method: &str, path: &str, cookie: &str, body: &str) -> Answer {
    let cookie = if cookie.is_empty() { String::new() } else { format!("Cookie: {cookie}\r\n") };
    let raw = format!(
        "{method} {path} HTTP/1.1\r\nHost: {addr}\r\n{cookie}Content-Type: application/x-www-form-urlencoded\r\n\
         Content-Length: {}\r\nConnection: close\r\n\r\n{body}",
        body.len()
    );
    exchange(addr, raw.as_bytes())
}

/// Answers the server's Digest challenge for `GET path` with `credentials`.
fn digest_get(addr: &str, path: &str, credentials: (&str, &str)) -> Answer {
    let challenge = request(addr, "GET", path, "", "");
    assert_eq!(challenge.status, 401, "no credentials: 401 ({})", challenge.head);
    let www = challenge.header("WWW-Authenticate").expect("a WWW-Authenticate header");
    let auth = rapid_serve::digest_authorization(www, credentials, "GET", path, "0a4f").expect("a digest challenge");
    let raw = format!("GET {path} HTTP/1.1\r\nHost: {addr}\r\nAuthorization: {auth}\r\nConnection: close\r\n\r\n");
    exchange(addr, raw.as_bytes())
}

/// Logs in with the default user; the `ABBCX` cookie.
pub(super) fn login(addr: &str) -> String {
    let answer = digest_get(addr, "/rw/panel/ctrlstate", ("Default User", "robotics"));
    assert_eq!(answer.status, 200, "{}", answer.head);
    let cookie = answer
        .head
        .lines()
        .filter_map(|l| l.split_once(':').filter(|(k, _)| k.eq_ignore_ascii_case("set-cookie")))
        .find_map(|(_, v)| v.trim().strip_prefix("ABBCX="))
        .expect("an ABBCX cookie");
    format!("ABBCX={}", cookie.split(';').next().unwrap_or_default())
}

/// The JSON value of `field` in the first item of `GET path?json=1`.
pub(super) fn read_field(addr: &str, cookie: &str, path: &str, field: &str) -> String {
    let answer = request(addr, "GET", &format!("{path}?json=1"), cookie, "");
    assert_eq!(answer.status, 200, "GET {path}: {} {}", answer.head, answer.body);
    let json: serde_json::Value = serde_json::from_str(&answer.body).expect("JSON");
    json["_embedded"]["_state"][0][field].as_str().unwrap_or_default().to_owned()
}

fn count(addr: &str, cookie: &str) -> f64 {
    read_field(addr, cookie, "/rw/rapid/symbol/data/RAPID/T_ROB1/count", "value").parse().expect("a number")
}

/// Opens the websocket of a new subscription to `di1`; the socket after the 101.
fn subscribe_di1(addr: &str, cookie: &str) -> TcpStream {
    let created = request(addr, "POST", "/subscription", cookie, "resources=1&1=/rw/iosystem/signals/di1;state&1-p=1");
    assert_eq!(created.status, 201, "{}", created.body);
    let location = created.header("Location").expect("a Location").to_owned();
    let path = &location[location.find("/poll/").expect("a poll address")..];
    let mut socket = TcpStream::connect(addr).expect("connect");
    socket.set_read_timeout(Some(Duration::from_secs(10))).expect("timeout");
    let upgrade = format!(
        "GET {path} HTTP/1.1\r\nHost: {addr}\r\nCookie: {cookie}\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n\
         Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\
         Sec-WebSocket-Protocol: robapi2_subscription\r\n\r\n"
    );
    socket.write_all(upgrade.as_bytes()).expect("upgrade");
    let mut head = Vec::new();
    let mut byte = [0u8; 1];
    while !head.ends_with(b"\r\n\r\n") {
        socket.read_exact(&mut byte).expect("the upgrade's answer");
        head.push(byte[0]);
    }
    assert!(head.starts_with(b"HTTP/1.1 101"), "{}", String::from_utf8_lossy(&head));
    socket
}

/// The next text frame's payload on a websocket (server frames are not masked).
fn next_text(socket: &mut TcpStream) -> String {
    loop {
        let mut head = [0u8; 2];
        socket.read_exact(&mut head).expect("a frame");
        let len = match head[1] & 0x7f {
            126 => {
                let mut n = [0u8; 2];
                socket.read_exact(&mut n).expect("a length");
                u16::from_be_bytes(n) as usize
            }
            127 => {
                let mut n = [0u8; 8];
                socket.read_exact(&mut n).expect("a length");
                u64::from_be_bytes(n) as usize
            }
            n => n as usize,
        };
        let mut payload = vec![0u8; len];
        socket.read_exact(&mut payload).expect("a payload");
        if head[0] & 0x0f == 1 {
            return String::from_utf8_lossy(&payload).into_owned();
        }
    }
}

fn set_signal(addr: &str, cookie: &str, name: &str, value: u8) {
    let answer =
        request(addr, "POST", &format!("/rw/iosystem/signals/{name}?action=set"), cookie, &format!("lvalue={value}"));
    assert_eq!(answer.status, 204, "set {name}: {}", answer.body);
}

fn project(dir: &Path) {
    std::fs::write(dir.join("rapid.toml"), MANIFEST).expect("manifest");
    std::fs::write(dir.join("main.mod"), PROGRAM).expect("module");
    std::fs::write(dir.join("eio.cfg"), EIO).expect("eio");
    std::fs::create_dir_all(dir.join("HOME")).expect("HOME");
    std::fs::write(dir.join("HOME/inside.txt"), "inside").expect("a HOME file");
    std::fs::write(dir.join("secret.txt"), "outside").expect("a file beside HOME");
}

#[test]
fn faults_get_their_http_errors_and_the_controller_loses_nothing() {
    let dir = scratch_in("serve_faults", "faults");
    project(&dir);
    #[cfg(unix)]
    std::os::unix::fs::symlink(dir.join("secret.txt"), dir.join("HOME/link.txt")).expect("a symbolic link");
    let (mut child, url, _stdout) = start_server(&dir);
    let addr = url.trim_start_matches("http://").to_owned();
    let cookie = login(&addr);
    let start = "regain=continue&execmode=continue&cycle=forever&condition=none&stopatbp=disabled&alltaskbytsp=false";
    assert_eq!(request(&addr, "POST", "/rw/rapid/execution?action=start", &cookie, start).status, 204);
    set_signal(&addr, &cookie, "do1", 1);

    // Credentials: none, a wrong password, an unknown user, a forged cookie.
    let none = request(&addr, "GET", "/rw/rapid/execution", "", "");
    assert_eq!(none.status, 401);
    let www = none.header("WWW-Authenticate").unwrap_or_default();
    assert!(www.starts_with("Digest ") && www.contains("realm=\"validusers@robapi.abb\""), "{}", none.head);
    assert_eq!(digest_get(&addr, "/rw/rapid/execution", ("Default User", "wrong")).status, 401);
    assert_eq!(digest_get(&addr, "/rw/rapid/execution", ("Nobody", "robotics")).status, 401);
    assert_eq!(request(&addr, "GET", "/rw/rapid/execution", "ABBCX=0123456789abcdef", "").status, 401);

    // Malformed requests: not HTTP, a path that is not UTF-8, a bad form value, an
    // unknown resource.
    let garbage = exchange(&addr, b"NOT HTTP AT ALL\r\n\r\n");
    assert_eq!(garbage.status, 400, "garbage: {}", garbage.head);
    assert_eq!(request(&addr, "GET", "/rw/%FF%FE", &cookie, "").status, 400);
    let bad_value = request(&addr, "POST", "/rw/iosystem/signals/do1?action=set", &cookie, "lvalue=abc");
    assert_eq!(bad_value.status, 400, "{}", bad_value.body);
    assert_eq!(request(&addr, "GET", "/rw/nothing/here", &cookie, "").status, 404);

    // A body over the limit (64 MiB) is refused from its length, before it is sent.
    let huge = format!(
        "PUT /fileservice/$HOME/huge.bin HTTP/1.1\r\nHost: {addr}\r\nCookie: {cookie}\r\n\
         Content-Length: 100000000\r\nConnection: close\r\n\r\n0123456789"
    );
    assert_eq!(exchange(&addr, huge.as_bytes()).status, 413);
    assert!(!dir.join("HOME/huge.bin").exists(), "nothing of the huge body was written");

    // Clients that hang up: in the request line, in a body, after a PUT's head.
    for partial in [
        "GET /rw/pan".to_owned(),
        format!("POST /rw/iosystem/signals/do1?action=set HTTP/1.1\r\nHost: {addr}\r\nCookie: {cookie}\r\nContent-Length: 1000\r\n\r\nlvalue=0&"),
        format!("PUT /fileservice/$HOME/partial.txt HTTP/1.1\r\nHost: {addr}\r\nCookie: {cookie}\r\nContent-Length: 50\r\n\r\nhalf"),
    ] {
        let mut stream = TcpStream::connect(&addr).expect("connect");
        stream.write_all(partial.as_bytes()).expect("send");
        drop(stream);
    }
    std::thread::sleep(Duration::from_millis(200));
    assert!(!dir.join("HOME/partial.txt").exists(), "a PUT cut short writes nothing");

    // Subscribers that hang up: at once, and with an event on its way.
    drop(subscribe_di1(&addr, &cookie));
    let leaving = subscribe_di1(&addr, &cookie);
    set_signal(&addr, &cookie, "di1", 1);
    drop(leaving);
    // A subscriber that stays is told of the next change.
    let mut staying = subscribe_di1(&addr, &cookie);
    set_signal(&addr, &cookie, "di1", 0);
    let event = next_text(&mut staying);
    assert!(event.contains("<span class=\"lvalue\">0</span>"), "{event}");

    // Paths leaving the file devices: `..` (raw and encoded), absolute, a link.
    for path in [
        "/fileservice/$HOME/../secret.txt",
        "/fileservice/$HOME/%2E%2E/secret.txt",
        "/fileservice/$HOME/%2Fetc%2Fpasswd",
        "/fileservice/$HOME/link.txt",
    ] {
        let answer = request(&addr, "GET", path, &cookie, "");
        assert_eq!(answer.status, 403, "GET {path}: {}", answer.body);
        assert!(!answer.body.contains("outside"), "GET {path} gave the file away");
    }
    assert_eq!(request(&addr, "PUT", "/fileservice/$HOME/link.txt", &cookie, "overwritten").status, 403);
    assert_eq!(request(&addr, "DELETE", "/fileservice/$HOME/link.txt", &cookie, "").status, 403);
    assert_eq!(request(&addr, "PUT", "/fileservice/$HOME/..%2Fescaped.txt", &cookie, "x").status, 403);
    assert_eq!(std::fs::read_to_string(dir.join("secret.txt")).expect("still there"), "outside");
    assert!(!dir.join("escaped.txt").exists());
    assert_eq!(request(&addr, "GET", "/fileservice/$HOME/inside.txt", &cookie, "").body, "inside");

    // Nothing lost: the program runs and counts on, do1 kept its value.
    assert_eq!(read_field(&addr, &cookie, "/rw/rapid/execution", "ctrlexecstate"), "running");
    let before = count(&addr, &cookie);
    std::thread::sleep(Duration::from_millis(300));
    let after = count(&addr, &cookie);
    assert!(after > before && before > 0.0, "the program counts on: {before} then {after}");
    assert_eq!(read_field(&addr, &cookie, "/rw/iosystem/signals/do1", "lvalue"), "1");

    // Ctrl-C still saves the persistents and exits 0.
    interrupt(&child);
    let status = wait_bounded(&mut child, Duration::from_secs(20)).expect("rapid serve stops on Ctrl-C");
    assert!(status.success(), "{status:?}");
    let saved = std::fs::read_to_string(dir.join("main.mod")).expect("the module");
    assert!(!saved.contains("PERS num count := 0;"), "count was saved: {saved}");
}
