//! Fuzz target `stimulus`: arbitrary bytes as a `--stimulus` file through its parser
//! (`rapid_controller::assembly::stimulus::parse`) against a small I/O configuration
//! (a device, digital, group and analog inputs, outputs of both access levels). Nothing
//! may panic. A stimulus read is what the controller can apply: orders and answers in
//! time order at finite times of 0 or later, each order on a signal or device of the
//! configuration with a value the signal takes, reactions watching a signal and
//! setting an input or an output every client may write. A refusal names the file and
//! a line of it.
#![no_main]

use std::sync::OnceLock;

use libfuzzer_sys::fuzz_target;
use rapid_controller::assembly::stimulus;
use rapid_io::{Access, IoSystem, SignalKind, DEVICE_EVENT};

/// The configuration the stimulus is read against, as a backup's EIO.cfg gives it.
const EIO: &str = "EIO:CFG_1.0:6:1::
#
EIO_DEVICE:
      -Name \"dGrip\" -Network \"Local\"
#
EIO_SIGNAL:
      -Name \"diPart\" -SignalType \"DI\" -Device \"dGrip\" -DeviceMap \"0\"
      -Name \"doGrip\" -SignalType \"DO\" -Device \"dGrip\" -DeviceMap \"1\"
      -Name \"giRecipe\" -SignalType \"GI\" -Device \"dGrip\" -DeviceMap \"2-5\"
      -Name \"aiPressure\" -SignalType \"AI\" -MaxLog 10 -MinLog 0
      -Name \"aoSpeed\" -SignalType \"AO\" -Access \"All\" -MaxLog 100 -MinLog 0
";

fn io() -> &'static IoSystem {
    static IO: OnceLock<IoSystem> = OnceLock::new();
    IO.get_or_init(|| {
        let file = rapid_config::parse(EIO);
        assert!(file.errors.is_empty(), "the target's EIO.cfg: {:?}", file.errors);
        let eio = rapid_config::eio::read(&file);
        rapid_controller::boot::io_config::io_system(&eio).expect("the target's I/O configuration")
    })
}

/// Whether `value` is one signal `id` of `io` takes from a stimulus.
fn settable(io: &IoSystem, id: u32, value: f64) -> bool {
    let Some(def) = io.def(id) else { return false };
    let writable = def.kind.is_input() || def.access == Access::All;
    let digital_ok = def.kind != SignalKind::DI || value == 0.0 || value == 1.0;
    writable && digital_ok && value.is_finite()
}

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let io = io();
    let (orders, reactions, answers) = match stimulus::parse("s.stim", text, io) {
        Ok(read) => read,
        Err(message) => {
            let line = message.strip_prefix("s.stim:").and_then(|rest| rest.split(':').next());
            let line: usize = line.and_then(|n| n.parse().ok()).unwrap_or_else(|| panic!("no line in `{message}`"));
            assert!(line >= 1 && line <= text.lines().count(), "line {line} of `{message}` is not in the file");
            return;
        }
    };
    let in_time = |t: f64| t.is_finite() && t >= 0.0;
    for pair in orders.windows(2) {
        assert!(pair[0].0 <= pair[1].0, "orders out of time order: {pair:?}");
    }
    for &(time, id, value) in &orders {
        assert!(in_time(time), "an order at {time}");
        if id & DEVICE_EVENT != 0 {
            assert!(value == 0.0 || value == 1.0, "a device order of {value}");
        } else {
            assert!(settable(io, id, value), "order ({time}, {id}, {value})");
        }
    }
    for reaction in &reactions {
        assert!(io.def(reaction.watch).is_some(), "a reaction watching {}", reaction.watch);
        assert!(reaction.value.is_finite(), "a reaction waiting for {}", reaction.value);
        assert!(in_time(reaction.delay), "a reaction delayed {}", reaction.delay);
        assert!(settable(io, reaction.target, reaction.set), "reaction {reaction:?}");
    }
    for pair in answers.windows(2) {
        assert!(pair[0].0 <= pair[1].0, "answers out of time order: {pair:?}");
    }
    for (time, answer) in &answers {
        assert!(in_time(*time) && !answer.is_empty(), "answer {answer:?} at {time}");
    }
});
