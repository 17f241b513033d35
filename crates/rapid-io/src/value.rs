//! Signal values: what each signal type accepts, the analog scaling between logical and
//! physical values, and the errors an order can meet (with the RAPID error each becomes).

use std::fmt;

use crate::def::{AnalogRange, SignalDef, SignalKind};

/// The largest value a group of `bits` bits holds: 2^bits - 1 (exact in f64 up to 32 bits).
pub fn group_max(bits: u8) -> f64 {
    let bits = bits.min(32);
    ((1u64 << bits) - 1) as f64
}

/// Logical → physical: the straight line through (MinLog, MinPhys) and (MaxLog, MaxPhys).
pub fn to_physical(range: &AnalogRange, logical: f64) -> f64 {
    let span = range.logical_max - range.logical_min;
    range.physical_min + (logical - range.logical_min) * (range.physical_max - range.physical_min) / span
}

/// Physical → logical, the inverse line.
pub fn to_logical(range: &AnalogRange, physical: f64) -> f64 {
    let span = range.physical_max - range.physical_min;
    range.logical_min + (physical - range.physical_min) * (range.logical_max - range.logical_min) / span
}

/// The converter's bit value for a logical value: the physical range split in 2^bits - 1 steps.
/// `None` when the range has no converter width.
pub fn to_bits(range: &AnalogRange, logical: f64) -> Option<u64> {
    if range.bits == 0 {
        return None;
    }
    let steps = group_max(range.bits);
    let fraction = (logical - range.logical_min) / (range.logical_max - range.logical_min);
    // The value was range-checked before, so the product lies in 0..=steps.
    Some((fraction * steps).round().clamp(0.0, steps) as u64)
}

/// The logical value the signal really holds after the converter: the set value rounded to
/// the nearest converter step, as read back from the device.
// uncertain: that reading an AO returns the quantised value (not the programmed one) is what
// users report of real controllers; the manual does not say it.
pub fn quantise(range: &AnalogRange, logical: f64) -> f64 {
    match to_bits(range, logical) {
        None => logical,
        Some(bits) => {
            let fraction = bits as f64 / group_max(range.bits);
            range.logical_min + fraction * (range.logical_max - range.logical_min)
        }
    }
}

