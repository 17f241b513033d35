# Independent hand calculation of the pick_and_place example's cycle time
# (IRB 2600-12/1.65 OPW parameters and axis speeds from shared/reference/motion.md;
# the timing model as docs/semantics.md states it). Not project code.
import math
import numpy as np
a1, a2, b, c1, c2, c3, c4 = 150.0, -115.0, 0.0, 445.0, 700.0, 795.0, 85.0
VMAX = np.array([175, 175, 175, 360, 360, 500.0])
k = math.hypot(a2, c3); psi3 = math.atan2(a2, c3)

def Rz(t): c, s = math.cos(t), math.sin(t); return np.array([[c,-s,0],[s,c,0],[0,0,1.0]])
def Ry(t): c, s = math.cos(t), math.sin(t); return np.array([[c,0,s],[0,1,0],[-s,0,c]])
def quat(q):
    w,x,y,z = q; n = math.sqrt(w*w+x*x+y*y+z*z); w,x,y,z = w/n,x/n,y/n,z/n
    return np.array([[1-2*(y*y+z*z), 2*(x*y-w*z), 2*(x*z+w*y)],[2*(x*y+w*z), 1-2*(x*x+z*z), 2*(y*z-w*x)],[2*(x*z-w*y), 2*(y*z+w*x), 1-2*(x*x+y*y)]])

def fk(q):
    t = np.radians(q); t3 = t[2] + math.pi/2
    cx1 = c2*math.sin(t[1]) + k*math.sin(t[1]+t3+psi3) + a1
    cz1 = c2*math.cos(t[1]) + k*math.cos(t[1]+t3+psi3)
    c0 = np.array([cx1*math.cos(t[0]), cx1*math.sin(t[0]), cz1 + c1])
    R0c = Rz(t[0]) @ Ry(t[1]+t3)
    R = R0c @ Rz(t[3]) @ Ry(t[4]) @ Rz(t[5])
    return c0 + c4 * R[:,2], R

def ik(flange_p, R, seed):
    wc = flange_p - c4 * R[:,2]
    best = None
    for front in (True, False):
        t1 = math.atan2(wc[1], wc[0]) if front else math.atan2(wc[1], wc[0]) + math.pi
        nx = math.hypot(wc[0], wc[1]) * (1 if front else -1) - a1
        h = wc[2] - c1
        s1sq = nx*nx + h*h; s1 = math.sqrt(s1sq)
        for up in (1, -1):
            c = (s1sq + c2*c2 - k*k) / (2*s1*c2)
            if abs(c) > 1: continue
            t2 = -up*math.acos(c) + math.atan2(nx, h)
            c3v = (s1sq - c2*c2 - k*k) / (2*c2*k)
            t3o = up*math.acos(c3v) - psi3
            q3 = t3o - math.pi/2
            R0c = Rz(t1) @ Ry(t2 + t3o)
            Rce = R0c.T @ R
            for flip in (1, -1):
                t5 = flip*math.acos(max(-1,min(1,Rce[2,2])))
                if abs(math.sin(t5)) < 1e-9: continue
                t4 = math.atan2(flip*Rce[1,2], flip*Rce[0,2])
                t6 = math.atan2(flip*Rce[2,1], -flip*Rce[2,0])
                q = np.degrees([t1, t2, q3, t4, t5, t6])
                q = (q + 180) % 360 - 180
                p2, R2 = fk(q)
                assert np.allclose(p2, flange_p, atol=1e-6) and np.allclose(R2, R, atol=1e-9), (q, p2, flange_p)
                d = np.max(np.abs(q - seed) / VMAX)
                if best is None or d < best[0]: best = (d, q)
    return best[1]

TOOL = 142.5
def flange_of(tcp, R): return np.array(tcp) - TOOL * R[:,2]
down = quat([0,0,1,0])
pallet = quat([0.707107,0,0,0.707107])
def world_pallet(x, y, z): return np.array([700,450,120]) + pallet @ np.array([x,y,z])
targets = {
  'home': (np.array([600,0,900.0]), down),
  'pickApp': (np.array([950,-400,310.0]) + [120,35,115], down),
  'pick': (np.array([950,-400,310.0]) + [120,35,15], down),
}
for i in range(4):
    targets[f'placeApp{i}'] = (world_pallet(50+110*i, 50, 120), pallet @ down)
    targets[f'place{i}'] = (world_pallet(50+110*i, 50, 20), pallet @ down)

