#!/usr/bin/env python3
"""Writes a RAPID module of about LINES lines for the language-server benchmark: data,
a record, and pairs of routines (a PROC with a FOR, an IF, a call, a move, and the
FUNC it calls), the shape of a large hand-written production module. It checks clean.

Usage: gen_module.py LINES OUT.mod
"""
import sys


def main():
    lines, out = int(sys.argv[1]), sys.argv[2]
    head = [
        "MODULE BigMod",
        "  RECORD partinfo",
        "    num weight;",
        "    string name;",
        "  ENDRECORD",
        "  CONST num N := 10;",
        "  VAR num counter := 0;",
        "  VAR partinfo part;",
        "  CONST robtarget pHome := [[500,0,600],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];",
    ]
    body = []
    r = 0
    while len(head) + len(body) + 1 < lines:
        body += [
            f"  PROC step{r}(num x)",
            "    VAR num i;",
            "    counter := counter + x;",
            "    FOR i FROM 1 TO N DO",
            "      IF i MOD 2 = 0 THEN",
            f"        counter := counter + twice{r}(i);",
            "      ELSE",
            "        TPWrite \"odd \" \\Num:=i;",
            "      ENDIF",
            "    ENDFOR",
            "    part.weight := counter;",
            "    MoveL pHome, v100, z10, tool0;",
            "  ENDPROC",
            f"  FUNC num twice{r}(num v)",
            f"    RETURN v * 2 + {r};",
            "  ENDFUNC",
        ]
        r += 1
    with open(out, "w", encoding="ascii", newline="\n") as f:
        f.write("\n".join(head + body + ["ENDMODULE"]) + "\n")


if __name__ == "__main__":
    main()
