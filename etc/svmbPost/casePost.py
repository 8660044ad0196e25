#!/usr/bin/env python3
"""Post-processing shared by the multi-dimensional tutorials (doc/benchmarks.md,
parts B and C).  Run in a case directory after solidVertexMBFoam:

    python3 -m svmbPost.casePost [--plane x|y|z] [--contact-times]
                    [--contact-patch name] [--plane-strain x|y|z]
    (the shell function svmbCasePost of etc/functions; a case adds its own
    figures to results/summary.json afterwards, as the Taylor bar does)

Reads every body's postProcessing/<body>/{energy,probes}.csv, the written
time directories (ASCII point fields) and their uniform/ files, and writes

  results/energy.csv     t, kinetic, strain, plastic, externalWork,
                         numericalDissipation summed over the bodies
  results/energy.png     the energy history
  results/probes.png     velocity and pressure histories of the probes
  results/pressure_<t>.png  pressure snapshots (points of the --plane
                         section, or all points seen along z) with their
                         smoothness figures in the title
  results/summary.json   headline numbers (see below) and wall time

Pressure smoothness at each written time and body:
  maxJump        largest |p_i - p_j| over mesh edges / (p_max - p_min)
                 (the range taken at least 1 % of the largest range of
                 the run, so that a body at rest does not count)
  ...Bulk        the same without the points of --contact-patch and their
                 neighbours
  extremaFraction  fraction of points that are strict local extrema of p
                 among their edge neighbours (by more than 1e-2 of the
                 range): a checkerboard makes about half of the points
                 extrema, a smooth field almost none
Numerical dissipation D = E0 + W_ext - (K + U + D_plastic): its smallest
value and its largest decrease, both relative to the initial energy.
--plane-strain: planeStrainMismatch, the largest velocity difference
between the two copies of an in-plane point of a one-layer mesh (across
the given direction) over the largest speed, at any written time: zero for
plane strain (solidBody ties the copies; round-off of the written fields
is about 1e-10).
--contact-times: first contact and last separation from the x-momentum
history of the first body (times at which it changes)."""
import argparse
import json
import os
import re
import sys

import numpy as np

import svmbPost


def bodies():
    path = 'constant/regionProperties'
    if os.path.isfile(path):
        text = open(path).read()
        m = re.search(r'solid\s*\(([^)]*)\)', text)
        return m.group(1).split()
    return ['region0']


def mesh_dir(body):
    return 'constant/polyMesh' if body == 'region0' \
        else 'constant/%s/polyMesh' % body


def field_path(time, body, name):
    return '%s/%s' % (time, name) if body == 'region0' \
        else '%s/%s/%s' % (time, body, name)


def mesh_edges(body):
    """Unique mesh edges (E x 2) from the polyMesh faces."""
    edges = set()
    for f in svmbPost.read_faces(mesh_dir(body) + '/faces'):
        v = [int(i) for i in f]
        for a, b in zip(v, v[1:] + v[:1]):
            edges.add((a, b) if a < b else (b, a))
    return np.array(sorted(edges), dtype=int)


def smoothness(p, edges, floor=0.0):
    """maxJump and extremaFraction of p; ranges below floor (a field at
    rest, before contact) are measured against floor instead"""
    rng = max(p.max() - p.min(), floor)
    if rng <= 0:
        return 0.0, 0.0
    jump = np.abs(p[edges[:, 0]] - p[edges[:, 1]])
    tol = 1e-2*rng
    n = len(p)
    # strict local extremum: above (below) every neighbour by more than tol
    lo_nbr = np.full(n, np.inf)
    hi_nbr = np.full(n, -np.inf)
    for a, b in ((0, 1), (1, 0)):
        np.minimum.at(lo_nbr, edges[:, a], p[edges[:, b]])
        np.maximum.at(hi_nbr, edges[:, a], p[edges[:, b]])
    extrema = (p > hi_nbr + tol) | (p < lo_nbr - tol)
    return float(jump.max()/rng), float(extrema.mean())


def patch_points(body, patch):
    """Mesh points of a patch (OpenFOAM writes nFaces before
    startFace)."""
    text = svmbPost.read_text(mesh_dir(body) + '/boundary')
    m = re.search(r'\b%s\s*\{[^}]*?nFaces\s+(\d+);[^}]*?startFace\s+(\d+);'
                  % patch, text)
    nf, start = int(m.group(1)), int(m.group(2))
    faces = svmbPost.read_faces(mesh_dir(body) + '/faces')
    pts = set()
    for f in faces[start:start + nf]:
        pts.update(int(i) for i in f)
    return np.array(sorted(pts), dtype=int)


