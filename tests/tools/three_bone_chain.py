#!/usr/bin/env python3
"""Independent reference for tests/core/forward_kinematics_test.cpp (ThreeBoneChain.NonAxisRotations).

The textbook three-bone chain (P0..P3, bones along +x in the initial pose):
    q_0 = q_0^local,  q_i = q_{i-1} q_i^local,
    p_i = p_{i-1} + Im( q_{i-1} [0, l^init_{(i-1)~i}] q_{i-1}^* ),  l^init = (l, 0, 0).
Plain Python quaternion arithmetic (w, x, y, z), in double precision; no Kinema code and no GLM.
Run: python3 tests/tools/three_bone_chain.py
"""
import math


def qmul(a, b):
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return (aw * bw - ax * bx - ay * by - az * bz,
            aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw)


def qconj(q):
    return (q[0], -q[1], -q[2], -q[3])


def qnormalize(q):
    n = math.sqrt(sum(c * c for c in q))
    return tuple(c / n for c in q)


def rotate(q, v):
    return qmul(qmul(q, (0.0,) + tuple(v)), qconj(q))[1:]


# Inputs (must match the test): un-normalised (w, x, y, z), normalised before use.
LOCAL = [qnormalize(q) for q in [(0.9, 0.2, -0.3, 0.25),
                                 (0.7, -0.4, 0.5, 0.1),
                                 (0.6, 0.3, 0.2, -0.7),
                                 (0.8, 0.1, 0.1, 0.5)]]
LENGTHS = [1.0, 2.0, 1.5]
P0 = (0.5, -1.0, 2.0)

q = [LOCAL[0]]
for i in range(1, 4):
    q.append(qmul(q[i - 1], LOCAL[i]))
p = [P0]
for i in range(1, 4):
    l = rotate(q[i - 1], (LENGTHS[i - 1], 0.0, 0.0))
    p.append(tuple(p[i - 1][k] + l[k] for k in range(3)))

for i in range(4):
    print("p%d = {%.9f, %.9f, %.9f}" % ((i,) + p[i]))
for i in range(4):
    print("q%d (w,x,y,z) = {%.9f, %.9f, %.9f, %.9f}" % ((i,) + q[i]))
