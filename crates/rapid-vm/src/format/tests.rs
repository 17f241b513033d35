//! Tests for value-to-text conversion. Expected texts come from ABB's documented examples
//! and from the rules in docs/semantics.md worked by hand, never from running this code.

use super::*;

fn texts(values: &[f32]) -> Vec<String> {
    values.iter().copied().map(num_to_text).collect()
}

// ---- num: documented examples -------------------------------------------------------

#[test]
fn num_examples_from_tpwrite_write_and_valtostr() {
    // TPWrite / Write conversion table and the ValToStr examples.
    assert_eq!(num_to_text(23.0), "23");
    assert_eq!(num_to_text(1.141367), "1.14137");
    assert_eq!(num_to_text(1.234567), "1.23457");
    assert_eq!(pos_to_text([1817.3, 905.17, 879.11]), "[1817.3,905.17,879.11]");
    assert_eq!(orient_to_text([0.96593, 0.0, 0.25882, 0.0]), "[0.96593,0,0.25882,0]");
    assert_eq!(pos_to_text([100.0, 200.0, 300.0]), "[100,200,300]");
}

#[test]
fn num_beyond_six_digits_uses_exponent_form() {
    // Observed on a controller: ValToStr(8388608+8388608) gave "1.67772E+07".
    assert_eq!(num_to_text(8388608.0 + 8388608.0), "1.67772E+07");
    // The unused-axis value 9E9, as every saved module writes it.
    assert_eq!(num_to_text(9e9), "9E+09");
    assert_eq!(num_to_text(-9e9), "-9E+09");
    assert_eq!(num_to_text(8388608.0), "8.38861E+06");
    assert_eq!(num_to_text(1234567.0), "1.23457E+06");
    assert_eq!(num_to_text(1_000_000.0), "1E+06");
    assert_eq!(num_to_text(f32::MAX), "3.40282E+38");
}

#[test]
fn num_up_to_six_integer_digits_prints_in_full() {
    assert_eq!(
        texts(&[0.0, 1.0, -1.0, 45.0, 123456.0, 999999.0, -999999.0]),
        ["0", "1", "-1", "45", "123456", "999999", "-999999"]
    );
}

#[test]
fn num_six_significant_digits_without_trailing_zeros() {
    assert_eq!(num_to_text(0.38521), "0.38521");
    assert_eq!(num_to_text(1.0 / 3.0), "0.333333");
    assert_eq!(num_to_text(-1.0 / 3.0), "-0.333333");
    assert_eq!(num_to_text(2.0 / 3.0), "0.666667");
    assert_eq!(num_to_text(0.1), "0.1");
    assert_eq!(num_to_text(-2.5), "-2.5");
    assert_eq!(num_to_text(100.25), "100.25");
    // f32 12345.678 is 12345.677734375: six digits give 12345.7.
    assert_eq!(num_to_text(12345.678), "12345.7");
    assert_eq!(num_to_text(0.0001), "0.0001");
}

#[test]
fn num_fraction_within_five_millionths_of_an_integer_prints_the_integer() {
    assert_eq!(num_to_text(0.999996), "1");
    assert_eq!(num_to_text(-0.999996), "-1");
    assert_eq!(num_to_text(2.000004), "2");
    assert_eq!(num_to_text(41.999996), "42");
    assert_eq!(num_to_text(0.000004), "0");
    // A value that rounds to zero shows no sign.
    assert_eq!(num_to_text(-0.000004), "0");
    assert_eq!(num_to_text(-0.0), "0");
    assert_eq!(num_to_text(f32::MIN_POSITIVE), "0");
}

#[test]
fn num_small_values_outside_the_snap_use_exponent_form() {
    // f32 0.00001 is 9.99999974…E-06: six digits round it up to 1.00000E-05.
    assert_eq!(num_to_text(0.00001), "1E-05");
    assert_eq!(num_to_text(0.00005), "5E-05");
    assert_eq!(num_to_text(0.000006), "6E-06");
    assert_eq!(num_to_text(-0.000012345), "-1.2345E-05");
}

#[test]
fn num_ties_round_away_from_zero() {
    // 999999.5 is exact in f32; its fraction is not near an integer, so %.6G rounds the
    // tie 9.999995 up.
    assert_eq!(num_to_text(999999.5), "1E+06");
    assert_eq!(num_to_text(-999999.5), "-1E+06");
}