def smoothness_subset(p, edges, keep, floor):
    """smoothness() over the points 'keep' and the edges between them"""
    idx = np.nonzero(keep)[0]
    remap = -np.ones(len(p), int)
    remap[idx] = np.arange(len(idx))
    return smoothness(p[idx], remap[edges], floor)


def written_times():
    times = []
    for d in os.listdir('.'):
        try:
            t = float(d)
        except ValueError:
            continue
        # (only directories the solver completed)
        if t > 0 and os.path.isfile(os.path.join(d, 'uniform', 'time')):
            times.append((t, d))
    return [d for t, d in sorted(times)]


def plane_strain_mismatch(names, X, c):
    """max over written times and bodies of max |v_a - v_b| / max |v| over
    the pairs (a, b) of points at the same in-plane position on the two
    planes c = min and c = max of a one-layer mesh"""
    worst = 0.0
    for b in names:
        x = X[b]
        size = np.ptp(x, axis=0).max()
        lo = np.abs(x[:, c] - x[:, c].min()) < 1e-9*size
        hi = np.abs(x[:, c] - x[:, c].max()) < 1e-9*size
        inplane = [k for k in range(3) if k != c]
        def order(mask):
            idx = np.nonzero(mask)[0]
            key = np.round(x[idx][:, inplane]/size, 9)
            return idx[np.lexsort((key[:, 1], key[:, 0]))]
        a, bb = order(lo), order(hi)
        if len(a) != len(bb) or len(a) + len(bb) != len(x):
            sys.exit('svmbCasePost: body %s is not a one-layer mesh across %s'
                     % (b, 'xyz'[c]))
        for time in written_times():
            path = field_path(time, b, 'v')
            if not svmbPost.foam_file_exists(path):
                continue
            try:
                v = svmbPost.read_point_field(path)
            except ValueError:      # uniform
                continue
            vmax = np.abs(v).max()
            if vmax > 0:
                worst = max(worst, float(
                    np.linalg.norm(v[a] - v[bb], axis=1).max()/vmax))
    return worst


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--plane', choices=['x', 'y', 'z'], default=None)
    ap.add_argument('--at', type=float, default=0.0,
                    help='coordinate of the --plane section')
    ap.add_argument('--contact-times', action='store_true')
    ap.add_argument('--plane-strain', choices=['x', 'y', 'z'], default=None)
    ap.add_argument('--contact-patch', default=None,
                    help='also measure smoothness away from this patch')
    args = ap.parse_args()

    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt

    os.makedirs('results', exist_ok=True)
    names = bodies()
    summary = {'case': os.path.basename(os.getcwd()), 'bodies': names}

    # Energies summed over the bodies (every body writes every step)
    keys = ['kinetic', 'strain', 'plastic', 'externalWork',
            'numericalDissipation']
    data = [svmbPost.read_csv('postProcessing/%s/energy.csv' % b)
            for b in names]
    n = min(len(d) for d in data)
    t = data[0]['t'][:n]
    E = {k: sum(d[k][:n] for d in data) for k in keys}
    E0 = E['kinetic'][0] + E['strain'][0] + E['plastic'][0] \
        + E['numericalDissipation'][0] - E['externalWork'][0]
    D = E['numericalDissipation']
    decrease = np.maximum.accumulate(D) - D
    np.savetxt('results/energy.csv', np.column_stack([t] + [E[k] for k in keys]),
               delimiter=',', header='t,' + ','.join(keys), comments='')
    summary.update({
        'endTime': float(t[-1]),
        'initialEnergy': float(E0),
        'finalKinetic': float(E['kinetic'][-1]),
        'finalStrain': float(E['strain'][-1]),
        'finalPlastic': float(E['plastic'][-1]),
        'finalExternalWork': float(E['externalWork'][-1]),
        'numericalDissipationPercent': float(100*D[-1]/E0),
        'minNumericalDissipationPercent': float(100*D.min()/E0),
        'maxDissipationDecreasePercent': float(100*decrease.max()/E0),
    })

    fig, ax = plt.subplots(figsize=(7, 4.5))
    scale = 1e3 if t[-1] < 0.1 else 1.0
    tl = 't [ms]' if scale == 1e3 else 't [s]'
    if t[-1] < 1e-3:
        scale, tl = 1e6, 't [us]'
    for k, lab in (('kinetic', 'kinetic'), ('strain', 'strain'),
                   ('plastic', 'plastic dissipation'),
                   ('numericalDissipation', 'numerical dissipation')):
        if k == 'plastic' and np.all(E[k] == 0):
            continue
        ax.plot(t*scale, E[k], label=lab)
    if np.any(E['externalWork'] != 0):
        ax.plot(t*scale, E['externalWork'], label='external work')
    ax.set_xlabel(tl)
    ax.set_ylabel('energy [J]')
    ax.legend()
    ax.grid(alpha=0.3)
    ax.set_title('%s: energy (%s)' % (summary['case'], ', '.join(names)))
    fig.tight_layout()
    fig.savefig('results/energy.png', dpi=110)
    plt.close(fig)

    # Probes: velocity magnitude components and pressure
    fig, axs = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    for b in names:
        pr = svmbPost.read_csv('postProcessing/%s/probes.csv' % b)
        k = 0
        while 'vx%d' % k in pr.dtype.names:
            lab = '%s probe %d' % (b, k)
            axs[0].plot(pr['t']*scale, pr['vx%d' % k], label=lab + ' vx')
            p = -(pr['sxx%d' % k] + pr['syy%d' % k] + pr['szz%d' % k])/3
            axs[1].plot(pr['t']*scale, p, label=lab)
            k += 1
    axs[0].set_ylabel('v_x [m/s]')
    axs[1].set_ylabel('pressure [Pa]')
    axs[1].set_xlabel(tl)
    for a in axs:
        a.grid(alpha=0.3)
        a.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig('results/probes.png', dpi=110)
    plt.close(fig)

    # Pressure snapshots and smoothness
    smooth = []
    edges = {b: mesh_edges(b) for b in names}
    X = {b: svmbPost.read_points(mesh_dir(b) + '/points') for b in names}
    fields = {}
    for time in written_times():
        for b in names:
            path = field_path(time, b, 'p')
            if svmbPost.foam_file_exists(path):
                try:
                    fields[(time, b)] = svmbPost.read_point_field(path)
                except ValueError:      # uniform: at rest
                    fields[(time, b)] = np.zeros(len(X[b]))
    scale = max([np.ptp(p) for p in fields.values()] + [0.0])
    # Bulk: without the contact-patch points and their neighbours (the
    # contact layer has its own error, reported separately)
    bulk = {}
    for b in names:
        keep = np.ones(len(X[b]), bool)
        if args.contact_patch:
            cpts = patch_points(b, args.contact_patch)
            near = np.zeros(len(X[b]), bool)
            near[cpts] = True
            e = edges[b]
            near[e[near[e[:, 1]], 0]] = True
            near[e[near[e[:, 0]], 1]] = True
            keep = ~near
        e = edges[b]
        bulk[b] = (keep, e[keep[e[:, 0]] & keep[e[:, 1]]])
    for time in written_times():
        fig, ax = plt.subplots(figsize=(7, 5))
        parts, pmin, pmax = [], np.inf, -np.inf
        entry = {'time': float(time)}
        for b in names:
            if (time, b) not in fields:
                continue
            p = fields[(time, b)]
            try:
                u = svmbPost.read_point_field(field_path(time, b, 'u'))
            except ValueError:
                u = np.zeros_like(X[b])
            jump, ext = smoothness(p, edges[b], 1e-2*scale)
            entry[b] = {'maxJump': jump, 'extremaFraction': ext,
                        'pMin': float(p.min()), 'pMax': float(p.max())}
            if args.contact_patch:
                keep, ke = bulk[b]
                jb, xb = smoothness_subset(p, ke, keep, 1e-2*scale)
                entry[b].update({'maxJumpBulk': jb, 'extremaFractionBulk': xb})
            x = X[b] + u
            # The shortest edge against its reference length: a crushed
            # edge (a contact corner rolling over) shows here first
            e = edges[b]
            stretch = np.linalg.norm(x[e[:, 0]] - x[e[:, 1]], axis=1) \
                / np.linalg.norm(X[b][e[:, 0]] - X[b][e[:, 1]], axis=1)
            entry[b]['minEdgeStretch'] = float(stretch.min())
            if args.plane is not None:
                c = 'xyz'.index(args.plane)
                size = np.ptp(X[b], axis=0).max()
                sel = np.abs(X[b][:, c] - args.at) < 1e-6*size
            else:
                sel = np.ones(len(p), bool)
            parts.append((x[sel], p[sel]))
            pmin, pmax = min(pmin, p.min()), max(pmax, p.max())
        if not parts:
            plt.close(fig)
            continue
        axes2d = [0, 1] if args.plane in (None, 'z') else \
            ([1, 2] if args.plane == 'x' else [0, 2])
        for x, p in parts:
            sc = ax.scatter(x[:, axes2d[0]], x[:, axes2d[1]], c=p, s=6,
                            cmap='jet', vmin=pmin, vmax=pmax)
        fig.colorbar(sc, ax=ax, label='pressure [Pa]')
        ax.set_aspect('equal')
        worst = max(entry[b]['maxJump'] for b in names if b in entry)
        wext = max(entry[b]['extremaFraction'] for b in names if b in entry)
        ax.set_title('t = %s: max jump %.2f of range, extrema %.1f %%'
                     % (time, worst, 100*wext))
        fig.tight_layout()
        fig.savefig('results/pressure_%s.png' % time, dpi=100)
        plt.close(fig)
        smooth.append(entry)
    summary['pressureSmoothness'] = smooth
    if smooth:
        summary['maxPressureJump'] = max(
            e[b]['maxJump'] for e in smooth for b in names if b in e)
        summary['maxExtremaFraction'] = max(
            e[b]['extremaFraction'] for e in smooth for b in names if b in e)
        summary['minEdgeStretch'] = min(
            e[b]['minEdgeStretch'] for e in smooth for b in names if b in e)
        if args.contact_patch:
            summary['maxPressureJumpBulk'] = max(
                e[b]['maxJumpBulk'] for e in smooth for b in names if b in e)
            summary['maxExtremaFractionBulk'] = max(
                e[b]['extremaFractionBulk'] for e in smooth for b in names
                if b in e)

    if args.plane_strain:
        summary['planeStrainMismatch'] = plane_strain_mismatch(
            names, X, 'xyz'.index(args.plane_strain))

    # Run statistics: from the newest complete time directory's uniform/
    # files (a restarted run's steps and wall time count since t = 0)
    stats = svmbPost.run_statistics()
    for k in ('steps', 'wallTime', 'runs', 'throughput', 'points'):
        summary[k] = stats[k]
    if 'maxInterpenetration' in stats:
        summary['maxInterpenetration'] = stats['maxInterpenetration']

    # Rigid walls: the largest depth of a touching point behind the wall, in
    # the patch's shortest edges, from the solver's log (this run's)
    depths = svmbPost.wall_depths()
    if depths:
        summary['maxWallDepth'] = max(depths)

    # Momentum of all bodies together (conserved without walls and gravity)
    P = sum(np.column_stack([d['px'], d['py'], d['pz']])[:n] for d in data)
    p0 = max(np.linalg.norm(np.column_stack(
        [data[0]['px'], data[0]['py'], data[0]['pz']])[0]), 1e-300)
    summary['totalMomentumChange'] = float(np.linalg.norm(P[-1] - P[0])/p0)

    if args.contact_times:
        d = data[0]
        pm = np.column_stack([d['px'], d['py'], d['pz']])[:n]
        tt = d['t'][:n]
        # x: the direction of approach in every tutorial (gravity acts
        # along y in the car case)
        force = np.abs(np.diff(pm[:, 0]))/np.diff(tt)
        active = force > 1e-3*force.max()
        idx = np.nonzero(active)[0]
        if len(idx):
            summary['firstContact'] = float(tt[idx[0]])
            summary['lastContact'] = float(tt[idx[-1] + 1])
            summary['separated'] = bool(idx[-1] + 1 < n - 1)
        summary['initialMomentum'] = pm[0].tolist()
        summary['finalMomentum'] = pm[-1].tolist()

    json.dump(summary, open('results/summary.json', 'w'), indent=2)
    short = {k: v for k, v in summary.items() if k != 'pressureSmoothness'}
    print(json.dumps(short, indent=2))


if __name__ == '__main__':
    main()
