//! Fuzz target `rws`: Robot Web Services request handling. The bytes choose one to
//! six requests (method, a path of RWS's own segments or arbitrary text, a query,
//! headers, a form or arbitrary body), sent in-process through `rapid_serve::router`
//! (tower's `oneshot`, no sockets) to a server on a small booted system (one task,
//! `di1`/`do1`, a scratch file root), logged in with Digest first so that most
//! requests reach the resources.
//!
//! Asserted (`rapid_fuzz::rws` says which statuses are allowed and why): no panic;
//! every answer's status one a client mistake may get (never 5xx) and its body one a
//! client parses (JSON when `json=1` was asked, well-formed XHTML otherwise); the
//! server still answers a plain GET of the controller state afterwards.
//!
//! The controller is booted once per process and shared by the inputs (a boot costs
//! far more than a request): what one input changes (the program state, signals,
//! loaded modules) the next one sees, so a finding may need the inputs before it.
//! Each input gets a fresh router (its own logins, subscriptions and DIPC queues) and
//! empty file devices.
#![no_main]

use std::sync::OnceLock;

use arbitrary::Unstructured;
use axum::body::Body;
use axum::http::{Request, StatusCode};
use axum::Router;
use libfuzzer_sys::fuzz_target;
use rapid_fuzz::rws::{self, Answer};
use tower::ServiceExt;

struct Fixture {
    runtime: tokio::runtime::Runtime,
    controller: rapid_serve::Controller,
}

fn fixture() -> &'static Fixture {
    static FIXTURE: OnceLock<Fixture> = OnceLock::new();
    FIXTURE.get_or_init(|| {
        let runtime = tokio::runtime::Builder::new_current_thread().enable_time().build().expect("a runtime");
        let controller = rws::boot().expect("the fuzz system boots");
        Fixture { runtime, controller }
    })
}

async fn send(router: &Router, request: Request<Body>) -> Answer {
    let response = router.clone().oneshot(request).await.expect("the router answers");
    let (parts, body) = response.into_parts();
    let body = axum::body::to_bytes(body, usize::MAX).await.expect("the body is read");
    Answer { status: parts.status, headers: parts.headers, body: body.to_vec() }
}

fuzz_target!(|data: &[u8]| {
    let fixture = fixture();
    let root = rws::file_root();
    let _ = std::fs::remove_dir_all(&root);
    let _ = std::fs::create_dir_all(&root);
    let router = rapid_serve::router(&fixture.controller, rapid_serve::Config::default());
    let mut u = Unstructured::new(data);
    fixture.runtime.block_on(async {
        let challenge = send(&router, rws::plain_get(None)).await;
        assert_eq!(challenge.status, StatusCode::UNAUTHORIZED, "a request without a login");
        let login = rws::login_request(&challenge).expect("a Digest challenge");
        let answer = send(&router, login).await;
        assert_eq!(answer.status, StatusCode::OK, "the default user logs in");
        let cookie = rws::cookies_of(&answer).expect("session cookies");
        for _ in 0..u.int_in_range(1..=6u8).unwrap_or(1) {
            let Ok(request) = rws::request(&mut u, Some(&cookie)) else { break };
            let json = request.uri().query().is_some_and(|q| q.split('&').any(|p| p == "json=1"));
            let what = format!("{} {}", request.method(), request.uri());
            let answer = send(&router, request).await;
            rws::check_answer(&what, json, &answer);
        }
        // The server still answers (a `/logout` among the requests ends the session).
        let answer = send(&router, rws::plain_get(Some(&cookie))).await;
        assert!(
            matches!(answer.status, StatusCode::OK | StatusCode::UNAUTHORIZED),
            "a plain GET after the requests got {}",
            answer.status
        );
    });
});
