# Independent hand calculation: the joint-interpolated corners of the palletizing
# example (IRB 120), by the timing model docs/semantics.md states: a corner is a
# constant-acceleration blend, time 4d/(v_in + v_out) with d and v in the corner's
# metric; joint corners use the metric of each axis divided by its maximum speed.
import math
import numpy as np
a1, a2, b, c1, c2, c3, c4 = 0.0, -70.0, 0.0, 290.0, 270.0, 302.0, 72.0
VMAX = np.array([250, 250, 250, 320, 320, 420.0])
W = 1.0 / VMAX
k = math.hypot(a2, c3); psi3 = math.atan2(a2, c3)
def Rz(t): c, s = math.cos(t), math.sin(t); return np.array([[c,-s,0],[s,c,0],[0,0,1.0]])
def Ry(t): c, s = math.cos(t), math.sin(t); return np.array([[c,0,s],[0,1,0],[-s,0,c]])
def fk(q):
    t = np.radians(q); t3 = t[2] + math.pi/2
    cx1 = c2*math.sin(t[1]) + k*math.sin(t[1]+t3+psi3) + a1
    cz1 = c2*math.cos(t[1]) + k*math.cos(t[1]+t3+psi3)
    c0 = np.array([cx1*math.cos(t[0]), cx1*math.sin(t[0]), cz1 + c1])
    R = Rz(t[0]) @ Ry(t[1]+t3) @ Rz(t[3]) @ Ry(t[4]) @ Rz(t[5])
    return c0 + c4 * R[:,2], R
def ik(p, R, seed):
    wc = p - c4 * R[:,2]; best = None
    for front in (True, False):
        t1 = math.atan2(wc[1], wc[0]) + (0 if front else math.pi)
        nx = math.hypot(wc[0], wc[1]) * (1 if front else -1) - a1; h = wc[2] - c1
        s1sq = nx*nx + h*h; s1 = math.sqrt(s1sq)
        for up in (1, -1):
            c = (s1sq + c2*c2 - k*k) / (2*s1*c2)
            if abs(c) > 1: continue
            t2 = -up*math.acos(c) + math.atan2(nx, h)
            t3o = up*math.acos((s1sq - c2*c2 - k*k) / (2*c2*k)) - psi3
            Rce = (Rz(t1) @ Ry(t2 + t3o)).T @ R
            for flip in (1, -1):
                t5 = flip*math.acos(max(-1,min(1,Rce[2,2])))
                t4 = math.atan2(flip*Rce[1,2], flip*Rce[0,2]); t6 = math.atan2(flip*Rce[2,1], -flip*Rce[2,0])
                q = (np.degrees([t1, t2, t3o - math.pi/2, t4, t5, t6]) + 180) % 360 - 180
                for j in (3, 5):   # turns nearest the seed
                    q[j] += 360 * round((seed[j] - q[j]) / 360)
                p2, R2 = fk(q); assert np.allclose(p2, p, atol=1e-6) and np.allclose(R2, R, atol=1e-9)
                d = np.max(np.abs(q - seed) * W)
                if best is None or d < best[0]: best = (d, q)
    return best[1]
R = np.diag([-1.0, 1.0, -1.0])     # [0,0,1,0]: tool z down
TOOL = 100.0
def q_at(tcp, seed): return ik(np.array(tcp) + TOOL * np.array([0,0,1.0]), R, seed)
def wdist(a, b): return float(np.linalg.norm((a - b) * W))
V = 400.0
pick = np.array([250, -250, 150.0]); P1 = pick + [0, 0, 100]
places = [(0,0),(80,0),(0,80),(80,80),(0,160),(80,160)]

# With the cap: each end's metric speed is at most `cap`; the TCP brakes from 400 mm/s
# to the end's speed on the move before (and speeds up after) at 10 m/s², each costing
# (v - v_e)² / (2·a·v) against cruising; the corner walks from rate v0/(2 L_in) to
# v1/(2 L_out).
ACC = 10000.0
def capped(prev_pt, point, next_pt, seed):
    d_in = (point - prev_pt) / np.linalg.norm(point - prev_pt)
    d_out = (next_pt - point) / np.linalg.norm(next_pt - point)
    qa = q_at(point - 20*d_in, seed); qa1 = q_at(point - 21*d_in, qa)
    qp = q_at(point, qa)
    qb = q_at(point + 20*d_out, qp); qb1 = q_at(point + 21*d_out, qb)
    s_in, s_out = wdist(qa, qa1), wdist(qb, qb1)
    L_in, L_out = wdist(qp, qa), wdist(qb, qp)
    u1, u2 = (qp - qa) * W, (qb - qp) * W
    turn = math.acos(np.dot(u1, u2) / np.linalg.norm(u1) / np.linalg.norm(u2))
    cap = math.sqrt(min(ACC * s_in, ACC * s_out) * min(L_in, L_out) / math.sin(turn / 2))
    v0, v1 = min(V * s_in, cap), min(V * s_out, cap)
    T = 2.0 / (v0 / (2 * L_in) + v1 / (2 * L_out))
    ve_in, ve_out = v0 / s_in, v1 / s_out          # TCP speeds at the ends
    pen = (V - ve_in)**2 / (2 * ACC * V) + (V - ve_out)**2 / (2 * ACC * V)
    return T + pen - 0.1, qp
total = 0.0
q = q_at(pick, np.array([0,0,0,0,90,0.0]))
for layer in (1, 2):
    for n, (x, y) in enumerate(places):
        target = np.array([200.0 + x, 100 + y, 150 + 50*(layer-1)]); A = target + [0, 0, 100]
        d1, qp = capped(pick, P1, A, q); total += d1
        if not (layer == 2 and n == 5):
            d2, _ = capped(target, A, P1, qp); total += d2
            print(f"L{layer} box{n}: {d1*1000:.2f} ms, {d2*1000:.2f} ms")
        else:
            print(f"L{layer} box{n}: {d1*1000:.2f} ms")
print("extra over TCP corners:", total)
