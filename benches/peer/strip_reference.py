#!/usr/bin/env python3
"""An independent reference for rollbem's strip of half-spaces (`[mesh] strip_width`): the normal problem of
CONTACT's examples/carter2d.inp (two identical bodies, G = 82 000, nu = 0.28, h = 0.001 x^2, FN = 35 780 on one row
of 55 elements of 0.04 x DY from XC1 = -1.05) solved in 40-digit arithmetic (mpmath).

Nothing is shared with rollbem or CONTACT: the influence coefficient is the point-load solution of a half-space,
u_z = (1 - nu) P / (2 pi G rho) per body, integrated over the rectangle in the textbook form
[[X ln(Y + rho) + Y ln(X + rho)]] (both bodies: twice that), and the contact problem is solved by an active-set
iteration on the exact equations (p >= 0, gap >= 0, p gap = 0, sum p DX DY = FN).

Usage: python3 strip_reference.py [DY]      (default DY = 200, CONTACT's)
Prints JSON: the approach "pen", the element pressures "p" (element i + 1 of CONTACT is p[i]), the contact size.
tests/strip.rs holds this script's output for DY = 200; benches/peer/README.md compares CONTACT with it.
Needs mpmath (pip install mpmath).
"""
import json
import sys

import mpmath as mp

mp.mp.dps = 40
G, NU = mp.mpf(82000), mp.mpf("0.28")
MX, XC1, DX, B1 = 55, mp.mpf("-1.05"), mp.mpf("0.04"), mp.mpf("0.001")
DY = mp.mpf(sys.argv[1]) if len(sys.argv) > 1 else mp.mpf(200)
FN = mp.mpf(35780) * DY / 200  # the same pressure on a wider strip
x = [XC1 + i * DX for i in range(MX)]
half = DY / 2


def corner(X, Y):
    """Antiderivative of 1/rho: d2/dXdY of it is 1/sqrt(X^2 + Y^2)."""
    r = mp.sqrt(X * X + Y * Y)
    return X * mp.log(Y + r) + Y * mp.log(X + r)


def rectangle(lo, hi):
    """The integral of 1/rho over X in [lo, hi], Y in [-half, half]."""
    return corner(hi, half) - corner(hi, -half) - corner(lo, half) + corner(lo, -half)


# Gap change at element i per unit pressure on element j, both bodies: (1 - nu)/(pi G) * integral.
A = [[(1 - NU) / (mp.pi * G) * rectangle(x[i] - x[j] - DX / 2, x[i] - x[j] + DX / 2) for j in range(MX)]
     for i in range(MX)]
h = [B1 * xi * xi for xi in x]
contact = set(range(MX))
for iteration in range(1, 101):
    c = sorted(contact)
    n = len(c)
    M = mp.matrix(n + 1, n + 1)
    rhs = mp.matrix(n + 1, 1)
    for a, i in enumerate(c):
        for b, j in enumerate(c):
            M[a, b] = A[i][j]
        M[a, n] = -1
        rhs[a] = -h[i]
        M[n, a] = DX * DY
    rhs[n] = FN
    s = mp.lu_solve(M, rhs)
    p = [mp.mpf(0)] * MX
    for a, i in enumerate(c):
        p[i] = s[a]
    pen = s[n]
    gap = [h[i] - pen + mp.fsum(A[i][j] * p[j] for j in range(MX)) for i in range(MX)]
    new = {i for i in contact if p[i] > 0} | {i for i in range(MX) if i not in contact and gap[i] < 0}
    if new == contact:
        break
    contact = new
else:
    sys.exit("the active set did not settle in 100 iterations")
print(json.dumps({"dy": float(DY), "pen": float(pen), "contact": len(contact), "iterations": iteration,
                  "p": [float(v) for v in p]}))
