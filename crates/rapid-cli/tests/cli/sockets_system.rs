//! Sockets and the controller clock: in a system of several tasks a task waiting on a
//! socket gives way to the others (the controller runs them while it waits), and its
//! `\Time` is the peer's in wall-clock time; while a program holds a socket open, its
//! waits pass in wall-clock time too, so the peer sees the controller's time pass. The peer is a Rust listener on 127.0.0.1 with a port the OS chose;
//! every wait is bounded on both sides.

use std::net::TcpListener;
use std::time::{Duration, Instant};

use crate::fixture::{client_and_ticker, hello_after_three_ticks, scratch_in, spawn_in, system, text, TaskDef};

#[test]
fn a_task_waiting_on_a_socket_lets_the_other_tasks_run() {
    let dir = scratch_in("sockets_system", "give_way");
    let listener = TcpListener::bind("127.0.0.1:0").expect("bind");
    let port = listener.local_addr().expect("addr").port();
    let client = "MODULE Client\n  VAR socketdev s;\n  VAR string got;\n  PROC main()\n    SocketCreate s;\n    \
                  SocketConnect s, \"127.0.0.1\", PORT;\n    SocketReceive s \\Str:=got \\Time:=10;\n    \
                  TPWrite \"got \" + got;\n    SocketClose s;\n  ENDPROC\nENDMODULE\n";
    client_and_ticker(&dir, client, port);
    let child = spawn_in(&dir, &["run", "sys"]);
    // The other task runs while T_ROB1 waits for data: its three ticks come first, and
    // only then does the peer send what T_ROB1 waits for.
    hello_after_three_ticks(&listener, child);
}

#[test]
fn a_socket_wait_in_a_system_gives_the_peer_its_time_in_wall_clock_time() {
    let dir = scratch_in("sockets_system", "time_out");
    let listener = TcpListener::bind("127.0.0.1:0").expect("bind");
    let port = listener.local_addr().expect("addr").port();
    let client = "MODULE Client\n  VAR socketdev s;\n  VAR string got;\n  PROC main()\n    SocketCreate s;\n    \
                  SocketConnect s, \"127.0.0.1\", PORT;\n    SocketReceive s \\Str:=got \\Time:=0.5;\n    \
                  TPWrite \"got \" + got;\n  ERROR\n    IF ERRNO = ERR_SOCK_TIMEOUT TPWrite \"timeout\";\n    \
                  SocketClose s;\n    RETURN;\n  ENDPROC\nENDMODULE\n";
    client_and_ticker(&dir, client, port);
    let started = Instant::now();
    let child = spawn_in(&dir, &["run", "sys"]);
    // The peer keeps the connection open and sends nothing.
    let (_peer, _) = listener.accept().expect("accept");
    let out = child.wait_with_output().expect("rapid ends");
    let elapsed = started.elapsed();
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    // The ticks at 0.1, 0.2 and 0.3 s come before the receive times out at 0.5 s, and
    // those 0.5 s passed on the wall clock: the peer had them.
    assert_eq!(text(&out.stdout), "tick\ntick\ntick\ntimeout\n");
    assert!(elapsed >= Duration::from_millis(450), "{elapsed:?}");
}

#[test]
fn waits_pass_in_wall_clock_time_while_a_socket_is_open() {
    let dir = scratch_in("sockets_system", "paced");
    let listener = TcpListener::bind("127.0.0.1:0").expect("bind");
    let port = listener.local_addr().expect("addr").port();
    // A state server of sorts, one task alone: 20 messages 50 ms apart. With the
    // socket open the 19 waits between them take 0.95 s of wall-clock time, as on a
    // controller, instead of passing at once.
    let module = "MODULE Sender\n  VAR socketdev s;\n  PROC main()\n    SocketCreate s;\n    \
                  SocketConnect s, \"127.0.0.1\", PORT;\n    FOR i FROM 1 TO 20 DO\n      \
                  SocketSend s \\Str:=\"m\";\n      IF i < 20 WaitTime 0.05;\n    ENDFOR\n    \
                  SocketClose s;\n  ENDPROC\nENDMODULE\n"
        .replace("PORT", &port.to_string());
    std::fs::write(dir.join("Sender.mod"), module).expect("module");
    let child = spawn_in(&dir, &["run", "--quiet", "Sender.mod"]);
    let (mut peer, _) = listener.accept().expect("accept");
    peer.set_read_timeout(Some(Duration::from_secs(10))).expect("timeout");
    let mut first = [0u8; 1];
    std::io::Read::read_exact(&mut peer, &mut first).expect("first message");
    let started = Instant::now();
    let mut rest = Vec::new();
    std::io::Read::read_to_end(&mut peer, &mut rest).expect("the other messages");
    let elapsed = started.elapsed();
    let out = child.wait_with_output().expect("rapid ends");
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(rest.len(), 19);
    assert!(elapsed >= Duration::from_millis(940), "{elapsed:?}");
}

