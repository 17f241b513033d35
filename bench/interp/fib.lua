-- Benchmark 1: naive recursive Fibonacci, fib(25) = 75025 (242785 calls).
local function fib(n)
  if n < 2 then
    return n
  end
  return fib(n - 1) + fib(n - 2)
end

local function main()
  print("fib(25)=" .. fib(25))
end

main()
