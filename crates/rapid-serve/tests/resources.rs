//! RWS resources as RobotWare 6's manual gives them (3HAC050973-001): the
//! configuration database (`/rw/cfg`), a module's attributes and the execution modes
//! of a start. Expected forms are the manual's class and span names, worked out by
//! hand from the `.cfg` text and the program each test gives.

mod support;

use axum::http::StatusCode;
use support::{body_text, get, json_of, post, state_field, Server, PROGRAM};

const EIO: &str = "EIO:CFG_1.0:6:1::
#
EIO_DEVICE:

      -Name \"d651\" -Network \"DeviceNet\" -Address 63
#
EIO_SIGNAL:

      -Name \"di1\" -SignalType \"DI\" -Device \"d651\" -DeviceMap \"0\"

      -Name \"do1\" -SignalType \"DO\" -Device \"d651\" -DeviceMap \"1\" -Access \"All\"
";

const SYS: &str = "SYS:CFG_1.0:6:0::
#
CAB_TASKS:

      -Name \"T_ROB1\" -Type \"NORMAL\" -MotionTask
";

/// The `_state` items of a JSON answer.
async fn items(server: &Server, uri: &str, cookie: &str) -> Vec<serde_json::Value> {
    let response = server.send(get(uri, Some(cookie))).await;
    assert_eq!(response.status(), StatusCode::OK, "{uri}");
    json_of(response).await["_embedded"]["_state"].as_array().cloned().unwrap_or_default()
}

fn titles(items: &[serde_json::Value]) -> Vec<&str> {
    items.iter().filter_map(|i| i["_title"].as_str()).collect()
}

