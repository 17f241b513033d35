-- Benchmark 6: 10^6 calls of a function that increments its by-reference argument
-- (a one-element table stands in for RAPID's VAR parameter).
local function incr(x)
  x[1] = x[1] + 1
end

local function main()
  local a = { 0 }
  local b = { 0 }
  for _ = 1, 500000 do
    incr(a)
    incr(b)
  end
  print("varcall a=" .. a[1])
  print("varcall b=" .. b[1])
end

main()
