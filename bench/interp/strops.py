# Benchmark: the string functions over 2*10^5 short strings built with str():
# len, find (a character and "not found"), slicing and a character map on each.


def main():
    table = str.maketrans("0123456789abcx", "9876543210ABCY")
    t = ""
    nines = 0
    chk = 0
    for i in range(1, 200001):
        s = "k" + str(i % 1000) + "x" + str(i % 7) + "abc"
        n = len(s)
        p = s.find("x", 1) + 1 or n + 1
        part = s[1 : p - 1]
        t = s.translate(table)
        q = t.find("9") + 1 or len(t) + 1
        if t[p : p + 1] == "9":
            nines = nines + 1
        chk = (chk * 31 + n * 7 + p * 3 + len(part) + q) % 65521
    print(f"strops nines={nines}")
    print(f"strops last={t}")
    print(f"strops chk={chk}")


main()
