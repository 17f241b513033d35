//! Bit functions on byte values 0..255 with bit positions 1..8, 1 the least significant
//! (semantics §3.2). 60 is 0011 1100 and 15 is 0000 1111.

use crate::eval::{check, Expect::*};

#[test]
fn and_or_xor_neg() {
    check(&[
        // 0011 1100 AND 0000 1111 = 0000 1100.
        (r#"BitAnd(60, 15)"#, Num(12.0)),
        // OR = 0011 1111.
        (r#"BitOr(60, 15)"#, Num(63.0)),
        // XOR = 0011 0011.
        (r#"BitXOr(60, 15)"#, Num(51.0)),
        // NOT within 8 bits = 1100 0011.
        (r#"BitNeg(60)"#, Num(195.0)),
        (r#"BitNeg(0)"#, Num(255.0)),
    ]);
}

#[test]
fn shifts_lose_the_bits_shifted_out() {
    check(&[
        // 0011 1100 << 2 = 1111 0000; << 3 = (1) 1110 0000, the top bit lost.
        (r#"BitLSh(60, 2)"#, Num(240.0)),
        (r#"BitLSh(60, 3)"#, Num(224.0)),
        (r#"BitLSh(128, 1)"#, Num(0.0)),
        // >> 2 = 0000 1111; >> 3 = 0000 0111 (the low 1 lost).
        (r#"BitRSh(60, 2)"#, Num(15.0)),
        (r#"BitRSh(60, 3)"#, Num(7.0)),
        (r#"BitRSh(1, 1)"#, Num(0.0)),
    ]);
}

#[test]
fn bitcheck_counts_from_the_least_significant_bit() {
    check(&[
        // 60 = 32 + 16 + 8 + 4: bits 3, 4, 5 and 6.
        (r#"BitCheck(60, 1)"#, Bool(false)),
        (r#"BitCheck(60, 2)"#, Bool(false)),
        (r#"BitCheck(60, 3)"#, Bool(true)),
        (r#"BitCheck(60, 6)"#, Bool(true)),
        (r#"BitCheck(60, 7)"#, Bool(false)),
        (r#"BitCheck(128, 8)"#, Bool(true)),
    ]);
}
