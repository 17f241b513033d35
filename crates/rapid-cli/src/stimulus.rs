//! `rapid run --stimulus FILE`: changes of inputs from outside, at given controller
//! times, so programs that wait on inputs run unattended and deterministically.
//!
//! One order per line; blank lines and lines starting with `#` are ignored:
//!
//! ```text
//! at 1.5 set diPartAtPick 1      # at 1.5 s of controller time, the input becomes 1
//! at 4 s set giRecipe 12         # an `s` after the time is allowed
//! ```
//!
//! Signals must be inputs (DI, GI, AI) of the I/O configuration; a digital input takes
//! 0 or 1. Other forms (reacting to outputs, pendant answers) are not supported yet and
//! are reported with their line.

use rapid_io::{IoSystem, SignalKind};

/// The stimulus of `text` (from file `path`) as (time, signal id, value), in time order.
pub(crate) fn parse(path: &str, text: &str, io: &IoSystem) -> Result<Vec<(f64, u32, f64)>, String> {
    let mut orders = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let order = parse_line(line, io).map_err(|message| format!("{path}:{}: {message}", n + 1))?;
        orders.push(order);
    }
    // Stable: orders at the same time apply in the order written.
    orders.sort_by(|a, b| a.0.total_cmp(&b.0));
    Ok(orders)
}

fn parse_line(line: &str, io: &IoSystem) -> Result<(f64, u32, f64), String> {
    let words: Vec<&str> = line.split_whitespace().collect();
    let words: Vec<&str> = match words.as_slice() {
        ["at", time, "s", rest @ ..] => [&["at", time][..], rest].concat(),
        _ => words,
    };
    let ["at", time, "set", name, value] = words.as_slice() else {
        return Err(format!("expected `at SECONDS set SIGNAL VALUE`, found `{line}`"));
    };
    let time: f64 = time.parse().map_err(|_| format!("`{time}` is not a time in seconds"))?;
    if !time.is_finite() || time < 0.0 {
        return Err(format!("the time {time} is not 0 or later"));
    }
    let id = io.id(name).ok_or_else(|| format!("no signal `{name}` in the I/O configuration"))?;
    let kind = io.def(id).map(|d| d.kind).ok_or_else(|| format!("no signal `{name}`"))?;
    if !kind.is_input() {
        return Err(format!("`{name}` is an output; a stimulus sets inputs only"));
    }
    let value: f64 = value.parse().map_err(|_| format!("`{value}` is not a number"))?;
    if kind == SignalKind::DI && value != 0.0 && value != 1.0 {
        return Err(format!("digital input `{name}` takes 0 or 1, not {value}"));
    }
    Ok((time, id, value))
}

#[cfg(test)]
mod tests {
    use rapid_io::{IoSystem, SignalDef, SignalKind};

    fn io() -> IoSystem {
        let defs = vec![SignalDef::new("di1", SignalKind::DI), SignalDef::new("do1", SignalKind::DO)];
        IoSystem::new(defs, Vec::new()).expect("a valid configuration")
    }

    #[test]
    fn orders_are_read_in_time_order_with_comments_and_units() {
        let text = "# start\nat 2 set di1 0\n\nat 1.5 s set DI1 1   # case ignored\n";
        assert_eq!(super::parse("s.txt", text, &io()), Ok(vec![(1.5, 0, 1.0), (2.0, 0, 0.0)]));
    }

    #[test]
    fn bad_lines_are_reported_with_their_line() {
        let io = io();
        let cases = [
            ("at x set di1 1", "s.txt:1: `x` is not a time in seconds"),
            ("at 1 set nosuch 1", "s.txt:1: no signal `nosuch` in the I/O configuration"),
            ("at 1 set do1 1", "s.txt:1: `do1` is an output; a stimulus sets inputs only"),
            ("at 1 set di1 2", "s.txt:1: digital input `di1` takes 0 or 1, not 2"),
            (
                "when do1 = 1 set di1 1",
                "s.txt:1: expected `at SECONDS set SIGNAL VALUE`, found `when do1 = 1 set di1 1`",
            ),
        ];
        for (text, message) in cases {
            assert_eq!(super::parse("s.txt", text, &io), Err(message.to_string()));
        }
    }
}
