# Benchmark 2: 10^7 iterations of integer arithmetic (+ - * // %).
# (acc - acc % 4) is a multiple of 4, so // is the exact equivalent of RAPID's /.


def main():
    acc = 1
    chk = 0
    for i in range(1, 1001):
        for j in range(1, 10001):
            acc = (acc * 7 + j + i) % 999983
            h = (acc - acc % 4) // 4
            chk = (chk + h) % 999983
    print(f"arith acc={acc}")
    print(f"arith chk={chk}")


main()
