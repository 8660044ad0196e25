#!/usr/bin/env python3
"""One-dimensional model of the bar scheme (doc/results.md, "Release fronts and
the limiter"): A1 by symmetry, one bar [0, 10] at v0 = 0.1 (c = 100, rho =
0.01), free at x = 0, its contact face at x = 10 held at the contact velocity
0.05 while the stick traction is compressive and traction-free once it is not.
Vertex-centred finite volumes on a uniform line (half cells at the ends), the
MUSCL reconstruction of the solver's per-edge limiters (upwind-biased
difference a = 2 G_i dx - b, central b; one-sided gradients at the ends), the
upwind (Godunov) flux with the solver's F-flux weight w_ij if --weight,
Heun's two stages.  Prints the contact face's L1 errors (time-averaged over
0-0.4 as the tutorial's summary), the growth of the contact stress before the
release and the tension after it.
    barModel1D.py <vanAlbada|superbee|koren|simpleWaveSuperbee> [--courant C]
                  [--cells N] [--characteristic] [--weight] [--spread S]
(--characteristic: limit t -+ Z v instead of v and the stress; --spread: the
simple-wave test's spread)"""
import argparse

import numpy as np

p = argparse.ArgumentParser()
p.add_argument('limiter')
p.add_argument('--courant', type=float, default=0.35)
p.add_argument('--cells', type=int, default=256)
p.add_argument('--characteristic', action='store_true')
p.add_argument('--weight', action='store_true')
p.add_argument('--spread', type=float, default=3.0)
o = p.parse_args()

c, rho, L, vC = 100.0, 0.01, 10.0, 0.05
Z = rho * c
N = o.cells + 1
h = L / o.cells


def limited(name, a, b):
    out = np.zeros_like(a)
    m = a * b > 0
    A, B = np.abs(a[m]), np.abs(b[m])
    s = {'vanAlbada': lambda: A * B * (A + B) / (A * A + B * B),
         'superbee': lambda: np.maximum(np.minimum(2 * A, B), np.minimum(A, 2 * B)),
         'koren': lambda: np.minimum(np.minimum(2 * A, 2 * B), (B + 2 * A) / 3)}[name]()
    out[m] = np.sign(b[m]) * s
    return out


def differences(f):
    g = np.zeros(N)
    g[1:-1] = (f[2:] - f[:-2]) / 2
    g[0], g[-1] = f[1] - f[0], f[-1] - f[-2]
    b = f[1:] - f[:-1]
    return b, 2 * g[:-1] - b, 2 * g[1:] - b


def ratio(a, b):
    with np.errstate(divide='ignore', invalid='ignore'):
        return np.where(b != 0, a / np.where(b == 0, 1, b), np.inf)


def midpoints(fields):
    """Midpoint states of each field seen from the left and the right"""
    parts = [differences(f) for f in fields]
    if o.limiter == 'simpleWaveSuperbee':
        sides = []
        for k in (1, 2):
            r = [ratio(d[k], d[0]) for d in parts]
            lo, hi = np.minimum(*r), np.maximum(*r)
            one = (hi - lo <= o.spread * (1 + np.minimum(np.abs(lo), np.abs(hi))))
            sides.append([np.where(one, limited('superbee', d[k], d[0]),
                                   limited('vanAlbada', d[k], d[0])) for d in parts])
    else:
        sides = [[limited(o.limiter, d[k], d[0]) for d in parts] for k in (1, 2)]
    return ([f[:-1] + 0.5 * s for f, s in zip(fields, sides[0])],
            [f[1:] - 0.5 * s for f, s in zip(fields, sides[1])])


vol = np.full(N, h)
vol[0] = vol[-1] = h / 2


def rates(v, s):
    if o.characteristic:
        (pL, mL), (pR, mR) = midpoints([s - Z * v, s + Z * v])
        vL, sL, vR, sR = (mL - pL) / (2 * Z), (pL + mL) / 2, (mR - pR) / (2 * Z), (pR + mR) / 2
    else:
        (vL, sL), (vR, sR) = midpoints([v, s])
    w = 1.0
    if o.weight:
        ds = np.abs(s[1:] - s[:-1])
        w = np.where(ds > 0, np.minimum(1, 2 * np.abs(sR - sL) / np.where(ds > 0, ds, 1)), 1)
    sF = 0.5 * (sL + sR) + 0.5 * Z * (vR - vL)
    vF = 0.5 * (vL + vR) + w * 0.5 / Z * (sR - sL)
    Rv, Rs = np.zeros(N), np.zeros(N)
    Rv[:-1] += sF
    Rv[1:] -= sF
    Rs[:-1] += vF
    Rs[1:] -= vF
    Rs[0] -= v[0] + s[0] / Z                  # free end
    stick = s[-1] - Z * (v[-1] - vC)
    if stick <= 0:                            # contact face held
        Rv[-1] += stick
        Rs[-1] += vC
    else:                                     # released: traction-free
        Rs[-1] += v[-1] - s[-1] / Z
    return Rv / (rho * vol), Rs * rho * c * c / vol


v, s = np.full(N, 0.1), np.zeros(N)
dt = o.courant * h / c
t, hist = 0.0, []
while t < 0.3 - 1e-12:
    k1v, k1s = rates(v, s)
    v1, s1 = v + dt * k1v, s + dt * k1s
    k2v, k2s = rates(v1, s1)
    v, s = 0.5 * (v + v1 + dt * k2v), 0.5 * (s + s1 + dt * k2s)
    t += dt
    hist.append((t, v[-1], s[-1]))
H = np.array(hist)
tt = H[:, 0]
L1v = np.sum(np.abs(H[:, 1] - np.where(tt < 0.2, vC, 0.0))) * dt / 0.4 / 0.1
L1s = np.sum(np.abs(H[:, 2] - np.where(tt < 0.2, -vC, 0.0))) * dt / 0.4 / vC
last = (tt > 0.15) & (tt < 0.2)
print('%s, Courant %.2f, %d cells%s%s: L1 velocity %.4f %%, stress %.4f %%, '
      'growth before the release %.2f %%, tension after it %.2f %%'
      % (o.limiter, o.courant, o.cells, ', characteristic' if o.characteristic else '',
         ', weighted F flux' if o.weight else '', 100 * L1v, 100 * L1s,
         100 * (-H[last, 2].min() / vC - 1), 100 * max(H[tt > 0.2, 2].max(), 0) / vC))
