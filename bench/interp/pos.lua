-- Benchmark 5: 3*10^5 rounds of pos arithmetic: record construction, add, scale,
-- cross product, dot product and field access. A pos is a table {x=, y=, z=}; each
-- operation returns a new one, as RAPID's value semantics do.
local function add(p, q)
  return { x = p.x + q.x, y = p.y + q.y, z = p.z + q.z }
end

local function scale(k, p)
  return { x = k * p.x, y = k * p.y, z = k * p.z }
end

local function cross(p, q)
  return { x = p.y * q.z - p.z * q.y, y = p.z * q.x - p.x * q.z, z = p.x * q.y - p.y * q.x }
end

local function dot(p, q)
  return p.x * q.x + p.y * q.y + p.z * q.z
end

local function main()
  local a, b, c, d
  local chk = 0
  for i = 1, 1000 do
    for j = 1, 300 do
      a = { x = i % 13, y = j % 11, z = (i + j) % 7 }
      b = { x = j % 5, y = 3, z = i % 9 }
      c = scale(2, add(a, b))
      c = cross(c, a)
      d = dot(c, b)
      chk = (chk + d + c.x + c.y + c.z + 100000) % 999983
    end
  end
  print("pos chk=" .. chk)
end

main()
