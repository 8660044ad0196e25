#!/usr/bin/env python3
"""Post-processing of a bar-impact tutorial (run in the case directory):
    python3 -m svmbPost.barImpact      (the shell function barImpactPost)

Reads the case from its dictionaries and meshes (materials, both initial
velocities, bar lengths and gap, Hugoniot slope), the probe and energy
histories from postProcessing/, the run figures from the newest complete
time directory (uniform/runStatistics, contactState), and the exact solution
from applications/utilities/barImpactExact (applied in the frame of Bar Two,
so Bar Two may move too).  The bars may lie along any direction: the axis
runs from the centre of Bar One to that of Bar Two, and velocities, stresses
and displacements are taken along it (for bars along x, the x columns).
A case outside what the exact solution covers (bars moving across their
axis or not approaching, probes not at the contact faces, a plastic
material) is refused with a message.  Elastic materials are
evaluated by their acoustic impedance (lambda + 2 mu) and, with a Hugoniot
pressure, by the Hugoniot plateau.  Writes
  results/history.csv   t,vx1,sxx1,ux1,vx2,sxx2,ux2 (the points initially at
                        the centres of the contact faces; along the axis)
  results/history.png   computed against exact histories
  results/summary.json  L1 errors (time-averaged, normalised by v0 and by the
                        exact contact stress), plateaus, contact times,
                        energy lost to numerical dissipation (% of initial),
                        largest interpenetration, wall time, and the
                        case's time scale transitTime = 2 min(L/c) (the
                        first relief's return to the contact; the windows
                        above are set in it, so any units work)
and prints the summary."""
import json
import os
import re
import sys

import numpy as np

project = os.environ['SVMB_PROJECT']
sys.path.insert(0, os.path.join(project, 'applications', 'utilities',
                                'barImpactExact'))
import barImpactExact  # noqa: E402
import svmbPost  # noqa: E402


def refuse(message):
    svmbPost.fail('barImpactPost', message + ' (this case is outside what '
                  'the exact bar-impact solution evaluates)')


def entry(path, key, default=None):
    return svmbPost.dict_entry(path, key, default, 'barImpactPost')


def points(region):
    return svmbPost.read_points('constant/%s/polyMesh/points' % region)


def axis():
    """The bars' axis: from the centre of Bar One to that of Bar Two."""
    centre = [0.5 * (X.min(axis=0) + X.max(axis=0))
              for X in (points('barOne'), points('barTwo'))]
    return svmbPost.bar_axis(centre[1] - centre[0])


def material(region, a):
    """The uniaxial modulus, density and initial velocity along a."""
    path = 'constant/%s/solidProperties' % region
    rho, M = svmbPost.uniaxial_material(path, refuse, 'barImpactPost')
    v = np.array([float(c) for c in re.findall(
        r'[-+0-9.eE]+', entry(path, 'initialVelocity', '(0 0 0)'))])
    va = float(np.dot(v, a))
    if svmbPost.across(v, a) > 1e-9 * max(abs(va), 1e-300):
        refuse('%s moves across the bar (initialVelocity %s, axis %s)'
               % (region, v, a))
    return M, rho, va


def extent(region, a):
    """Bar extent along a, from the mesh."""
    lo, hi, radius, _ = svmbPost.bar_geometry(points(region), a)
    if radius > hi - lo:
        refuse('%s is not a bar along %s (length %g, %g across)'
               % (region, a, hi - lo, 2 * radius))
    return lo, hi


def probe_axial(region, a):
    """The first probe's position along a."""
    loc = entry('constant/%s/solidProperties' % region, 'probes/locations',
                '()')
    xs = re.findall(r'[-+0-9.eE]+', loc)
    if len(xs) < 3:
        refuse('%s has no probe' % region)
    return float(np.dot([float(x) for x in xs[:3]], a))


def linear_exact(M1, M2, rho1, rho2, v0, v2, gap, tEnd, L1, L2):
    """The exact linear history t,vx1,sxx1,ux1,vx2,sxx2,ux2 with Bar Two
    moving at v2: evaluated in Bar Two's frame at the closing speed v0,
    then brought back (velocities + v2, displacements + v2 t)"""
    exact, _, _ = barImpactExact.linear_history(
        M1, M2, rho1, rho2, v0, gap, tEnd, L1=L1, L2=L2)
    exact[:, 1] += v2
    exact[:, 4] += v2
    exact[:, 3] += v2 * exact[:, 0]
    exact[:, 6] += v2 * exact[:, 0]
    return exact


