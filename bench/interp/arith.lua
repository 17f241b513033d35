-- Benchmark 2: 10^7 iterations of integer arithmetic (+ - * // %).
-- (acc - acc % 4) is a multiple of 4, so // is the exact equivalent of RAPID's /.
local function main()
  local acc = 1
  local chk = 0
  local h
  for i = 1, 1000 do
    for j = 1, 10000 do
      acc = (acc * 7 + j + i) % 999983
      h = (acc - acc % 4) // 4
      chk = (chk + h) % 999983
    end
  end
  print("arith acc=" .. acc)
  print("arith chk=" .. chk)
end

main()
