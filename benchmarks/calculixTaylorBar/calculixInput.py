#!/usr/bin/env python3
"""Write CalculiX 2.20's input for the Taylor bar (doc/benchmarks.md, C1)
from gmsh's Abaqus export of the tutorial's hexahedral O-grid.

    calculixInput.py mesh.inp bar.inp increment [endTime]

The same quarter model as tutorials/taylorBar: copper, J2 plasticity with
linear hardening (0.4 GPa yield, 0.1 GPa plastic modulus), 227 m/s towards
the wall at y = 0, which holds the impact face in y (frictionless, the
tutorial's symmetry plane), symmetry planes x = 0 and z = 0.  C3D8R
elements, large strain (NLGEOM), explicit central differences at the fixed
increment given (CalculiX keeps its step fixed through a step, at its
initial Courant value unless DIRECT sets one: the crushed foot needs a
smaller one).  The node initially at the edge of the impact face, (R, 0,
0), is printed at the end: its final radius is R + u_x.
"""
import sys

R = 3.2e-3                       # bar radius (taylorBar.geo)


def read_gmsh_inp(path):
    """Nodes and the C3D8 elements of gmsh's export (its surface elements
    and sets are not needed: the sets are made here from coordinates)."""
    nodes, elements, block = {}, [], None
    with open(path) as f:
        for line in f:
            s = line.strip()
            if s.startswith('*'):
                key = s.upper().replace(' ', '')
                block = ('node' if key.startswith('*NODE') else
                         'hex' if key.startswith('*ELEMENT')
                         and 'TYPE=C3D8' in key else None)
                continue
            if not s or block is None:
                continue
            v = [t for t in s.split(',') if t.strip()]
            if block == 'node':
                nodes[int(v[0])] = tuple(float(t) for t in v[1:4])
            else:
                elements.append([int(t) for t in v[1:9]])
    if not elements:
        sys.exit('calculixInput.py: no C3D8 elements in %s (needs the '
                 'hexahedral O-grid, hex = 1)' % path)
    return nodes, elements


def id_lines(ids):
    return [', '.join(str(n) for n in ids[i:i + 10])
            for i in range(0, len(ids), 10)]


def main():
    if len(sys.argv) not in (4, 5):
        sys.exit(__doc__)
    src, dst, increment = sys.argv[1:4]
    end_time = sys.argv[4] if len(sys.argv) == 5 else '80e-6'
    nodes, elements = read_gmsh_inp(src)
    used = sorted({n for e in elements for n in e})
    tol = 1e-4*R
    sets = {
        'NSYMX': lambda p: abs(p[0]) < tol,
        'NSYMZ': lambda p: abs(p[2]) < tol,
        'NWALL': lambda p: abs(p[1]) < tol,
        'NEDGE': lambda p: (abs(p[1]) < tol and abs(p[2]) < tol
                            and abs(p[0] - R) < tol),
    }
    out = ['*HEADING', 'Taylor bar C1, quarter model (svmb benchmark)',
           '*NODE']
    out += ['%d, %.12g, %.12g, %.12g' % ((n,) + nodes[n]) for n in used]
    out.append('*ELEMENT, TYPE=C3D8R, ELSET=EBAR')
    out += ['%d, %s' % (i + 1, ', '.join(map(str, e)))
            for i, e in enumerate(elements)]
    for name, inside in sets.items():
        ids = [n for n in used if inside(nodes[n])]
        if name == 'NEDGE' and len(ids) != 1:
            sys.exit('calculixInput.py: %d nodes at (R, 0, 0)' % len(ids))
        out += ['*NSET, NSET=%s' % name] + id_lines(ids)
    out += ['*NSET, NSET=NALL'] + id_lines(used)
    out += [
        '*MATERIAL, NAME=COPPER',
        '*ELASTIC', '117e9, 0.35',
        '*DENSITY', '8930',
        # true stress against equivalent plastic strain: linear hardening
        '*PLASTIC', '0.4e9, 0.0', '1.4e9, 10.0',
        '*SOLID SECTION, ELSET=EBAR, MATERIAL=COPPER',
        '*BOUNDARY', 'NSYMX, 1, 1', 'NSYMZ, 3, 3', 'NWALL, 2, 2',
        '*INITIAL CONDITIONS, TYPE=VELOCITY', 'NALL, 2, -227.0',
        '*STEP, NLGEOM, INC=100000000',
        # DIRECT: the increment given, fixed (initial, period, minimum,
        # maximum; a minimum above zero would trigger mass scaling)
        '*DYNAMIC, EXPLICIT, DIRECT',
        '%s, %s, 1e-20, %s' % (increment, end_time, increment),
        '*NODE PRINT, NSET=NEDGE, FREQUENCY=100000000', 'U',
        '*END STEP']
    with open(dst, 'w') as f:
        f.write('\n'.join(out) + '\n')


if __name__ == '__main__':
    main()
