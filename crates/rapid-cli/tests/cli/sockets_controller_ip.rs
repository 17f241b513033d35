//! SocketBind to the controller's own addresses: the service port's 192.168.125.1 and
//! the address `--controller-ip` gives bind the loopback, as a virtual controller maps
//! its addresses, and the run says so once per address on stderr.

use std::fs;
use std::io::{Read, Write};
use std::net::{Ipv4Addr, TcpListener, TcpStream};
use std::process::{Child, Command, Stdio};
use std::thread;
use std::time::{Duration, Instant};

use crate::fixture::scratch_in;

/// How long the test waits for the RAPID side before it fails.
const PEER_TIMEOUT: Duration = Duration::from_secs(10);

/// A port free on the loopback now (the OS chose it; the program binds it next).
pub(crate) fn free_port() -> u16 {
    let listener = TcpListener::bind((Ipv4Addr::LOCALHOST, 0)).expect("bind a free port");
    listener.local_addr().expect("its address").port()
}

/// A module `srv` that binds a TCP server to `address`:`port`, takes one client and
/// writes `got ` and what the client sent.
pub(crate) fn echo_server(address: &str, port: u16) -> String {
    format!(
        "MODULE srv
    PROC main()
        VAR socketdev server;
        VAR socketdev client;
        VAR string text;
        SocketCreate server;
        SocketBind server, \"{address}\", {port};
        SocketListen server;
        SocketAccept server, client \\Time:=10;
        SocketReceive client \\Str:=text \\Time:=10;
        TPWrite \"got \" + text;
        SocketClose client;
        SocketClose server;
    ENDPROC
ENDMODULE
"
    )
}

/// Greets the [`echo_server`] that `child` (a `rapid run` with piped output) binds to
/// the controller address `address`, on the loopback at `port`; the run must end well,
/// print `got hello`, and say once on stderr that `address` was bound on 127.0.0.1.
pub(crate) fn greet_on_the_loopback(child: Child, port: u16, address: &str) {
    let started = Instant::now();
    let mut stream = loop {
        match TcpStream::connect((Ipv4Addr::LOCALHOST, port)) {
            Ok(stream) => break stream,
            Err(err) if started.elapsed() > PEER_TIMEOUT => panic!("the program never listened: {err}"),
            Err(_) => thread::sleep(Duration::from_millis(20)),
        }
    };
    stream.write_all(b"hello").expect("send");
    let mut rest = Vec::new();
    stream.set_read_timeout(Some(PEER_TIMEOUT)).expect("timeout");
    let _ = stream.read_to_end(&mut rest);
    let out = child.wait_with_output().expect("rapid ends");
    let (stdout, stderr) = (String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    assert_eq!(out.status.code(), Some(0), "stdout:\n{stdout}\nstderr:\n{stderr}");
    assert_eq!(stdout, "got hello\n");
    let notes: Vec<&str> = stderr.lines().filter(|l| l.starts_with("note: SocketBind")).collect();
    assert_eq!(notes.len(), 1, "{stderr}");
    assert!(notes[0].contains(address) && notes[0].contains("127.0.0.1"), "{}", notes[0]);
}

#[test]
fn a_server_on_the_service_port_address_is_reached_on_the_loopback() {
    let port = free_port();
    let dir = scratch_in("sockets_controller_ip", "service");
    let path = dir.join("srv.mod");
    fs::write(&path, echo_server("192.168.125.1", port)).expect("write module");
    let child = Command::new(env!("CARGO_BIN_EXE_rapid"))
        .arg("run")
        .arg(&path)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("start rapid");
    greet_on_the_loopback(child, port, "192.168.125.1");
}

#[test]
fn the_controller_ip_binds_the_loopback_and_is_told_once() {
    let dir = scratch_in("sockets_controller_ip", "flag");
    let path = dir.join("udp.mod");
    let program = "MODULE udp
    PROC main()
        VAR socketdev a;
        VAR socketdev b;
        SocketCreate a \\UDP;
        SocketCreate b \\UDP;
        SocketBind a, \"10.11.12.13\", 0;
        SocketBind b, \"10.11.12.13\", 0;
        TPWrite \"bound \" \\Bool:=SocketGetStatus(a) = SOCKET_BOUND AND SocketGetStatus(b) = SOCKET_BOUND;
        SocketClose a;
        SocketClose b;
    ENDPROC
ENDMODULE
";
    fs::write(&path, program).expect("write module");
    let run = |extra: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_rapid")).arg("run").args(extra).arg(&path).output().expect("run rapid")
    };
    let out = run(&["--controller-ip", "10.11.12.13"]);
    let (stdout, stderr) = (String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    assert_eq!(out.status.code(), Some(0), "stdout:\n{stdout}\nstderr:\n{stderr}");
    assert_eq!(stdout, "bound TRUE\n");
    let notes: Vec<&str> = stderr.lines().filter(|l| l.starts_with("note: SocketBind")).collect();
    assert_eq!(notes.len(), 1, "{stderr}");
    assert!(notes[0].contains("10.11.12.13"), "{}", notes[0]);
    // Without the flag the address is no controller's: the bind is the OS's, which
    // has no such address, and the program stops with a socket error.
    let out = run(&[]);
    assert_ne!(out.status.code(), Some(0));
    assert!(!String::from_utf8_lossy(&out.stderr).contains("note: SocketBind"));
}
