//! Who may talk to the controller: HTTP Digest authentication as RobotWare 6 asks for
//! it (RFC 7616 with MD5 and `qop="auth"`, realm `validusers@robapi.abb`), then a
//! session kept by two cookies, `-http-session-` and `ABBCX`, until `/logout`.
//!
//! The digest check is ours (a few lines on the `md-5` crate): HA1 = MD5(user:realm:
//! password), HA2 = MD5(method:uri), response = MD5(HA1:nonce:nc:cnonce:qop:HA2). A
//! nonce must be one this server issued (the newest [`MAX_NONCES`] are kept; an older
//! one is answered `stale=TRUE`, so clients retry with a fresh one). The nonce count is
//! not checked for replays: the server listens on the loopback interface by default.
//! Sessions are bounded too ([`MAX_SESSIONS`], the oldest dropped first).

use std::collections::{HashMap, HashSet, VecDeque};
use std::sync::Mutex;

use md5::{Digest, Md5};

/// The realm RobotWare 6 names in its challenge.
pub const REALM: &str = "validusers@robapi.abb";
/// The default user of a RobotWare controller.
pub const DEFAULT_USER: (&str, &str) = ("Default User", "robotics");
/// Nonces remembered.
const MAX_NONCES: usize = 4096;
/// Sessions remembered.
const MAX_SESSIONS: usize = 512;
/// The `opaque` value RobotWare sends (seen in a captured challenge).
const OPAQUE: &str = "799d5";

/// The users and what they are logged in with.
#[derive(Debug)]
pub struct Auth {
    users: HashMap<String, String>,
    state: Mutex<State>,
}

#[derive(Debug, Default)]
struct State {
    nonces: HashSet<String>,
    nonce_order: VecDeque<String>,
    sessions: HashSet<String>,
    session_order: VecDeque<String>,
}

/// What a request's credentials come to.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum Verdict {
    /// A known session cookie.
    Session,
    /// A valid digest: a new session was opened (its id goes into both cookies).
    NewSession(String),
    /// No or wrong credentials: answer 401 with this `WWW-Authenticate` value.
    Challenge(String),
}

impl Auth {
    /// Users as (name, password) pairs.
    pub fn new(users: impl IntoIterator<Item = (String, String)>) -> Auth {
        Auth { users: users.into_iter().collect(), state: Mutex::new(State::default()) }
    }

    /// Reads a users file: one `name:password` a line (the name may hold spaces, the
    /// password is everything after the first `:`); blank lines and `#` comments are
    /// skipped.
    pub fn parse_users(text: &str) -> Result<Vec<(String, String)>, String> {
        let mut users = Vec::new();
        for (n, line) in text.lines().enumerate() {
            let line = line.trim_end_matches('\r');
            if line.trim().is_empty() || line.trim_start().starts_with('#') {
                continue;
            }
            let Some((name, password)) = line.split_once(':') else {
                return Err(format!("line {}: expected `name:password`", n + 1));
            };
            if name.trim().is_empty() {
                return Err(format!("line {}: the user name is empty", n + 1));
            }
            users.push((name.trim().to_owned(), password.to_owned()));
        }
        Ok(users)
    }

