//! Exact decimal digits of binary floating-point values, rounded half away from zero.
//!
//! Every `num` (f32) and `dnum` (f64) is a finite binary fraction, so it has a finite
//! decimal expansion. We take that exact expansion and round it ourselves, which lets us
//! pick the tie rule (half away from zero, see docs/semantics.md) instead of inheriting
//! the half-to-even rule of Rust's own formatting.

/// An upper bound on the significant digits of the exact decimal expansion of `v`.
///
/// `v = m × 2^e` with `m < 2^53`. For `e < 0` the expansion is `m × 5^-e / 10^-e`, whose
/// digits number at most `log10(m) + 1 + (-e)·log10(5)`; for `e ≥ 0` it is `m × 2^e`,
/// with at most `log10(m) + 1 + e·log10(2)` digits. The smallest subnormal needs 751.
fn exact_digits_bound(v: f64) -> usize {
    let biased = ((v.to_bits() >> 52) & 0x7FF) as i32;
    let e = if biased == 0 { -1074 } else { biased - 1075 };
    let scale = if e < 0 { f64::from(-e) * 0.699 } else { f64::from(e) * 0.302 };
    17 + scale.ceil() as usize + 1
}

/// A non-negative decimal number `d1.d2d3… × 10^exp`.
///
/// `digits` holds values 0..=9 with no leading or trailing zeros; an empty list is zero.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct Digits {
    pub(super) digits: Vec<u8>,
    pub(super) exp: i32,
}

impl Digits {
    fn zero() -> Digits {
        Digits { digits: Vec::new(), exp: 0 }
    }

    pub(super) fn is_zero(&self) -> bool {
        self.digits.is_empty()
    }

    /// The exact decimal expansion of `|v|` for an f32 value. `v` must be finite.
    pub(super) fn exact_f32(v: f32) -> Digits {
        Digits::exact_f64(f64::from(v))
    }

    /// The exact decimal expansion of `|v|` for an f64 value. `v` must be finite.
    pub(super) fn exact_f64(v: f64) -> Digits {
        debug_assert!(v.is_finite());
        let magnitude = v.abs();
        if magnitude == 0.0 {
            return Digits::zero();
        }
        // Rust's exponent formatting is correctly rounded; asking for more digits than the
        // expansion has makes it exact (padded with zeros, which we trim).
        let text = format!("{:.*e}", exact_digits_bound(magnitude) - 1, magnitude);
        let (mantissa, exponent) = text.split_once('e').expect("exponent formatting always has an 'e'");
        let mut digits: Vec<u8> = mantissa.bytes().filter(u8::is_ascii_digit).map(|b| b - b'0').collect();
        while digits.last() == Some(&0) {
            digits.pop();
        }
        let exp = exponent.parse().expect("exponent is an integer");
        Digits { digits, exp }
    }

    /// Keeps the first `keep` significant digits, rounding half away from zero.
    /// `keep` may be zero or negative: the value then rounds to zero or to one unit in
    /// the place just before the first digit.
    pub(super) fn round_to(&self, keep: i64) -> Digits {
        let len = self.digits.len() as i64;
        if self.is_zero() || keep >= len {
            return self.clone();
        }
        if keep < 0 {
            return Digits::zero();
        }
        let keep = keep as usize;
        // The expansion is exact and has no trailing zeros, so a next digit of 5 or more
        // means "at least half a unit": round up. Exactly 5 is the tie, also rounded up.
        let round_up = self.digits[keep] >= 5;
        let mut digits = self.digits[..keep].to_vec();
        let mut exp = self.exp;
        if round_up {
            let mut i = digits.len();
            loop {
                if i == 0 {
                    // Every kept digit was 9 (or none was kept): 99.9 → 100.
                    digits.insert(0, 1);
                    exp += 1;
                    break;
                }
                i -= 1;
                if digits[i] == 9 {
                    digits[i] = 0;
                } else {
                    digits[i] += 1;
                    break;
                }
            }
        }
        while digits.last() == Some(&0) {
            digits.pop();
        }
        if digits.is_empty() {
            return Digits::zero();
        }
        Digits { digits, exp }
    }

    /// Rounds to `sig` significant digits.
    pub(super) fn round_significant(&self, sig: usize) -> Digits {
        self.round_to(sig as i64)
    }

    /// Rounds to `dec` digits after the decimal point.
    pub(super) fn round_decimals(&self, dec: usize) -> Digits {
        self.round_to(i64::from(self.exp) + 1 + dec as i64)
    }

    /// The digit standing at the place of `10^power` (0 outside the expansion).
    fn digit_at(&self, power: i64) -> u8 {
        let index = i64::from(self.exp) - power;
        if index < 0 {
            return 0;
        }
        self.digits.get(index as usize).copied().unwrap_or(0)
    }

    /// Fixed-point text with exactly `dec` decimals (no sign). The value must already be
    /// rounded to `dec` decimals.
    pub(super) fn fixed(&self, dec: usize) -> String {
        let mut out = String::new();
        if self.is_zero() || self.exp < 0 {
            out.push('0');
        } else {
            for power in (0..=i64::from(self.exp)).rev() {
                out.push(char::from(b'0' + self.digit_at(power)));
            }
        }
        if dec > 0 {
            out.push('.');
            for power in 1..=dec as i64 {
                out.push(char::from(b'0' + self.digit_at(-power)));
            }
        }
        out
    }

