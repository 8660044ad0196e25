#!/usr/bin/env python3
"""Post-processing of a bar on a rigid wall (run in the case directory):
    python3 -m svmbPost.barWall [region]      (default region0)

The exact solution of an elastic bar meeting a flat rigid wall across its
end (the bar along the wall's normal, in any direction), for any material, length, velocity, gap, wall velocity and
side (the wall before either end), read from the case: the material and
initial velocity from [constant/<region>/]solidProperties, the wall from its
`rigidWall` condition (point, normal, velocity), the bar's extent from the
mesh, the probes from `probes/locations`.  In the wall's frame the bar
approaches at a = -(v0 - V).n; from the touch, t0 = gap/a, a plane front
of stress -Z a and wall velocity V runs up the bar (Z = rho c, c from the
uniaxial-strain modulus lambda + 2 mu: the sides are symmetry planes), is
reflected from the free end as a relief front, and the bar leaves at
V + a n at t0 + 2L/c, stress-free.  A probe at distance d from the struck
face holds v0 and zero stress until t0 + d/c, then V and -Z a until
t0 + (2L - d)/c, then V + a n and zero stress.  With a Hugoniot pressure
(hugoniot { s }) the plateau is the shock's, -rho (c + s a) a (with shear
stiffness from the jump conditions on the material's own uniaxial stress
curve: svmbPost.shock_plateau), and only
the plateau is evaluated.  Finite-strain materials without one (neoHookean,
mooneyRivlin) are evaluated acoustically, which is exact as the impact Mach
number a/c (in the summary) goes to zero: at a/c = 0.3 the shocked stress
of a neo-Hookean bar (nu 0.3) is 8.7 % above the acoustic one
(tests/solidBody/shockPlateau has the jump conditions).  Velocities, stresses and momenta are taken along
the bar's axis e, the wall's normal or its opposite, whichever has a
positive largest component (for a bar along x: the x columns, and the
signs of x).  A case outside this (a bar not along the wall's normal,
moving across it, a plastic material) is refused with a message.  Writes
  results/history.csv   t, then vx, sxx (and their exact values) per probe
  results/history.png   computed against exact histories
  results/summary.json  the exact values, the struck face's plateau,
                        contact time and rebound velocity, L1 errors per
                        probe (time-averaged, normalised by a and Z a),
                        numerical dissipation, final momentum, run figures
and prints the summary."""
import json
import os
import re
import sys

import numpy as np

import svmbPost


def refuse(message):
    svmbPost.fail('barWallPost', message + ' (this case is outside what the '
                  'exact solution of a bar on a rigid wall evaluates)')


def entry(path, key, default=None):
    return svmbPost.dict_entry(path, key, default, 'barWallPost')


def vector(text):
    v = [float(c) for c in re.findall(r'[-+0-9.eE]+', text)]
    if len(v) != 3:
        refuse('not a vector: %s' % text)
    return np.array(v)


