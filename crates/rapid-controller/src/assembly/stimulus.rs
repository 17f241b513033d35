//! `rapid run --stimulus FILE`: changes of inputs from outside, at given controller
//! times, so programs that wait on inputs run unattended and deterministically.
//!
//! One order per line; blank lines and lines starting with `#` are ignored:
//!
//! ```text
//! at 1.5 set diPartAtPick 1      # at 1.5 s of controller time, the input becomes 1
//! at 4 s set giRecipe 12         # an `s` after the time is allowed
//! when doGrip = 1 after 0.2 s set diGripClosed 1   # every time doGrip becomes 1
//! when doGrip = 0 set diGripClosed 0               # at once
//! at 4 s answer TPReadNum 7     # the operator answers the next pendant dialog at 4 s
//! at 6 disconnect dToolIO        # the I/O device stops answering (a tool is uncoupled)
//! at 9 connect dToolIO           # and answers again
//! ```
//!
//! `set` names inputs (DI, GI, AI) of the I/O configuration; a digital input takes 0
//! or 1; `when` watches any signal. `answer [DIALOG] TEXT` is the operator's answer to
//! the next pendant dialog (TPReadNum, TPReadFK, UINumEntry, …; the dialog's name is
//! optional and only checked to be one): a dialog shown earlier waits for it.
//! `connect`/`disconnect` name a device of the I/O configuration: while it does not
//! answer, its signals cannot be reached (ERR_NORUNUNIT) and IOEnable waits for it (at
//! most its MaxTime: ERR_IOENABLE). Any other line is reported with its line number.

use rapid_io::{IoSystem, SignalKind};
use rapid_signals::Reaction;

/// A stimulus: timed input changes (time, signal id, value) in time order, reactions,
/// and timed operator answers (time, text) in time order.
pub type Stimulus = (Vec<(f64, u32, f64)>, Vec<Reaction>, Vec<(f64, String)>);

/// The pendant dialogs an `answer` line may name.
const DIALOGS: &[&str] = &[
    "TPReadNum",
    "TPReadDnum",
    "TPReadFK",
    "UINumEntry",
    "UIDnumEntry",
    "UIAlphaEntry",
    "UIMsgBox",
    "UIMessageBox",
    "UIListView",
    "UINumTune",
    "UIDnumTune",
];

/// The stimulus of `text` (from file `path`).
pub fn parse(path: &str, text: &str, io: &IoSystem) -> Result<Stimulus, String> {
    let (mut orders, mut reactions, mut answers) = (Vec::new(), Vec::new(), Vec::new());
    for (n, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let at_line = |message: String| format!("{path}:{}: {message}", n + 1);
        if line.starts_with("when ") {
            reactions.push(parse_reaction(line, io).map_err(at_line)?);
        } else if line.split_whitespace().any(|w| w == "answer") {
            answers.push(parse_answer(line).map_err(at_line)?);
        } else {
            orders.push(parse_order(line, io).map_err(at_line)?);
        }
    }
    // Stable: orders at the same time apply in the order written.
    orders.sort_by(|a, b| a.0.total_cmp(&b.0));
    answers.sort_by(|a, b| a.0.total_cmp(&b.0));
    Ok((orders, reactions, answers))
}

/// `at SECONDS [s] answer [DIALOG] TEXT`.
fn parse_answer(line: &str) -> Result<(f64, String), String> {
    let words = without_units(line);
    let ["at", time, "answer", rest @ ..] = words.as_slice() else {
        return Err(format!("expected `at SECONDS answer [DIALOG] TEXT`, found `{line}`"));
    };
    let time = seconds(time)?;
    let rest = match rest.first() {
        Some(first) if DIALOGS.iter().any(|d| d.eq_ignore_ascii_case(first)) => &rest[1..],
        _ => rest,
    };
    if rest.is_empty() {
        return Err(format!("an answer needs a text, found `{line}`"));
    }
    Ok((time, rest.join(" ")))
}

