#!/usr/bin/env python3
"""Recreate the generated inputs of this folder byte for byte.

Files too large to write by hand (E0122_*) and binary inputs whose expectations live in
a sidecar `<name>.expect` (E0109_1, E0101_3, E0121_8, E0110_2, OK_latin1_fallback).
Run from anywhere: `python3 tests/check/err/gen_generated.py`.
"""
import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))


def write(name, data):
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(data)


def text(lines):
    return ("\n".join(lines) + "\n").encode("utf-8")


# E0122_1: 10,000 nested parentheses on one line (line 7).
depth = 10000
write("E0122_1_deep_parens.mod", text([
    "! expect: E0122 line 7",
    f"! {depth} nested parentheses on one line: deeper than the 256-level expression limit",
    "MODULE E0122_1",
    "  VAR num n;",
    "  PROC main()",
    "    n := 0;",
    "    n := " + "(" * depth + "1" + ")" * depth + ";",
    "  ENDPROC",
    "ENDMODULE",
]))

# E0122_2: 1,000 nested IFs, one per line; IF number k is on line 5 + k, so the 257th is on 262.
nif = 1000
write("E0122_2_deep_if.mod", text(
    ["! expect: E0122 line 262",
     f"! {nif} nested IF blocks, one per line: the 257th crosses the 256-level statement limit",
     "MODULE E0122_2", "  VAR bool b;", "  PROC main()"]
    + ["    IF b THEN"] * nif + ["    b := FALSE;"] + ["    ENDIF"] * nif
    + ["  ENDPROC", "ENDMODULE"]))

# Sidecar inputs: the expectation cannot (or should not) be a comment inside the file.
rng = random.Random(1109)
write("E0109_1_encrypted.mod", bytes([0xFC]) + bytes(rng.getrandbits(8) for _ in range(200)))
write("E0109_1_encrypted.expect", b"E0109 line 1\n")

write("E0101_3_nul_bytes.mod",
      b"MODULE E0101_3\n  VAR num n;\n  PROC main()\n    n := 1;\n"
      b"    n := n\x00\x00\x00 + 1;\n  ENDPROC\nENDMODULE\n")
write("E0101_3_nul_bytes.expect", b"E0101 line 5\n")

# Ends right after a complete statement, without a final newline.
write("E0121_8_truncated.mod",
      b"MODULE E0121_8\n  VAR num n;\n  PROC main()\n    n := 1;\n    n := n + 1;")
write("E0121_8_truncated.expect", b"E0121 line 1\nE0121 line 3\n")

write("E0110_2_header_bad_close.mod",
      b"%%%\n  VERSION:1\n  LANGUAGE:ENGLISH\n%%\nMODULE E0110_2\n  VAR num n;\nENDMODULE\n")
write("E0110_2_header_bad_close.expect", b"E0110 line 1\n")

write("OK_latin1_fallback.mod",
      b"! Not valid UTF-8 (a lone 0xE9 byte in the comment below): decoded as Latin-1, checks clean.\n"
      b"MODULE OK_latin1_fallback\n"
      b"  ! Caf\xe9 cr\xe8me br\xfbl\xe9e \xff\n"
      b"  VAR num n;\n  PROC main()\n    n := 1;\n  ENDPROC\nENDMODULE\n")
write("OK_latin1_fallback.expect", b"")
