# Benchmark 0: start-up floor. Prints one line.
print(f"startup ok={1}")