/// `at SECONDS [s] set INPUT VALUE`.
fn parse_order(line: &str, io: &IoSystem) -> Result<(f64, u32, f64), String> {
    let words = without_units(line);
    let (time, id, value) = match words.as_slice() {
        ["at", time, "set", name, value] => {
            let (id, value) = input(io, name, value)?;
            (time, id, value)
        }
        ["at", time, verb @ ("connect" | "disconnect"), device] => {
            let index = io.units().index_of(device).ok_or_else(|| format!("no I/O device `{device}` is configured"))?;
            let id = u32::try_from(index).ok().filter(|&i| i < rapid_io::DEVICE_EVENT).ok_or("too many devices")?;
            (time, rapid_io::DEVICE_EVENT | id, if *verb == "connect" { 1.0 } else { 0.0 })
        }
        _ => {
            return Err(format!(
                "expected `at SECONDS set SIGNAL VALUE`, `at SECONDS connect|disconnect DEVICE` or `when …`, \
                 found `{line}`"
            ))
        }
    };
    Ok((seconds(time)?, id, value))
}

/// `when SIGNAL = VALUE [after SECONDS [s]] set INPUT VALUE`.
fn parse_reaction(line: &str, io: &IoSystem) -> Result<Reaction, String> {
    let words = without_units(line);
    let (watch, value, delay, target, set) = match words.as_slice() {
        ["when", watch, "=", value, "after", delay, "set", target, set] => (watch, value, Some(delay), target, set),
        ["when", watch, "=", value, "set", target, set] => (watch, value, None, target, set),
        _ => return Err(format!("expected `when SIGNAL = VALUE [after SECONDS] set SIGNAL VALUE`, found `{line}`")),
    };
    let watch_id = io.id(watch).ok_or_else(|| format!("no signal `{watch}` in the I/O configuration"))?;
    let value = number(value)?;
    let delay = delay.map_or(Ok(0.0), |d| seconds(d))?;
    let (target, set) = input(io, target, set)?;
    Ok(Reaction { watch: watch_id, value, delay, target, set })
}

/// The words of a line, with the unit `s` after a time dropped.
fn without_units(line: &str) -> Vec<&str> {
    let words: Vec<&str> = line.split_whitespace().collect();
    let mut out = Vec::with_capacity(words.len());
    for (i, word) in words.iter().enumerate() {
        // Two words back: `at`/`after`, then the time (a line may start with a number).
        let after_time =
            i >= 2 && words[i - 1].parse::<f64>().is_ok() && matches!(words.get(i - 2), Some(&"at" | &"after"));
        if *word == "s" && after_time {
            continue;
        }
        out.push(*word);
    }
    out
}

fn seconds(text: &str) -> Result<f64, String> {
    let time: f64 = text.parse().map_err(|_| format!("`{text}` is not a time in seconds"))?;
    if !time.is_finite() || time < 0.0 {
        return Err(format!("the time {time} is not 0 or later"));
    }
    Ok(time)
}

/// A finite number. Rust reads `inf` and `NaN` as numbers too; no signal takes them,
/// and a reaction waiting for NaN would never fire, so they are refused as text that is
/// not a number (fuzz finding, `stimulus` target).
fn number(text: &str) -> Result<f64, String> {
    text.parse::<f64>().ok().filter(|v| v.is_finite()).ok_or_else(|| format!("`{text}` is not a number"))
}

/// An input of the configuration, or an output every client may write (`-Access
/// "All"`: a remote client such as an RWS application sets it), and a value it can take.
fn input(io: &IoSystem, name: &str, value: &str) -> Result<(u32, f64), String> {
    let id = io.id(name).ok_or_else(|| format!("no signal `{name}` in the I/O configuration"))?;
    let def = io.def(id).ok_or_else(|| format!("no signal `{name}`"))?;
    let kind = def.kind;
    if !kind.is_input() && def.access != rapid_io::Access::All {
        return Err(format!(
            "`{name}` is an output; a stimulus sets inputs, and outputs every client may write (-Access \"All\")"
        ));
    }
    let value = number(value)?;
    if kind == SignalKind::DI && value != 0.0 && value != 1.0 {
        return Err(format!("digital input `{name}` takes 0 or 1, not {value}"));
    }
    Ok((id, value))
}

#[cfg(test)]
mod tests {
    use rapid_io::{IoSystem, SignalDef, SignalKind};

    fn io() -> IoSystem {
        let open = SignalDef { access: rapid_io::Access::All, ..SignalDef::new("doOpen", SignalKind::AO) };
        let defs = vec![SignalDef::new("di1", SignalKind::DI), SignalDef::new("do1", SignalKind::DO), open];
        IoSystem::new(defs, Vec::new()).expect("a valid configuration")
    }

    #[test]
    fn an_output_every_client_may_write_is_set_as_a_remote_client_sets_it() {
        // doOpen (-Access "All") as an RWS client writes it; do1 (default access) not.
        assert_eq!(
            super::parse("s.txt", "at 1 set doOpen 2.5\n", &io()),
            Ok((vec![(1.0, 2, 2.5)], Vec::new(), Vec::new()))
        );
    }

