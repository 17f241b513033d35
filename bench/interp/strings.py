# Benchmark 3: 10^6 string concatenations. The string grows by 2 or 3 characters at a
# time and is reset once longer than 76 characters, so it never exceeds 80.


def main():
    s = ""
    resets = 0
    chk = 0
    for i in range(1, 1001):
        for j in range(1, 1001):
            s = s + str((i + j) % 97) + ";"
            n = len(s)
            if n > 76:
                chk = (chk * 31 + n) % 65521
                resets = resets + 1
                s = ""
    chk = (chk * 31 + len(s)) % 65521
    print(f"strings resets={resets}")
    print(f"strings chk={chk}")


main()
