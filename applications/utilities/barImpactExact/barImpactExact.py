#!/usr/bin/env python3
"""Exact solution of two bars hitting each other (doc/benchmarks.md, part A).

Bar One [0, L1] moves at +v0 towards Bar Two [L1 + gap, L1 + gap + L2] at
rest; unilateral contact (the bars touch, push, and separate when the
contact would pull); both outer ends free.

Linear bars (any impedances): method of characteristics.  In each bar the
invariants w+ = sigma - Z v (moving at +c) and w- = sigma + Z v (moving at
-c) are carried exactly on a lattice with dx = c dt; free ends reflect
(sigma = 0); the interface solves the contact Riemann problem each step and
separates on tension.  The only approximation is the time resolution dt of
the events (and, when L2/c2 is not a multiple of dt, a length rounding of
at most half a lattice cell of Bar Two, reported).

Hugoniot bars (shock speed U = c + s v_p, s > 0): the in-contact plateau
from the non-linear Riemann solver (doc/method.md, section 3).

    barImpactExact.py --E1 100 --E2 100 --rho1 0.01 --rho2 0.01 --v0 0.1 \
        --gap 0.01 --tEnd 0.4 [--s 1] [--out exact.csv]
prints the plateau values and writes t,vx1,sxx1,ux1,vx2,sxx2,ux2 (the
points initially at the centres of the contact faces)."""
import argparse
import math
import numpy as np


def contact_plateau(E1, E2, rho1, rho2, v0, s=0.0):
    """Contact velocity and (compressive, negative) stress at first
    contact: acoustic for s = 0, Hugoniot otherwise."""
    c1, c2 = math.sqrt(E1 / rho1), math.sqrt(E2 / rho2)
    Z1, Z2 = rho1 * c1, rho2 * c2
    if s == 0:
        v = Z1 * v0 / (Z1 + Z2)
        return v, -Z1 * Z2 * v0 / (Z1 + Z2)
    # doc/method.md: L = Bar One (vL = v0), R = Bar Two (vR = 0), t = 0, Lambda = 1
    a = s * (rho2 - rho1)
    b = Z1 + Z2 + 2 * s * rho1 * v0
    c0 = -(Z1 * v0 + s * rho1 * v0 ** 2)
    v = -c0 / b if abs(a) < 1e-14 * abs(b) else \
        2 * (-c0) / (b + math.sqrt(max(b * b - 4 * a * c0, 0.0)))
    t = Z1 * (v - v0) - s * rho1 * (v - v0) ** 2
    return v, t


def linear_history(E1, E2, rho1, rho2, v0, gap, tEnd, L1=10.0, L2=10.0,
                   N1=2000):
    c1, c2 = math.sqrt(E1 / rho1), math.sqrt(E2 / rho2)
    Z1, Z2 = rho1 * c1, rho2 * c2
    dt = L1 / (c1 * N1)
    N2 = max(1, int(round(L2 / (c2 * dt))))
    rounding = abs(N2 * c2 * dt - L2)

    # invariants at the lattice nodes: w+ = sigma - Z v, w- = sigma + Z v
    p1 = np.full(N1 + 1, -Z1 * v0)
    m1 = np.full(N1 + 1, Z1 * v0)
    p2 = np.zeros(N2 + 1)
    m2 = np.zeros(N2 + 1)
    g = gap
    u1 = u2 = 0.0
    nSteps = int(math.ceil(tEnd / dt))
    out = np.zeros((nSteps + 1, 7))
    v1e, v2e, s1e, s2e = v0, 0.0, 0.0, 0.0
    out[0] = (0, v1e, s1e, u1, v2e, s2e, u2)
    for n in range(1, nSteps + 1):
        # interior transport
        p1[1:] = p1[:-1].copy()
        m1[:-1] = m1[1:].copy()
        p2[1:] = p2[:-1].copy()
        m2[:-1] = m2[1:].copy()
        # outer free ends: sigma = 0
        p1[0] = -m1[0]
        m2[-1] = -p2[-1]
        # interface: incoming w+ of Bar One, w- of Bar Two
        wp, wm = p1[-1], m2[0]
        closed = False
        if g <= 1e-14 * L1:
            v = (wm - wp) / (Z1 + Z2)
            sig = wp + Z1 * v
            closed = sig < 0
        if closed:
            v1e = v2e = v
            s1e = s2e = sig
        else:
            v1e, s1e = -wp / Z1, 0.0
            v2e, s2e = wm / Z2, 0.0
        m1[-1] = s1e + Z1 * v1e
        p2[0] = s2e - Z2 * v2e
        # gap (free flight of the faces), displacements of the probes
        g_new = g + dt * (v2e - v1e)
        if not closed and g > 0 and g_new < 0:
            g_new = 0.0
        g = max(g_new, 0.0) if not closed else 0.0
        u1 += dt * v1e
        u2 += dt * v2e
        out[n] = (n * dt, v1e, s1e, u1, v2e, s2e, u2)
    return out, dt, rounding


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    for k, d in (('E1', 100), ('E2', 100), ('rho1', 0.01), ('rho2', 0.01),
                 ('v0', 0.1), ('gap', 0.01), ('tEnd', 0.4), ('s', 0.0),
                 ('L1', 10.0), ('L2', 10.0)):
        ap.add_argument('--' + k, type=float, default=d)
    ap.add_argument('--N1', type=int, default=2000)
    ap.add_argument('--out', default=None)
    a = ap.parse_args()
    v, t = contact_plateau(a.E1, a.E2, a.rho1, a.rho2, a.v0, a.s)
    print('contact plateau: velocity %.10g, stress %.10g' % (v, t))
    if a.s == 0:
        h, dt, r = linear_history(a.E1, a.E2, a.rho1, a.rho2, a.v0, a.gap,
                                  a.tEnd, a.L1, a.L2, a.N1)
        print('lattice dt %.3g, Bar Two length rounding %.3g' % (dt, r))
        if a.out:
            np.savetxt(a.out, h, delimiter=',', comments='',
                       header='t,vx1,sxx1,ux1,vx2,sxx2,ux2')


if __name__ == '__main__':
    main()
