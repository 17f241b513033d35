//! The adapter's loop: requests are read on a thread of their own (a read blocks),
//! so that the program runs between them in bounded slices and a `pause` reaches it
//! at once; responses and events are written in the order the adapter made them.

use std::io::{self, BufReader, Read, Write};
use std::sync::mpsc;
use std::time::Duration;

use serde_json::Value;

use crate::adapter::Adapter;
use crate::{wire, Launcher};

/// How long the loop waits for a request while the program stands still.
const IDLE_WAIT: Duration = Duration::from_millis(200);

/// Serves one debug session: reads requests from `input` and writes responses and
/// events to `output` until the client disconnects or the input ends.
pub fn serve(input: impl Read + Send + 'static, output: &mut dyn Write, launcher: &dyn Launcher) -> io::Result<()> {
    let (sender, requests) = mpsc::channel::<io::Result<Value>>();
    std::thread::spawn(move || {
        let mut input = BufReader::new(input);
        loop {
            let message = wire::read_message(&mut input);
            let end = !matches!(message, Ok(Some(_)));
            let sent = match message {
                Ok(Some(message)) => sender.send(Ok(message)),
                Ok(None) => break,
                Err(e) => sender.send(Err(e)),
            };
            if end || sent.is_err() {
                break;
            }
        }
    });
    let mut adapter = Adapter::new(launcher);
    loop {
        let idle = adapter.take_idle();
        let next = if adapter.is_running() && idle.is_none() {
            match requests.try_recv() {
                Ok(message) => Some(message),
                Err(mpsc::TryRecvError::Empty) => None,
                Err(mpsc::TryRecvError::Disconnected) => break,
            }
        } else {
            // A paced clock's wait, or a program standing still: a request may come.
            match requests.recv_timeout(idle.unwrap_or(IDLE_WAIT).min(IDLE_WAIT)) {
                Ok(message) => Some(message),
                Err(mpsc::RecvTimeoutError::Timeout) => None,
                Err(mpsc::RecvTimeoutError::Disconnected) => break,
            }
        };
        match next {
            Some(message) => adapter.handle(&message?),
            None if adapter.is_running() => adapter.advance(),
            None => {}
        }
        for message in adapter.take_outgoing() {
            wire::write_message(output, &message)?;
        }
        if adapter.is_done() {
            break;
        }
    }
    Ok(())
}
