#!/usr/bin/env python3
"""The Taylor bar's own figures (benchmark C1, doc/benchmarks.md, part C),
added to results/summary.json after svmbPost.casePost:
  finalRadius_mm        radius of probe 0 (initially at the edge of the
                        impact face, (R 0 0))
  finalLength_mm        bar length from probe 2 (the top centre)
  finalRadiusRange_mm   smallest and largest final radius of all points on
                        the edge of the impact face (the foot's roundness)
  radiusTarget_mm, radiusReference_mm   the published values"""
import json

import numpy as np

import svmbPost
from svmbPost.casePost import field_path, mesh_dir, written_times

R = 3.2e-3      # bar radius
L = 32.4e-3     # bar length

summary = json.load(open('results/summary.json'))
pr = svmbPost.read_csv('postProcessing/region0/probes.csv')
summary['finalRadius_mm'] = float(1e3*np.hypot(R + pr['ux0'][-1], pr['uz0'][-1]))
summary['finalLength_mm'] = float(1e3*(L + pr['uy2'][-1]))

X = svmbPost.read_points(mesh_dir('region0') + '/points')
edge = (np.abs(X[:, 1]) < 1e-9) & (np.hypot(X[:, 0], X[:, 2]) > (1 - 1e-6)*R)
u = svmbPost.read_point_field(field_path(written_times()[-1], 'region0', 'u'))
x = X[edge] + u[edge]
radii = 1e3*np.hypot(x[:, 0], x[:, 2])
summary['finalRadiusRange_mm'] = [float(radii.min()), float(radii.max())]
summary['radiusTarget_mm'] = [7.0, 7.15]
summary['radiusReference_mm'] = {
    'vertex-centred first-order FV (25519 points)': 7.06,
    'average nodal pressure FEM (tet)': 6.99,
    'standard FEM (hex)': 6.95, 'standard FEM (tet)': 5.55}

json.dump(summary, open('results/summary.json', 'w'), indent=2)
for k in ('finalRadius_mm', 'finalLength_mm', 'finalRadiusRange_mm'):
    print('  %-22s %s' % (k, summary[k]))
