-- Benchmark: the string functions over 2*10^5 short strings built with tostring:
-- length, find (a character and "not found"), sub and a character map on each.
local function main()
  local map = {}
  local from, to = "0123456789abcx", "9876543210ABCY"
  for k = 1, #from do
    map[from:sub(k, k)] = to:sub(k, k)
  end
  local s, t, part, n, p, q
  local nines = 0
  local chk = 0
  for i = 1, 200000 do
    s = "k" .. tostring(i % 1000) .. "x" .. tostring(i % 7) .. "abc"
    n = #s
    p = s:find("x", 2, true) or (n + 1)
    part = s:sub(2, p - 1)
    t = (s:gsub(".", map))
    q = t:find("9", 1, true) or (#t + 1)
    if t:sub(p + 1, p + 1) == "9" then
      nines = nines + 1
    end
    chk = (chk * 31 + n * 7 + p * 3 + #part + q) % 65521
  end
  print("strops nines=" .. nines)
  print("strops last=" .. t)
  print("strops chk=" .. chk)
end

main()
