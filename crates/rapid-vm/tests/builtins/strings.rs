//! The string functions (semantics §3.1, §2.3): positions are 1-based and "not found"
//! is StrLen + 1.

use crate::eval::{check, Expect::*};

#[test]
fn strlen_and_strpart() {
    check(&[
        (r#"StrLen("Robotics")"#, Num(8.0)),
        (r#"StrLen("")"#, Num(0.0)),
        // A part is Len characters from ChPos: "Robot" is 1..5, "ics" 6..8.
        (r#"StrPart("Robotics", 1, 5)"#, Str("Robot")),
        (r#"StrPart("Robotics", 6, 3)"#, Str("ics")),
        (r#"StrPart("Robotics", 8, 1)"#, Str("s")),
    ]);
}

#[test]
fn strfind_finds_the_first_character_of_a_set() {
    check(&[
        // The manual's examples.
        (r#"StrFind("Robotics", 1, STR_DIGIT)"#, Num(9.0)),
        (r#"StrFind("IRB 6400", 1, STR_WHITE)"#, Num(4.0)),
        (r#"StrFind("Robotics", 1, "aeiou")"#, Num(2.0)),
        // From position 3 ("botics") the first vowel is the o at 4.
        (r#"StrFind("Robotics", 3, "aeiou")"#, Num(4.0)),
        // \NotInSet: R is upper case, the o at 2 is the first that is not.
        (r#"StrFind("Robotics", 1, STR_UPPER \NotInSet)"#, Num(2.0)),
        (r#"StrFind("IRB 6400", 5, STR_DIGIT \NotInSet)"#, Num(9.0)),
    ]);
}

#[test]
fn strmatch_finds_a_pattern() {
    check(&[
        (r#"StrMatch("Robotics", 1, "bo")"#, Num(3.0)),
        (r#"StrMatch("Robotics", 1, "ics")"#, Num(6.0)),
        // "bo" starts at 3, before ChPos 4: not found, StrLen + 1.
        (r#"StrMatch("Robotics", 4, "bo")"#, Num(9.0)),
    ]);
}

#[test]
fn strmemb_tests_one_character() {
    check(&[
        (r#"StrMemb("Robotics", 2, "aeiou")"#, Bool(true)),
        (r#"StrMemb("Robotics", 3, "aeiou")"#, Bool(false)),
        (r#"StrMemb("IRB 6400", 5, STR_DIGIT)"#, Bool(true)),
    ]);
}

#[test]
fn strorder_compares_by_the_given_order() {
    check(&[
        (r#"StrOrder("FIRST", "SECOND", STR_UPPER)"#, Bool(true)),
        (r#"StrOrder("SECOND", "FIRST", STR_UPPER)"#, Bool(false)),
        // A prefix sorts before the longer string.
        (r#"StrOrder("AB", "ABC", STR_UPPER)"#, Bool(true)),
        (r#"StrOrder("ABC", "AB", STR_UPPER)"#, Bool(false)),
        // The order is Order's, not the character codes': with "CBA", C comes first.
        (r#"StrOrder("C", "A", "CBA")"#, Bool(true)),
    ]);
}

#[test]
fn strmap_replaces_characters_by_position() {
    check(&[
        (r#"StrMap("Robotics", STR_LOWER, STR_UPPER)"#, Str("ROBOTICS")),
        (r#"StrMap("abcabc", "ab", "xy")"#, Str("xycxyc")),
        (r#"StrMap("IRB 6400", " ", "_")"#, Str("IRB_6400")),
    ]);
}

#[test]
fn numtostr_writes_dec_decimals() {
    check(&[
        (r#"NumToStr(0.38521, 3)"#, Str("0.385")),
        (r#"NumToStr(0.38521, 2 \Exp)"#, Str("3.85E-01")),
        (r#"NumToStr(42, 0)"#, Str("42")),
        // Exactly Dec decimals, rounded: 2.74 → 2.7, 2.76 → 2.8, 12 → 12.00.
        (r#"NumToStr(2.74, 1)"#, Str("2.7")),
        (r#"NumToStr(2.76, 1)"#, Str("2.8")),
        (r#"NumToStr(12, 2)"#, Str("12.00")),
    ]);
}

#[test]
fn hex_and_byte_conversions() {
    check(&[
        // 99999999 = 5 * 16^6 + 15 * 16^5 + 5 * 16^4 + 14 * 16^3 + 0 + 15 * 16 + 15.
        (r#"DecToHex("99999999")"#, Str("5F5E0FF")),
        (r#"HexToDec("5F5E0FF")"#, Str("99999999")),
        (r#"DecToHex("255")"#, Str("FF")),
        (r#"StrToByte("10")"#, Num(10.0)),
        (r#"StrToByte("FF" \Hex)"#, Num(255.0)),
        (r#"StrToByte("377" \Okt)"#, Num(255.0)),
        (r#"StrToByte("00001010" \Bin)"#, Num(10.0)),
        (r#"StrToByte("A" \Char)"#, Num(65.0)),
        (r#"ByteToStr(10)"#, Str("10")),
        (r#"ByteToStr(10 \Hex)"#, Str("0A")),
        (r#"ByteToStr(8 \Okt)"#, Str("010")),
        (r#"ByteToStr(5 \Bin)"#, Str("00000101")),
        (r#"ByteToStr(65 \Char)"#, Str("A")),
    ]);
}

#[test]
fn a_string_longer_than_80_characters_is_err_strtoolng() {
    // 41 + 40 = 81 characters, one past the limit; 41 + 39 = 80 is allowed (semantics §2.5).
    let a = "a".repeat(41);
    let too_long = format!("\"{a}\" + \"{}\"", "b".repeat(40));
    let longest = format!("StrLen(\"{a}\" + \"{}\")", "b".repeat(39));
    check(&[(&too_long, Error("string", "ERR_STRTOOLNG")), (&longest, Num(80.0))]);
}
