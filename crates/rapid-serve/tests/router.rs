//! The router in process: authentication, cookies, formats, data, signals,
//! execution, malformed requests and the file service's sandbox, on a controller
//! built here (one task with two digital signals).

use std::time::Duration;

use axum::body::Body;
use axum::http::{header, Request, Response, StatusCode};
use axum::Router;
use md5::{Digest, Md5};
use rapid_controller::api::{ClockPolicy, Session};
use rapid_controller::{Controller, TaskSpec};
use rapid_sema::SourceInput;
use tower::ServiceExt;

const PROGRAM: &str = "MODULE MainModule
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
fn boot_with_queue(
    root: std::path::PathBuf,
    program: &str,
    rmq: rapid_config::sys::RmqType,
) -> Result<Session, String> {
    let names = [("di1", "signaldi", "DI"), ("do1", "signaldo", "DO")];
    let predefined = names
        .iter()
        .map(|(n, ty, _)| rapid_sema::PredefinedData { name: (*n).to_owned(), type_name: (*ty).to_owned() })
        .collect();
    let options = rapid_sema::Options { predefined, ..rapid_sema::Options::default() };
    let mut loaded = rapid_vm::load_with(&[SourceInput::from_text("T_ROB1/MainModule.mod", program)], "main", &options)
        .map_err(|e| format!("{e:?}"))?;
    loaded.vm.resources_mut().files.set_root(root);
    let signals: String =
        names.iter().map(|(n, _, kind)| format!("\n      -Name \"{n}\" -SignalType \"{kind}\"\n")).collect();
    let eio = rapid_config::eio::read(&rapid_config::parse(&format!("EIO:CFG_1.0:6:0::\n#\nEIO_SIGNAL:\n{signals}")));
    let io = rapid_vm::builtins::io_config::io_system(&eio)?;
    let mut spec = TaskSpec::normal("T_ROB1", true);
    spec.rmq.rmq_type = rmq;
    Ok(Session::new(Controller::new(vec![(spec, loaded)], Some(io))?))
}

/// A server on a fresh controller, and its scratch folder.
struct Server {
    router: Router,
    controller: Option<rapid_serve::Controller>,
    root: std::path::PathBuf,
}

impl Server {
    fn new(name: &str) -> Server {
        Server::with_program(name, PROGRAM)
    }

    fn with_program(name: &str, program: &'static str) -> Server {
        Server::with_queue(name, program, rapid_config::sys::RmqType::None)
    }

