//! What the trigger family keeps with the robot: the definitions that are more than
//! one output or interrupt at one time (checks, inhibited outputs, ramps, speed
//! outputs), the copies a move took of them, the checks waiting for the robot to get
//! there, and the processes (ramps, TriggSpeed) that go on over the following moves.

use std::collections::BTreeMap;

use rapid_vm::ext::Place;

/// The relation of TriggCheckIO (opnum LT=1 … GT=6).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Relation {
    Lt,
    LtEq,
    Eq,
    NotEq,
    GtEq,
    Gt,
}

impl Relation {
    /// The relation an opnum value names.
    pub fn from_opnum(n: f64) -> Option<Relation> {
        Some(match n as i64 {
            _ if n.fract() != 0.0 => return None,
            1 => Relation::Lt,
            2 => Relation::LtEq,
            3 => Relation::Eq,
            4 => Relation::NotEq,
            5 => Relation::GtEq,
            6 => Relation::Gt,
            _ => return None,
        })
    }

    /// Whether `value relation check` holds.
    pub fn holds(self, value: f64, check: f64) -> bool {
        match self {
            Relation::Lt => value < check,
            Relation::LtEq => value <= check,
            Relation::Eq => value == check,
            Relation::NotEq => value != check,
            Relation::GtEq => value >= check,
            Relation::Gt => value > check,
        }
    }
}

/// A trigger whose action is decided or spread out along the path.
#[derive(Debug, Clone, PartialEq)]
pub enum Special {
    /// TriggCheckIO: at the place `signal relation value` must hold; when it does not,
    /// `interrupt` fires and with `stop` the robot stops on its path.
    Check { signal: u32, relation: Relation, value: f64, stop: bool, interrupt: u32, inhib: Option<Place> },
    /// TriggIO/TriggEquip with `\Inhib`: at the place the output gets `value`, or
    /// `inhib_value` when the flag is TRUE then.
    Inhibited { signal: u32, value: f64, inhib: Place, inhib_value: f64 },
    /// TriggInt with `\Inhib`: the interrupt fires unless the flag is TRUE then.
    InhibitedInterrupt { interrupt: u32, inhib: Place },
    /// TriggRampAO: the output goes from `from` to `to` over `length` mm of path
    /// (seconds with `by_time`), all of it `lag` seconds early.
    Ramp { signal: u32, from: f64, to: f64, length: f64, by_time: bool, lag: f64 },
    /// TriggSpeed: the output follows `scale` × TCP speed, `lag` seconds early;
    /// speed dips `dip` seconds early; above `max` the output stays at `max` and
    /// `err_do` goes to 1.
    Speed { signal: u32, scale: f64, lag: f64, dip: f64, max: Option<f64>, err_do: Option<u32> },
}

impl Special {
    /// Whether the action is decided when the robot gets to the place (it reads a
    /// signal or a persistent then), rather than laid out when the move is planned.
    pub fn deferred(&self) -> bool {
        matches!(self, Special::Check { .. } | Special::Inhibited { .. } | Special::InhibitedInterrupt { .. })
    }
}

/// A ramp or TriggSpeed output that goes on into the next move.
#[derive(Debug, Clone, PartialEq)]
pub enum Run {
    /// A ramp `done` mm (or s) into its length.
    Ramp { special: Special, done: f64 },
    /// TriggSpeed until the next one or a stop point.
    Speed(Special),
}

/// The trigger family's part of the robot.
#[derive(Debug, Clone, Default)]
pub struct TriggState {
    /// The special definitions, by the trigger index a triggdata holds.
    pub defs: Vec<Option<Special>>,
    /// The specials of moves given and not yet on the path, by key.
    pub live: BTreeMap<u32, Special>,
    next_key: u32,
    /// Deferred actions whose time is known: (controller time, action).
    pub pending: Vec<(f64, Special)>,
    /// Ramps and TriggSpeed going on over the next move.
    pub runs: Vec<Run>,
    /// The outputs TriggSpeed drives and until when (infinity: into the next move); a
    /// robot stopped on its path sets them to 0 while it stands.
    pub speed_outputs: Vec<(u32, f64)>,
    /// TriggStopProc's supervision of program stops.
    pub stop_proc: Option<super::stopproc::StopProc>,
}

impl TriggState {
    /// The special definition of trigger `index` (None: a plain one).
    pub fn def(&self, index: usize) -> Option<&Special> {
        self.defs.get(index).and_then(Option::as_ref)
    }

    /// Stores (or clears) the special definition of trigger `index`.
    pub fn set_def(&mut self, index: usize, special: Option<Special>) {
        if self.defs.len() <= index {
            self.defs.resize(index + 1, None);
        }
        self.defs[index] = special;
    }

    /// A move takes its copy of a special definition: its key.
    pub fn take_copy(&mut self, special: Special) -> u32 {
        let key = self.next_key;
        self.next_key = self.next_key.wrapping_add(1);
        self.live.insert(key, special);
        key
    }

    /// StartMove: what was due after `since` comes `dt` later.
    pub fn delay_from(&mut self, since: f64, dt: f64) {
        for (t, _) in &mut self.pending {
            if *t > since {
                *t += dt;
            }
        }
        for (_, t) in &mut self.speed_outputs {
            if *t > since {
                *t += dt;
            }
        }
    }

    /// The TriggSpeed outputs still driven after `t`.
    pub fn speed_outputs_after(&self, t: f64) -> Vec<u32> {
        self.speed_outputs.iter().filter(|&&(_, until)| until > t).map(|&(s, _)| s).collect()
    }
}
