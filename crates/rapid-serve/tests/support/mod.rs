//! What the router tests share: a controller built here (one task with two digital
//! signals, or a program of the test's own), a server on it, requests, logging in
//! with Digest, and reading answers.

#![allow(dead_code)]

use axum::body::Body;
use axum::http::{header, Request, Response, StatusCode};
use axum::Router;
use md5::{Digest, Md5};
use rapid_controller::api::{ClockPolicy, Session};
use rapid_controller::{Controller, TaskSpec};
use rapid_sema::SourceInput;
use tower::ServiceExt;

pub(crate) const PROGRAM: &str = "MODULE MainModule
  PERS num count := 0;
  PERS pos here := [1, 2, 3];
  VAR string name := \"abc\";
  CONST num limit := 3;
  PERS tooldata tGrip := [TRUE, [[0, 0, 100], [1, 0, 0, 0]], [1, [0, 0, 1], [1, 0, 0, 0], 0, 0, 0]];
  PERS wobjdata wTable := [FALSE, TRUE, \"\", [[100, 0, 0], [1, 0, 0, 0]], [[0, 0, 50], [1, 0, 0, 0]]];
  PROC other()
    count := 100;
  ENDPROC
  PROC main()
    WaitDI di1, 1;
    count := count + 1;
    SetDO do1, 1;
    WHILE TRUE DO
      WaitTime 0.05;
    ENDWHILE
  ENDPROC
ENDMODULE
";

/// A controller for `program` with `di1` and `do1`, its file devices under `root`,
/// T_ROB1's RAPID Message Queue of type `rmq`.
pub(crate) fn boot_with_queue(
    root: std::path::PathBuf,
    program: &str,
    rmq: rapid_config::sys::RmqType,
) -> Result<Session, String> {
    boot_with(root, program, rmq, Vec::new())
}

/// As [`boot_with_queue`], T_ROB1 configured with `config` ((domain, `.cfg` text) pairs)
/// as a backup's system parameters configure a task.
pub(crate) fn boot_with(
    root: std::path::PathBuf,
    program: &str,
    rmq: rapid_config::sys::RmqType,
    config: Vec<(String, String)>,
) -> Result<Session, String> {
    let names = [("di1", "signaldi", "DI"), ("do1", "signaldo", "DO")];
    let predefined = names
        .iter()
        .map(|(n, ty, _)| rapid_sema::PredefinedData { name: (*n).to_owned(), type_name: (*ty).to_owned() })
        .collect();
    let options = rapid_sema::Options { predefined, ..rapid_sema::Options::default() };
    let mut loaded = rapid_controller::builtin_set::load_with(
        &[SourceInput::from_text("T_ROB1/MainModule.mod", program)],
        "main",
        &options,
    )
    .map_err(|e| format!("{e:?}"))?;
    loaded.vm.resources_mut().files.set_root(root);
    let config = config.into_iter().map(|(domain, text)| (domain, rapid_config::parse(&text))).collect();
    loaded.vm.resources_mut().cfgdata.set_config(Box::new(rapid_controller::boot::cfgdata::SysParams::new(config)));
    let signals: String =
        names.iter().map(|(n, _, kind)| format!("\n      -Name \"{n}\" -SignalType \"{kind}\"\n")).collect();
    let eio = rapid_config::eio::read(&rapid_config::parse(&format!("EIO:CFG_1.0:6:0::\n#\nEIO_SIGNAL:\n{signals}")));
    let io = rapid_controller::boot::io_config::io_system(&eio)?;
    let mut spec = TaskSpec::normal("T_ROB1", true);
    spec.rmq.rmq_type = rmq;
    Ok(Session::new(Controller::new(vec![(spec, loaded)], Some(io))?))
}

/// A server on a fresh controller, and its scratch folder.
pub(crate) struct Server {
    pub(crate) router: Router,
    pub(crate) controller: Option<rapid_serve::Controller>,
    pub(crate) root: std::path::PathBuf,
}

impl Server {
    pub(crate) fn new(name: &str) -> Server {
        Server::with_program(name, PROGRAM)
    }

    pub(crate) fn with_program(name: &str, program: &'static str) -> Server {
        Server::with_queue(name, program, rapid_config::sys::RmqType::None)
    }

    pub(crate) fn with_queue(name: &str, program: &'static str, rmq: rapid_config::sys::RmqType) -> Server {
        Server::with_config(name, program, rmq, &[])
    }

    /// A server whose T_ROB1 is configured with `config`: (domain, `.cfg` text) pairs.
    pub(crate) fn with_config(
        name: &str,
        program: &'static str,
        rmq: rapid_config::sys::RmqType,
        config: &[(&str, &str)],
    ) -> Server {
        let config: Vec<(String, String)> = config.iter().map(|(d, t)| ((*d).to_owned(), (*t).to_owned())).collect();
        let root = std::env::temp_dir().join(format!("rapid-serve-test-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&root);
        std::fs::create_dir_all(&root).expect("scratch folder");
        let for_boot = root.clone();
        let boot = rapid_serve::Boot {
            session: Box::new(move || boot_with(for_boot, program, rmq, config)),
            clock: ClockPolicy::Paced { rate: 20.0 },
            on_exit: None,
            on_tp_write: None,
        };
        let controller = rapid_serve::Controller::start(boot).expect("the controller boots");
        let router = rapid_serve::router(&controller, rapid_serve::Config::default());
        Server { router, controller: Some(controller), root }
    }

    pub(crate) async fn send(&self, request: Request<Body>) -> Response<Body> {
        self.router.clone().oneshot(request).await.expect("the router answers")
    }

    /// Logs in with the default user; the session cookie.
    pub(crate) async fn login(&self) -> String {
        let challenge = self.send(get("/rw/panel/ctrlstate", None)).await;
        let nonce = field(header_text(&challenge, header::WWW_AUTHENTICATE.as_str()).as_str(), "nonce");
        let auth = digest("Default User", "robotics", "GET", "/rw/panel/ctrlstate", &nonce);
        let response = self.send(get_with("/rw/panel/ctrlstate", &[(header::AUTHORIZATION.as_str(), &auth)])).await;
        assert_eq!(response.status(), StatusCode::OK);
        let cookies: Vec<String> = response
            .headers()
            .get_all(header::SET_COOKIE)
            .iter()
            .map(|v| v.to_str().unwrap().split(';').next().unwrap().to_owned())
            .collect();
        assert!(cookies.iter().any(|c| c.starts_with("-http-session-=")), "{cookies:?}");
        let abbcx = cookies.iter().find(|c| c.starts_with("ABBCX=")).expect("an ABBCX cookie").clone();
        abbcx
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        if let Some(controller) = self.controller.take() {
            let _ = controller.shutdown();
        }
        let _ = std::fs::remove_dir_all(&self.root);
    }
}

pub(crate) fn get(uri: &str, cookie: Option<&str>) -> Request<Body> {
    match cookie {
        Some(c) => get_with(uri, &[("cookie", c)]),
        None => get_with(uri, &[]),
    }
}

pub(crate) fn get_with(uri: &str, headers: &[(&str, &str)]) -> Request<Body> {
    let mut builder = Request::get(uri);
    for (k, v) in headers {
        builder = builder.header(*k, *v);
    }
    builder.body(Body::empty()).unwrap()
}

pub(crate) fn post(uri: &str, cookie: &str, form: &str) -> Request<Body> {
    Request::post(uri)
        .header("cookie", cookie)
        .header(header::CONTENT_TYPE, "application/x-www-form-urlencoded")
        .body(Body::from(form.to_owned()))
        .unwrap()
}

pub(crate) fn header_text(response: &Response<Body>, name: &str) -> String {
    response.headers().get(name).map(|v| v.to_str().unwrap().to_owned()).unwrap_or_default()
}

pub(crate) async fn body_text(response: Response<Body>) -> String {
    let bytes = axum::body::to_bytes(response.into_body(), 1 << 20).await.unwrap();
    String::from_utf8_lossy(&bytes).into_owned()
}

pub(crate) async fn json_of(response: Response<Body>) -> serde_json::Value {
    serde_json::from_str(&body_text(response).await).expect("a JSON body")
}

/// A quoted field of a Digest challenge.
pub(crate) fn field(challenge: &str, name: &str) -> String {
    let start = challenge.find(&format!("{name}=\"")).expect("the field") + name.len() + 2;
    challenge[start..].split('"').next().unwrap().to_owned()
}

pub(crate) fn md5_hex(text: &str) -> String {
    Md5::digest(text.as_bytes()).iter().map(|b| format!("{b:02x}")).collect()
}

/// RFC 7616's client answer (MD5, qop=auth), written out here independently.
pub(crate) fn digest(user: &str, password: &str, method: &str, uri: &str, nonce: &str) -> String {
    let ha1 = md5_hex(&format!("{user}:validusers@robapi.abb:{password}"));
    let ha2 = md5_hex(&format!("{method}:{uri}"));
    let response = md5_hex(&format!("{ha1}:{nonce}:00000001:0a4f113b:auth:{ha2}"));
    format!(
        "Digest username=\"{user}\", realm=\"validusers@robapi.abb\", nonce=\"{nonce}\", uri=\"{uri}\", \
         algorithm=MD5, response=\"{response}\", qop=auth, nc=00000001, cnonce=\"0a4f113b\""
    )
}

/// The first `_state` item's field `key` of a JSON answer.
pub(crate) async fn state_field(server: &Server, uri: &str, cookie: &str, key: &str) -> String {
    let response = server.send(get(uri, Some(cookie))).await;
    assert_eq!(response.status(), StatusCode::OK, "{uri}");
    json_of(response).await["_embedded"]["_state"][0][key].as_str().unwrap_or_default().to_owned()
}
