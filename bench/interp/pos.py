# Benchmark 5: 3*10^5 rounds of pos arithmetic: record construction, add, scale,
# cross product, dot product and field access. A pos is an immutable (x, y, z) tuple;
# each operation returns a new one, as RAPID's value semantics do.


def add(p, q):
    return (p[0] + q[0], p[1] + q[1], p[2] + q[2])


def scale(k, p):
    return (k * p[0], k * p[1], k * p[2])


def cross(p, q):
    return (p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0])


def dot(p, q):
    return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]


def main():
    chk = 0
    for i in range(1, 1001):
        for j in range(1, 301):
            a = (i % 13, j % 11, (i + j) % 7)
            b = (j % 5, 3, i % 9)
            c = scale(2, add(a, b))
            c = cross(c, a)
            d = dot(c, b)
            chk = (chk + d + c[0] + c[1] + c[2] + 100000) % 999983
    print(f"pos chk={chk}")


main()