/// Why an order or a hardware write was refused. [`IoError::rapid_error`] names the RAPID error.
#[derive(Debug, Clone, PartialEq)]
pub enum IoError {
    /// The id is not a signal of this system.
    UnknownSignal(u32),
    /// The order does not fit the signal's type (e.g. a program order to an input, a pulse to
    /// a group, a hardware write to an output).
    WrongKind { signal: String, kind: SignalKind, order: &'static str },
    /// The signal's access level does not let RAPID write it.
    AccessDenied { signal: String },
    /// A digital value other than 0 or 1 from the hardware (a program order takes any value
    /// other than 0 as 1).
    DigitalValue { signal: String, value: f64 },
    /// A group value that is not an integer in 0..=max.
    GroupLimit { signal: String, value: f64, max: f64 },
    /// An analog value outside the logical limits.
    AnalogLimit { signal: String, value: f64, min: f64, max: f64 },
    /// A delay or pulse length that is not a positive number of seconds (at most 2000).
    BadTime { what: &'static str, value: f64 },
    /// More than [`crate::MAX_PULSING`] signals would be pulsing at once.
    TooManyPulses { signal: String },
    /// More than [`crate::MAX_DELAYED`] signals would have a delayed order at once.
    TooManyDelayed { signal: String },
    /// The signal's device is disabled: the controller has no contact with it.
    NotRunning { signal: String, device: String },
}

impl IoError {
    /// The RAPID error name the VM raises for this error, or `None` where the controller
    /// stops the program with an event-log error instead of a recoverable error.
    pub fn rapid_error(&self) -> Option<&'static str> {
        match self {
            IoError::GroupLimit { .. } => Some("ERR_GO_LIM"),
            // Manual §1.9: no contact with the I/O device.
            IoError::NotRunning { .. } => Some("ERR_NORUNUNIT"),
            IoError::AnalogLimit { .. } => Some("ERR_AO_LIM"),
            // uncertain: the manuals list no recoverable error for a write refused by the
            // access level; ERR_SIG_NOT_VALID ("the signal cannot be accessed") is the closest.
            IoError::AccessDenied { .. } => Some("ERR_SIG_NOT_VALID"),
            // uncertain: a delay or pulse length out of range is an argument error.
            IoError::BadTime { .. } => Some("ERR_ARGVALERR"),
            // uncertain: the limits of 10 pulsing / 20 delayed signals (§2.10) come with no named
            // error; the controller reports them in the event log and stops.
            IoError::TooManyPulses { .. } | IoError::TooManyDelayed { .. } => None,
            // The checker already refuses these, and a bad digital value only comes from the
            // hardware side (a stimulus): reaching them from RAPID is a bug of the caller.
            IoError::UnknownSignal(_) | IoError::WrongKind { .. } | IoError::DigitalValue { .. } => None,
        }
    }
}

impl fmt::Display for IoError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            IoError::UnknownSignal(id) => write!(f, "no signal has id {id}"),
            IoError::WrongKind { signal, kind, order } => {
                write!(f, "{order} is not possible on {kind} signal `{signal}`")
            }
            IoError::AccessDenied { signal } => {
                write!(f, "the access level of signal `{signal}` does not allow RAPID to write it")
            }
            IoError::DigitalValue { signal, value } => {
                write!(f, "value {value} for digital signal `{signal}` is not 0 or 1")
            }
            IoError::GroupLimit { signal, value, max } => {
                write!(f, "value {value} for group signal `{signal}` is outside 0..{max}")
            }
            IoError::AnalogLimit { signal, value, min, max } => {
                write!(f, "value {value} for analog signal `{signal}` is outside {min}..{max}")
            }
            IoError::BadTime { what, value } => {
                write!(f, "{what} {value} s is not in 0.001..2000 s")
            }
            IoError::TooManyPulses { signal } => {
                write!(f, "cannot pulse `{signal}`: {} signals are pulsing already", crate::MAX_PULSING)
            }
            IoError::NotRunning { signal, device } => {
                write!(f, "signal `{signal}` cannot be reached: its I/O device `{device}` is disabled")
            }
            IoError::TooManyDelayed { signal } => write!(
                f,
                "cannot delay a change of `{signal}`: {} signals have delayed changes already",
                crate::MAX_DELAYED
            ),
        }
    }
}

impl std::error::Error for IoError {}

/// Checks a value against the signal's type and limits and returns the value the signal will
/// hold (analog values after the converter).
pub(crate) fn check_value(def: &SignalDef, value: f64) -> Result<f64, IoError> {
    let signal = || def.name.clone();
    match def.kind {
        SignalKind::DI | SignalKind::DO => {
            if value == 0.0 || value == 1.0 {
                Ok(value)
            } else {
                Err(IoError::DigitalValue { signal: signal(), value })
            }
        }
        SignalKind::GI | SignalKind::GO => {
            let max = group_max(def.group_bits);
            // uncertain: a fraction is refused like an out-of-range value (ERR_GO_LIM); the
            // manual asks for "a positive integer" without naming what a fraction does.
            if value.is_finite() && value >= 0.0 && value <= max && value.fract() == 0.0 {
                Ok(value)
            } else {
                Err(IoError::GroupLimit { signal: signal(), value, max })
            }
        }
        SignalKind::AI | SignalKind::AO => match &def.analog {
            None if value.is_finite() => Ok(value),
            None => Err(IoError::AnalogLimit { signal: signal(), value, min: f64::NEG_INFINITY, max: f64::INFINITY }),
            Some(range) => {
                if value.is_finite() && value >= range.logical_min && value <= range.logical_max {
                    Ok(quantise(range, value))
                } else {
                    Err(IoError::AnalogLimit {
                        signal: signal(),
                        value,
                        min: range.logical_min,
                        max: range.logical_max,
                    })
                }
            }
        },
    }
}

/// The longest delay or pulse the controller accepts, in seconds.
pub const MAX_TIME: f64 = 2000.0;

/// Checks a delay or pulse length: positive, finite, at most [`MAX_TIME`].
// uncertain: the manuals give 0.001..2000 s for PLength and \SDelay; shorter positive values
// are accepted here as they are (the controller's resolution is not modelled).
pub(crate) fn check_time(what: &'static str, value: f64) -> Result<f64, IoError> {
    if value.is_finite() && value > 0.0 && value <= MAX_TIME {
        Ok(value)
    } else {
        Err(IoError::BadTime { what, value })
    }
}