#[test]
fn num_text_is_never_longer_than_twelve_characters() {
    let mut state = 0x2545_F491_u32;
    for _ in 0..20_000 {
        state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
        let v = f32::from_bits(state);
        if v.is_finite() {
            let text = num_to_text(v);
            assert!(text.len() <= 12, "{v:e} gave {text}");
        }
    }
}

// ---- num: round trip ----------------------------------------------------------------

#[test]
fn num_integers_below_a_million_read_back_exactly() {
    for n in (-999_999..=999_999).step_by(7) {
        let v = n as f32;
        assert_eq!(num_to_text(v).parse::<f32>().unwrap(), v, "{n}");
    }
}

#[test]
fn num_reads_back_within_half_a_sixth_digit() {
    // Six digits lose precision by design: the text is within half a unit of the sixth
    // significant digit, or within 0.000005 where the snap to an integer applied.
    let mut state = 12_345_u32;
    for _ in 0..20_000 {
        state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
        let v = f32::from_bits(state);
        if !v.is_finite() {
            continue;
        }
        let exact = f64::from(v);
        let back: f64 = num_to_text(v).parse().unwrap();
        let bound = 5.0e-6 * exact.abs().max(1.0) * (1.0 + 1e-9);
        assert!((back - exact).abs() <= bound, "{v:e} gave {}", num_to_text(v));
    }
}

#[test]
fn num_six_digits_do_not_round_trip_every_value() {
    let v = 1.2345678_f32;
    assert_eq!(num_to_text(v), "1.23457");
    assert_ne!("1.23457".parse::<f32>().unwrap(), v);
}

// ---- dnum ---------------------------------------------------------------------------

#[test]
fn dnum_examples() {
    // TPWrite \Dnum and ValToStr example value.
    assert_eq!(dnum_to_text(4294967295.0), "4294967295");
    assert_eq!(dnum_to_text(9e9), "9000000000");
    assert_eq!(dnum_to_text(0.1 + 0.2), "0.3");
    assert_eq!(dnum_to_text(1.0 / 3.0), "0.333333333333333");
    assert_eq!(dnum_to_text(-2.0 / 3.0), "-0.666666666666667");
    assert_eq!(dnum_to_text(123456.789), "123456.789");
    assert_eq!(dnum_to_text(999_999_999_999_999.0), "999999999999999");
    assert_eq!(dnum_to_text(1e15), "1E+15");
    // 2^52, the end of the exact-integer range: 16 digits, so exponent form.
    assert_eq!(dnum_to_text(4503599627370496.0), "4.5035996273705E+15");
    assert_eq!(dnum_to_text(0.0001), "0.0001");
    assert_eq!(dnum_to_text(0.00001), "1E-05");
    assert_eq!(dnum_to_text(1e300), "1E+300");
    assert_eq!(dnum_to_text(-0.0), "0");
    assert_eq!(dnum_to_text(0.000001), "1E-06");
}

#[test]
fn dnum_reads_back_within_half_a_fifteenth_digit() {
    let mut state = 0x9E37_79B9_7F4A_7C15_u64;
    for _ in 0..20_000 {
        state = state.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        let v = f64::from_bits(state);
        // Subnormals carry too few bits to read back 15 digits faithfully.
        if !v.is_normal() {
            continue;
        }
        let back: f64 = dnum_to_text(v).parse().unwrap();
        // Half a unit of the 15th digit, plus the rounding of the read-back itself.
        assert!(((back - v) / v).abs() <= 5.0e-15 + 3.0e-16, "{v:e} gave {}", dnum_to_text(v));
    }
}

// ---- NumToStr / DnumToStr -----------------------------------------------------------

#[test]
fn num_to_str_documented_examples() {
    assert_eq!(num_to_str(0.38521, 3, false).unwrap(), "0.385");
    assert_eq!(num_to_str(0.38521, 2, true).unwrap(), "3.85E-01");
}

#[test]
fn num_to_str_fixed_decimals() {
    assert_eq!(num_to_str(23.0, 0, false).unwrap(), "23");
    assert_eq!(num_to_str(23.0, 2, false).unwrap(), "23.00");
    assert_eq!(num_to_str(0.0, 3, false).unwrap(), "0.000");
    assert_eq!(num_to_str(-7.25, 1, false).unwrap(), "-7.3");
    // f32 1234.5678 is 1234.5677490234375.
    assert_eq!(num_to_str(1234.5678, 2, false).unwrap(), "1234.57");
    // f32 99.96 is 99.95999908447266: one decimal carries into a new digit.
    assert_eq!(num_to_str(99.96, 1, false).unwrap(), "100.0");
}