#[tokio::test]
async fn the_configuration_database_lists_domains_types_and_instances() {
    let config = [("SYS", SYS), ("EIO", EIO)];
    let server = Server::with_config("cfg", PROGRAM, rapid_config::sys::RmqType::None, &config);
    let cookie = server.login().await;

    // The domains the system has, in RobotWare's order (EIO before SYS).
    let domains = items(&server, "/rw/cfg?json=1", &cookie).await;
    assert_eq!(titles(&domains), ["EIO", "SYS"]);
    assert_eq!(domains[0]["_type"], "cfg-domain-li");
    assert_eq!(domains[0]["_links"]["self"]["href"], "cfg/EIO");

    // Types, linked by the domain as asked; a page of one has a next link.
    let types = items(&server, "/rw/cfg/eio?json=1", &cookie).await;
    assert_eq!(titles(&types), ["EIO_DEVICE", "EIO_SIGNAL"]);
    assert_eq!(types[1]["_type"], "cfg-dt-li");
    assert_eq!(types[1]["_links"]["self"]["href"], "eio/EIO_SIGNAL");
    let page = json_of(server.send(get("/rw/cfg/eio?limit=1&json=1", Some(&cookie))).await).await;
    assert_eq!(titles(page["_embedded"]["_state"].as_array().unwrap()), ["EIO_DEVICE"]);
    assert_eq!(page["_links"]["next"]["href"], "eio?start=1&limit=1");
    let last = json_of(server.send(get("/rw/cfg/eio?start=1&limit=1&json=1", Some(&cookie))).await).await;
    assert_eq!(titles(last["_embedded"]["_state"].as_array().unwrap()), ["EIO_SIGNAL"]);
    assert!(last["_links"].get("next").is_none(), "the last page has no next link");

    // A type: its instances counted.
    let ty = items(&server, "/rw/cfg/EIO/EIO_SIGNAL?json=1", &cookie).await;
    assert_eq!(ty[1]["_type"], "cfg-dt-instances-li");
    assert_eq!(ty[1]["cfg-no-of-instances"], "2");
    assert_eq!(ty[1]["_links"]["self"]["href"], "EIO/EIO_SIGNAL/instances");

    // Instances with their attributes as the file writes them; ids count the
    // domain's instances from 1 (d651 is 1, di1 2, do1 3).
    let signals = items(&server, "/rw/cfg/EIO/EIO_SIGNAL/instances?json=1", &cookie).await;
    assert_eq!(titles(&signals), ["di1", "do1"]);
    let do1 = items(&server, "/rw/cfg/EIO/EIO_SIGNAL/instances/DO1?json=1", &cookie).await;
    assert_eq!(do1.len(), 1);
    assert_eq!((do1[0]["_type"].as_str(), do1[0]["_title"].as_str()), (Some("cfg-dt-instance-li"), Some("do1")));
    assert_eq!((do1[0]["rdonly"].as_str(), do1[0]["instanceid"].as_str()), (Some("false"), Some("3")));
    let attrs: Vec<(&str, &str)> = do1[0]["attrib"]
        .as_array()
        .unwrap()
        .iter()
        .map(|a| {
            assert_eq!(a["_type"], "cfg-ia-t-li");
            (a["_title"].as_str().unwrap(), a["value"].as_str().unwrap())
        })
        .collect();
    assert_eq!(
        attrs,
        [("Name", "do1"), ("SignalType", "DO"), ("Device", "d651"), ("DeviceMap", "1"), ("Access", "All")]
    );

    // The same instance as XHTML: the attributes are a list inside the instance's item.
    let xhtml = body_text(server.send(get("/rw/cfg/EIO/EIO_DEVICE/instances/d651", Some(&cookie))).await).await;
    let expected = "<li class=\"cfg-dt-instance-li\" title=\"d651\"><span class=\"rdonly\">false</span>\
        <span class=\"instanceid\">1</span><ul>\
        <li class=\"cfg-ia-t-li\" title=\"Name\"><span class=\"value\">d651</span></li>\
        <li class=\"cfg-ia-t-li\" title=\"Network\"><span class=\"value\">DeviceNet</span></li>\
        <li class=\"cfg-ia-t-li\" title=\"Address\"><span class=\"value\">63</span></li></ul></li>";
    assert!(xhtml.contains(expected), "{xhtml}");

    // A flag attribute (written bare) is true.
    let task = items(&server, "/rw/cfg/SYS/CAB_TASKS/instances/T_ROB1?json=1", &cookie).await;
    let motion = task[0]["attrib"].as_array().unwrap().iter().find(|a| a["_title"] == "MotionTask").cloned();
    assert_eq!(motion.unwrap()["value"], "true");

    // What is not there, and what is not done.
    let missing = server.send(get("/rw/cfg/MOC?json=1", Some(&cookie))).await;
    assert_eq!(missing.status(), StatusCode::NOT_FOUND);
    assert!(json_of(missing).await["_embedded"]["status"]["msg"].as_str().unwrap().contains("MOC.cfg"));
    let no_instance = server.send(get("/rw/cfg/EIO/EIO_SIGNAL/instances/di9?json=1", Some(&cookie))).await;
    assert_eq!(no_instance.status(), StatusCode::NOT_FOUND);
    let set =
        server.send(post("/rw/cfg/EIO/EIO_SIGNAL/instances/do1?action=set&json=1", &cookie, "Access=ReadOnly")).await;
    assert_eq!(set.status(), StatusCode::BAD_REQUEST);
    let status = json_of(set).await["_embedded"]["status"].clone();
    assert_eq!(status["code"], -1_073_445_868, "not supported");
    assert!(status["msg"].as_str().unwrap().starts_with("not supported yet: changing the configuration"));
    let unchanged = items(&server, "/rw/cfg/EIO/EIO_SIGNAL/instances/do1?json=1", &cookie).await;
    assert_eq!(unchanged[0]["attrib"][4]["value"], "All");
    let attributes = server.send(get("/rw/cfg/EIO/EIO_SIGNAL/attributes?json=1", Some(&cookie))).await;
    assert_eq!(attributes.status(), StatusCode::BAD_REQUEST);
}

#[tokio::test]
async fn a_module_s_attributes_by_plain_get() {
    let server = Server::new("modattr");
    let cookie = server.login().await;
    std::fs::create_dir_all(server.root.join("HOME")).unwrap();
    let tools = "MODULE Tools(SYSMODULE, NOSTEPIN, READONLY)\n  PROC tool_proc()\n  ENDPROC\nENDMODULE\n";
    std::fs::write(server.root.join("HOME/Tools.sys"), tools).unwrap();
    let load = server
        .send(post("/rw/rapid/tasks/T_ROB1?action=loadmod&json=1", &cookie, "modulepath=%24HOME%2FTools.sys"))
        .await;
    assert_eq!(load.status(), StatusCode::NO_CONTENT);

    let tools = items(&server, "/rw/rapid/modules/tools?task=t_rob1&json=1", &cookie).await;
    assert_eq!(tools.len(), 1);
    let t = &tools[0];
    assert_eq!((t["_type"].as_str(), t["_title"].as_str()), (Some("rap-module"), Some("T_ROB1/Tools")));
    assert_eq!((t["modname"].as_str(), t["filename"].as_str()), (Some("Tools"), Some("Tools.sys")));
    assert_eq!(t["attribute"], "sysmod,nostepin,readonly");

    let main = "/rw/rapid/modules/MainModule?task=T_ROB1&json=1";
    assert_eq!(state_field(&server, main, &cookie, "filename").await, "MainModule.mod");
    assert_eq!(state_field(&server, main, &cookie, "attribute").await, "");
    let none = server.send(get("/rw/rapid/modules/Nowhere?task=T_ROB1&json=1", Some(&cookie))).await;
    assert!(none.status().is_client_error());
    let xhtml = body_text(server.send(get("/rw/rapid/modules/Tools?task=T_ROB1", Some(&cookie))).await).await;
    assert!(
        xhtml.contains(
            "<li class=\"rap-module\" title=\"T_ROB1/Tools\"><span class=\"modname\">Tools</span>\
             <span class=\"filename\">Tools.sys</span><span class=\"attribute\">sysmod,nostepin,readonly</span></li>"
        ),
        "{xhtml}"
    );
}