    fn with_queue(name: &str, program: &'static str, rmq: rapid_config::sys::RmqType) -> Server {
        let root = std::env::temp_dir().join(format!("rapid-serve-test-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&root);
        std::fs::create_dir_all(&root).expect("scratch folder");
        let for_boot = root.clone();
        let boot = rapid_serve::Boot {
            session: Box::new(move || boot_with_queue(for_boot, program, rmq)),
            clock: ClockPolicy::Paced { rate: 20.0 },
            on_exit: None,
            on_tp_write: None,
        };
        let controller = rapid_serve::Controller::start(boot).expect("the controller boots");
        let router = rapid_serve::router(&controller, rapid_serve::Config::default());
        Server { router, controller: Some(controller), root }
    }

    async fn send(&self, request: Request<Body>) -> Response<Body> {
        self.router.clone().oneshot(request).await.expect("the router answers")
    }

    /// Logs in with the default user; the session cookie.
    async fn login(&self) -> String {
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

fn get(uri: &str, cookie: Option<&str>) -> Request<Body> {
    match cookie {
        Some(c) => get_with(uri, &[("cookie", c)]),
        None => get_with(uri, &[]),
    }
}

fn get_with(uri: &str, headers: &[(&str, &str)]) -> Request<Body> {
    let mut builder = Request::get(uri);
    for (k, v) in headers {
        builder = builder.header(*k, *v);
    }
    builder.body(Body::empty()).unwrap()
}

fn post(uri: &str, cookie: &str, form: &str) -> Request<Body> {
    Request::post(uri)
        .header("cookie", cookie)
        .header(header::CONTENT_TYPE, "application/x-www-form-urlencoded")
        .body(Body::from(form.to_owned()))
        .unwrap()
}

fn header_text(response: &Response<Body>, name: &str) -> String {
    response.headers().get(name).map(|v| v.to_str().unwrap().to_owned()).unwrap_or_default()
}

async fn body_text(response: Response<Body>) -> String {
    let bytes = axum::body::to_bytes(response.into_body(), 1 << 20).await.unwrap();
    String::from_utf8_lossy(&bytes).into_owned()
}

async fn json_of(response: Response<Body>) -> serde_json::Value {
    serde_json::from_str(&body_text(response).await).expect("a JSON body")
}

/// A quoted field of a Digest challenge.
fn field(challenge: &str, name: &str) -> String {
    let start = challenge.find(&format!("{name}=\"")).expect("the field") + name.len() + 2;
    challenge[start..].split('"').next().unwrap().to_owned()
}

fn md5_hex(text: &str) -> String {
    Md5::digest(text.as_bytes()).iter().map(|b| format!("{b:02x}")).collect()
}

/// RFC 7616's client answer (MD5, qop=auth), written out here independently.
fn digest(user: &str, password: &str, method: &str, uri: &str, nonce: &str) -> String {
    let ha1 = md5_hex(&format!("{user}:validusers@robapi.abb:{password}"));
    let ha2 = md5_hex(&format!("{method}:{uri}"));
    let response = md5_hex(&format!("{ha1}:{nonce}:00000001:0a4f113b:auth:{ha2}"));
    format!(
        "Digest username=\"{user}\", realm=\"validusers@robapi.abb\", nonce=\"{nonce}\", uri=\"{uri}\", \
         algorithm=MD5, response=\"{response}\", qop=auth, nc=00000001, cnonce=\"0a4f113b\""
    )
}

/// The first `_state` item's field `key` of a JSON answer.
async fn state_field(server: &Server, uri: &str, cookie: &str, key: &str) -> String {
    let response = server.send(get(uri, Some(cookie))).await;
    assert_eq!(response.status(), StatusCode::OK, "{uri}");
    json_of(response).await["_embedded"]["_state"][0][key].as_str().unwrap_or_default().to_owned()
}

#[tokio::test]
async fn digest_auth_challenges_refuses_and_opens_a_session() {
    let server = Server::new("auth");
    let bare = server.send(get("/rw/panel/ctrlstate?json=1", None)).await;
    assert_eq!(bare.status(), StatusCode::UNAUTHORIZED);
    let challenge = header_text(&bare, "www-authenticate");
    assert!(challenge.starts_with("Digest ") && challenge.contains("realm=\"validusers@robapi.abb\""));
    assert!(challenge.contains("qop=\"auth\"") && challenge.contains("algorithm=\"MD5\""));
    let nonce = field(&challenge, "nonce");
    let wrong = digest("Default User", "wrong", "GET", "/rw/panel/ctrlstate?json=1", &nonce);
    let refused = server.send(get_with("/rw/panel/ctrlstate?json=1", &[("authorization", &wrong)])).await;
    assert_eq!(refused.status(), StatusCode::UNAUTHORIZED);
    let cookie = server.login().await;
    // The cookie alone is enough from now on.
    assert_eq!(state_field(&server, "/rw/panel/ctrlstate?json=1", &cookie, "ctrlstate").await, "motoron");
    // Logged out, it is not.
    let out = server.send(get("/logout", Some(&cookie))).await;
    assert!(out.status().is_success());
    assert_eq!(server.send(get("/rw/panel/ctrlstate", Some(&cookie))).await.status(), StatusCode::UNAUTHORIZED);
}

#[tokio::test]
async fn json_is_exactly_application_json_and_xhtml_is_the_default() {
    let server = Server::new("formats");
    let cookie = server.login().await;
    let json = server.send(get("/rw/panel/opmode?json=1", Some(&cookie))).await;
    assert_eq!(header_text(&json, "content-type"), "application/json");
    let value = json_of(json).await;
    assert_eq!(value["_embedded"]["_state"][0]["_type"], "pnl-opmode");
    assert_eq!(value["_embedded"]["_state"][0]["opmode"], "AUTO");
    let xhtml = server.send(get("/rw/panel/opmode", Some(&cookie))).await;
    assert!(header_text(&xhtml, "content-type").starts_with("application/xhtml+xml"));
    let text = body_text(xhtml).await;
    assert!(
        text.contains("<li class=\"pnl-opmode\" title=\"opmode\"><span class=\"opmode\">AUTO</span></li>"),
        "{text}"
    );
}

#[tokio::test]
async fn data_round_trips_through_rapid_literals() {
    let server = Server::new("data");
    let cookie = server.login().await;
    let base = "/rw/rapid/symbol/data/RAPID/T_ROB1";
    assert_eq!(state_field(&server, &format!("{base}/here?json=1"), &cookie, "value").await, "[1,2,3]");
    let set = server
        .send(post(&format!("{base}/MainModule/here?action=set&json=1"), &cookie, "value=%5B4%2C5.5%2C-6%5D"))
        .await;
    assert_eq!(set.status(), StatusCode::NO_CONTENT);
    assert_eq!(state_field(&server, &format!("{base}/here;value?json=1"), &cookie, "value").await, "[4,5.5,-6]");
    // A record component, and a module variable with its module.
    assert_eq!(state_field(&server, &format!("{base}/here.y?json=1"), &cookie, "value").await, "5.5");
    assert_eq!(state_field(&server, &format!("{base}/MainModule/name?json=1"), &cookie, "value").await, "\"abc\"");
    // A literal of another type is refused with RobotWare's status body; so is a CONST.
    let bad = server.send(post(&format!("{base}/count?action=set&json=1"), &cookie, "value=%22x%22")).await;
    assert_eq!(bad.status(), StatusCode::BAD_REQUEST);
    let status = &json_of(bad).await["_embedded"]["status"];
    assert!(status["code"].as_i64().is_some_and(|c| c < 0) && status["msg"].as_str().is_some(), "{status}");
    let constant = server.send(post(&format!("{base}/limit?action=set&json=1"), &cookie, "value=4")).await;
    assert!(constant.status().is_client_error());
    assert_eq!(state_field(&server, &format!("{base}/limit?json=1"), &cookie, "value").await, "3");
}

#[tokio::test]
async fn a_signal_set_over_rws_is_seen_by_the_program() {
    let server = Server::new("signals");
    let cookie = server.login().await;
    assert_eq!(state_field(&server, "/rw/rapid/execution?json=1", &cookie, "ctrlexecstate").await, "stopped");
    let start = "regain=continue&execmode=continue&cycle=forever&condition=none&stopatbp=disabled&alltaskbytsp=true";
    let started = server.send(post("/rw/rapid/execution?action=start&json=1", &cookie, start)).await;
    assert_eq!(started.status(), StatusCode::NO_CONTENT);
    assert_eq!(state_field(&server, "/rw/rapid/execution?json=1", &cookie, "ctrlexecstate").await, "running");
    let sig = "/rw/iosystem/signals/Local/DRV_1";
    assert_eq!(state_field(&server, &format!("{sig}/do1?json=1"), &cookie, "lvalue").await, "0");
    let set = server.send(post(&format!("{sig}/di1?action=set&json=1"), &cookie, "lvalue=1")).await;
    assert_eq!(set.status(), StatusCode::NO_CONTENT);
    let mut seen = false;
    for _ in 0..200 {
        if state_field(&server, &format!("{sig}/do1?json=1"), &cookie, "lvalue").await == "1" {
            seen = true;
            break;
        }
        tokio::time::sleep(Duration::from_millis(10)).await;
    }
    assert!(seen, "the program did not set do1 within 2 s");
    let count = state_field(&server, "/rw/rapid/symbol/data/RAPID/T_ROB1/count?json=1", &cookie, "value").await;
    assert_eq!(count, "1");
    let stopped = server.send(post("/rw/rapid/execution?action=stop&json=1", &cookie, "stopmode=stop")).await;
    assert_eq!(stopped.status(), StatusCode::NO_CONTENT);
    assert_eq!(state_field(&server, "/rw/rapid/execution?json=1", &cookie, "ctrlexecstate").await, "stopped");
    // A digital signal is 0 or 1.
    let two = server.send(post(&format!("{sig}/do1?action=set&json=1"), &cookie, "lvalue=2")).await;
    assert_eq!(two.status(), StatusCode::BAD_REQUEST);
}

#[tokio::test]
async fn malformed_requests_get_their_errors() {
    let server = Server::new("malformed");
    let cookie = server.login().await;
    let bad_cycle = server.send(post("/rw/rapid/execution?action=start&json=1", &cookie, "cycle=sometimes")).await;
    assert_eq!(bad_cycle.status(), StatusCode::BAD_REQUEST);
    assert!(json_of(bad_cycle).await["_embedded"]["status"]["msg"].as_str().unwrap().contains("cycle"));
    let no_value = server.send(post("/rw/rapid/symbol/data/RAPID/T_ROB1/count?action=set&json=1", &cookie, "")).await;
    assert_eq!(no_value.status(), StatusCode::BAD_REQUEST);
    let unknown = server.send(get("/rw/nothing/here?json=1", Some(&cookie))).await;
    assert_eq!(unknown.status(), StatusCode::NOT_FOUND);
    let no_task = server.send(get("/rw/rapid/symbol/data/RAPID/T_NONE/count?json=1", Some(&cookie))).await;
    assert!(no_task.status().is_client_error());
    let bad_ratio = server.send(post("/rw/panel/speedratio?action=setspeedratio", &cookie, "speed-ratio=150")).await;
    assert_eq!(bad_ratio.status(), StatusCode::BAD_REQUEST);
    let bad_sub = server.send(post("/subscription", &cookie, "resources=1&1=/rw/panel/ctrlstate&1-p=2")).await;
    assert_eq!(bad_sub.status(), StatusCode::BAD_REQUEST);
}

#[tokio::test]
async fn the_file_service_stays_inside_its_devices() {
    let server = Server::new("files");
    let cookie = server.login().await;
    let put = Request::put("/fileservice/$HOME/a.txt").header("cookie", &cookie).body(Body::from("abc")).unwrap();
    assert_eq!(server.send(put).await.status(), StatusCode::CREATED);
    assert_eq!(std::fs::read(server.root.join("HOME/a.txt")).unwrap(), b"abc");
    let read = server.send(get("/fileservice/$HOME/a.txt", Some(&cookie))).await;
    assert_eq!(body_text(read).await, "abc");
    let listing = json_of(server.send(get("/fileservice/$HOME?json=1", Some(&cookie))).await).await;
    assert_eq!(listing["_embedded"]["_state"][0]["_title"], "a.txt");
    std::fs::write(server.root.join("secret.txt"), "no").unwrap();
    for path in [
        "/fileservice/$HOME/../secret.txt",
        "/fileservice/$HOME/%2e%2e/secret.txt",
        "/fileservice/$HOME/..%2Fsecret.txt",
    ] {
        let response = server.send(get(path, Some(&cookie))).await;
        assert!(response.status().is_client_error(), "{path}: {}", response.status());
        assert_ne!(body_text(response).await, "no", "{path}");
    }
    #[cfg(unix)]
    {
        std::os::unix::fs::symlink(server.root.join("secret.txt"), server.root.join("HOME/link.txt")).unwrap();
        let linked = server.send(get("/fileservice/$HOME/link.txt", Some(&cookie))).await;
        assert_eq!(linked.status(), StatusCode::FORBIDDEN);
    }
    let unknown = server.send(get("/fileservice/$NOWHERE/x", Some(&cookie))).await;
    assert!(unknown.status().is_client_error());
    let delete = Request::delete("/fileservice/$HOME/a.txt").header("cookie", &cookie).body(Body::empty()).unwrap();
    assert_eq!(server.send(delete).await.status(), StatusCode::NO_CONTENT);
    assert!(!server.root.join("HOME/a.txt").exists());
}

#[tokio::test]
async fn a_subscription_answers_with_its_websocket_address() {
    let server = Server::new("subscription");
    let cookie = server.login().await;
    let form = "resources=1&1=%2Frw%2Fiosystem%2Fsignals%2FLocal%2FDRV_1%2Fdo1%3Bstate&1-p=2\
                &resources=2&2=%2Frw%2Frapid%2Fexecution%3Bctrlexecstate&2-p=1";
    let mut request = post("/subscription?json=1", &cookie, form);
    request.headers_mut().insert(header::HOST, "127.0.0.1:8080".parse().unwrap());
    let created = server.send(request).await;
    assert_eq!(created.status(), StatusCode::CREATED);
    assert_eq!(header_text(&created, "location"), "ws://127.0.0.1:8080/poll/1");
    assert_ne!(header_text(&created, "content-type"), "application/json");
    let body = body_text(created).await;
    assert!(body.contains("<a href=\"ws://127.0.0.1:8080/poll/1\" rel=\"self\">"), "{body}");
    let deleted =
        server.send(Request::delete("/subscription/1").header("cookie", &cookie).body(Body::empty()).unwrap()).await;
    assert_eq!(deleted.status(), StatusCode::NO_CONTENT);
}

#[tokio::test]
async fn symbol_properties_tasks_and_the_run_mode() {
    let server = Server::new("small");
    let cookie = server.login().await;
    let props = "/rw/rapid/symbol/properties/RAPID/T_ROB1/MainModule/limit?json=1";
    assert_eq!(state_field(&server, props, &cookie, "symtyp").await, "con");
    assert_eq!(state_field(&server, props, &cookie, "rdonly").await, "true");
    assert_eq!(
        state_field(&server, "/rw/rapid/symbol/properties/RAPID/T_ROB1/here?json=1", &cookie, "dattyp").await,
        "pos"
    );
    let setcycle = server.send(post("/rw/rapid/execution?action=setcycle&json=1", &cookie, "cycle=once")).await;
    assert_eq!(setcycle.status(), StatusCode::NO_CONTENT);
    assert_eq!(state_field(&server, "/rw/rapid/execution?json=1", &cookie, "cycle").await, "once");
    let tasks = json_of(server.send(get("/rw/rapid/tasks?json=1", Some(&cookie))).await).await;
    let task = &tasks["_embedded"]["_state"][0];
    assert_eq!(
        (task["name"].as_str(), task["type"].as_str(), task["excstate"].as_str()),
        (Some("T_ROB1"), Some("normal"), Some("stopped"))
    );
    // PP at main, on its first statement (column 5 of WaitDI's line).
    let line = PROGRAM.lines().position(|l| l.contains("WaitDI")).unwrap() + 1;
    let pcp = "/rw/rapid/tasks/T_ROB1/pcp?json=1";
    assert_eq!(state_field(&server, pcp, &cookie, "routinename").await, "main");
    assert_eq!(state_field(&server, pcp, &cookie, "beginposition").await, format!("{line},5"));
    assert_eq!(state_field(&server, "/ctrl/$RAMDISK?json=1", &cookie, "_value").await, "$RAMDISK");
    // PP to a routine, and back to main.
    let to_other =
        server.send(post("/rw/rapid/tasks/T_ROB1/pcp?action=set-pp-routine&json=1", &cookie, "routine=other")).await;
    assert_eq!(to_other.status(), StatusCode::NO_CONTENT);
    assert_eq!(state_field(&server, pcp, &cookie, "routinename").await, "other");
    let nowhere =
        server.send(post("/rw/rapid/tasks/T_ROB1/pcp?action=set-pp-routine&json=1", &cookie, "routine=nowhere")).await;
    assert!(nowhere.status().is_client_error());
    assert_eq!(
        server.send(post("/rw/rapid/execution?action=resetpp", &cookie, "")).await.status(),
        StatusCode::NO_CONTENT
    );
    assert_eq!(state_field(&server, pcp, &cookie, "routinename").await, "main");
    let signals = json_of(server.send(get("/rw/iosystem/signals?json=1", Some(&cookie))).await).await;
    let names: Vec<&str> =
        signals["_embedded"]["_state"].as_array().unwrap().iter().filter_map(|s| s["name"].as_str()).collect();
    assert_eq!(names, ["di1", "do1"]);
    assert_eq!(state_field(&server, "/rw/iosystem/signals/di1?json=1", &cookie, "type").await, "DI");
}

/// A robtarget answer's x, y, z and q1..q4.
async fn robtarget(server: &Server, cookie: &str, query: &str) -> ([f64; 3], [f64; 4]) {
    let uri = format!("/rw/motionsystem/mechunits/ROB_1/robtarget?{query}&json=1");
    let response = server.send(get(&uri, Some(cookie))).await;
    assert_eq!(response.status(), StatusCode::OK, "{uri}");
    let item = json_of(response).await["_embedded"]["_state"][0].clone();
    assert_eq!(item["_type"], "ms-robtargets");
    let num = |k: &str| item[k].as_str().unwrap().parse::<f64>().unwrap();
    ([num("x"), num("y"), num("z")], [num("q1"), num("q2"), num("q3"), num("q4")])
}

/// `v` turned by the unit quaternion `q` (scalar first), written out.
fn rotate(q: [f64; 4], v: [f64; 3]) -> [f64; 3] {
    let [w, x, y, z] = q;
    let r = [
        [1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y)],
        [2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x)],
        [2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y)],
    ];
    [0, 1, 2].map(|i| r[i][0] * v[0] + r[i][1] * v[1] + r[i][2] * v[2])
}

fn close(a: &[f64], b: &[f64]) -> bool {
    a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-3)
}

