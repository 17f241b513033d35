//! The configuration the I/O system is built from: signal definitions and cross-connections,
//! as plain data (the EIO.cfg adapter fills them in), and the load errors they can carry.

use std::fmt;

/// The six signal types of EIO_SIGNAL `-SignalType`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SignalKind {
    DI,
    DO,
    AI,
    AO,
    GI,
    GO,
}

impl SignalKind {
    /// Inputs are written by the hardware (or a stimulus), never by a program order.
    pub fn is_input(self) -> bool {
        matches!(self, SignalKind::DI | SignalKind::AI | SignalKind::GI)
    }

    /// Digital signals are the only ones a cross-connection may name.
    pub fn is_digital(self) -> bool {
        matches!(self, SignalKind::DI | SignalKind::DO)
    }

    pub fn is_group(self) -> bool {
        matches!(self, SignalKind::GI | SignalKind::GO)
    }

    pub fn is_analog(self) -> bool {
        matches!(self, SignalKind::AI | SignalKind::AO)
    }

    /// The RAPID data type a variable bound to this signal has.
    pub fn rapid_type(self) -> &'static str {
        match self {
            SignalKind::DI => "signaldi",
            SignalKind::DO => "signaldo",
            SignalKind::AI => "signalai",
            SignalKind::AO => "signalao",
            SignalKind::GI => "signalgi",
            SignalKind::GO => "signalgo",
        }
    }
}

impl fmt::Display for SignalKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self, f)
    }
}

/// EIO_SIGNAL `-Access`: which clients may write the signal. RAPID is one client.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Access {
    /// No client may write (the hardware still drives an input).
    ReadOnly,
    /// RAPID may write in every mode; other clients only in manual mode.
    Default,
    /// Every client may write in every mode.
    All,
    /// A level of EIO_ACCESS; `rapid` is its `-Rapid` flag.
    Custom { name: String, rapid: bool },
}

impl Access {
    /// Whether a RAPID instruction may write a signal with this access level.
    pub fn rapid_may_write(&self) -> bool {
        match self {
            Access::ReadOnly => false,
            Access::Default | Access::All => true,
            Access::Custom { rapid, .. } => *rapid,
        }
    }
}

/// EIO_SIGNAL `-MinLog -MaxLog -MinPhys -MaxPhys` and the width of the converter in bits
/// (`-MinBitVal/-MaxBitVal` span `0 ..= 2^bits - 1`). `bits == 0` means no quantisation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AnalogRange {
    pub logical_min: f64,
    pub logical_max: f64,
    pub physical_min: f64,
    pub physical_max: f64,
    pub bits: u8,
}

/// One signal as the configuration defines it.
#[derive(Debug, Clone, PartialEq)]
pub struct SignalDef {
    pub name: String,
    pub kind: SignalKind,
    /// `-Default`: the value at start-up (logical value for analog signals).
    pub default: f64,
    pub access: Access,
    /// Only for AI/AO. `None`: no logical limits and physical = logical.
    pub analog: Option<AnalogRange>,
    /// Only for GI/GO: how many bits the group has (1..=32).
    pub group_bits: u8,
    /// `-Device` (`-Unit`): the I/O device the signal is on; `None` for a virtual signal.
    pub device: Option<String>,
    /// `-Label`: the signal's label text (empty when not configured).
    pub label: String,
    /// The first bit of `-DeviceMap` (`-UnitMap`), if the signal is mapped.
    pub start_bit: Option<u32>,
}

impl SignalDef {
    /// A signal with default 0, access Default, no analog range and no group width.
    pub fn new(name: &str, kind: SignalKind) -> SignalDef {
        SignalDef {
            name: name.to_string(),
            kind,
            default: 0.0,
            access: Access::Default,
            analog: None,
            group_bits: 0,
            device: None,
            label: String::new(),
            start_bit: None,
        }
    }
}

/// EIO_CROSS `-Oper1 … -Oper4`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CrossOp {
    And,
    Or,
}

/// One EIO_CROSS entry: `result = term1 op1 term2 op2 …`, each term a signal name with
/// `inverted` for `-ActN_invert` (NOT). `ops.len()` must be `terms.len() - 1`.
#[derive(Debug, Clone, PartialEq)]
pub struct CrossConnection {
    pub result: String,
    pub terms: Vec<(String, bool)>,
    pub ops: Vec<CrossOp>,
}