const STEPS: &str = "MODULE MainModule
  VAR num n := 0;
  PROC main()
    n := 1;
    n := 2;
    n := 3;
  ENDPROC
ENDMODULE
";

/// The line of `STEPS` that holds `text` (1-based).
fn line_of(text: &str) -> usize {
    STEPS.lines().position(|l| l.contains(text)).unwrap() + 1
}

/// Waits (at most 5 s) for the program pointer to stand at `line`, the program stopped.
async fn pointer_at(server: &Server, cookie: &str, line: usize) {
    let pcp = "/rw/rapid/tasks/T_ROB1/pcp?json=1";
    for _ in 0..100 {
        let stopped = state_field(server, "/rw/rapid/execution?json=1", cookie, "ctrlexecstate").await == "stopped";
        if stopped && state_field(server, pcp, cookie, "beginposition").await == format!("{line},5") {
            return;
        }
        tokio::time::sleep(std::time::Duration::from_millis(50)).await;
    }
    panic!(
        "the program pointer never stood at line {line}: {}",
        state_field(server, pcp, cookie, "beginposition").await
    );
}

fn start_form(execmode: &str) -> String {
    format!("regain=continue&execmode={execmode}&cycle=asis&condition=none&stopatbp=disabled&alltaskbytsp=false")
}

#[tokio::test]
async fn execution_modes_step_forward_and_back_and_refuse_what_is_not_known() {
    let server = Server::with_program("execmode", STEPS);
    let cookie = server.login().await;
    let start = |mode: &str| post("/rw/rapid/execution?action=start&json=1", &cookie, &start_form(mode));

    // One step in: `n := 1` done, the pointer on `n := 2`.
    assert_eq!(server.send(start("stepin")).await.status(), StatusCode::NO_CONTENT);
    pointer_at(&server, &cookie, line_of("n := 2")).await;
    assert_eq!(state_field(&server, "/rw/rapid/symbol/data/RAPID/T_ROB1/n?json=1", &cookie, "value").await, "1");
    assert_eq!(server.send(start("stepover")).await.status(), StatusCode::NO_CONTENT);
    pointer_at(&server, &cookie, line_of("n := 3")).await;

    // One step back: the pointer returns over `n := 2` (which is not undone).
    assert_eq!(server.send(start("stepback")).await.status(), StatusCode::NO_CONTENT);
    pointer_at(&server, &cookie, line_of("n := 2")).await;
    assert_eq!(server.send(start("stepback")).await.status(), StatusCode::NO_CONTENT);
    pointer_at(&server, &cookie, line_of("n := 1")).await;
    // At the routine's start there is nothing to step back over.
    let refused = server.send(start("stepback")).await;
    assert_eq!(refused.status(), StatusCode::CONFLICT);
    pointer_at(&server, &cookie, line_of("n := 1")).await;

    // `stepmotion` is accepted (tested below); `steplast`'s meaning is not public.
    for mode in ["steplast"] {
        let answer = server.send(start(mode)).await;
        assert_eq!(answer.status(), StatusCode::BAD_REQUEST, "{mode}");
        let status = json_of(answer).await["_embedded"]["status"].clone();
        assert_eq!(status["code"], -1_073_445_868, "{mode}: not supported");
        assert!(status["msg"].as_str().unwrap().contains(mode));
    }
    let unknown = server.send(start("stepsideways")).await;
    assert_eq!(unknown.status(), StatusCode::BAD_REQUEST);
    assert_eq!(json_of(unknown).await["_embedded"]["status"]["code"], -1_073_445_866, "a bad value");
    // Nothing of the refused starts ran.
    pointer_at(&server, &cookie, line_of("n := 1")).await;
}

