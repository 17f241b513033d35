#!/usr/bin/env python3
"""Writes an offline-programming style module of N MoveL lines for an IRB 120: a
zigzag raster over a 200 x 200 mm patch in front of the robot, tool pointing down,
fly-by zones, a fine point at the end. Deterministic (no randomness)."""
import sys

def main() -> None:
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 100_000
    out = sys.argv[2] if len(sys.argv) > 2 else "/dev/stdout"
    lines = ["MODULE OlpRaster", "  PROC main()"]
    lines.append("    MoveAbsJ [[0,0,0,0,60,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;")
    for i in range(n):
        row, col = divmod(i, 20)
        x = 300 + (col * 10 if row % 2 == 0 else (19 - col) * 10)
        y = -100 + (row % 20) * 10
        z = 350 + (row // 20 % 5) * 10
        zone = "fine" if i == n - 1 else "z5"
        lines.append(f"    MoveL [[{x},{y},{z}],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v500, {zone}, tool0;")
    lines += ["  ENDPROC", "ENDMODULE", ""]
    with open(out, "w", encoding="ascii") as f:
        f.write("\n".join(lines))

if __name__ == "__main__":
    main()
