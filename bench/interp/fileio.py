# Benchmark: 10^5 lines written (text with a number, then a number alone) to a file
# in the folder given as the first argument, then read back line by line.
import sys


def main():
    path = (sys.argv[1] if len(sys.argv) > 1 else ".") + "/bench_fileio.txt"
    with open(path, "w") as f:
        for i in range(1, 50001):
            f.write(f"row {i}\n")
            f.write(f"{(i * 7) % 9973}\n")
    lines = 0
    chk = 0
    with open(path) as f:
        for _ in range(50000):
            s = f.readline().rstrip("\n")
            n = int(f.readline())
            chk = (chk * 31 + len(s) + n) % 65521
            lines = lines + 2
        last = f.readline().rstrip("\n") or "EOF"
    print(f"fileio lines={lines}")
    print(f"fileio chk={chk}")
    print(f"fileio end={last}")


main()