def main():
    a = axis()
    M1, rho1, v1 = material('barOne', a)
    M2, rho2, v2 = material('barTwo', a)
    # The exact solution has Bar Two at rest: evaluate it in Bar Two's
    # frame with v0 = v1 - v2, then add v2 back (Galilean invariance)
    v0 = v1 - v2
    if not v0 > 0:
        refuse('the bars do not approach (Bar One at %g, Bar Two at %g)'
               % (v1, v2))
    a1, b1 = extent('barOne', a)
    a2, b2 = extent('barTwo', a)
    if not a2 >= b1:
        refuse('Bar Two does not lie after Bar One along %s' % a)
    L1, L2, gap = b1 - a1, b2 - a2, a2 - b1
    tol = 1e-6 * max(L1, L2)
    if abs(probe_axial('barOne', a) - b1) > tol \
            or abs(probe_axial('barTwo', a) - a2) > tol:
        refuse('the first probe of each bar must be at its contact face '
               '(%g and %g along %s)' % (b1, a2, a))
    # Hugoniot slope: each material's (the physics; the contact and interior
    # Riemann solvers take theirs from there); the exact solution covers one
    # slope for both bars
    s1, s2 = (float(entry('constant/%s/solidProperties' % r,
                          'material/hugoniot/s', '0'))
              for r in ('barOne', 'barTwo'))
    if s1 != s2:
        refuse('the bars have different Hugoniot slopes (%g, %g)' % (s1, s2))
    s = s1

    p1 = svmbPost.axial_probes(svmbPost.read_csv(
        'postProcessing/barOne/probes.csv'), a)
    p2 = svmbPost.axial_probes(svmbPost.read_csv(
        'postProcessing/barTwo/probes.csv'), a)
    e1 = np.genfromtxt('postProcessing/barOne/energy.csv', delimiter=',', names=True)
    e2 = np.genfromtxt('postProcessing/barTwo/energy.csv', delimiter=',', names=True)
    t = p1['t']
    os.makedirs('results', exist_ok=True)
    hist = np.vstack([t, p1['vx0'], p1['sxx0'], p1['ux0'],
                      p2['vx0'], p2['sxx0'], p2['ux0']]).T
    np.savetxt('results/history.csv', hist, delimiter=',', comments='',
               header='t,vx1,sxx1,ux1,vx2,sxx2,ux2')

    if s > 0:
        # the shocks' jump conditions on each material's own uniaxial
        # stress curve (with shear stiffness the deviatoric stress has its
        # own; for mu = 0 this is barImpactExact's U = c + s v)
        vC, sC = svmbPost.shock_plateau(
            svmbPost.uniaxial_stress_curve(
                'constant/barOne/solidProperties', 'barImpactPost'), rho1,
            svmbPost.uniaxial_stress_curve(
                'constant/barTwo/solidProperties', 'barImpactPost'), rho2,
            v0)
        vC, sC = float(vC), float(sC)
    else:
        vC, sC = barImpactExact.contact_plateau(M1, M2, rho1, rho2, v0, s)
    tEnd = float(t[-1])
    vC += v2
    summary = {'axis': [float(c) for c in a],
               'v0': v0, 'vBarTwo': v2, 'lengths': [float(L1), float(L2)],
               'gap': float(gap),
               'hugoniotS': s, 'exactContactVelocity': vC,
               'exactContactStress': sC}

    # The case's own time scale: the first relief's return to the contact,
    # twice the shorter transit time of the two bars (0.2 for A1)
    transit = 2 * min(L1 / np.sqrt(M1 / rho1), L2 / np.sqrt(M2 / rho2))
    summary['transitTime'] = float(transit)

    # contact window from the computed histories: start when Bar Two's face
    # moves (half the contact velocity), end when Bar One's face stress is
    # back to zero (5 % of the contact stress), looked for from a tenth of
    # the transit time after the start (past the rise of the onset)
    moving = np.where(np.abs(p2['vx0'] - v2) > 0.5 * abs(vC - v2))[0]
    tContact = float(t[moving[0]]) if len(moving) else None
    summary['contactStart'] = tContact
    summary['contactStartExact'] = gap / v0
    sep = None
    if tContact is not None:
        after = np.where((t > tContact + 0.1 * transit)
                         & (np.abs(p1['sxx0']) < 0.05 * abs(sC)))[0]
        sep = float(t[after[0]]) if len(after) else None
    summary['separation'] = sep
    if tContact is not None and sep is not None:
        d = sep - tContact
        w = (t > tContact + 0.1 * d) & (t < tContact + 0.4 * d)
        summary['plateauStressBarOne'] = float(p1['sxx0'][w].mean())
        summary['plateauStressBarTwo'] = float(p2['sxx0'][w].mean())
        summary['plateauVelocityBarOne'] = float(p1['vx0'][w].mean())
        summary['plateauVelocityBarTwo'] = float(p2['vx0'][w].mean())

    exact = None
    if s == 0:
        exact = linear_exact(M1, M2, rho1, rho2, v0, v2, gap, tEnd, L1, L2)
        ex = {k: np.interp(t, exact[:, 0], exact[:, i])
              for i, k in enumerate(['t', 'vx1', 'sxx1', 'ux1', 'vx2', 'sxx2', 'ux2'])}
        L1 = {
            'L1_v_barOne': float(np.mean(np.abs(p1['vx0'] - ex['vx1'])) / abs(v0)),
            'L1_v_barTwo': float(np.mean(np.abs(p2['vx0'] - ex['vx2'])) / abs(v0)),
            'L1_s_barOne': float(np.mean(np.abs(p1['sxx0'] - ex['sxx1'])) / abs(sC)),
            'L1_s_barTwo': float(np.mean(np.abs(p2['sxx0'] - ex['sxx2'])) / abs(sC)),
        }
        L1['L1_v'] = 0.5 * (L1['L1_v_barOne'] + L1['L1_v_barTwo'])
        L1['L1_s'] = 0.5 * (L1['L1_s_barOne'] + L1['L1_s_barTwo'])
        summary.update(L1)
        sep = np.where((exact[:, 0] > gap / v0 + 0.05 * transit)
                       & (exact[:, 2] == 0))[0]
        summary['separationExact'] = float(exact[sep[0], 0]) if len(sep) else None

    E0 = e1['total'][0] + e2['total'][0]
    D = e1['numericalDissipation'] + e2['numericalDissipation']
    summary['energyInitial'] = float(E0)
    summary['energyLostPercent'] = float(100 * D[-1] / E0)
    P = svmbPost.axial_momentum(e1, a) + svmbPost.axial_momentum(e2, a)
    summary['momentumInitial'] = float(P[0])
    summary['momentumFinal'] = float(P[-1])
    summary['momentumError'] = float(abs(summary['momentumFinal'] - summary['momentumInitial'])
                                     / abs(summary['momentumInitial']))
    stats = svmbPost.run_statistics()
    summary['maxInterpenetration'] = stats.get('maxInterpenetration')
    for k in ('steps', 'wallTime', 'points', 'throughput'):
        summary[k] = stats[k]

    json.dump(summary, open('results/summary.json', 'w'), indent=2)

    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
        for i, lab in enumerate(('velocity', 'axial Cauchy stress')):
            ax[i].plot(t, hist[:, 1 + i], 'b-', label='Bar One')
            ax[i].plot(t, hist[:, 4 + i], 'r-', label='Bar Two')
            if exact is not None:
                ax[i].plot(exact[:, 0], exact[:, 1 + i], 'b:', label='Bar One exact')
                ax[i].plot(exact[:, 0], exact[:, 4 + i], 'r:', label='Bar Two exact')
            else:
                ax[i].axhline([vC, sC][i], color='k', ls=':', label='exact plateau')
            ax[i].set_ylabel(lab)
            ax[i].legend(fontsize=8)
        ax[1].set_xlabel('t')
        svmbPost.save_history_plot(fig, 'contact-face probes', summary)
    except ImportError:
        print('barImpactPost: matplotlib not available, no plot')

    svmbPost.print_summary(summary)


if __name__ == '__main__':
    main()
