-- Benchmark 0: start-up floor. Prints one line.
print("startup ok=" .. 1)
