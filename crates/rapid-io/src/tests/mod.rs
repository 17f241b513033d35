//! Unit tests of the I/O system. Every expectation is worked out by hand from the manual
//! (§1.9, §2.10) and the rules in the crate docs, never copied from a run.

mod config;
mod cross;
mod orders;
mod units;
mod values;

use crate::{Cause, Change, CrossConnection, CrossOp, IoSystem, SignalDef, SignalId, SignalKind};

fn sig(name: &str, kind: SignalKind) -> SignalDef {
    SignalDef::new(name, kind)
}

fn group(name: &str, kind: SignalKind, bits: u8) -> SignalDef {
    SignalDef { group_bits: bits, ..SignalDef::new(name, kind) }
}

fn cross(result: &str, terms: &[(&str, bool)], ops: &[CrossOp]) -> CrossConnection {
    CrossConnection {
        result: result.to_string(),
        terms: terms.iter().map(|(n, inv)| (n.to_string(), *inv)).collect(),
        ops: ops.to_vec(),
    }
}

fn system(defs: Vec<SignalDef>, crosses: Vec<CrossConnection>) -> IoSystem {
    match IoSystem::new(defs, crosses) {
        Ok(io) => io,
        Err(e) => panic!("configuration refused: {e}"),
    }
}

fn id(io: &IoSystem, name: &str) -> SignalId {
    match io.id(name) {
        Some(id) => id,
        None => panic!("no signal {name}"),
    }
}

fn val(io: &IoSystem, name: &str) -> f64 {
    io.value_by_name(name).unwrap_or(f64::NAN)
}

/// The log as (time, name, old, new, cause) tuples, easy to compare.
fn log(io: &IoSystem) -> Vec<(f64, String, f64, f64, Cause)> {
    io.changes().iter().map(row).collect()
}

fn row(c: &Change) -> (f64, String, f64, f64, Cause) {
    (c.time, c.signal.to_string(), c.old, c.new, c.cause)
}

fn entry(time: f64, name: &str, old: f64, new: f64, cause: Cause) -> (f64, String, f64, f64, Cause) {
    (time, name.to_string(), old, new, cause)
}