#[tokio::test]
async fn robtargets_of_a_tool_in_base_world_and_a_work_object() {
    let server = Server::new("robtarget");
    let cookie = server.login().await;
    let (flange, q) = robtarget(&server, &cookie, "tool=tool0&wobj=wobj0&coordinate=Base").await;
    assert!((q.iter().map(|c| c * c).sum::<f64>() - 1.0).abs() < 1e-6);
    // tGrip's TCP is 100 mm along the flange's z axis, turned as the flange is.
    let offset = rotate(q, [0.0, 0.0, 100.0]);
    let want = [flange[0] + offset[0], flange[1] + offset[1], flange[2] + offset[2]];
    let (base, q_base) = robtarget(&server, &cookie, "tool=tGrip&wobj=wobj0&coordinate=Base").await;
    assert!(close(&base, &want) && close(&q_base, &q), "{base:?} {q_base:?}, expected {want:?}");
    // The robot's base is the world's origin here.
    let (world, _) = robtarget(&server, &cookie, "tool=tGrip&wobj=wobj0&coordinate=World").await;
    assert!(close(&world, &want), "{world:?}");
    // wTable's object frame is at [100, 0, 0] + [0, 0, 50], not turned.
    let (in_wobj, q_wobj) = robtarget(&server, &cookie, "tool=tGrip&wobj=wTable&coordinate=Wobj").await;
    assert!(close(&in_wobj, &[want[0] - 100.0, want[1], want[2] - 50.0]) && close(&q_wobj, &q), "{in_wobj:?}");
    let unknown =
        server.send(get("/rw/motionsystem/mechunits/ROB_1/robtarget?tool=nothing&json=1", Some(&cookie))).await;
    assert!(unknown.status().is_client_error());
    let tool =
        server.send(get("/rw/motionsystem/mechunits/ROB_1/robtarget?coordinate=Tool&json=1", Some(&cookie))).await;
    assert_eq!(tool.status(), StatusCode::BAD_REQUEST);
    let no_unit = server.send(get("/rw/motionsystem/mechunits/ROB_2/jointtarget?json=1", Some(&cookie))).await;
    assert!(no_unit.status().is_client_error());
}

