# Benchmark 1: naive recursive Fibonacci, fib(25) = 75025 (242785 calls).


def fib(n):
    if n < 2:
        return n
    return fib(n - 1) + fib(n - 2)


def main():
    print(f"fib(25)={fib(25)}")


main()
