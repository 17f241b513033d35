# Benchmark 6: 10^6 calls of a function that increments its by-reference argument
# (a one-element list stands in for RAPID's VAR parameter).


def incr(x):
    x[0] = x[0] + 1


def main():
    a = [0]
    b = [0]
    for _ in range(500000):
        incr(a)
        incr(b)
    print(f"varcall a={a[0]}")
    print(f"varcall b={b[0]}")


main()
