//! `rapid serve --controller-ip`: the controller's own address, as `rapid run` takes
//! it and a manifest's `[system] controller_ip` gives it, reaches the served program
//! (a SocketBind to it binds the loopback), and the flag wins over the manifest.
//! 10.11.12.13 and 192.0.2.44 (TEST-NET-1) are no addresses of the host: a bind to
//! one that is not the controller's fails.

use std::io::{Read, Write};
use std::net::{Ipv4Addr, TcpStream};
use std::time::{Duration, Instant};

use crate::fixture::scratch_in;
use crate::serve::{interrupt, start_server_with, wait_bounded};
use crate::serve_faults::{login, read_field, request};
use crate::sockets_controller_ip::{echo_server, free_port};

const START: &str = "regain=continue&execmode=continue&cycle=once&condition=none&stopatbp=disabled&alltaskbytsp=false";

/// A project whose manifest gives the controller address 192.0.2.44 and whose
/// program serves one TCP client on `address`:`port`.
fn project(name: &str, address: &str, port: u16) -> crate::fixture::Scratch {
    let dir = scratch_in("serve_controller_ip", name);
    let manifest = "[system]\ncontroller_ip = \"192.0.2.44\"\n\n[[task]]\nname = \"T_ROB1\"\nmodules = [\"srv.mod\"]\n";
    std::fs::write(dir.join("rapid.toml"), manifest).expect("manifest");
    std::fs::write(dir.join("srv.mod"), echo_server(address, port)).expect("module");
    dir
}

/// Sends `hello` to the program's server on the loopback (it may take a moment to
/// listen); Err when nothing listened within `limit`.
fn greet(port: u16, limit: Duration) -> Result<(), std::io::Error> {
    let started = Instant::now();
    let mut stream = loop {
        match TcpStream::connect((Ipv4Addr::LOCALHOST, port)) {
            Ok(stream) => break stream,
            Err(err) if started.elapsed() > limit => return Err(err),
            Err(_) => std::thread::sleep(Duration::from_millis(20)),
        }
    };
    stream.write_all(b"hello")?;
    stream.set_read_timeout(Some(Duration::from_secs(10)))?;
    let mut rest = Vec::new();
    let _ = stream.read_to_end(&mut rest);
    Ok(())
}

#[test]
fn the_flag_gives_the_served_controller_its_address_over_the_manifests() {
    // The flag's address is the controller's: the program's server on it is reached
    // on the loopback, and what it got goes to the pendant (stdout).
    let port = free_port();
    let dir = project("flag", "10.11.12.13", port);
    let (mut child, url, stdout) = start_server_with(&dir, &["--controller-ip", "10.11.12.13"]);
    let addr = url.trim_start_matches("http://").to_owned();
    let cookie = login(&addr);
    assert_eq!(request(&addr, "POST", "/rw/rapid/execution?action=start", &cookie, START).status, 204);
    greet(port, Duration::from_secs(10)).expect("the program's server listens on the loopback");
    let deadline = Instant::now() + Duration::from_secs(10);
    while read_field(&addr, &cookie, "/rw/rapid/execution", "ctrlexecstate") != "stopped" {
        assert!(Instant::now() < deadline, "the program never ended");
        std::thread::sleep(Duration::from_millis(50));
    }
    interrupt(&child);
    assert_eq!(wait_bounded(&mut child, Duration::from_secs(20)).and_then(|s| s.code()), Some(0));
    assert_eq!(stdout.join().unwrap_or_default(), "got hello\n");

    // The manifest's address is then no controller's: the program's bind to it is the
    // host's, which has no such address, and the task stops with the socket error.
    let port = free_port();
    let dir = project("manifest", "192.0.2.44", port);
    let (mut child, url, stdout) = start_server_with(&dir, &["--controller-ip", "10.11.12.13"]);
    let addr = url.trim_start_matches("http://").to_owned();
    let cookie = login(&addr);
    assert_eq!(request(&addr, "POST", "/rw/rapid/execution?action=start", &cookie, START).status, 204);
    let deadline = Instant::now() + Duration::from_secs(10);
    while read_field(&addr, &cookie, "/rw/rapid/execution", "ctrlexecstate") != "stopped" {
        assert!(Instant::now() < deadline, "the program never stopped");
        std::thread::sleep(Duration::from_millis(50));
    }
    assert!(greet(port, Duration::from_millis(200)).is_err(), "nothing listens on the loopback");
    interrupt(&child);
    assert_eq!(wait_bounded(&mut child, Duration::from_secs(20)).and_then(|s| s.code()), Some(0));
    assert_eq!(stdout.join().unwrap_or_default(), "", "the program never got a client");
}