#[tokio::test]
async fn modules_are_listed_loaded_and_unloaded() {
    let server = Server::new("modules");
    let cookie = server.login().await;
    std::fs::create_dir_all(server.root.join("HOME")).unwrap();
    std::fs::write(server.root.join("HOME/Extra.mod"), "MODULE Extra\n  PROC extra_proc()\n  ENDPROC\nENDMODULE\n")
        .unwrap();
    let names = |value: serde_json::Value| -> Vec<String> {
        value["_embedded"]["_state"]
            .as_array()
            .unwrap()
            .iter()
            .map(|m| m["name"].as_str().unwrap().to_owned())
            .collect()
    };
    let list = json_of(server.send(get("/rw/rapid/modules?task=T_ROB1&json=1", Some(&cookie))).await).await;
    assert_eq!(names(list), ["MainModule"]);
    let load = server
        .send(post(
            "/rw/rapid/tasks/T_ROB1?action=loadmod&json=1",
            &cookie,
            "modulepath=%24HOME%2FExtra.mod&replace=false",
        ))
        .await;
    assert_eq!(load.status(), StatusCode::NO_CONTENT);
    let list = json_of(server.send(get("/rw/rapid/modules?task=T_ROB1&json=1", Some(&cookie))).await).await;
    assert_eq!(names(list), ["MainModule", "Extra"]);
    // Loaded again: refused; with replace=true, the old one goes first.
    let again = server
        .send(post("/rw/rapid/tasks/T_ROB1?action=loadmod&json=1", &cookie, "modulepath=%24HOME%2FExtra.mod"))
        .await;
    assert!(again.status().is_client_error());
    let replaced = server
        .send(post(
            "/rw/rapid/tasks/T_ROB1?action=loadmod&json=1",
            &cookie,
            "modulepath=HOME%3A%2FExtra.mod&replace=true",
        ))
        .await;
    assert_eq!(replaced.status(), StatusCode::NO_CONTENT);
    let unload = server.send(post("/rw/rapid/tasks/T_ROB1?action=unloadmod&json=1", &cookie, "module=Extra")).await;
    assert_eq!(unload.status(), StatusCode::NO_CONTENT);
    let list = json_of(server.send(get("/rw/rapid/modules?task=T_ROB1&json=1", Some(&cookie))).await).await;
    assert_eq!(names(list), ["MainModule"]);
    let outside = server
        .send(post("/rw/rapid/tasks/T_ROB1?action=loadmod&json=1", &cookie, "modulepath=%24HOME%2F..%2Fx.mod"))
        .await;
    assert!(outside.status().is_client_error());
}

