-- Benchmark 3: 10^6 string concatenations. The string grows by 2 or 3 characters at a
-- time and is reset once longer than 76 characters, so it never exceeds 80.
local function main()
  local s = ""
  local n
  local resets = 0
  local chk = 0
  for i = 1, 1000 do
    for j = 1, 1000 do
      s = s .. tostring((i + j) % 97) .. ";"
      n = #s
      if n > 76 then
        chk = (chk * 31 + n) % 65521
        resets = resets + 1
        s = ""
      end
    end
  end
  chk = (chk * 31 + #s) % 65521
  print("strings resets=" .. resets)
  print("strings chk=" .. chk)
end

main()
