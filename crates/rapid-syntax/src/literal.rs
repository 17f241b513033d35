//! Values of literals, computed from their text when a later layer needs them.

/// The value of a num literal (`3`, `-` is an operator), `None` if malformed.
pub fn num_value(text: &str) -> Option<f64> {
    let lower = text.get(..2).map(|p| p.to_ascii_lowercase());
    let radix = match lower.as_deref() {
        Some("0x") => 16,
        Some("0o") => 8,
        Some("0b") => 2,
        _ => return text.parse::<f64>().ok(),
    };
    let digits = &text[2..];
    if digits.is_empty() {
        return None;
    }
    // u128 parsing would overflow past 128 bits; fold digits into an f64 instead.
    digits.chars().try_fold(0f64, |acc, c| c.to_digit(radix).map(|d| acc * radix as f64 + d as f64))
}

/// An upper bound on the decimal exponent of a num literal's value (the number of
/// integer digits plus the written exponent), computed without converting it, so
/// range checks can skip the conversion for ordinary literals.
pub fn decimal_magnitude_bound(text: &str) -> i64 {
    let bytes = text.as_bytes();
    if bytes.len() > 2 && bytes[0] == b'0' && matches!(bytes[1], b'x' | b'X' | b'o' | b'O' | b'b' | b'B') {
        // 4 bits per hex digit at most: about 1.21 decimal digits per digit.
        return (bytes.len() as i64 - 2) * 2;
    }
    let mut int_digits: i64 = 0;
    let mut in_integer_part = true;
    for (idx, &b) in bytes.iter().enumerate() {
        match b {
            b'.' => in_integer_part = false,
            b'e' | b'E' => return int_digits.saturating_add(small_exponent(&bytes[idx + 1..])),
            _ if in_integer_part => int_digits += 1,
            _ => {}
        }
    }
    int_digits
}

/// A written exponent (`+12`, `-3`); anything longer than 6 digits counts as huge.
fn small_exponent(bytes: &[u8]) -> i64 {
    let (negative, digits) = match bytes.first() {
        Some(b'-') => (true, &bytes[1..]),
        Some(b'+') => (false, &bytes[1..]),
        _ => (false, bytes),
    };
    if digits.len() > 6 {
        return if negative { -1_000_000 } else { 1_000_000 };
    }
    let value = digits.iter().fold(0i64, |acc, &d| acc * 10 + i64::from(d.wrapping_sub(b'0') % 10));
    if negative {
        -value
    } else {
        value
    }
}

/// The characters of a string literal (quotes removed, `""`, `\\` and `\hh` decoded).
/// Returns Latin-1 code points; characters outside Latin-1 are kept as they are.
pub fn string_value(text: &str) -> String {
    let inner = text.strip_prefix('"').unwrap_or(text);
    let inner = inner.strip_suffix('"').unwrap_or(inner);
    let mut out = String::with_capacity(inner.len());
    let mut chars = inner.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '"' if chars.peek() == Some(&'"') => {
                chars.next();
                out.push('"');
            }
            '\\' if chars.peek() == Some(&'\\') => {
                chars.next();
                out.push('\\');
            }
            '\\' => {
                let hi = chars.next().and_then(|c| c.to_digit(16));
                let lo = chars.next().and_then(|c| c.to_digit(16));
                match (hi, lo) {
                    (Some(hi), Some(lo)) => out.push(char::from_u32(hi * 16 + lo).unwrap_or('?')),
                    _ => out.push('\\'),
                }
            }
            _ => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn num_values() {
        assert_eq!(num_value("3E2"), Some(300.0));
        assert_eq!(num_value(".5"), Some(0.5));
        assert_eq!(num_value("3."), Some(3.0));
        assert_eq!(num_value("0xFF"), Some(255.0));
        assert_eq!(num_value("0o17"), Some(15.0));
        assert_eq!(num_value("0b1011"), Some(11.0));
        assert_eq!(num_value("-245E-2"), Some(-2.45));
    }

    #[test]
    fn magnitude_bounds_are_upper_bounds() {
        for text in ["9E9", "123.456", ".5", "3.4E38", "1E-5", "0xFFFF", "0b1", "12345678901234567890"] {
            let value = num_value(text).unwrap();
            let bound = decimal_magnitude_bound(text);
            assert!(value < 10f64.powi(bound as i32 + 1), "{text}: {value} vs 1E{bound}");
        }
        assert!(decimal_magnitude_bound("1E400") > 300);
        assert!(decimal_magnitude_bound("1.5") < 38);
    }

    #[test]
    fn string_values() {
        assert_eq!(string_value(r#""a""b""#), "a\"b");
        assert_eq!(string_value(r#""x\\y""#), "x\\y");
        assert_eq!(string_value(r#""\41\07""#), "A\u{7}");
    }
}