#[test]
fn num_to_str_rounds_the_binary_value() {
    // The num holds f32 0.100000001490116…, and more decimals show it.
    assert_eq!(num_to_str(0.1, 10, false).unwrap(), "0.1000000015");
    // f32 1.005 is 1.00499999523…, below the tie.
    assert_eq!(num_to_str(1.005, 2, false).unwrap(), "1.00");
    // f32 9E9 is 8999999488.
    assert_eq!(num_to_str(9e9, 0, false).unwrap(), "8999999488");
    assert_eq!(num_to_str(f64::from(f32::MAX), 0, false).unwrap(), "340282346638528859811704183484516925440");
    // The argument is a num: a double is narrowed first.
    assert_eq!(num_to_str(0.1_f64, 10, false).unwrap(), "0.1000000015");
}

#[test]
fn num_to_str_exact_ties_round_away_from_zero() {
    assert_eq!(num_to_str(2.5, 0, false).unwrap(), "3");
    assert_eq!(num_to_str(-2.5, 0, false).unwrap(), "-3");
    assert_eq!(num_to_str(0.125, 2, false).unwrap(), "0.13");
    assert_eq!(num_to_str(0.5, 0, false).unwrap(), "1");
    assert_eq!(num_to_str(1.25, 0, true).unwrap(), "1E+00");
    assert_eq!(num_to_str(1.25, 1, true).unwrap(), "1.3E+00");
}

#[test]
fn num_to_str_exponent_form() {
    assert_eq!(num_to_str(12345.0, 0, true).unwrap(), "1E+04");
    assert_eq!(num_to_str(12345.0, 2, true).unwrap(), "1.23E+04");
    assert_eq!(num_to_str(99999.0, 2, true).unwrap(), "1.00E+05");
    assert_eq!(num_to_str(0.0, 2, true).unwrap(), "0.00E+00");
    assert_eq!(num_to_str(-0.00038521, 3, true).unwrap(), "-3.852E-04");
    assert_eq!(num_to_str(9e9, 1, true).unwrap(), "9.0E+09");
}

#[test]
fn num_to_str_negative_values_keep_their_sign() {
    assert_eq!(num_to_str(-0.001, 2, false).unwrap(), "-0.00");
    assert_eq!(num_to_str(-0.001, 3, false).unwrap(), "-0.001");
}

#[test]
fn num_to_str_refuses_bad_decimals() {
    assert_eq!(num_to_str(1.0, -1, false), Err(FormatError::BadDecimals));
    assert_eq!(num_to_str(1.0, NUM_MAX_DECIMALS + 1, false), Err(FormatError::BadDecimals));
    assert_eq!(num_to_str(1.0, NUM_MAX_DECIMALS, false).unwrap(), "1.000000000000000");
    assert_eq!(FormatError::BadDecimals.errno_name(), "ERR_ARGVALERR");
    assert_eq!(decimals_argument(2.0), Ok(2));
    assert_eq!(decimals_argument(2.5), Err(FormatError::BadDecimals));
    assert_eq!(decimals_argument(f64::NAN), Err(FormatError::BadDecimals));
}

#[test]
fn num_to_str_of_non_finite_values() {
    assert_eq!(num_to_str(1e39, 2, false).unwrap(), "INF");
    assert_eq!(num_to_str(f64::NAN, 2, true).unwrap(), "NAN");
    assert_eq!(num_to_text(f32::NEG_INFINITY), "-INF");
}

#[test]
fn dnum_to_str_examples() {
    assert_eq!(dnum_to_str(0.38521, 3, false).unwrap(), "0.385");
    assert_eq!(dnum_to_str(0.38521, 2, true).unwrap(), "3.85E-01");
    assert_eq!(dnum_to_str(4294967295.0, 2, false).unwrap(), "4294967295.00");
    assert_eq!(dnum_to_str(0.1, 15, false).unwrap(), "0.100000000000000");
    assert_eq!(dnum_to_str(2.5, 0, false).unwrap(), "3");
    assert_eq!(dnum_to_str(0.125, 2, false).unwrap(), "0.13");
    assert_eq!(dnum_to_str(1e300, 2, true).unwrap(), "1.00E+300");
    assert_eq!(dnum_to_str(4503599627370496.0, 0, false).unwrap(), "4503599627370496");
}