    /// Exponent text `d.ddd` with exactly `dec` decimals, then `E`, a sign and at least
    /// two exponent digits (no sign on the number). The value must already be rounded to
    /// `dec + 1` significant digits.
    pub(super) fn scientific(&self, dec: usize) -> String {
        let exp = if self.is_zero() { 0 } else { self.exp };
        let mut out = String::new();
        out.push(char::from(b'0' + self.digits.first().copied().unwrap_or(0)));
        if dec > 0 {
            out.push('.');
            for i in 1..=dec {
                out.push(char::from(b'0' + self.digits.get(i).copied().unwrap_or(0)));
            }
        }
        push_exponent(&mut out, exp);
        out
    }

    /// C's `%.{sig}G` without trailing zeros: exponent form when the decimal exponent after
    /// rounding is below -4 or at least `sig`, fixed-point otherwise. No sign.
    pub(super) fn general(&self, sig: usize) -> String {
        let rounded = self.round_significant(sig);
        if rounded.is_zero() {
            return "0".to_string();
        }
        let exp = rounded.exp;
        // After rounding the digit list holds only the significant, non-zero-terminated
        // digits, so printing all of them is exactly "strip the trailing zeros".
        let shown = rounded.digits.len() - 1;
        if exp < -4 || i64::from(exp) >= sig as i64 {
            rounded.scientific(shown)
        } else {
            let dec = (shown as i64 - i64::from(exp)).max(0) as usize;
            rounded.fixed(dec)
        }
    }
}

fn push_exponent(out: &mut String, exp: i32) {
    out.push('E');
    out.push(if exp < 0 { '-' } else { '+' });
    let magnitude = exp.unsigned_abs();
    if magnitude < 10 {
        out.push('0');
    }
    out.push_str(&magnitude.to_string());
}

#[cfg(test)]
mod tests {
    use super::Digits;

    fn d(digits: &[u8], exp: i32) -> Digits {
        Digits { digits: digits.to_vec(), exp }
    }

    #[test]
    fn exact_expansion_of_simple_values() {
        assert_eq!(Digits::exact_f64(0.5), d(&[5], -1));
        assert_eq!(Digits::exact_f64(1234.0), d(&[1, 2, 3, 4], 3));
        assert_eq!(Digits::exact_f64(-0.125), d(&[1, 2, 5], -1));
        assert!(Digits::exact_f64(0.0).is_zero());
        // f32 0.1 is 0.100000001490116119384765625 exactly.
        let tenth = Digits::exact_f32(0.1);
        assert_eq!(tenth.exp, -1);
        assert_eq!(tenth.digits.len(), 27);
        assert_eq!(tenth.digits[..9], [1, 0, 0, 0, 0, 0, 0, 0, 1]);
    }

    #[test]
    fn exact_expansion_of_extreme_values() {
        // Smallest f32 subnormal, 2^-149: 105 significant digits, starting 1.4012984…E-45.
        let tiny = Digits::exact_f32(f32::from_bits(1));
        assert_eq!(tiny.exp, -45);
        assert_eq!(tiny.digits.len(), 105);
        assert_eq!(tiny.digits[..5], [1, 4, 0, 1, 2]);
        // Smallest f64 subnormal, 2^-1074: 751 significant digits.
        let tiniest = Digits::exact_f64(f64::from_bits(1));
        assert_eq!(tiniest.exp, -324);
        assert_eq!(tiniest.digits.len(), 751);
    }

    #[test]
    fn the_digit_bound_always_leaves_room_for_the_exact_expansion() {
        let mut state = 0x0123_4567_89AB_CDEF_u64;
        for _ in 0..5_000 {
            state = state.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
            let v = f64::from_bits(state >> 1);
            if !v.is_finite() || v == 0.0 {
                continue;
            }
            let exact = Digits::exact_f64(v);
            assert!(exact.digits.len() < super::exact_digits_bound(v), "{v:e}");
            // The exact digits read back as the very same double.
            let text: String = exact.digits.iter().map(|d| char::from(b'0' + d)).collect();
            let back: f64 = format!("0.{text}e{}", exact.exp + 1).parse().unwrap();
            assert_eq!(back, v);
        }
    }

    #[test]
    fn rounding_is_half_away_from_zero() {
        assert_eq!(d(&[2, 5], 0).round_decimals(0), d(&[3], 0));
        assert_eq!(d(&[2, 4, 9], 0).round_decimals(1), d(&[2, 5], 0));
        assert_eq!(d(&[1, 2, 5], -1).round_decimals(2), d(&[1, 3], -1));
        assert_eq!(d(&[9, 9, 9, 5], 2).round_significant(3), d(&[1], 3));
        assert_eq!(d(&[4, 9], -3).round_decimals(2), Digits::zero());
        assert_eq!(d(&[5], -3).round_decimals(2), d(&[1], -2));
        assert_eq!(d(&[5], -4).round_decimals(2), Digits::zero());
    }

    #[test]
    fn fixed_and_scientific_rendering() {
        assert_eq!(d(&[3, 8, 5], -1).fixed(3), "0.385");
        assert_eq!(d(&[1, 2], 3).fixed(2), "1200.00");
        assert_eq!(d(&[1, 2, 5], -3).fixed(5), "0.00125");
        assert_eq!(Digits::zero().fixed(0), "0");
        assert_eq!(d(&[3, 8, 5], -1).scientific(2), "3.85E-01");
        assert_eq!(d(&[9], 9).scientific(0), "9E+09");
        assert_eq!(d(&[1], 308).scientific(1), "1.0E+308");
        assert_eq!(Digits::zero().scientific(2), "0.00E+00");
    }
}
