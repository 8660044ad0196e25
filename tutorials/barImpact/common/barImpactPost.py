#!/usr/bin/env python3
"""Post-processing of a bar-impact tutorial (run in the case directory).

Reads the case (materials, initial velocity, gap, Hugoniot slope) from its
dictionaries, the probe and energy histories from postProcessing/, the wall
time and interpenetration from log.solidVertexMBFoam, and the exact solution
from applications/utilities/barImpactExact.  Writes
  results/history.csv   t,vx1,sxx1,ux1,vx2,sxx2,ux2 (the points initially at
                        the centres of the contact faces)
  results/history.png   computed against exact histories
  results/summary.json  L1 errors (time-averaged, normalised by v0 and by the
                        exact contact stress), plateaus, contact times,
                        energy lost to numerical dissipation (% of initial),
                        largest interpenetration, wall time
and prints the summary."""
import json
import os
import re
import subprocess
import sys

import numpy as np

project = os.environ['SVMB_PROJECT']
sys.path.insert(0, os.path.join(project, 'applications', 'utilities',
                                'barImpactExact'))
import barImpactExact  # noqa: E402


def entry(path, key, default=None):
    r = subprocess.run(['foamDictionary', '-entry', key, '-value', path],
                       capture_output=True, text=True)
    if r.returncode != 0:
        if default is None:
            sys.exit('barImpactPost: no %s in %s' % (key, path))
        return default
    return r.stdout.strip()


def material(region):
    path = 'constant/%s/solidProperties' % region
    rho = float(entry(path, 'material/rho'))
    E = entry(path, 'material/E', 'none')
    if E != 'none':
        nu = float(entry(path, 'material/nu'))
        E = float(E)
        # uniaxial-strain modulus (symmetry sides): lambda + 2 mu
        M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
    else:
        kappa = float(entry(path, 'material/kappa'))
        mu = float(entry(path, 'material/mu'))
        M = kappa + 4.0 * mu / 3.0
    v = entry(path, 'initialVelocity', '(0 0 0)')
    return M, rho, float(v.strip('()').split()[0])


def main():
    M1, rho1, v0 = material('barOne')
    M2, rho2, _ = material('barTwo')
    s = float(entry('constant/contactProperties', 'contacts/barContact/s', '0')
              if entry('constant/contactProperties',
                       'contacts/barContact/riemannSolver',
                       'acoustic') == 'hugoniot' else 0.0)
    # gap: from the probe location of Bar Two (initially at 10 + gap)
    loc = entry('constant/barTwo/solidProperties', 'probes/locations')
    gap = float(re.findall(r'[-+0-9.eE]+', loc)[0]) - 10.0

    p1 = np.genfromtxt('postProcessing/barOne/probes.csv', delimiter=',', names=True)
    p2 = np.genfromtxt('postProcessing/barTwo/probes.csv', delimiter=',', names=True)
    e1 = np.genfromtxt('postProcessing/barOne/energy.csv', delimiter=',', names=True)
    e2 = np.genfromtxt('postProcessing/barTwo/energy.csv', delimiter=',', names=True)
    t = p1['t']
    os.makedirs('results', exist_ok=True)
    hist = np.vstack([t, p1['vx0'], p1['sxx0'], p1['ux0'],
                      p2['vx0'], p2['sxx0'], p2['ux0']]).T
    np.savetxt('results/history.csv', hist, delimiter=',', comments='',
               header='t,vx1,sxx1,ux1,vx2,sxx2,ux2')

    vC, sC = barImpactExact.contact_plateau(M1, M2, rho1, rho2, v0, s)
    tEnd = float(t[-1])
    summary = {'v0': v0, 'gap': gap, 'hugoniotS': s,
               'exactContactVelocity': vC, 'exactContactStress': sC}

    # contact window from the computed histories: start when Bar Two's face
    # moves (half the contact velocity), end when Bar One's face stress is
    # back to zero (5 % of the contact stress)
    moving = np.where(np.abs(p2['vx0']) > 0.5 * abs(vC))[0]
    tContact = float(t[moving[0]]) if len(moving) else None
    summary['contactStart'] = tContact
    summary['contactStartExact'] = gap / v0
    sep = None
    if tContact is not None:
        after = np.where((t > tContact + 0.02)
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
        exact, dt, _ = barImpactExact.linear_history(
            M1, M2, rho1, rho2, v0, gap, tEnd)
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
        sep = np.where((exact[:, 0] > gap / v0 + 0.01) & (exact[:, 2] == 0))[0]
        summary['separationExact'] = float(exact[sep[0], 0]) if len(sep) else None

    E0 = e1['total'][0] + e2['total'][0]
    D = e1['numericalDissipation'] + e2['numericalDissipation']
    summary['energyInitial'] = float(E0)
    summary['energyLostPercent'] = float(100 * D[-1] / E0)
    summary['momentumInitial'] = float(e1['px'][0] + e2['px'][0])
    summary['momentumFinal'] = float(e1['px'][-1] + e2['px'][-1])
    summary['momentumError'] = float(abs(summary['momentumFinal'] - summary['momentumInitial'])
                                     / abs(summary['momentumInitial']))
    log = open('log.solidVertexMBFoam').read()
    m = re.search(r'largest interpenetration (\S+)', log)
    summary['maxInterpenetration'] = float(m.group(1)) if m else None
    m = re.search(r'^Finished (\d+) steps in (\S+) s wall', log, re.M)
    summary['steps'], summary['wallTime'] = int(m.group(1)), float(m.group(2))
    m = re.search(r'\((\d+) points, (\d+) cores\)', log)
    summary['points'] = int(m.group(1))

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
        fig.suptitle('%s: contact-face probes (%d points, %.1f s wall)'
                     % (os.path.basename(os.getcwd()), summary['points'],
                        summary['wallTime']))
        fig.tight_layout()
        fig.savefig('results/history.png', dpi=90)
    except ImportError:
        print('barImpactPost: matplotlib not available, no plot')

    for k, v in summary.items():
        print('  %-24s %s' % (k, ('%.6g' % v) if isinstance(v, float) else v))


if __name__ == '__main__':
    main()
