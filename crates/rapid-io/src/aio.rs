//! The condition of an analog signal interrupt (ISignalAI / ISignalAO, data type
//! `aiotrigg`), as pure logic: the VM feeds it every new value of the signal and orders
//! the interrupt when [`AnalogTrigger::sample`] says so.
//!
//! The rule (ISignalAI's description and its examples of interrupt generation): a value
//! counts only when it meets the condition on HighValue/LowValue and differs from the
//! stored reference value by more than DeltaValue. Such a value becomes the new
//! reference; it generates an interrupt unless `\DPos` (`\DNeg`) asks for increases
//! (decreases) only and the difference goes the other way. The first reference is the
//! value when the interrupt is ordered.

use std::fmt;

/// `aiotrigg`: which values meet the condition.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AioCondition {
    /// AIO_ABOVE_HIGH (1): above HighValue.
    AboveHigh,
    /// AIO_BELOW_HIGH (2): below HighValue.
    BelowHigh,
    /// AIO_ABOVE_LOW (3): above LowValue.
    AboveLow,
    /// AIO_BELOW_LOW (4): below LowValue.
    BelowLow,
    /// AIO_BETWEEN (5): from LowValue to HighValue.
    Between,
    /// AIO_OUTSIDE (6): below LowValue or above HighValue.
    Outside,
    /// AIO_ALWAYS (7): every value, whatever the limits.
    Always,
}

impl AioCondition {
    /// The condition of an `aiotrigg` value (1 to 7, in the order the manual lists the
    /// constants).
    pub fn from_code(code: f64) -> Option<AioCondition> {
        const ALL: [AioCondition; 7] = [
            AioCondition::AboveHigh,
            AioCondition::BelowHigh,
            AioCondition::AboveLow,
            AioCondition::BelowLow,
            AioCondition::Between,
            AioCondition::Outside,
            AioCondition::Always,
        ];
        if code.fract() != 0.0 || !(1.0..=7.0).contains(&code) {
            return None;
        }
        ALL.get(code as usize - 1).copied()
    }

    /// Whether `value` meets the condition.
    // uncertain: "above"/"below" are strict and "between" includes both limits; the manual
    // does not say what a value equal to a limit does.
    pub fn holds(self, value: f64, high: f64, low: f64) -> bool {
        match self {
            AioCondition::AboveHigh => value > high,
            AioCondition::BelowHigh => value < high,
            AioCondition::AboveLow => value > low,
            AioCondition::BelowLow => value < low,
            AioCondition::Between => low <= value && value <= high,
            AioCondition::Outside => value < low || value > high,
            AioCondition::Always => true,
        }
    }

    /// Whether the condition reads both limits (and so needs LowValue ≤ HighValue).
    fn uses_both(self) -> bool {
        matches!(self, AioCondition::Between | AioCondition::Outside)
    }
}

/// `\DPos`, `\DNeg` or neither.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AioDirection {
    Both,
    /// Only increases generate interrupts.
    Pos,
    /// Only decreases generate interrupts.
    Neg,
}

/// Why an analog interrupt cannot be ordered.
#[derive(Debug, Clone, PartialEq)]
pub enum AioError {
    Condition(f64),
    Delta(f64),
    Limits { high: f64, low: f64 },
}

impl fmt::Display for AioError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            AioError::Condition(code) => write!(f, "{code} is not an aiotrigg condition (1 to 7)"),
            AioError::Delta(delta) => write!(f, "DeltaValue {delta} is not a number of 0 or more"),
            AioError::Limits { high, low } => write!(f, "HighValue {high} is below LowValue {low}"),
        }
    }
}

impl std::error::Error for AioError {}

/// One ordered analog interrupt: its condition and the stored reference value.
#[derive(Debug, Clone, PartialEq)]
pub struct AnalogTrigger {
    pub condition: AioCondition,
    pub high: f64,
    pub low: f64,
    pub delta: f64,
    pub direction: AioDirection,
    /// The value the next one is compared with.
    pub reference: f64,
}

impl AnalogTrigger {
    /// An interrupt condition ordered while the signal has the value `current`.
    // uncertain: a negative DeltaValue, and HighValue below LowValue for AIO_BETWEEN and
    // AIO_OUTSIDE, are refused (the caller raises ERR_ARGVALERR); the manual names no error.
    pub fn new(
        condition: f64,
        high: f64,
        low: f64,
        delta: f64,
        direction: AioDirection,
        current: f64,
    ) -> Result<AnalogTrigger, AioError> {
        let condition = AioCondition::from_code(condition).ok_or(AioError::Condition(condition))?;
        if !delta.is_finite() || delta < 0.0 {
            return Err(AioError::Delta(delta));
        }
        if condition.uses_both() && high < low {
            return Err(AioError::Limits { high, low });
        }
        Ok(AnalogTrigger { condition, high, low, delta, direction, reference: current })
    }

    /// A new value of the signal; `true` when it generates an interrupt.
    pub fn sample(&mut self, value: f64) -> bool {
        if !self.condition.holds(value, self.high, self.low) {
            return false;
        }
        let difference = value - self.reference;
        if difference.abs() <= self.delta {
            return false;
        }
        self.reference = value;
        match self.direction {
            AioDirection::Both => true,
            AioDirection::Pos => difference > 0.0,
            AioDirection::Neg => difference < 0.0,
        }
    }
}
