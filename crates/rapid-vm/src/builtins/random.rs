//! `Rand()` (RobotWare 6.15, manual §1.15 "数值数据相关简单计算": generates a random
//! number). The public record gives no signature or range beyond that; ours, from the
//! catalogue, is `FUNC num Rand()` giving a num in [0, 1).
// uncertain: the range [0, 1) and the sequence are ours. The sequence is the same on
// every run (a fixed seed), because the virtual controller is deterministic by design:
// the same program gives the same output.

use super::{native, Ctx, Family};
use crate::error::RapidError;
use crate::value::Value;

/// The task's random-number generator (SplitMix64).
#[derive(Debug, Clone)]
pub struct RandomState {
    state: u64,
}

/// Where every task's sequence starts.
const SEED: u64 = 0x0DDB_1A5E_5BAD_5EED;

impl Default for RandomState {
    fn default() -> Self {
        RandomState { state: SEED }
    }
}

impl RandomState {
    fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A num in [0, 1): 24 random bits, exactly representable in a num.
    pub fn next_num(&mut self) -> f32 {
        (self.next_u64() >> 40) as f32 / (1u32 << 24) as f32
    }
}

fn rand(ctx: &mut Ctx<'_>, _args: &[Value]) -> Result<Option<Value>, RapidError> {
    Ok(Some(Value::Num(ctx.resources.random.next_num())))
}

pub(super) static FAMILY: Family = Family { file: file!(), builtins: &[native("Rand", rand)] };

#[cfg(test)]
mod tests {
    use super::RandomState;

    #[test]
    fn values_lie_in_zero_to_one_and_are_spread() {
        let mut random = RandomState::default();
        let values: Vec<f32> = (0..10_000).map(|_| random.next_num()).collect();
        assert!(values.iter().all(|v| (0.0..1.0).contains(v)));
        let low = values.iter().filter(|&&v| v < 0.5).count();
        // A fair generator puts about half below 0.5 (5000 ± 5 standard deviations).
        assert!((4750..=5250).contains(&low), "{low} of 10000 below 0.5");
    }

    #[test]
    fn every_task_starts_the_same_sequence() {
        let (mut a, mut b) = (RandomState::default(), RandomState::default());
        assert!((0..100).all(|_| a.next_num() == b.next_num()));
    }
}