    fn state(&self) -> std::sync::MutexGuard<'_, State> {
        // A panic while holding the lock cannot leave the sets inconsistent.
        self.state.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
    }

    /// Judges a request by its cookies and `Authorization` header.
    pub(crate) fn check(&self, method: &str, uri: &str, cookies: &[(String, String)], auth: Option<&str>) -> Verdict {
        {
            let state = self.state();
            let known = cookies
                .iter()
                .any(|(name, value)| (name == "-http-session-" || name == "ABBCX") && state.sessions.contains(value));
            if known {
                return Verdict::Session;
            }
        }
        let mut stale = false;
        if let Some(fields) = auth.and_then(|a| a.strip_prefix("Digest ")).map(parse_fields) {
            match self.verify(method, uri, &fields) {
                Ok(()) => return Verdict::NewSession(self.open_session()),
                Err(is_stale) => stale = is_stale,
            }
        }
        Verdict::Challenge(self.challenge(stale))
    }

    /// Ok when the digest is right; Err(true) when only the nonce is unknown.
    fn verify(&self, method: &str, uri: &str, fields: &HashMap<String, String>) -> Result<(), bool> {
        let field = |name: &str| fields.get(name).map(String::as_str).unwrap_or("");
        let Some(password) = self.users.get(field("username")) else { return Err(false) };
        if field("realm") != REALM || field("uri") != uri || field("qop") != "auth" {
            return Err(false);
        }
        if !matches!(field("algorithm"), "" | "MD5") {
            return Err(false);
        }
        let ha1 = md5_hex(&format!("{}:{REALM}:{password}", field("username")));
        let ha2 = md5_hex(&format!("{method}:{uri}"));
        let expected = md5_hex(&format!("{ha1}:{}:{}:{}:auth:{ha2}", field("nonce"), field("nc"), field("cnonce")));
        if !expected.eq_ignore_ascii_case(field("response")) {
            return Err(false);
        }
        if !self.state().nonces.contains(field("nonce")) {
            return Err(true);
        }
        Ok(())
    }

    /// A new nonce and the challenge that carries it.
    fn challenge(&self, stale: bool) -> String {
        let nonce = random_hex(16);
        let state = &mut *self.state();
        remember(&mut state.nonces, &mut state.nonce_order, nonce.clone(), MAX_NONCES);
        format!(
            "Digest realm=\"{REALM}\", domain=\"/\", qop=\"auth\", nonce=\"{nonce}\", opaque=\"{OPAQUE}\", \
             algorithm=\"MD5\", stale=\"{}\"",
            if stale { "TRUE" } else { "FALSE" }
        )
    }

    fn open_session(&self) -> String {
        let id = random_hex(16);
        let state = &mut *self.state();
        remember(&mut state.sessions, &mut state.session_order, id.clone(), MAX_SESSIONS);
        id
    }

    /// Ends the sessions these cookies name.
    pub(crate) fn logout(&self, cookies: &[(String, String)]) {
        let mut state = self.state();
        for (_, value) in cookies {
            if state.sessions.remove(value) {
                state.session_order.retain(|s| s != value);
            }
        }
    }
}

fn remember(set: &mut HashSet<String>, order: &mut VecDeque<String>, value: String, max: usize) {
    while order.len() >= max {
        if let Some(old) = order.pop_front() {
            set.remove(&old);
        }
    }
    set.insert(value.clone());
    order.push_back(value);
}

/// The client's side of the login, for tests, the load bench and Rust clients: the
/// `Authorization` value that answers `challenge` (a `WWW-Authenticate: Digest …`
/// value) for `method` and `uri` (path and query as sent) with `cnonce`; None when
/// the challenge is no Digest challenge with a nonce.
pub fn digest_authorization(
    challenge: &str,
    (user, password): (&str, &str),
    method: &str,
    uri: &str,
    cnonce: &str,
) -> Option<String> {
    let fields = parse_fields(challenge.trim().strip_prefix("Digest ")?);
    let nonce = fields.get("nonce")?;
    let realm = fields.get("realm").map_or(REALM, String::as_str);
    let ha1 = md5_hex(&format!("{user}:{realm}:{password}"));
    let ha2 = md5_hex(&format!("{method}:{uri}"));
    let response = md5_hex(&format!("{ha1}:{nonce}:00000001:{cnonce}:auth:{ha2}"));
    let opaque = fields.get("opaque").map_or_else(String::new, |o| format!(", opaque=\"{o}\""));
    Some(format!(
        "Digest username=\"{user}\", realm=\"{realm}\", nonce=\"{nonce}\", uri=\"{uri}\", \
         response=\"{response}\", qop=auth, nc=00000001, cnonce=\"{cnonce}\", algorithm=MD5{opaque}"
    ))
}

/// The `key=value` / `key="value"` pairs of a Digest header.
fn parse_fields(text: &str) -> HashMap<String, String> {
    let mut fields = HashMap::new();
    let mut rest = text.trim();
    while !rest.is_empty() {
        let Some(eq) = rest.find('=') else { break };
        let key = rest[..eq].trim().trim_start_matches(',').trim().to_ascii_lowercase();
        let after = rest[eq + 1..].trim_start();
        let (value, tail) = if let Some(quoted) = after.strip_prefix('"') {
            match quoted.find('"') {
                Some(end) => (&quoted[..end], &quoted[end + 1..]),
                None => (quoted, ""),
            }
        } else {
            let end = after.find(',').unwrap_or(after.len());
            (after[..end].trim(), &after[end..])
        };
        fields.insert(key, value.to_owned());
        rest = tail.trim_start().trim_start_matches(',').trim_start();
    }
    fields
}

/// The cookies of a `Cookie` header value, as (name, value).
pub(crate) fn parse_cookies(header: &str) -> Vec<(String, String)> {
    header
        .split(';')
        .filter_map(|pair| pair.split_once('='))
        .map(|(name, value)| (name.trim().to_owned(), value.trim().to_owned()))
        .collect()
}

fn md5_hex(text: &str) -> String {
    Md5::digest(text.as_bytes()).iter().map(|b| format!("{b:02x}")).collect()
}

