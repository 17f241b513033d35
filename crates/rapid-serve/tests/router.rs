//! The router in process: authentication, cookies, formats, data, signals,
//! execution, malformed requests and the file service's sandbox, on a controller
//! built here (one task with two digital signals).

mod support;

use std::time::Duration;

use axum::body::Body;
use axum::http::{header, Request, StatusCode};
use support::*;

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

/// Found by the `rws` fuzz target: `/poll/{id}` refused in XHTML even when `json=1`
/// was asked, an answer a JSON client cannot read. Both refusals (no such
/// subscription; no websocket upgrade) follow the format asked for.
#[tokio::test]
async fn poll_refusals_are_json_when_json_is_asked() {
    let server = Server::new("poll-json");
    let cookie = server.login().await;
    let missing = server.send(get("/poll/%00?json=1", Some(&cookie))).await;
    assert_eq!(missing.status(), StatusCode::NOT_FOUND);
    assert_eq!(header_text(&missing, "content-type"), "application/json");
    let status = &json_of(missing).await["_embedded"]["status"];
    assert_eq!(status["msg"], "no such subscription");
    let form = "resources=1&1=%2Frw%2Frapid%2Fexecution%3Bctrlexecstate&1-p=1";
    assert_eq!(server.send(post("/subscription?json=1", &cookie, form)).await.status(), StatusCode::CREATED);
    let no_upgrade = server.send(get("/poll/1?json=1", Some(&cookie))).await;
    assert_eq!(no_upgrade.status(), StatusCode::BAD_REQUEST);
    assert!(json_of(no_upgrade).await["_embedded"]["status"]["msg"].as_str().unwrap().contains("websocket"));
    // Without json=1 the refusal stays XHTML, as before.
    let xhtml = server.send(get("/poll/7", Some(&cookie))).await;
    assert!(header_text(&xhtml, "content-type").starts_with("application/xhtml+xml"));
}
