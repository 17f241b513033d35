//! Catalogue chapter: string functions and conversions (manual §1.19, plus ByteToStr/StrToByte of §1.6).

use super::entry::*;

pub(crate) const ENTRIES: &[Entry] = &[
    // --- Basic operations -----------------------------------------------------------------
    // uncertain: added in RW 6.11. Programs use its value (`s := StrFormat("p{1}.bin"\Arg1:=n)`),
    // so it is a function; the public record shows {1}/{2} placeholders but not the highest
    // \ArgN, so ten are accepted rather than reject a real program.
    routine(
        r#"FUNC string StrFormat(string Str \string Arg1 \string Arg2 \string Arg3 \string Arg4 \string Arg5 \string Arg6 \string Arg7 \string Arg8 \string Arg9 \string Arg10)"#,
        "Returns a text with its {1}, {2} ... placeholders replaced by the given strings.",
    ),
    routine(r#"FUNC num StrLen(string Str)"#, "Returns the number of characters in a string."),
    routine(
        r#"FUNC string StrPart(string Str, num ChPos, num Len)"#,
        "Returns Len characters of Str starting at position ChPos (1-based).",
    ),
    // --- Comparing and searching ----------------------------------------------------------
    routine(
        r#"FUNC bool StrMemb(string Str, num ChPos, string Set)"#,
        "Tells whether the character at ChPos belongs to the character set Set.",
    ),
    routine(
        r#"FUNC num StrFind(string Str, num ChPos, string Set \switch NotInSet)"#,
        "Position of the first character from ChPos in (or not in) Set; length+1 if none.",
    ),
    routine(
        r#"FUNC num StrMatch(string Str, num ChPos, string Pattern)"#,
        "Position of the first occurrence of Pattern from ChPos; length+1 if none.",
    ),
    routine(
        r#"FUNC bool StrOrder(string Str1, string Str2, string Order)"#,
        "Tells whether Str1 sorts before or equal to Str2 in the character order Order.",
    ),
    // --- Conversions ------------------------------------------------------------------------
    routine(
        r#"FUNC num DnumToNum(dnum Value \switch Integer)"#,
        "Converts a dnum to a num; error if it does not fit (or is not integral with Integer).",
    ),
    routine(r#"FUNC dnum NumToDnum(num Value)"#, "Converts a num to a dnum."),
    routine(
        r#"FUNC string NumToStr(num Val, num Dec \switch Exp)"#,
        "Formats a num with Dec decimals, optionally in exponent form.",
    ),
    routine(
        r#"FUNC string DnumToStr(dnum Val, num Dec \switch Exp)"#,
        "Formats a dnum with Dec decimals, optionally in exponent form.",
    ),
    routine(r#"FUNC string ValToStr(anytype Val)"#, "Writes a value of any type as text in RAPID literal syntax."),
    routine(
        r#"FUNC bool StrToVal(string Str, INOUT anytype Val)"#,
        "Parses a RAPID literal into Val; returns FALSE when the text does not fit its type.",
    ),
    routine(
        r#"FUNC string StrMap(string Str, string FromMap, string ToMap)"#,
        "Copies Str, replacing each character found in FromMap by the one at the same place in ToMap.",
    ),
    routine(
        r#"FUNC byte StrToByte(string ConStr \switch Hex | switch Okt | switch Bin | switch Char)"#,
        "Converts a decimal, hex, octal, binary or one-character string to a byte.",
    ),
    routine(
        r#"FUNC string ByteToStr(byte BitData \switch Hex | switch Okt | switch Bin | switch Char)"#,
        "Converts a byte to decimal, hex, octal, binary or one-character text.",
    ),
    routine(r#"FUNC string DecToHex(string Str)"#, "Converts a decimal digit string to a hexadecimal digit string."),
    routine(r#"FUNC string HexToDec(string Str)"#, "Converts a hexadecimal digit string to a decimal digit string."),
];
