//! rapid-io: the virtual controller's I/O system (manual §1.9 and §2.10), as pure logic.
//!
//! Invariant: no IO, no threads, no wall clock. Every operation takes the controller's virtual
//! time in seconds; the VM drives the system and decides when to wake up
//! ([`IoSystem::next_event_time`]).
//!
//! # The pieces
//! - [`SignalDef`] and [`CrossConnection`] are the configuration as plain data (EIO_SIGNAL and
//!   EIO_CROSS); the EIO.cfg adapter fills them in. [`IoSystem::new`] checks them and refuses
//!   duplicate names (case-insensitive, like RAPID names), bad defaults and ranges,
//!   cross-connections naming unknown or non-digital signals, and any loop through the
//!   cross-connections ([`ConfigError`], with the position in the input list for file:line).
//! - Signal ids ([`SignalId`]) are dense indices in definition order; the VM stores them.
//! - Values are `f64`: digital 0/1 (a program order takes any value but 0 as 1), groups integers `0..=2^bits-1` (exact up to 32 bits),
//!   analog the logical value. [`IoSystem::physical`] scales analog values to physical ones
//!   along the line through (MinLog, MinPhys) and (MaxLog, MaxPhys); with a converter width,
//!   a written analog value is rounded to the nearest of its `2^bits` steps.
//!
//! # Orders in time
//! [`IoSystem::set`], [`IoSystem::set_delayed`] (`\SDelay`), [`IoSystem::pulse`] (PulseDO,
//! default 0.2 s) and [`IoSystem::invert`] are program orders at a time `t`. A new order to a
//! signal cancels its pulse end or delayed change not yet carried out (§2.10). At most
//! [`MAX_PULSING`] signals pulse and [`MAX_DELAYED`] signals have a delayed change at once;
//! one more is refused with an [`IoError`]. Refused orders change nothing.
//! [`IoSystem::set_input`] is the hardware (a stimulus) changing an input; an input that a
//! cross-connection drives has its physical channel disconnected and ignores it (§2.10).
//! [`IoSystem::advance`] carries out what is due, in time order; every order first advances
//! to its own time, so the caller never misses a due change.
//!
//! # Cross-connections
//! After every change, the cross-connections reading the changed signal are evaluated
//! (`NOT` per actor, `AND` before `OR`), transitively, upstream first and each once per
//! change. Pulses and delays are not copied along them: a result follows the value its actors
//! actually take. A signal written by several connections holds the value of the one
//! activated last.
//!
//! # The log
//! Every change is logged ([`Change`]: time, signal, old, new, cause) for `--io-log`; the
//! caller drains it ([`IoSystem::drain_changes`]), or it grows with every change.
//!
//! # Devices and networks
//! [`IoSystem::with_units`] adds the I/O devices and networks ([`Units`]): each signal's
//! `device` must name a configured device. A disabled device's signals refuse orders and
//! reads ([`IoError::NotRunning`], ERR_NORUNUNIT) and ignore the hardware; disabling
//! cancels their pending pulse ends and delayed changes.
//!
//! # Analog interrupts
//! [`AnalogTrigger`] is the `aiotrigg` condition of ISignalAI/ISignalAO with its DeltaValue
//! and stored reference value; the VM samples it with every change of the signal.
//!
//! # Errors for RAPID
//! [`IoError::rapid_error`] names the RAPID error each refusal becomes (`ERR_GO_LIM`,
//! `ERR_AO_LIM`, …), or `None` where the controller stops with an event-log error.

mod aio;
mod cross;
mod def;
mod system;
mod units;
mod value;

pub use aio::{AioCondition, AioDirection, AioError, AnalogTrigger};
pub use def::{Access, AnalogRange, ConfigError, CrossConnection, CrossOp, SignalDef, SignalKind, MAX_CROSS_TERMS};
pub use system::{Cause, Change, IoSystem, SignalId, DEFAULT_PULSE_LENGTH, MAX_DELAYED, MAX_PULSING};
pub use units::{DeviceDef, UnitError, Units, DEVICE_EVENT, LOCAL_NETWORK};
pub use value::{group_max, quantise, to_bits, to_logical, to_physical, IoError, MAX_TIME};

#[cfg(test)]
mod tests;