/// `bytes` random bytes as hex, from the operating system's generator.
pub(crate) fn random_hex(bytes: usize) -> String {
    let mut buf = vec![0u8; bytes];
    if getrandom::fill(&mut buf).is_err() {
        // No OS randomness: fall back on the clock (nonces then only need to differ).
        let nanos = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_nanos());
        for (i, b) in buf.iter_mut().enumerate() {
            *b = (nanos >> ((i % 16) * 8)) as u8 ^ i as u8;
        }
    }
    buf.iter().map(|b| format!("{b:02x}")).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn nonce_of(challenge: &str) -> String {
        parse_fields(challenge.strip_prefix("Digest ").unwrap())["nonce"].clone()
    }

    /// The client's side of RFC 7616 (MD5, qop=auth), written out by hand.
    fn answer(user: &str, password: &str, method: &str, uri: &str, nonce: &str) -> String {
        let ha1 = md5_hex(&format!("{user}:{REALM}:{password}"));
        let ha2 = md5_hex(&format!("{method}:{uri}"));
        let response = md5_hex(&format!("{ha1}:{nonce}:00000001:abcdef:auth:{ha2}"));
        format!(
            "Digest username=\"{user}\", realm=\"{REALM}\", nonce=\"{nonce}\", uri=\"{uri}\", \
             response=\"{response}\", qop=auth, nc=00000001, cnonce=\"abcdef\", algorithm=MD5"
        )
    }

    #[test]
    fn md5_of_the_rfc_1321_sample() {
        assert_eq!(md5_hex("abc"), "900150983cd24fb0d6963f7d28e17f72");
    }

    #[test]
    fn a_right_digest_opens_a_session_and_a_wrong_one_is_challenged() {
        let auth = Auth::new([("Default User".to_owned(), "robotics".to_owned())]);
        let Verdict::Challenge(challenge) = auth.check("GET", "/rw", &[], None) else { panic!("no challenge") };
        assert!(challenge.contains("realm=\"validusers@robapi.abb\"") && challenge.contains("qop=\"auth\""));
        let nonce = nonce_of(&challenge);
        let wrong = answer("Default User", "nope", "GET", "/rw", &nonce);
        assert!(matches!(auth.check("GET", "/rw", &[], Some(&wrong)), Verdict::Challenge(_)));
        let other_uri = answer("Default User", "robotics", "GET", "/other", &nonce);
        assert!(matches!(auth.check("GET", "/rw", &[], Some(&other_uri)), Verdict::Challenge(_)));
        let right = answer("Default User", "robotics", "GET", "/rw", &nonce);
        let Verdict::NewSession(id) = auth.check("GET", "/rw", &[], Some(&right)) else { panic!("refused") };
        let cookies = vec![("ABBCX".to_owned(), id)];
        assert_eq!(auth.check("POST", "/x", &cookies, None), Verdict::Session);
        auth.logout(&cookies);
        assert!(matches!(auth.check("POST", "/x", &cookies, None), Verdict::Challenge(_)));
    }

    #[test]
    fn the_client_side_answers_the_servers_challenge() {
        let auth = Auth::new([("u".to_owned(), "p".to_owned())]);
        let Verdict::Challenge(challenge) = auth.check("GET", "/x", &[], None) else { panic!("a challenge") };
        let good = digest_authorization(&challenge, ("u", "p"), "GET", "/x", "c1").unwrap();
        assert!(matches!(auth.check("GET", "/x", &[], Some(&good)), Verdict::NewSession(_)));
        let bad = digest_authorization(&challenge, ("u", "q"), "GET", "/x", "c1").unwrap();
        assert!(matches!(auth.check("GET", "/x", &[], Some(&bad)), Verdict::Challenge(_)));
        assert_eq!(digest_authorization("Basic realm=\"x\"", ("u", "p"), "GET", "/", "c"), None);
    }

    #[test]
    fn an_unknown_nonce_is_stale() {
        let auth = Auth::new([("u".to_owned(), "p".to_owned())]);
        let forged = answer("u", "p", "GET", "/", "0123");
        let Verdict::Challenge(challenge) = auth.check("GET", "/", &[], Some(&forged)) else { panic!() };
        assert!(challenge.contains("stale=\"TRUE\""));
    }

    #[test]
    fn users_files() {
        let users = Auth::parse_users("# who\nDefault User:robotics\n\nop:a:b\n").unwrap();
        assert_eq!(users, vec![("Default User".into(), "robotics".into()), ("op".into(), "a:b".into())]);
        assert!(Auth::parse_users("nocolon").is_err());
    }
}