#[test]
fn traps_run_while_a_task_running_alone_waits_on_a_socket() {
    let dir = scratch_in("sockets_system", "trap_during_receive");
    let listener = TcpListener::bind("127.0.0.1:0").expect("bind");
    let port = listener.local_addr().expect("addr").port();
    // A timer trap every 0.1 s (three times) while the one task waits for data: the
    // ticks come first, and only then does the peer send what the task waits for.
    let module = "MODULE Client\n  VAR socketdev s;\n  VAR string got;\n  VAR intnum tick;\n  VAR num ticks := 0;\n  \
                  PROC main()\n    CONNECT tick WITH on_tick;\n    ITimer 0.1, tick;\n    SocketCreate s;\n    \
                  SocketConnect s, \"127.0.0.1\", PORT;\n    SocketReceive s \\Str:=got \\Time:=10;\n    \
                  TPWrite \"got \" + got;\n    SocketClose s;\n  ENDPROC\n  TRAP on_tick\n    ticks := ticks + 1;\n    \
                  TPWrite \"tick\";\n    IF ticks = 3 IDelete tick;\n  ENDTRAP\nENDMODULE\n"
        .replace("PORT", &port.to_string());
    std::fs::write(dir.join("Client.mod"), module).expect("module");
    let child = spawn_in(&dir, &["run", "--quiet", "Client.mod"]);
    hello_after_three_ticks(&listener, child);
}

#[test]
fn tasks_computing_beside_an_open_socket_keep_wall_clock_time() {
    let dir = scratch_in("sockets_system", "busy");
    let listener = TcpListener::bind("127.0.0.1:0").expect("bind");
    let port = listener.local_addr().expect("addr").port();
    // T_ROB1 holds a connection open; T_B computes without ever waiting. The controller's
    // clock is the wall clock then, computing too: --max-time 1 ends the run after a
    // second of wall-clock time (not after a million statements at the nominal 1 µs).
    let client = "MODULE Client\n  VAR socketdev s;\n  VAR string got;\n  PROC main()\n    SocketCreate s;\n    \
                  SocketConnect s, \"127.0.0.1\", PORT;\n    SocketReceive s \\Str:=got \\Time:=60;\n  ENDPROC\nENDMODULE\n"
        .replace("PORT", &port.to_string());
    let busy = "MODULE Busy\n  VAR num n := 0;\n  PROC main()\n    WHILE TRUE DO\n      n := n + 1;\n    ENDWHILE\n  \
                ENDPROC\nENDMODULE\n";
    let tasks = [
        TaskDef { name: "T_ROB1", attrs: "-Type \"NORMAL\"", module: &client },
        TaskDef { name: "T_B", attrs: "-Type \"NORMAL\"", module: busy },
    ];
    system(&dir, &tasks, "");
    let started = Instant::now();
    let child = spawn_in(&dir, &["run", "--max-time", "1", "sys"]);
    let (_peer, _) = listener.accept().expect("accept");
    let out = child.wait_with_output().expect("rapid ends");
    let elapsed = started.elapsed();
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    assert!(text(&out.stderr).contains("stopped at 1 s of controller time (--max-time)"), "{}", text(&out.stderr));
    assert!(elapsed >= Duration::from_millis(950), "{elapsed:?}");
}
