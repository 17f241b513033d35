-- Benchmark 4: bubble sort of 1000 numbers filled by the LCG x := (75x + 74) mod 65537.
local N = 1000
local a = {}

local function main()
  local x = 12345
  local t
  local chk = 0
  for i = 1, N do
    x = (x * 75 + 74) % 65537
    a[i] = x
  end
  for i = 1, N - 1 do
    for j = 1, N - i do
      if a[j] > a[j + 1] then
        t = a[j]
        a[j] = a[j + 1]
        a[j + 1] = t
      end
    end
  end
  for i = 1, N do
    chk = (chk * 31 + a[i]) % 65521
  end
  print("bubble first=" .. a[1])
  print("bubble last=" .. a[N])
  print("bubble chk=" .. chk)
end

main()
