"""Post-processing of benchmark C3 (tutorials/nonMatchingBars), after
svmbPost.casePost.  Run in the case directory:

    python3 -m svmbPost.nonMatchingBars

Writes
  results/contactCentre.csv   t, vx and sxx at the centre of each contact face
                              (the probes of the two bars)
  results/centreline.csv      x, pressure along Bar Two's centreline
                              (y = z = 0) at the last written time
  results/nonMatchingBars.png both
and adds to results/summary.json: the last written time, the mesh sizes
across (from the points on the contact faces) and whether the pair was
mapped through the AMI."""
import json
import os
import re

import numpy as np

import svmbPost
from svmbPost.casePost import written_times


def centreline(body, time):
    """Pressure along the bar's axis (y = z = 0): the points on it, or, on
    a mesh with an odd number of cells across, the mean over the ring of
    points nearest to it at each x"""
    X = svmbPost.read_points('constant/%s/polyMesh/points' % body)
    s = svmbPost.read_point_field('%s/%s/sigma' % (time, body))
    tol = 1e-6 * np.ptp(X[:, 0])
    r = np.hypot(X[:, 1], X[:, 2])
    on = r < r.min() + tol
    p = -(s[on, 0] + s[on, 3] + s[on, 5]) / 3
    x = X[on, 0]
    key = np.round(x / tol)
    keys = np.unique(key)
    return (np.array([x[key == k].mean() for k in keys]),
            np.array([p[key == k].mean() for k in keys]))


def main():
    one = np.genfromtxt('postProcessing/barOne/probes.csv', delimiter=',',
                        names=True)
    two = np.genfromtxt('postProcessing/barTwo/probes.csv', delimiter=',',
                        names=True)
    n = min(len(one), len(two))
    np.savetxt('results/contactCentre.csv',
               np.column_stack([one['t'][:n], one['vx0'][:n], one['sxx0'][:n],
                                two['vx0'][:n], two['sxx0'][:n]]),
               delimiter=',', header='t,vxBarOne,sxxBarOne,vxBarTwo,sxxBarTwo',
               comments='')
    last = written_times()[-1]
    x, p = centreline('barTwo', last)
    np.savetxt('results/centreline.csv', np.column_stack([x, p]),
               delimiter=',', header='x,p', comments='')

    log = open('log.solidVertexMBFoam').read()
    summary = json.load(open('results/summary.json'))
    summary['centrelineTime'] = float(last)
    summary['nonMatching'] = 'non-matching (AMI' in log
    m = re.search(r'(\d+) AMI mappings', log)
    summary['AMIMappings'] = int(m.group(1)) if m else 0
    summary['centrelinePressureMax'] = float(np.max(np.abs(p)))
    json.dump(summary, open('results/summary.json', 'w'), indent=2)

    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    t = 1e6 * one['t'][:n]
    ax[0].plot(t, one['vx0'][:n], label='Bar One')
    ax[0].plot(t, two['vx0'][:n], label='Bar Two')
    ax[0].set_xlabel('t (us)')
    ax[0].set_ylabel('vx at the contact-face centre (m/s)')
    ax[0].legend()
    ax[1].plot(1e3 * x, 1e-6 * p, '.-')
    ax[1].set_xlabel('x (mm)')
    ax[1].set_ylabel('pressure on Bar Two\'s centreline (MPa) at %s s' % last)
    fig.tight_layout()
    fig.savefig('results/nonMatchingBars.png', dpi=100)


if __name__ == '__main__':
    main()