def setup(region='region0'):
    """The case's exact problem (a dict)."""
    sub = '' if region == 'region0' else region + '/'
    path = 'constant/%ssolidProperties' % sub
    rho, M = svmbPost.uniaxial_material(path, refuse, 'barWallPost')
    s = float(entry(path, 'material/hugoniot/s', '0'))
    v0 = vector(entry(path, 'initialVelocity', '(0 0 0)'))
    walls = [patch for patch in svmbPost.dict_keywords(path,
                                                      'boundaryConditions')
             if entry(path, 'boundaryConditions/%s/type' % patch)
             == 'rigidWall']
    if len(walls) != 1:
        refuse('%d rigidWall conditions (one is evaluated)' % len(walls))
    w = 'boundaryConditions/%s/' % walls[0]
    xw = vector(entry(path, w + 'point'))
    n = svmbPost.bar_axis(vector(entry(path, w + 'normal')))
    V = vector(entry(path, w + 'velocity', '(0 0 0)'))
    # the axis: the normal or its opposite, whichever has a positive
    # largest component (x for a bar along x, either side of the wall)
    e = n if n[int(np.argmax(np.abs(n)))] > 0 else -n
    if svmbPost.across(V, e) > 1e-9 * max(abs(np.dot(V, e)), 1e-300):
        refuse('the wall moves along itself (velocity %s)' % V)
    if svmbPost.across(v0, e) > 1e-9 * max(abs(np.dot(v0, e)), 1e-300):
        refuse('the bar moves across the wall\'s normal (initialVelocity '
               '%s, normal %s)' % (v0, n))
    X = svmbPost.read_points('constant/%spolyMesh/points' % sub)
    lo, hi, radius, area = svmbPost.bar_geometry(X, e)
    L = hi - lo
    if radius > L:
        refuse('the body is not a bar along the wall\'s normal %s (length '
               '%g, %g across)' % (n, L, 2 * radius))
    # The struck face: the end facing the wall (the normal points into
    # the body)
    ne = float(np.dot(n, e))
    xf = lo if ne > 0 else hi
    gap = (xf - np.dot(xw, e)) * ne
    if gap < -1e-9 * L:
        refuse('the bar starts behind the wall (gap %g)' % gap)
    gap = gap if gap > 0 else 0.0
    a = -(np.dot(v0, e) - np.dot(V, e)) * ne
    if not a > 0:
        refuse('the bar and the wall do not approach (relative speed %g)'
               % -a)
    c = np.sqrt(M / rho)
    Z = rho * c
    # The shock's state: with a Hugoniot pressure and shear stiffness the
    # deviatoric stress has its own curve (svmbPost.shock_plateau; for
    # mu = 0 it is -rho (c + s a) a)
    stress = -rho * c * a
    U = c
    if s > 0:
        stress = svmbPost.shock_plateau(
            svmbPost.uniaxial_stress_curve(path, 'barWallPost'), rho, None,
            0.0, a)[1]
        U = -stress / (rho * a)
    probes = [vector(p) for p in re.findall(
        r'\([^()]*\)', entry(path, 'probes/locations', '()'))]
    if not probes:
        refuse('no probes')
    return {'axis': [float(c) for c in e],
            'rho': rho, 'M': M, 'c': c, 'Z': Z, 'hugoniotS': s,
            'v0': float(np.dot(v0, e)), 'wallVelocity': float(np.dot(V, e)),
            'normal': ne, 'a': a,
            'impactMach': a / c,
            'gap': gap, 'length': L, 'mass': rho * L * area,
            'contactStartExact': gap / a,
            # (with a Hugoniot pressure: the wall's plateau lasts at least
            # until the shock reaches the free end; the release and the
            # rebound are not evaluated)
            'plateauDuration': 2 * L / c if s == 0 else L / U,
            'contactTimeExact': 2 * L / c if s == 0 else None,
            'stressExact': float(stress),
            'reboundVelocityExact': float(np.dot(V, e)) + a * ne
            if s == 0 else None,
            'probeDistances': [abs(np.dot(p, e) - xf) for p in probes]}


def read_probes(S, region='region0'):
    """The probe histories along the bar's axis (svmbPost.axial_probes)."""
    return svmbPost.axial_probes(svmbPost.read_csv(
        'postProcessing/%s/probes.csv' % region), np.array(S['axis']))


def exact_probe(S, t, d):
    """Exact velocity and axial stress at distance d from the struck face
    (linear bar).  A sample that falls on one of the exact solution's jumps
    (within 1e-9 of the contact's duration: the end of contact of a bar of
    length 1 sampled every step lands on 2L/c) takes the mean of the two
    sides, so that the L1 errors do not depend on how that time rounds
    (the bar turned as a rigid body: 1.068 against 1.155 % at the face)."""
    t0, c, L = S['contactStartExact'], S['c'], S['length']
    t1, t2 = t0 + d / c, t0 + (2 * L - d) / c
    v = np.where(t < t1, S['v0'],
                 np.where(t < t2, S['wallVelocity'],
                          S['reboundVelocityExact']))
    s = np.where((t >= t1) & (t < t2), S['stressExact'], 0.0)
    tol = 1e-9 * 2 * L / c
    on1, on2 = np.abs(t - t1) <= tol, np.abs(t - t2) <= tol
    v = np.where(on1, 0.5 * (S['v0'] + S['wallVelocity']), v)
    v = np.where(on2, 0.5 * (S['wallVelocity'] + S['reboundVelocityExact']), v)
    s = np.where(on1 | on2, 0.5 * S['stressExact'], s)
    return v, s