    #[test]
    fn orders_are_read_in_time_order_with_comments_and_units() {
        let text = "# start\nat 2 set di1 0\n\nat 1.5 s set DI1 1   # case ignored\n";
        assert_eq!(
            super::parse("s.txt", text, &io()),
            Ok((vec![(1.5, 0, 1.0), (2.0, 0, 0.0)], Vec::new(), Vec::new()))
        );
    }

    #[test]
    fn reactions_watch_any_signal_and_set_an_input() {
        let text = "when do1 = 1 after 0.2 s set di1 1\nwhen do1 = 0 set di1 0\n";
        let reaction = |value, delay, set| rapid_signals::Reaction { watch: 1, value, delay, target: 0, set };
        let expected = vec![reaction(1.0, 0.2, 1.0), reaction(0.0, 0.0, 0.0)];
        assert_eq!(super::parse("s.txt", text, &io()), Ok((Vec::new(), expected, Vec::new())));
    }

    #[test]
    fn bad_lines_are_reported_with_their_line() {
        let io = io();
        let cases = [
            ("at x set di1 1", "s.txt:1: `x` is not a time in seconds"),
            ("at 1 set nosuch 1", "s.txt:1: no signal `nosuch` in the I/O configuration"),
            ("at 1 set do1 1", "s.txt:1: `do1` is an output; a stimulus sets inputs, and outputs every client may write (-Access \"All\")"),
            ("at 1 set di1 2", "s.txt:1: digital input `di1` takes 0 or 1, not 2"),
            ("answer 7 at 1", "s.txt:1: expected `at SECONDS answer [DIALOG] TEXT`, found `answer 7 at 1`"),
            (
                "at 1 jump di1 1",
                "s.txt:1: expected `at SECONDS set SIGNAL VALUE`, `at SECONDS connect|disconnect DEVICE` or \
                 `when …`, found `at 1 jump di1 1`",
            ),
            ("at 1 connect nodevice", "s.txt:1: no I/O device `nodevice` is configured"),
            ("when do1 = 1 set do1 1", "s.txt:1: `do1` is an output; a stimulus sets inputs, and outputs every client may write (-Access \"All\")"),
            ("when di1 = 1 after -1 set di1 0", "s.txt:1: the time -1 is not 0 or later"),
        ];
        for (text, message) in cases {
            assert_eq!(super::parse("s.txt", text, &io), Err(message.to_string()));
        }
    }

    #[test]
    fn a_line_starting_with_a_time_and_its_unit_is_refused_not_a_panic() {
        // Fuzz finding (`stimulus` target): a number then `s` as the first two words
        // looked two words back from the second, before the line's start.
        let expected = "s.txt:1: expected `at SECONDS set SIGNAL VALUE`, `at SECONDS connect|disconnect DEVICE` \
                        or `when …`, found `3 s set di1 1`";
        assert_eq!(super::parse("s.txt", "3 s set di1 1\n", &io()), Err(expected.to_string()));
    }

    #[test]
    fn values_that_are_no_finite_number_are_refused() {
        // Fuzz finding (`stimulus` target): `inf` and `NaN` parse as f64.
        let io = io();
        let cases = [
            ("at 1 set doOpen inf", "s.txt:1: `inf` is not a number"),
            ("at 1 set doOpen -infinity", "s.txt:1: `-infinity` is not a number"),
            ("when do1 = NaN set di1 1", "s.txt:1: `NaN` is not a number"),
            ("when do1 = 1 set doOpen nan", "s.txt:1: `nan` is not a number"),
        ];
        for (text, message) in cases {
            assert_eq!(super::parse("s.txt", text, &io), Err(message.to_string()), "{text}");
        }
    }

    #[test]
    fn answers_at_their_times_with_or_without_the_dialog_name() {
        let text = "at 4 s answer TPReadNum 7\nat 1 answer yes please\n";
        let (_, _, answers) = super::parse("s.txt", text, &io()).expect("parses");
        assert_eq!(answers, [(1.0, "yes please".to_string()), (4.0, "7".to_string())]);
        let err = super::parse("s.txt", "at 2 answer TPReadFK\n", &io()).expect_err("no text");
        assert!(err.starts_with("s.txt:1: an answer needs a text"), "{err}");
    }
}
