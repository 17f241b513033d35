-- Benchmark: 10^5 lines written (text with a number, then a number alone) to a file
-- in the folder given as the first argument, then read back line by line.
local function main()
  local path = (arg[1] or ".") .. "/bench_fileio.txt"
  local f = assert(io.open(path, "w"))
  for i = 1, 50000 do
    f:write("row ", i, "\n")
    f:write((i * 7) % 9973, "\n")
  end
  f:close()
  f = assert(io.open(path, "r"))
  local lines = 0
  local chk = 0
  for _ = 1, 50000 do
    local s = f:read("l")
    local n = tonumber(f:read("l"))
    chk = (chk * 31 + #s + n) % 65521
    lines = lines + 2
  end
  local last = f:read("l") or "EOF"
  f:close()
  print("fileio lines=" .. lines)
  print("fileio chk=" .. chk)
  print("fileio end=" .. last)
end

main()