def evaluate(S, probes, energy):
    """The summary's measured figures from the probe and energy histories
    (structured arrays of probes.csv and energy.csv)."""
    t = probes['t']
    t0, T, a = S['contactStartExact'], S['plateauDuration'], S['a']
    out = {}
    face = int(np.argmin(S['probeDistances']))
    if S['probeDistances'][face] > 1e-9 * S['length']:
        refuse('no probe on the struck face')
    m = (t > t0 + 0.15 * T) & (t < t0 + 0.85 * T)
    out['plateauStress'] = float(probes['sxx%d' % face][m].mean())
    if S['hugoniotS'] > 0:
        out.update(dissipation(energy))
        return out
    # the end of contact: the face halfway from the wall's velocity to the
    # rebound velocity
    vf = (probes['vx%d' % face] - S['wallVelocity']) * S['normal']
    after = np.where((t > t0 + 0.5 * T) & (vf > 0.5 * a))[0]
    out['contactTime'] = float(t[after[0]] - t0) if len(after) else None
    m = t > t0 + 1.05 * T
    out['reboundVelocity'] = (float(probes['vx%d' % face][m].mean())
                              if m.any() else None)
    for k, d in enumerate(S['probeDistances']):
        v, s = exact_probe(S, t, d)
        out['L1_v_probe%d' % k] = float(
            np.mean(np.abs(probes['vx%d' % k] - v)) / a)
        out['L1_s_probe%d' % k] = float(
            np.mean(np.abs(probes['sxx%d' % k] - s)) / abs(S['stressExact']))
    out.update(dissipation(energy))
    out['momentumFinal'] = float(
        svmbPost.axial_momentum(energy, np.array(S['axis']))[-1])
    out['momentumExactAfterSeparation'] = \
        S['mass'] * S['reboundVelocityExact']
    return out


def dissipation(energy):
    out = {}
    D = energy['numericalDissipation']
    # (a bar at rest struck by a moving wall starts without energy: the
    # wall's work is the scale then)
    E0 = max(energy['total'][0], np.abs(energy['externalWork']).max())
    out['energyScale'] = float(E0)
    out['dissipationMin'] = float(D.min() / E0)
    out['dissipationLargestFall'] = float(
        max(0.0, np.max(np.maximum.accumulate(D) - D)) / E0)
    out['energyLostPercent'] = float(100 * D[-1] / E0)
    return out


def main():
    region = sys.argv[1] if len(sys.argv) > 1 else 'region0'
    S = setup(region)
    P = read_probes(S, region)
    E = svmbPost.read_csv('postProcessing/%s/energy.csv' % region)
    summary = {k: v for k, v in S.items() if k != 'probeDistances'}
    summary['probeDistances'] = S['probeDistances']
    summary.update(evaluate(S, P, E))
    stats = svmbPost.run_statistics()
    for k in ('steps', 'wallTime', 'points', 'throughput'):
        summary[k] = stats[k]

    os.makedirs('results', exist_ok=True)
    t = P['t']
    cols, names = [t], ['t']
    linear = S['hugoniotS'] == 0
    for k, d in enumerate(S['probeDistances']):
        cols += [P['vx%d' % k], P['sxx%d' % k]]
        names += ['vx%d' % k, 'sxx%d' % k]
        if linear:
            v, s = exact_probe(S, t, d)
            cols += [v, s]
            names += ['vx%dExact' % k, 'sxx%dExact' % k]
    np.savetxt('results/history.csv', np.vstack(cols).T, delimiter=',',
               comments='', header=','.join(names))
    json.dump(summary, open('results/summary.json', 'w'), indent=2)

    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
        for k, d in enumerate(S['probeDistances']):
            v, s = exact_probe(S, t, d)
            for i, (q, e) in enumerate(((P['vx%d' % k], v),
                                        (P['sxx%d' % k], s))):
                line, = ax[i].plot(t, q, label='%g from the face' % d)
                if linear:
                    ax[i].plot(t, e, ':', color=line.get_color())
        if not linear:
            ax[1].axhline(S['stressExact'], color='k', ls=':')
        ax[0].set_ylabel('velocity (dotted: exact)' if linear else 'velocity')
        ax[1].set_ylabel('axial Cauchy stress')
        ax[0].legend(fontsize=8)
        ax[1].set_xlabel('t')
        svmbPost.save_history_plot(fig, 'bar on a rigid wall', summary)
    except ImportError:
        print('barWallPost: matplotlib not available, no plot')

    svmbPost.print_summary(summary, 28)


if __name__ == '__main__':
    main()
