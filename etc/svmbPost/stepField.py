#!/usr/bin/env python3
"""What sets the time step, from the written point field stableDeltaT (each
point's stable step at cfl 1; the run steps with cfl times the smallest).
Run in a case directory after solidVertexMBFoam (ASCII writes):

    python3 -m svmbPost.stepField [time ...]     (default: every written time)

Prints, per body and time: the smallest step and the point that has it, the
median over the smallest, how many points lie within 2, 5 and 10 times the
smallest, and the work of a multirate (local) time stepping relative to the
global step: each point stepping with the largest power-of-two multiple of
the smallest step within its own, i.e. the mean over the points of 2^-level.
A value well below one says that a few points hold the whole body to their
step (doc/results.md, "What sets the Taylor bar's step")."""
import os
import sys

import numpy as np

import svmbPost
from svmbPost.casePost import bodies, field_path, mesh_dir


def figures(dt):
    """The figures of one field (numpy array of the points' steps)."""
    m = float(dt.min())
    level = np.floor(np.log2(dt / m))
    return {
        'min': m,
        'argmin': int(dt.argmin()),
        'medianOverMin': float(np.median(dt) / m),
        'within': [int((dt < k * m).sum()) for k in (2, 5, 10)],
        'points': len(dt),
        'multirateWork': float(np.mean(2.0 ** (-level))),
    }


def main():
    times = sys.argv[1:] or [os.path.basename(t)
                             for t in svmbPost.complete_times()]
    if not times:
        svmbPost.fail('stepField', 'no written time in %s' % os.getcwd())
    for body in bodies():
        X = svmbPost.read_points(mesh_dir(body) + '/points')
        for t in times:
            path = field_path(t, body, 'stableDeltaT')
            if not svmbPost.foam_file_exists(path):
                svmbPost.fail('stepField', '%s does not exist (a run of the '
                              'solver before the field was written?)' % path)
            dt = svmbPost.read_point_field(path)
            f = figures(dt)
            x = X[f['argmin']]
            print('%s t = %s: smallest step %.4g s at point %d (%.6g %.6g '
                  '%.6g); median %.3g times it; within 2 / 5 / 10 times: '
                  '%d / %d / %d of %d points; multirate work %.3f of the '
                  'global step'
                  % (body, t, f['min'], f['argmin'], x[0], x[1], x[2],
                     f['medianOverMin'], *f['within'], f['points'],
                     f['multirateWork']))


if __name__ == '__main__':
    main()