#[test]
fn dnum_to_str_errors() {
    assert_eq!(dnum_to_str(1.0, -1, false), Err(FormatError::BadDecimals));
    assert_eq!(dnum_to_str(1.0, 16, false), Err(FormatError::BadDecimals));
    // 301 integer digits cannot fit in a string.
    assert_eq!(dnum_to_str(1e300, 2, false), Err(FormatError::StringTooLong));
    assert_eq!(FormatError::StringTooLong.errno_name(), "ERR_STRTOOLNG");
}

// ---- bool, strings, aggregates ------------------------------------------------------

#[test]
fn bool_text() {
    assert_eq!(bool_to_text(true), "TRUE");
    assert_eq!(bool_to_text(false), "FALSE");
}

#[test]
fn string_literals_double_quotes_and_backslashes() {
    assert_eq!(string_to_literal("abc"), "\"abc\"");
    assert_eq!(string_to_literal(""), "\"\"");
    assert_eq!(string_to_literal("say \"hi\""), "\"say \"\"hi\"\"\"");
    assert_eq!(string_to_literal("C:\\dir"), "\"C:\\\\dir\"");
    assert_eq!(string_to_literal("bell\u{7}"), "\"bell\\07\"");
    assert_eq!(string_to_literal("tab\there"), "\"tab\\09here\"");
    assert_eq!(string_to_literal("caf\u{e9}"), "\"caf\u{e9}\"");
}

#[test]
fn aggregates_have_no_spaces() {
    assert_eq!(aggregate_to_text(&[]), "[]");
    assert_eq!(aggregate_to_text(&["1".to_string()]), "[1]");
    let wobj0 = aggregate_to_text(&[
        bool_to_text(false).to_string(),
        bool_to_text(true).to_string(),
        string_to_literal(""),
        aggregate_to_text(&[pos_to_text([0.0; 3]), orient_to_text([1.0, 0.0, 0.0, 0.0])]),
        aggregate_to_text(&[pos_to_text([0.0; 3]), orient_to_text([1.0, 0.0, 0.0, 0.0])]),
    ]);
    assert_eq!(wobj0, "[FALSE,TRUE,\"\",[[0,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]]");
    assert_eq!(check_length(wobj0.clone()), Ok(wobj0));
}

#[test]
fn a_robtarget_is_too_long_for_valtostr() {
    let robtarget = aggregate_to_text(&[
        pos_to_text([1817.3, 905.17, 879.11]),
        orient_to_text([0.96593, 0.0, 0.25882, 0.0]),
        aggregate_to_text(&texts(&[0.0, 0.0, 0.0, 0.0])),
        aggregate_to_text(&texts(&[9e9; 6])),
    ]);
    assert_eq!(
        robtarget,
        "[[1817.3,905.17,879.11],[0.96593,0,0.25882,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]]"
    );
    assert_eq!(char_len(&robtarget), 94);
    assert_eq!(check_length(robtarget), Err(FormatError::StringTooLong));
}

#[test]
fn length_counts_characters_not_bytes() {
    let eighty = "\u{e9}".repeat(80);
    assert_eq!(char_len(&eighty), 80);
    assert!(check_length(eighty.clone()).is_ok());
    assert_eq!(check_length(eighty + "x"), Err(FormatError::StringTooLong));
}

#[test]
fn num_to_str_value_gives_num_to_strs_text() {
    // The allocation-light path for integers must give the same text as NumToStr's
    // general one, for every number of decimals and with \Exp.
    let values = [0.0, -0.0, 1.0, -1.0, 42.0, -999_999.0, 16_777_216.0, 1e14, 2.5, -0.125, f64::from(f32::MAX)];
    for &v in &values {
        for dec in 0..=6 {
            for exp in [false, true] {
                let text = num_to_str(v, dec, exp).map(|s| s.to_string());
                let value = super::num_to_str_value(v, dec, exp).map(|s| s.to_string());
                assert_eq!(text.ok(), value.ok(), "{v} dec {dec} exp {exp}");
            }
        }
    }
}

#[test]
fn num_to_text_writes_small_integers_as_the_digit_rules_do() {
    // The direct path for integers below a million must give %.6G's text.
    for n in (-999_999i32..=999_999).step_by(997).chain([0, 1, -1, 999_999, -999_999, 100_000]) {
        let v = n as f32;
        let rule = Digits::exact_f64(f64::from(n).abs()).general(NUM_SIGNIFICANT_DIGITS);
        let expected = if n < 0 { format!("-{rule}") } else { rule };
        assert_eq!(num_to_text(v), expected, "{n}");
    }
    assert_eq!(num_to_text(-0.0), "0");
    assert_eq!(num_to_text(1e6), "1E+06");
}
