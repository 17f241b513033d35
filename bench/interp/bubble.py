# Benchmark 4: bubble sort of 1000 numbers filled by the LCG x := (75x + 74) mod 65537.
N = 1000
a = [0] * N


def main():
    x = 12345
    chk = 0
    for i in range(N):
        x = (x * 75 + 74) % 65537
        a[i] = x
    for i in range(1, N):
        for j in range(N - i):
            if a[j] > a[j + 1]:
                t = a[j]
                a[j] = a[j + 1]
                a[j + 1] = t
    for i in range(N):
        chk = (chk * 31 + a[i]) % 65521
    print(f"bubble first={a[0]}")
    print(f"bubble last={a[N - 1]}")
    print(f"bubble chk={chk}")


main()