const MOVE_STEPS: &str = "MODULE MainModule
  VAR num n := 0;
  CONST robtarget p10 := [[300, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST robtarget p20 := [[400, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    n := 1;
    Approach;
    n := 3;
    MoveL p20, v100, fine, tool0;
    n := 4;
  ENDPROC
  PROC Approach()
    MoveJ p10, v1000, fine, tool0;
    n := 2;
  ENDPROC
ENDMODULE
";

/// Waits (at most 5 s) for the program to stand stopped; then T_ROB1's program
/// pointer (routine, line), `n` and the robot's TCP x (tool0, mm).
async fn after_step(server: &Server, cookie: &str) -> (String, usize, String, f64) {
    for _ in 0..100 {
        if state_field(server, "/rw/rapid/execution?json=1", cookie, "ctrlexecstate").await == "stopped" {
            break;
        }
        tokio::time::sleep(std::time::Duration::from_millis(50)).await;
    }
    let pcp = "/rw/rapid/tasks/T_ROB1/pcp?json=1";
    let routine = state_field(server, pcp, cookie, "routinename").await;
    let begin = state_field(server, pcp, cookie, "beginposition").await;
    let line = begin.split(',').next().and_then(|l| l.parse().ok()).unwrap_or(0);
    let n = state_field(server, "/rw/rapid/symbol/data/RAPID/T_ROB1/n?json=1", cookie, "value").await;
    let x = state_field(server, "/rw/motionsystem/mechunits/ROB_1/robtarget?json=1", cookie, "x").await;
    (routine, line, n, x.parse().unwrap_or(f64::NAN))
}

#[tokio::test]
async fn a_move_step_runs_on_to_the_statement_after_the_next_motion_instruction() {
    let server = Server::with_program("stepmotion", MOVE_STEPS);
    let cookie = server.login().await;
    let line = |text: &str| MOVE_STEPS.lines().position(|l| l.contains(text)).unwrap() + 1;
    let step = || post("/rw/rapid/execution?action=start&json=1", &cookie, &start_form("stepmotion"));

    // `n := 1`, into Approach, the MoveJ to p10 (a stop point: done once the robot
    // stands there): the pointer on `n := 2` inside Approach.
    assert_eq!(server.send(step()).await.status(), StatusCode::NO_CONTENT);
    let (routine, at, n, x) = after_step(&server, &cookie).await;
    assert_eq!((routine.as_str(), at, n.as_str()), ("Approach", line("n := 2"), "1"));
    assert!((x - 300.0).abs() < 0.01, "the robot at p10: {x}");

    // `n := 2`, back in main, `n := 3`, the MoveL to p20: the pointer on `n := 4`.
    assert_eq!(server.send(step()).await.status(), StatusCode::NO_CONTENT);
    let (routine, at, n, x) = after_step(&server, &cookie).await;
    assert_eq!((routine.as_str(), at, n.as_str()), ("main", line("n := 4"), "3"));
    assert!((x - 400.0).abs() < 0.01, "the robot at p20: {x}");

    // `n := 4` ends main; a served program runs cycle after cycle (`forever`), so the
    // step goes on from main's start to the next motion instruction, the MoveJ.
    assert_eq!(server.send(step()).await.status(), StatusCode::NO_CONTENT);
    let (routine, at, n, x) = after_step(&server, &cookie).await;
    assert_eq!((routine.as_str(), at, n.as_str()), ("Approach", line("n := 2"), "1"));
    assert!((x - 300.0).abs() < 0.01, "the robot back at p10: {x}");
}

const MESSENGER: &str = "MODULE MainModule
  VAR intnum on_pos;
  VAR intnum on_list;
  VAR rmqmessage msg;
  VAR rmqslot sender;
  VAR rmqslot pc;
  VAR pos got := [0, 0, 0];
  VAR num list{3} := [0, 0, 0];
  VAR bool ready := FALSE;
  TRAP got_pos
    RMQGetMessage msg;
    RMQGetMsgData msg, got;
    RMQGetMsgHeader msg \\SenderId:=sender;
    RMQSendMessage sender, got.x + got.y + got.z \\UserDef:=5;
  ENDTRAP
  TRAP got_list
    RMQGetMessage msg;
    RMQGetMsgData msg, list;
  ENDTRAP
  PROC main()
    CONNECT on_pos WITH got_pos;
    IRMQMessage got, on_pos;
    CONNECT on_list WITH got_list;
    IRMQMessage list, on_list;
    RMQFindSlot pc, \"PC_Q\";
    RMQSendMessage pc, \"hello\";
    ready := TRUE;
    WHILE TRUE DO
      WaitTime 0.05;
    ENDWHILE
  ENDPROC
ENDMODULE
";

/// The first message of DIPC queue `queue` within 5 s: (data, userdef, sender queue).
async fn next_message(server: &Server, cookie: &str, queue: &str) -> (String, String, String) {
    let uri = format!("/rw/dipc/{queue}?action=dipc-read&json=1");
    for _ in 0..100 {
        let found = items(server, &uri, cookie).await;
        if let Some(m) = found.first() {
            assert_eq!(m["_type"], "dipc-read-li");
            let text = |k: &str| m[k].as_str().unwrap_or_default().to_owned();
            return (text("dipc-data"), text("dipc-userdef"), text("queue-name"));
        }
        tokio::time::sleep(std::time::Duration::from_millis(50)).await;
    }
    panic!("no message came to {queue}");
}

/// A datum of T_ROB1, waited for (5 s) to read `want`.
async fn value_becomes(server: &Server, cookie: &str, name: &str, want: &str) {
    let uri = format!("/rw/rapid/symbol/data/RAPID/T_ROB1/{name}?json=1");
    let mut value = String::new();
    for _ in 0..100 {
        value = state_field(server, &uri, cookie, "value").await;
        if value == want {
            return;
        }
        tokio::time::sleep(std::time::Duration::from_millis(50)).await;
    }
    panic!("{name} is {value}, not {want}");
}

#[tokio::test]
async fn dipc_records_and_arrays_reach_a_task_and_its_answer_the_client() {
    let server = Server::with_queue("dipc-records", MESSENGER, rapid_config::sys::RmqType::Remote);
    let cookie = server.login().await;
    let create = "dipc-queue-name=PC_Q&dipc-queue-size=10&dipc-max-msg-size=444";
    assert_eq!(
        server.send(post("/rw/dipc?action=dipc-create&json=1", &cookie, create)).await.status(),
        StatusCode::CREATED
    );
    let start = server.send(post("/rw/rapid/execution?action=start&json=1", &cookie, "regain=continue")).await;
    assert_eq!(start.status(), StatusCode::NO_CONTENT);
    value_becomes(&server, &cookie, "ready", "TRUE").await;

    // RMQFindSlot found the client's queue by its name; the task's message is there,
    // as `<datatype>;<value>`, from RMQ_T_ROB1, without \UserDef (-1).
    let hello = next_message(&server, &cookie, "PC_Q").await;
    assert_eq!(hello, ("string;\"hello\"".to_owned(), "-1".to_owned(), "RMQ_T_ROB1".to_owned()));

    // A record, read as the task declares pos; the trap answers its sender (the
    // client's queue) with the sum of the components.
    let send = |data: &str| post("/rw/dipc/RMQ_T_ROB1?action=dipc-send&json=1", &cookie, data);
    let record = "dipc-data=pos%3B%5B1%2C2%2C3.5%5D&dipc-userdef=0&dipc-src-queue-name=PC_Q";
    assert_eq!(server.send(send(record)).await.status(), StatusCode::NO_CONTENT);
    value_becomes(&server, &cookie, "got", "[1,2,3.5]").await;
    let answer = next_message(&server, &cookie, "PC_Q").await;
    assert_eq!(answer, ("num;6.5".to_owned(), "5".to_owned(), "RMQ_T_ROB1".to_owned()));

    // An array of num: an aggregate that is no num literal, of three items.
    assert_eq!(server.send(send("dipc-data=num%3B%5B4%2C5%2C6%5D")).await.status(), StatusCode::NO_CONTENT);
    value_becomes(&server, &cookie, "list", "[4,5,6]").await;

    // A pos of two components, a type the task does not have, a two-dimensional array.
    for bad in
        ["dipc-data=pos%3B%5B1%2C2%5D", "dipc-data=nosuch%3B%5B1%5D", "dipc-data=num%3B%5B%5B1%2C2%5D%2C%5B3%2C4%5D%5D"]
    {
        let refused = server.send(send(bad)).await;
        assert_eq!(refused.status(), StatusCode::BAD_REQUEST, "{bad}");
    }
    assert_eq!(
        state_field(&server, "/rw/rapid/symbol/data/RAPID/T_ROB1/got?json=1", &cookie, "value").await,
        "[1,2,3.5]"
    );

    // Deleted: gone for the client and for the tasks.
    let delete = axum::http::Request::delete("/rw/dipc/PC_Q?json=1")
        .header("cookie", &cookie)
        .body(axum::body::Body::empty())
        .unwrap();
    assert_eq!(server.send(delete).await.status(), StatusCode::NO_CONTENT);
    let gone = server.send(get("/rw/dipc/PC_Q?action=dipc-read&json=1", Some(&cookie))).await;
    assert_eq!(gone.status(), StatusCode::NOT_FOUND);
}