/// The next text frame of `ws` that contains `needle`, within 5 s.
async fn frame_with<S>(ws: &mut S, needle: &str) -> String
where
    S: futures_util::Stream<
            Item = Result<tokio_tungstenite::tungstenite::Message, tokio_tungstenite::tungstenite::Error>,
        > + Unpin,
{
    use futures_util::StreamExt;
    let deadline = tokio::time::Instant::now() + Duration::from_secs(5);
    loop {
        let next = tokio::time::timeout_at(deadline, ws.next()).await;
        match next {
            Ok(Some(Ok(tokio_tungstenite::tungstenite::Message::Text(text)))) if text.contains(needle) => {
                return text.to_string();
            }
            Ok(Some(Ok(_))) => {}
            other => panic!("no frame with `{needle}`: {other:?}"),
        }
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_websocket_subscription_delivers_signals_execution_and_queue_messages() {
    use tokio_tungstenite::tungstenite::client::IntoClientRequest;
    let server = Server::new("websocket");
    let cookie = server.login().await;
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.unwrap();
    let host = listener.local_addr().unwrap().to_string();
    let (stop_tx, stop_rx) = tokio::sync::oneshot::channel::<()>();
    let serving = tokio::spawn(rapid_serve::serve(listener, server.router.clone(), async move {
        let _ = stop_rx.await;
    }));
    let create = server
        .send(post(
            "/rw/dipc?action=dipc-create&json=1",
            &cookie,
            "dipc-queue-name=q1&dipc-queue-size=10&dipc-max-msg-size=100",
        ))
        .await;
    assert_eq!(create.status(), StatusCode::CREATED);
    let form = "resources=1&1=%2Frw%2Fiosystem%2Fsignals%2FLocal%2FDRV_1%2Fdo1%3Bstate&1-p=2\
                &resources=2&2=%2Frw%2Frapid%2Fexecution%3Bctrlexecstate&2-p=1\
                &resources=3&3=%2Frw%2Fdipc%2Fq1&3-p=1\
                &resources=4&4=%2Frw%2Frapid%2Ftasks%2FT_ROB1%2Fpcp%3Bprogrampointerchange&4-p=1";
    let mut request = post("/subscription", &cookie, form);
    request.headers_mut().insert(header::HOST, host.parse().unwrap());
    let created = server.send(request).await;
    assert_eq!(created.status(), StatusCode::CREATED);
    let location = header_text(&created, "location");
    // Without a session cookie or credentials, the websocket is refused like any request.
    let bare = server.send(get("/poll/1", None)).await;
    assert_eq!(bare.status(), StatusCode::UNAUTHORIZED);
    assert_eq!(location, format!("ws://{host}/poll/1"));
    let mut ws_request = location.into_client_request().unwrap();
    ws_request.headers_mut().insert("cookie", cookie.parse().unwrap());
    ws_request.headers_mut().insert("sec-websocket-protocol", "robapi2_subscription".parse().unwrap());
    let (mut ws, response) = tokio_tungstenite::connect_async(ws_request).await.expect("the websocket opens");
    assert_eq!(header_text_of(response.headers(), "sec-websocket-protocol"), "robapi2_subscription");
    // The program waits for di1, then sets do1.
    let start = "regain=continue&execmode=continue&cycle=forever&condition=none&stopatbp=disabled&alltaskbytsp=true";
    assert_eq!(
        server.send(post("/rw/rapid/execution?action=start", &cookie, start)).await.status(),
        StatusCode::NO_CONTENT
    );
    let running = frame_with(&mut ws, "rap-ctrlexecstate-ev").await;
    assert!(running.contains("<span class=\"ctrlexecstate\">running</span>") && !running.contains('\n'), "{running}");
    let set = server.send(post("/rw/iosystem/signals/Local/DRV_1/di1?action=set", &cookie, "lvalue=1")).await;
    assert_eq!(set.status(), StatusCode::NO_CONTENT);
    let signal = frame_with(&mut ws, "ios-signalstate-ev").await;
    assert!(
        signal.contains(
            "<a href=\"/rw/iosystem/signals/Local/DRV_1/do1;state\" rel=\"self\"/><span class=\"lvalue\">1</span>"
        ),
        "{signal}"
    );
    let send = "dipc-src-queue-name=q1&dipc-cmd=111&dipc-userdef=5&dipc-msgtype=1&dipc-data=hello";
    assert_eq!(server.send(post("/rw/dipc/q1?action=dipc-send", &cookie, send)).await.status(), StatusCode::NO_CONTENT);
    let message = frame_with(&mut ws, "dipc-msg-ev").await;
    assert!(
        message.contains("<span class=\"dipc-data\">hello</span><span class=\"dipc-userdef\">5</span>"),
        "{message}"
    );
    // Stopped, then PP to Main: the pointer goes back to main's first statement.
    assert_eq!(
        server.send(post("/rw/rapid/execution?action=stop", &cookie, "stopmode=stop")).await.status(),
        StatusCode::NO_CONTENT
    );
    let stopped = frame_with(&mut ws, "<span class=\"ctrlexecstate\">stopped</span>").await;
    assert!(stopped.contains("rap-ctrlexecstate-ev"));
    assert_eq!(
        server.send(post("/rw/rapid/execution?action=resetpp", &cookie, "")).await.status(),
        StatusCode::NO_CONTENT
    );
    let line = PROGRAM.lines().position(|l| l.contains("WaitDI")).unwrap() + 1;
    let pointer = frame_with(&mut ws, &format!("<span class=\"beginposition\">{line},5</span>")).await;
    assert!(pointer.contains("<span class=\"routinename\">main</span>"), "{pointer}");
    let _ = stop_tx.send(());
    drop(ws);
    let _ = tokio::time::timeout(Duration::from_secs(5), serving).await;
}

fn header_text_of(headers: &axum::http::HeaderMap, name: &str) -> String {
    headers.get(name).map(|v| v.to_str().unwrap().to_owned()).unwrap_or_default()
}

#[tokio::test]
async fn dipc_queues_between_clients_and_not_yet_to_tasks() {
    let server = Server::new("dipc");
    let cookie = server.login().await;
    let create = |name: &str| format!("dipc-queue-name={name}&dipc-queue-size=10&dipc-max-msg-size=20");
    let made = server.send(post("/rw/dipc?action=dipc-create&json=1", &cookie, &create("T_mine"))).await;
    assert_eq!(made.status(), StatusCode::CREATED);
    let again = server.send(post("/rw/dipc?action=dipc-create&json=1", &cookie, &create("T_mine"))).await;
    assert_eq!(json_of(again).await["_embedded"]["status"]["code"], -1_073_445_879_i64);
    let task = server.send(post("/rw/dipc?action=dipc-create&json=1", &cookie, &create("t_rob1"))).await;
    assert_eq!(task.status(), StatusCode::BAD_REQUEST);
    // T_ROB1 has no queue here (RmqType None): `a_dipc_message_to_a_task_reaches_its_rmq`.
    let to_task = server.send(post("/rw/dipc/RMQ_T_ROB1?action=dipc-send&json=1", &cookie, "dipc-data=x")).await;
    let msg = json_of(to_task).await["_embedded"]["status"]["msg"].as_str().unwrap_or_default().to_owned();
    assert!(msg.contains("no RAPID message queue"), "{msg}");
    let long =
        server.send(post("/rw/dipc/T_mine?action=dipc-send&json=1", &cookie, "dipc-data=012345678901234567890")).await;
    assert_eq!(long.status(), StatusCode::BAD_REQUEST);
    let sent =
        server.send(post("/rw/dipc/T_mine?action=dipc-send&json=1", &cookie, "dipc-data=ok&dipc-userdef=2")).await;
    assert_eq!(sent.status(), StatusCode::NO_CONTENT);
    assert_eq!(state_field(&server, "/rw/dipc/T_mine?action=dipc-read&json=1", &cookie, "dipc-data").await, "ok");
    let empty = json_of(server.send(get("/rw/dipc/T_mine?action=dipc-read&json=1", Some(&cookie))).await).await;
    assert_eq!(empty["_embedded"]["_state"].as_array().map(Vec::len), Some(0));
}

#[tokio::test]
async fn the_pendant_page_and_its_json_resources_are_behind_the_login() {
    let server = Server::new("pendant");
    assert_eq!(server.send(get("/", None)).await.status(), StatusCode::UNAUTHORIZED);
    assert_eq!(server.send(get("/pendant/api/arms", None)).await.status(), StatusCode::UNAUTHORIZED);
    let cookie = server.login().await;
    let page = server.send(get("/", Some(&cookie))).await;
    assert_eq!(page.status(), StatusCode::OK);
    assert!(header_text(&page, "content-type").starts_with("text/html"));
    assert!(body_text(page).await.contains("/pendant/pendant.js"));
    let script = server.send(get("/pendant/pendant.js", Some(&cookie))).await;
    assert!(header_text(&script, "content-type").starts_with("text/javascript"));
    assert_eq!(server.send(get("/pendant/other.js", Some(&cookie))).await.status(), StatusCode::NOT_FOUND);

    let screen = json_of(server.send(get("/pendant/api/screen", Some(&cookie))).await).await;
    assert_eq!(screen, serde_json::json!({"lines": [], "prompts": []}));
    let no_such = server.send(post("/pendant/api/answer", &cookie, "id=99&answer=1")).await;
    assert_eq!(no_such.status(), StatusCode::BAD_REQUEST);
    assert_eq!(server.send(post("/pendant/api/answer", &cookie, "answer=1")).await.status(), StatusCode::BAD_REQUEST);

    // The arm's points: the base at the world's origin, the column straight up, and the
    // flange where the robtarget of tool0 in the world says it is.
    let arms = json_of(server.send(get("/pendant/api/arms", Some(&cookie))).await).await;
    let arm = &arms["arms"][0];
    assert_eq!(arm["task"], "T_ROB1");
    let points: Vec<Vec<f64>> = serde_json::from_value(arm["points"].clone()).unwrap();
    assert_eq!(points.len(), 6);
    assert_eq!(points[0], vec![0.0, 0.0, 0.0]);
    assert!(points[1][0].abs() < 1e-9 && points[1][1].abs() < 1e-9 && points[1][2] > 0.0, "{points:?}");
    let (flange, _) = robtarget(&server, &cookie, "tool=tool0&coordinate=World").await;
    for axis in 0..3 {
        assert!((points[5][axis] - flange[axis]).abs() < 0.01, "{points:?} vs {flange:?}");
        // No tool moved yet: the active tool is tool0, its TCP the flange.
        assert!((arm["tcp"][axis].as_f64().unwrap() - flange[axis]).abs() < 0.01);
    }

    let program = json_of(server.send(get("/pendant/api/program?task=T_ROB1", Some(&cookie))).await).await;
    assert_eq!(program["pointer"]["routine"], "main");
    assert_eq!(program["text"], serde_json::Value::Null, "the module is not on disk");
    let unknown = server.send(get("/pendant/api/program?task=NOPE", Some(&cookie))).await;
    assert_eq!(unknown.status(), StatusCode::BAD_REQUEST);
    let missing = server.send(get("/pendant/api/program", Some(&cookie))).await;
    assert_eq!(missing.status(), StatusCode::BAD_REQUEST);
}

#[tokio::test]
async fn a_module_text_is_the_module_in_program_memory() {
    let server = Server::new("module-text");
    let cookie = server.login().await;
    let text_of = |module: &str| format!("/rw/rapid/modules/{module}?task=T_ROB1&resource=module-text&json=1");
    let answer = json_of(server.send(get(&text_of("MainModule"), Some(&cookie))).await).await;
    let item = &answer["_embedded"]["_state"][0];
    assert_eq!(item["_type"], "rap-module-text");
    assert_eq!(item["_title"], "moduletext");
    let text = item["module-text"].as_str().unwrap();
    assert!(text.starts_with("MODULE MainModule") && text.contains("ENDMODULE"), "{text}");
    assert!(text.contains("PERS num count := 0;"), "{text}");
    assert_eq!(item["module-length"].as_str().unwrap(), text.len().to_string());
    // A persistent set through RWS: program memory holds the new value, so does the text.
    let set = server.send(post("/rw/rapid/symbol/data/RAPID/T_ROB1/count?action=set", &cookie, "value=42")).await;
    assert_eq!(set.status(), StatusCode::NO_CONTENT);
    let text = state_field(&server, &text_of("MainModule"), &cookie, "module-text").await;
    assert!(text.contains("PERS num count := 42;"), "{text}");
    // A module loaded through RWS has its text too; an unknown one is not found.
    std::fs::create_dir_all(server.root.join("HOME")).unwrap();
    let extra = "MODULE Extra\n  PROC extra_proc()\n  ENDPROC\nENDMODULE\n";
    std::fs::write(server.root.join("HOME/Extra.mod"), extra).unwrap();
    let load =
        server.send(post("/rw/rapid/tasks/T_ROB1?action=loadmod", &cookie, "modulepath=%24HOME%2FExtra.mod")).await;
    assert_eq!(load.status(), StatusCode::NO_CONTENT);
    assert_eq!(state_field(&server, &text_of("Extra"), &cookie, "module-text").await, extra);
    let missing = server.send(get(&text_of("NoSuch"), Some(&cookie))).await;
    assert!(missing.status().is_client_error());
    // XHTML keeps the document on one line: the text's line breaks are escaped.
    let page =
        body_text(server.send(get("/rw/rapid/modules/Extra?task=T_ROB1&resource=module-text", Some(&cookie))).await)
            .await;
    assert!(page.contains("class=\"module-text\">MODULE Extra&#10;"), "{page}");
}

#[tokio::test]
async fn the_data_of_a_module_loaded_through_rws_is_found_by_name_until_unloaded() {
    let server = Server::new("loaded-data");
    let cookie = server.login().await;
    std::fs::create_dir_all(server.root.join("HOME")).unwrap();
    let extra = "MODULE Extra\n  PERS num extra_count := 7;\n  LOCAL VAR string extra_name := \"x\";\nENDMODULE\n";
    std::fs::write(server.root.join("HOME/Extra.mod"), extra).unwrap();
    let value = "/rw/rapid/symbol/data/RAPID/T_ROB1/extra_count?json=1";
    let before = server.send(get(value, Some(&cookie))).await;
    assert!(before.status().is_client_error(), "not loaded yet");
    let load =
        server.send(post("/rw/rapid/tasks/T_ROB1?action=loadmod", &cookie, "modulepath=%24HOME%2FExtra.mod")).await;
    assert_eq!(load.status(), StatusCode::NO_CONTENT);
    // Read by its global name and through its module; set, read back.
    assert_eq!(state_field(&server, value, &cookie, "value").await, "7");
    let local = "/rw/rapid/symbol/data/RAPID/T_ROB1/Extra/extra_name?json=1";
    assert_eq!(state_field(&server, local, &cookie, "value").await, "\"x\"");
    let set =
        server.send(post("/rw/rapid/symbol/data/RAPID/T_ROB1/Extra/extra_count?action=set", &cookie, "value=12")).await;
    assert_eq!(set.status(), StatusCode::NO_CONTENT);
    assert_eq!(state_field(&server, value, &cookie, "value").await, "12");
    // Properties and search see it too.
    let props = "/rw/rapid/symbol/properties/RAPID/T_ROB1/Extra/extra_count?json=1";
    assert_eq!(state_field(&server, props, &cookie, "symtyp").await, "per");
    let search = server
        .send(post(
            "/rw/rapid/symbols?action=search-symbols&json=1",
            &cookie,
            "blockurl=RAPID%2FT_ROB1%2FExtra&symtyp=any",
        ))
        .await;
    assert_eq!(search.status(), StatusCode::OK);
    let found: Vec<String> = json_of(search).await["_embedded"]["_state"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| d["name"].as_str().unwrap().to_owned())
        .collect();
    assert_eq!(found, ["extra_count", "extra_name"]);
    // The booted module's data is still found as before.
    assert_eq!(state_field(&server, "/rw/rapid/symbol/data/RAPID/T_ROB1/count?json=1", &cookie, "value").await, "0");
    // Unloaded: its data is no more.
    let unload = server.send(post("/rw/rapid/tasks/T_ROB1?action=unloadmod", &cookie, "module=Extra")).await;
    assert_eq!(unload.status(), StatusCode::NO_CONTENT);
    for uri in [value, local, props] {
        let gone = server.send(get(uri, Some(&cookie))).await;
        assert!(gone.status().is_client_error(), "{uri}");
        let body = json_of(gone).await;
        assert_eq!(body["_embedded"]["status"]["code"], not_found_code(&server, &cookie).await, "{uri}");
    }
}

/// The status code RWS answers for a symbol that does not exist (one never declared).
async fn not_found_code(server: &Server, cookie: &str) -> serde_json::Value {
    let never = server.send(get("/rw/rapid/symbol/data/RAPID/T_ROB1/never_declared?json=1", Some(cookie))).await;
    json_of(never).await["_embedded"]["status"]["code"].clone()
}

#[tokio::test]
async fn the_speed_ratio_slows_the_robot() {
    const TIMED: &str = "MODULE MainModule
  VAR clock c;
  VAR num took := -1;
  PROC main()
    MoveAbsJ [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v1000, fine, tool0;
    ClkReset c;
    ClkStart c;
    MoveL Offs(CRobT(), 0, 200, 0), v100, fine, tool0;
    ClkStop c;
    took := ClkRead(c \\HighRes);
  ENDPROC
ENDMODULE
";
    let server = Server::with_program("speedratio", TIMED);
    let cookie = server.login().await;
    let ratio = "/rw/panel/speedratio?json=1";
    assert_eq!(state_field(&server, ratio, &cookie, "speedratio").await, "100");
    let zero = server.send(post("/rw/panel/speedratio?action=setspeedratio", &cookie, "speed-ratio=0")).await;
    assert!(zero.status().is_client_error(), "0 % is not supported yet");
    let set = server.send(post("/rw/panel/speedratio?action=setspeedratio", &cookie, "speed-ratio=50")).await;
    assert_eq!(set.status(), StatusCode::NO_CONTENT);
    assert_eq!(state_field(&server, ratio, &cookie, "speedratio").await, "50");
    let start = server.send(post("/rw/rapid/execution?action=start", &cookie, "regain=continue&cycle=once")).await;
    assert_eq!(start.status(), StatusCode::NO_CONTENT);
    let took = "/rw/rapid/symbol/data/RAPID/T_ROB1/took?json=1";
    let mut value = String::new();
    for _ in 0..200 {
        value = state_field(&server, took, &cookie, "value").await;
        if value != "-1" {
            break;
        }
        tokio::time::sleep(Duration::from_millis(50)).await;
    }
    // 200 mm at 50 % of 100 mm/s: 4 s, plus the short ramps from and to a stand-still
    // (at full speed it is 2 s: `the_speed_override_slows_the_programmed_moves`).
    let took: f64 = value.parse().expect("a number");
    assert!((4.0..4.1).contains(&took), "{took}");
}

#[tokio::test]
async fn a_dipc_message_to_a_task_reaches_its_rmq() {
    const RECEIVER: &str = "MODULE MainModule
  VAR intnum on_text;
  VAR intnum on_num;
  VAR rmqmessage msg;
  VAR string text := \"\";
  VAR num n := 0;
  VAR num userdef := 0;
  TRAP got_text
    RMQGetMessage msg;
    RMQGetMsgData msg, text;
    RMQGetMsgHeader msg \\UserDef:=userdef;
  ENDTRAP
  TRAP got_num
    RMQGetMessage msg;
    RMQGetMsgData msg, n;
  ENDTRAP
  PROC main()
    CONNECT on_text WITH got_text;
    IRMQMessage text, on_text;
    CONNECT on_num WITH got_num;
    IRMQMessage n, on_num;
    WHILE TRUE DO
      WaitTime 0.05;
    ENDWHILE
  ENDPROC
ENDMODULE
";
    let server = Server::with_queue("rmq", RECEIVER, rapid_config::sys::RmqType::Remote);
    let cookie = server.login().await;
    let start = server.send(post("/rw/rapid/execution?action=start", &cookie, "regain=continue")).await;
    assert_eq!(start.status(), StatusCode::NO_CONTENT);
    let send = |data: &str| post("/rw/dipc/RMQ_T_ROB1?action=dipc-send&json=1", &cookie, data);
    let sent = server.send(send("dipc-data=string%3B%22hello%22&dipc-userdef=7")).await;
    assert_eq!(sent.status(), StatusCode::NO_CONTENT);
    let sent = server.send(send("dipc-data=num%3B42&dipc-userdef=1")).await;
    assert_eq!(sent.status(), StatusCode::NO_CONTENT);
    let read = |name: &str| format!("/rw/rapid/symbol/data/RAPID/T_ROB1/{name}?json=1");
    let mut got = (String::new(), String::new(), String::new());
    for _ in 0..200 {
        got = (
            state_field(&server, &read("text"), &cookie, "value").await,
            state_field(&server, &read("n"), &cookie, "value").await,
            state_field(&server, &read("userdef"), &cookie, "value").await,
        );
        if got.1 == "42" && got.0 != "\"\"" {
            break;
        }
        tokio::time::sleep(Duration::from_millis(50)).await;
    }
    assert_eq!(got, ("\"hello\"".to_owned(), "42".to_owned(), "7".to_owned()));
    // Not `<datatype>;<value>`, no literal of its type, a record type (not yet).
    for bad in ["dipc-data=hello", "dipc-data=num%3Babc", "dipc-data=pos%3B%5B1%2C2%2C3%5D"] {
        let refused = server.send(send(bad)).await;
        assert_eq!(refused.status(), StatusCode::BAD_REQUEST, "{bad}");
    }
}
