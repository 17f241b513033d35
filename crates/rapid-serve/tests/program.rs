//! The router in process on programs of the tests' own: a module's text, the data
//! of a module loaded through RWS, the speed ratio's effect on a move, and DIPC
//! messages to a task's RAPID Message Queue.

mod support;

use std::time::Duration;

use axum::http::StatusCode;
use support::*;

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
async fn a_new_speed_ratio_slows_the_move_under_way() {
    const SLOW: &str = "MODULE MainModule
  VAR clock c;
  VAR num took := -1;
  PROC main()
    MoveAbsJ [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v1000, fine, tool0;
    ClkReset c;
    ClkStart c;
    MoveL Offs(CRobT(), 0, 200, 0), v10, fine, tool0;
    ClkStop c;
    took := ClkRead(c \\HighRes);
  ENDPROC
ENDMODULE
";
    let server = Server::with_program("speedratio_live", SLOW);
    let cookie = server.login().await;
    let y = || async { state_field(&server, "/rw/motionsystem/mechunits/ROB_1/robtarget?json=1", &cookie, "y").await };
    let start = server.send(post("/rw/rapid/execution?action=start", &cookie, "regain=continue&cycle=once")).await;
    assert_eq!(start.status(), StatusCode::NO_CONTENT);
    // The MoveAbsJ turns axis 5 only: the TCP stays at y = 0 until the MoveL moves it.
    let mut before = 0.0;
    for _ in 0..400 {
        before = y().await.parse::<f64>().expect("a number");
        if before > 1.0 {
            break;
        }
        tokio::time::sleep(Duration::from_millis(5)).await;
    }
    let set = server.send(post("/rw/panel/speedratio?action=setspeedratio", &cookie, "speed-ratio=50")).await;
    assert_eq!(set.status(), StatusCode::NO_CONTENT);
    let after: f64 = y().await.parse().expect("a number");
    assert!(before > 1.0 && after < 100.0, "set while the robot was on its way: {before} {after}");
    let took = "/rw/rapid/symbol/data/RAPID/T_ROB1/took?json=1";
    let mut value = String::new();
    for _ in 0..400 {
        value = state_field(&server, took, &cookie, "value").await;
        if value != "-1" {
            break;
        }
        tokio::time::sleep(Duration::from_millis(50)).await;
    }
    // 200 mm at 10 mm/s (ramps of 1 ms): at y mm the ratio halves the speed, so the
    // rest takes (200 − y)/5 s: y/10 + (200 − y)/5 = 40 − y/10 s, and 0.05 s of
    // settling. The ratio came when the robot stood between `before` and `after`.
    let took: f64 = value.parse().expect("a number");
    let (earliest, latest) = (40.05 - after / 10.0, 40.05 - before / 10.0);
    assert!(took > earliest - 0.02 && took < latest + 0.02, "{took} not in {earliest}..{latest}");
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
  VAR bool ready := FALSE;
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
    ready := TRUE;
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
    // In interrupt mode a message no IRMQMessage is ordered for is thrown away: the
    // messages go once the program has ordered its traps.
    let ready = "/rw/rapid/symbol/data/RAPID/T_ROB1/ready?json=1";
    for _ in 0..200 {
        if state_field(&server, ready, &cookie, "value").await == "TRUE" {
            break;
        }
        tokio::time::sleep(Duration::from_millis(50)).await;
    }
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
    // Not `<datatype>;<value>`, no literal of its type, a type the task does not have
    // (records the task has: `dipc_records_and_arrays_reach_a_task_and_its_answer_the_client`).
    for bad in ["dipc-data=hello", "dipc-data=num%3Babc", "dipc-data=nosuchtype%3B%5B1%2C2%2C3%5D"] {
        let refused = server.send(send(bad)).await;
        assert_eq!(refused.status(), StatusCode::BAD_REQUEST, "{bad}");
    }
}
