//! Arithmetic and math functions (semantics §2.3, §3.2): trigonometry in degrees,
//! Round and Trunc to `\Dec` decimals, DIV and MOD on integers.

use crate::eval::{check, Expect::*};

#[test]
fn round_and_trunc() {
    check(&[
        // The manual's examples: 0.38521 to 3, 1 and 0 decimals.
        (r#"Round(0.38521 \Dec:=3)"#, Num(0.385)),
        (r#"Round(0.38521 \Dec:=1)"#, Num(0.4)),
        (r#"Round(0.38521)"#, Num(0.0)),
        (r#"Trunc(0.38521 \Dec:=3)"#, Num(0.385)),
        (r#"Trunc(0.38521 \Dec:=1)"#, Num(0.3)),
        (r#"Trunc(0.38521)"#, Num(0.0)),
        (r#"Round(2.7)"#, Num(3.0)),
        (r#"Trunc(2.7)"#, Num(2.0)),
    ]);
}

#[test]
fn powers_roots_and_absolute_values() {
    check(&[
        (r#"Abs(-3.5)"#, Num(3.5)),
        (r#"Abs(2)"#, Num(2.0)),
        (r#"Sqrt(16)"#, Num(4.0)),
        (r#"Sqrt(2.25)"#, Num(1.5)),
        (r#"Pow(2, 10)"#, Num(1024.0)),
        (r#"Pow(9, 0.5)"#, Num(3.0)),
        (r#"Exp(0)"#, Num(1.0)),
    ]);
}

#[test]
fn trigonometry_is_in_degrees() {
    check(&[
        (r#"Sin(30)"#, Num(0.5)),
        (r#"Cos(60)"#, Num(0.5)),
        (r#"Tan(45)"#, Num(1.0)),
        (r#"Sin(90)"#, Num(1.0)),
        (r#"ASin(1)"#, Num(90.0)),
        (r#"ACos(0)"#, Num(90.0)),
        (r#"ACos(-1)"#, Num(180.0)),
        (r#"ATan(1)"#, Num(45.0)),
        // ATan2(Y, X) in (-180, 180]: (-1, 1) is in the second quadrant, (-1, -1) the third.
        (r#"ATan2(1, -1)"#, Num(135.0)),
        (r#"ATan2(-1, -1)"#, Num(-135.0)),
        (r#"ATan2(0, -1)"#, Num(180.0)),
    ]);
}

#[test]
fn div_and_mod_on_integers() {
    check(&[
        (r#"7 DIV 2"#, Num(3.0)),
        (r#"7 MOD 2"#, Num(1.0)),
        (r#"12 DIV 4"#, Num(3.0)),
        (r#"12 MOD 5"#, Num(2.0)),
        (r#"7 DIV 0"#, Error("num", "ERR_DIVZERO")),
        (r#"1 / 0"#, Error("num", "ERR_DIVZERO")),
    ]);
}
