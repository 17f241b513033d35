//! Ctrl-C during `rapid run`: the run ends as a bound ends it (the trace, the report
//! and the cycle time are still written) instead of the process dying with nothing.
//! A server waiting for its peers (a socket program, `--cycles 0`) is often ended so.

use std::sync::atomic::{AtomicBool, Ordering};

static REQUESTED: AtomicBool = AtomicBool::new(false);

/// Catches Ctrl-C (SIGINT) for the rest of the process; a second one while the run
/// winds down still ends the process at once.
pub(crate) fn install() {
    let _ = ctrlc::set_handler(|| {
        if REQUESTED.swap(true, Ordering::SeqCst) {
            std::process::exit(130);
        }
    });
}

/// Whether the user asked the run to end.
pub(crate) fn requested() -> bool {
    REQUESTED.load(Ordering::Relaxed)
}
