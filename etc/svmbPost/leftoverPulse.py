#!/usr/bin/env python3
"""What a release leaves in two bars after they part (run in a bar-impact
case directory after barImpactPost, benchmarks/leftoverPulse):
    python3 -m svmbPost.leftoverPulse [case cells label]

For linear bars the exact contact-face histories (barImpactExact) are taken
to the run's end.  From the exact separation on, each bar's time is cut
into round trips of its own relief (2 L/c, centred on the returns of what
the release sends into the bar), and in each the largest and the mean
departure of the face velocity from the exact history are reported in % of
the impact speed v0.  The exact A1 bars are then at rest and at v0, so any
departure is a pulse left by the release; the exact A2 bars carry waves
on, whose captured fronts make the largest departure near their jumps
(the mean is the measure there).  The momentum each bar keeps after the run
(postProcessing energy.csv, px) is compared with its initial momentum plus
the exact impulse of the contact stress (in % of its initial momentum
m v0 for Bar One, of Bar One's for Bar Two).  Hugoniot bars (no exact
history after separation) get the plot only.  Writes results/pulse.png and
results/pulse.json and prints one markdown table row, headed by the case,
its cells and a label (by default the directory's name, '-', 'tutorial')."""
import json
import os
import sys

import numpy as np

import svmbPost
from svmbPost import barImpact


def section_area(region):
    X = svmbPost.read_points('constant/%s/polyMesh/points' % region)
    lo, hi = X.min(axis=0), X.max(axis=0)
    return (hi[1] - lo[1]) * (hi[2] - lo[2])


def main():
    name, cells, label = (sys.argv[1:4] if len(sys.argv) > 3 else
                          (os.path.basename(os.getcwd()), '-', 'tutorial'))
    summary = json.load(open('results/summary.json'))
    hist = svmbPost.read_csv('results/history.csv')
    t = hist['t']
    a = np.array(summary.get('axis', [1.0, 0.0, 0.0]))
    M1, rho1, v1 = barImpact.material('barOne', a)
    M2, rho2, v2 = barImpact.material('barTwo', a)
    (L1, L2), gap, v0 = summary['lengths'], summary['gap'], summary['v0']
    s = summary['hugoniotS']
    trips = (2 * L1 / np.sqrt(M1 / rho1), 2 * L2 / np.sqrt(M2 / rho2))
    result = {'case': name, 'label': label, 'v0': v0, 'roundTrips': trips}

    exact = None
    rows = ['-', '-']
    momentum = '-'
    if s == 0:
        exact = barImpact.linear_exact(M1, M2, rho1, rho2, v0, v2, gap,
                                       float(t[-1]), L1, L2)
        tSep = summary['separationExact']
        result['separationExact'] = tSep
        departures = []
        for k, (col, T) in enumerate((('vx1', trips[0]), ('vx2', trips[1]))):
            ve = np.interp(t, exact[:, 0], exact[:, 1 + 3 * k])
            d = np.abs(hist[col] - ve) / abs(v0)
            per = []
            n = 1
            while tSep + (n - 0.5) * T < t[-1]:
                w = (t > tSep + (n - 0.5) * T) & (t <= tSep + (n + 0.5) * T)
                if w.any():
                    per.append((float(100 * d[w].max()),
                                float(100 * d[w].mean())))
                n += 1
            departures.append(per)
        result['faceVelocityDeparturePercent'] = [
            {'largest': [x[0] for x in per], 'mean': [x[1] for x in per]}
            for per in departures]
        rows = [', '.join('%.1f (%.2f)' % x for x in per) or '-'
                for per in departures]

        # momentum after the run against the exact impulse of the contact
        # stress (the face stress history while the bars touch; A the
        # section, the same for both bars here)
        A = section_area('barOne')
        te, se = exact[:, 0], exact[:, 2]
        impulse = A * float(np.sum(0.5 * (se[1:] + se[:-1]) * np.diff(te)))
        m1, m2 = rho1 * L1 * A, rho2 * L2 * A
        P1 = m1 * v1 + impulse
        P2 = m2 * v2 - impulse
        e1 = svmbPost.read_csv('postProcessing/barOne/energy.csv')
        e2 = svmbPost.read_csv('postProcessing/barTwo/energy.csv')
        scale = m1 * abs(v0)
        kept = (100 * (e1['px'][-1] - P1) / scale,
                100 * (e2['px'][-1] - P2) / scale)
        result['momentumKeptPercent'] = kept
        momentum = '%.2f / %.2f' % kept

    json.dump(result, open('results/pulse.json', 'w'), indent=2)
    stats = svmbPost.run_statistics()
    print('| %s | %s | %s | %s / %s | %s | %.1f |'
          % (name, cells, label, rows[0], rows[1], momentum,
             stats['wallTime']))

    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(2, 1, figsize=(9, 7), sharex=True)
        for i, lab in enumerate(('velocity', 'axial Cauchy stress')):
            col1, col2 = ('vx1', 'vx2') if i == 0 else ('sxx1', 'sxx2')
            ax[i].plot(t, hist[col1], 'b-', lw=0.8, label='Bar One')
            ax[i].plot(t, hist[col2], 'r-', lw=0.8, label='Bar Two')
            if exact is not None:
                ax[i].plot(exact[:, 0], exact[:, 1 + i], 'b:',
                           label='Bar One exact')
                ax[i].plot(exact[:, 0], exact[:, 4 + i], 'r:',
                           label='Bar Two exact')
            ax[i].set_ylabel(lab)
            ax[i].legend(fontsize=8)
        ax[1].set_xlabel('t')
        svmbPost.save_history_plot(
            fig, 'contact-face histories to t = %g (%s)' % (t[-1], label),
            stats, 'results/pulse.png')
    except ImportError:
        print('leftoverPulse: matplotlib not available, no plot')


if __name__ == '__main__':
    main()