/// EIO_CROSS allows the actors `-Act1` to `-Act5`.
pub const MAX_CROSS_TERMS: usize = 5;

/// Why a configuration cannot be loaded. `index` is the 0-based position of the signal or
/// cross-connection in the list given to [`crate::IoSystem::new`], so the adapter can map it
/// back to file:line.
#[derive(Debug, Clone, PartialEq)]
pub enum ConfigError {
    DuplicateSignal {
        index: usize,
        name: String,
    },
    BadSignal {
        index: usize,
        name: String,
        reason: String,
    },
    BadCross {
        index: usize,
        reason: String,
    },
    UnknownCrossSignal {
        index: usize,
        name: String,
    },
    /// The cross-connections form a cycle; `path` lists it, first name repeated at the end.
    CrossLoop {
        index: usize,
        path: Vec<String>,
    },
    /// The devices and networks do not fit together (or with the signals).
    Units(crate::units::UnitError),
}

impl fmt::Display for ConfigError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ConfigError::DuplicateSignal { name, .. } => {
                write!(f, "signal `{name}` is defined more than once")
            }
            ConfigError::BadSignal { name, reason, .. } => write!(f, "signal `{name}`: {reason}"),
            ConfigError::BadCross { index, reason } => {
                write!(f, "cross-connection {}: {reason}", index + 1)
            }
            ConfigError::UnknownCrossSignal { index, name } => {
                write!(f, "cross-connection {} names `{name}`, which is not a defined signal", index + 1)
            }
            ConfigError::CrossLoop { index, path } => {
                write!(f, "cross-connection {} closes a loop: {}", index + 1, path.join(" -> "))
            }
            ConfigError::Units(err) => write!(f, "{err}"),
        }
    }
}

impl std::error::Error for ConfigError {}

/// Checks one signal definition on its own (names are checked by the caller).
pub(crate) fn check_signal(index: usize, def: &SignalDef) -> Result<(), ConfigError> {
    let bad = |reason: String| ConfigError::BadSignal { index, name: def.name.clone(), reason };
    if def.name.is_empty() {
        return Err(bad("the name is empty".to_string()));
    }
    if !def.default.is_finite() {
        return Err(bad(format!("default {} is not a number", def.default)));
    }
    match def.kind {
        SignalKind::DI | SignalKind::DO => {
            if def.default != 0.0 && def.default != 1.0 {
                return Err(bad(format!("default {} is not 0 or 1", def.default)));
            }
        }
        SignalKind::GI | SignalKind::GO => {
            if !(1..=32).contains(&def.group_bits) {
                return Err(bad(format!("a group has 1 to 32 bits, not {}", def.group_bits)));
            }
            let max = crate::value::group_max(def.group_bits);
            if def.default < 0.0 || def.default > max || def.default.fract() != 0.0 {
                return Err(bad(format!("default {} is not an integer in 0..={max}", def.default)));
            }
        }
        SignalKind::AI | SignalKind::AO => {
            if let Some(range) = &def.analog {
                check_analog(range).map_err(bad)?;
                if def.default < range.logical_min || def.default > range.logical_max {
                    return Err(bad(format!(
                        "default {} is outside the logical range {}..{}",
                        def.default, range.logical_min, range.logical_max
                    )));
                }
            }
        }
    }
    Ok(())
}

fn check_analog(range: &AnalogRange) -> Result<(), String> {
    let all = [range.logical_min, range.logical_max, range.physical_min, range.physical_max];
    if all.iter().any(|v| !v.is_finite()) {
        return Err("an analog limit is not a number".to_string());
    }
    if range.logical_min >= range.logical_max {
        return Err(format!(
            "logical minimum {} is not below logical maximum {}",
            range.logical_min, range.logical_max
        ));
    }
    if range.physical_min == range.physical_max {
        return Err("physical minimum and maximum are equal".to_string());
    }
    if range.bits > 32 {
        return Err(format!("an analog converter has at most 32 bits, not {}", range.bits));
    }
    Ok(())
}