q0 = np.zeros(6)
p0, R0 = fk(q0)
tcp0 = p0 + TOOL * R0[:,2]
print('start tcp', tcp0)
def angle(Ra, Rb):
    M = Ra.T @ Rb; return math.degrees(math.acos(max(-1,min(1,(np.trace(M)-1)/2))))
ACC = 10000 * 175/250; SETTLE = 0.05
def movej(qa, qb, tcpa, tcpb, Ra, Rb, v=1000.0, vori=500.0):
    t_axis = np.max(np.abs(qb-qa)/VMAX)
    chord = np.linalg.norm(np.array(tcpb)-np.array(tcpa)); ang = angle(Ra, Rb)
    cap = max(t_axis, chord/v, ang/vori)
    f = t_axis / cap
    T = t_axis/f + f*0.15 if t_axis > 0 else 0
    return T, t_axis, chord, ang, f
def movel(L, v): return L/v + v/ACC if L >= v*v/ACC else 2*math.sqrt(L/ACC)

Q = {}
seed = q0
order = ['home','pickApp','pick'] + [f'placeApp{i}' for i in range(4)]
Q['home'] = ik(flange_of(*targets['home']), targets['home'][1], q0)
Q['pickApp'] = ik(flange_of(*targets['pickApp']), down, Q['home'])
for i in range(4):
    Q[f'placeApp{i}'] = ik(flange_of(*targets[f'placeApp{i}']), targets[f'placeApp{i}'][1], Q['pickApp'])
for n, q in Q.items(): print(n, np.round(q, 3), 'tcp', np.round(targets[n][0], 3))

def J(a, b):
    (ta, Ra), (tb, Rb) = targets[a] if a != 'start' else (tcp0, R0), targets[b]
    qa = Q[a] if a != 'start' else q0
    return movej(qa, Q[b], ta, tb, Ra, Rb)
print()
m0 = J('start', 'home'); print('move0 start->home', m0)
ja = J('home', 'pickApp'); print('first a home->pickApp', ja)
Lb = movel(100, 200); Lc = movel(100, 500)
print('MoveL 100 v200', Lb, ' v500', Lc)
A = {}; D = {}
for i in range(4):
    D[i] = J('pickApp', f'placeApp{i}'); print('d', i, D[i])
    if i > 0:
        A[i] = J(f'placeApp{i-1}', 'pickApp'); print('a', i, A[i])
E = J('placeApp3', 'home'); print('end', E)

# Upper bound: every point a stop point (fine points settle 0.05 s).
t = max(m0[0], 0.5)          # the part is there at 0.5 s; a starts when both hold
t += ja[0] + Lb + SETTLE + 0.3 + Lc + D[0][0] + Lb + SETTLE   # Reset of part 1 at t
for i in range(1, 4):
    t += 1.2 + A[i][0] + Lb + SETTLE + 0.3 + Lc + D[i][0] + Lb + SETTLE
t += 0.2 + Lc + E[0] + SETTLE
print('upper bound', t)
# Largest saving of a corner: half of each ramp on its two sides (the ramp time a
# stop costs beyond cruising) plus the zone legs d/v_in + d/v_out it may cut.
def ramp_half_j(m): return m[4] * 0.15 / 2
def ramp_half_l(v): return v / ACC / 2
def zone_cut(d, vin, vout): return d / vin + d / vout
save = 0.0
save += ramp_half_j(m0) + ramp_half_j(ja) + zone_cut(50, 1000, 1000)           # pHome z50
for i in range(4):
    a = ja if i == 0 else A[i]
    save += ramp_half_j(a) + ramp_half_l(200) + zone_cut(20, 1000, 200)          # a -> b
    save += ramp_half_l(500) + ramp_half_j(D[i]) + zone_cut(20, 500, 1000)       # c -> d
    save += ramp_half_j(D[i]) + ramp_half_l(200) + zone_cut(20, 1000, 200)       # d -> e
save += ramp_half_l(500) + ramp_half_j(E) + zone_cut(20, 500, 1000)              # f3 -> end
print('largest saving', save, 'lower bound', t - save, 'mid', t - save/2, '+-', save/2)
