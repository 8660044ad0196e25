"""The project's post-processing package (one place for all tutorials and
tests; put $SVMB_PROJECT/etc on PYTHONPATH, as etc/bashrc does):
    svmbPost             readers and run figures (this module)
    svmbPost.casePost    results/ of the multi-dimensional tutorials
    svmbPost.barImpact   results/ of the bar-impact tutorials (exact solution)
    svmbPost.barWall     results/ of a bar on a rigid wall (exact solution)
    svmbPost.stepField   what sets the time step (the stableDeltaT field)
    svmbPost.solverLog   a log's closing figures, for benchmarks/*/Allrun
Case-specific figures live with the case (tutorials/taylorBar/taylorBarPost.py).

Helpers:
reading OpenFOAM point fields, mesh points and faces (ASCII or binary,
compressed or not), the solver's CSV monitors, and the figures it writes
with every complete time directory (<time>/uniform/runStatistics,
contactState.<pair>).  Figures come from these files, never from the
wording of the log; the one exception is svmbPost.solverLog, which the
benchmark scripts use for what only the log's closing lines print (the
multirate updates and work, the time loop's own wall time).
"""
import gzip
import os
import re
import subprocess
import sys
import numpy as np

_NUM = r'[-+0-9.eE]+'


# Components per point of each field type
_NCOMP = {'scalar': 1, 'vector': 3, 'symmTensor': 6, 'tensor': 9,
          'sphericalTensor': 1}


def _read_foam_file(path):
    """(header, body) bytes of an OpenFOAM file, written with or without
    writeCompression (path or path.gz); the header ends at the FoamFile
    dictionary's closing brace."""
    if not os.path.isfile(path) and os.path.isfile(path + '.gz'):
        raw = gzip.open(path + '.gz', 'rb').read()
    else:
        raw = open(path, 'rb').read()
    end = raw.index(b'}', raw.index(b'FoamFile')) + 1
    return raw[:end], raw[end:]


def foam_file_exists(path):
    """Whether an OpenFOAM file was written (compressed or not)."""
    return os.path.isfile(path) or os.path.isfile(path + '.gz')


def read_text(path):
    """The whole of a text OpenFOAM file (a dictionary such as
    polyMesh/boundary), compressed or not."""
    return b''.join(_read_foam_file(path)).decode()


def _is_binary(header):
    return re.search(rb'format\s+binary', header) is not None


def is_binary_file(path):
    """Whether an OpenFOAM file (compressed or not) was written in binary."""
    return _is_binary(_read_foam_file(path)[0])


def _label_type(header):
    # (the build's WM_LABEL_SIZE, from the file's "arch" entry)
    m = re.search(rb'label=(\d+)', header)
    return np.int64 if m and m.group(1) == b'64' else np.int32


def _binary_list(body, start, dtype, count):
    """count values of dtype from the raw block after the '(' at or after
    start; returns them and the offset after the closing ')'."""
    open_paren = body.index(b'(', start)
    n = np.dtype(dtype).itemsize*count
    data = np.frombuffer(body[open_paren + 1:open_paren + 1 + n],
                         dtype=dtype).copy()
    return data, open_paren + 1 + n + 1


def read_points(path):
    """Mesh points (N x 3) from constant/[region/]polyMesh/points (ASCII or
    binary, compressed or not)."""
    head, body = _read_foam_file(path)
    m = re.search(rb'\n\s*(\d+)\s*\n?\s*\(', body)
    n = int(m.group(1))
    if _is_binary(head):
        return _binary_list(body, m.end() - 1, np.float64, 3*n)[0] \
            .reshape(n, 3)
    return read_vector_list((head + body).decode())


def read_faces(path):
    """Faces of constant/[region/]polyMesh/faces as a list of point-label
    arrays: the ASCII faceList (n(a b c)) or the binary faceCompactList
    (the offsets, then the concatenated labels)."""
    head, body = _read_foam_file(path)
    if _is_binary(head):
        label = _label_type(head)
        m = re.search(rb'(\d+)\s*\(', body)
        offsets, pos = _binary_list(body, m.end() - 1, label,
                                    int(m.group(1)))
        m = re.compile(rb'(\d+)\s*\(').search(body, pos)
        labels = _binary_list(body, m.end() - 1, label, int(m.group(1)))[0]
        return [labels[a:b] for a, b in zip(offsets[:-1], offsets[1:])]
    faces = re.findall(r'\d+\(([\d\s]+)\)', body.decode())
    return [np.array(f.split(), dtype=int) for f in faces]


def read_vector_list(text, start_key=None):
    if start_key is not None:
        text = text[text.index(start_key):]
    # skip the FoamFile header: the list starts after the first count
    m = re.search(r'\n\s*(\d+)\s*\n?\s*\(', text[text.index('}') + 1:])
    body = text[text.index('}') + 1 + m.end():]
    vals = re.findall(r'\(\s*(%s)\s+(%s)\s+(%s)\s*\)' % (_NUM, _NUM, _NUM),
                      body[:body.index('\n)')])
    return np.array(vals, dtype=float)


def read_point_field(path):
    """Internal values of a point field (scalar: N, vector: N x 3,
    tensor: N x 9, symmTensor: N x 6), ASCII or binary, compressed or
    not."""
    head, body = _read_foam_file(path)
    i = body.index(b'internalField')
    m = re.compile(rb'internalField\s+(nonuniform\s+List<(\w+)>\s*(\d+)'
                   rb'\s*\(|uniform)').match(body, i)
    if m is None or m.group(1) == b'uniform':
        raise ValueError('uniform field ' + path)
    kind, n = m.group(2).decode(), int(m.group(3))
    if kind not in _NCOMP:
        raise ValueError('%s: unknown field type %s' % (path, kind))
    if _is_binary(head):
        values = _binary_list(body, m.end() - 1, np.float64,
                              _NCOMP[kind]*n)[0]
    else:
        text = body[m.end():].decode()
        # (a short list is written on one line: n(a b c))
        end = text.find('\n)')
        text = text[:end if end >= 0 else text.index(')')]
        values = np.array(text.split() if kind == 'scalar'
                          else re.findall(_NUM, text), dtype=float)
    return values if kind == 'scalar' else values.reshape(n, -1)


def fail(tool, message):
    """Stop post-processing with a clear message (never a wrong number)."""
    sys.exit('%s: %s' % (tool, message))


def complete_times(case='.'):
    """Time directories the solver completed (uniform/time written last),
    oldest first; of processor0 for an undecomposed-but-parallel case."""
    root = case
    if not any(os.path.isfile(os.path.join(case, d, 'uniform', 'time'))
               for d in os.listdir(case)) \
            and os.path.isdir(os.path.join(case, 'processor0')):
        root = os.path.join(case, 'processor0')
    out = []
    for d in os.listdir(root):
        try:
            t = float(d)
        except ValueError:
            continue
        if os.path.isfile(os.path.join(root, d, 'uniform', 'time')):
            out.append((t, os.path.join(root, d)))
    return [p for t, p in sorted(out)]


def read_dict(path):
    """Scalar entries of a small OpenFOAM dictionary (uniform/ files)."""
    text = open(path).read()
    text = text[text.index('}', text.index('FoamFile')) + 1:]
    out = {}
    for key, value in re.findall(r'^\s*(\w[\w.]*)\s+([^;{}]+);', text, re.M):
        try:
            out[key] = float(value)
        except ValueError:
            out[key] = value.strip()
    return out


def run_statistics(case='.'):
    """Figures of the run up to the newest complete time: steps and
    wallTime since t = 0, runs; points, cores, throughput, peakMemory of
    the last run; maxInterpenetration over the contact pairs (if any)."""
    times = complete_times(case)
    if not times:
        fail('svmbPost', 'no complete time directory in %s: did the run '
             'write anything?' % os.path.abspath(case))
    uniform = os.path.join(times[-1], 'uniform')
    stats = read_dict(os.path.join(uniform, 'runStatistics'))
    out = {'time': float(os.path.basename(times[-1]))}
    for k in ('steps', 'runs', 'points', 'cores'):
        out[k] = int(stats[k])
    for k in ('wallTime', 'throughput', 'peakMemory'):
        out[k] = float(stats[k])
    pen = [read_dict(os.path.join(uniform, f))['maxPenetration']
           for f in sorted(os.listdir(uniform))
           if f.startswith('contactState.')]
    if pen:
        out['maxInterpenetration'] = max(pen)
    return out


def wall_depths(log='log.solidVertexMBFoam'):
    """Each rigid wall's largest depth of a point behind it, in the patch's
    shortest edges, as the solver's log ends with it (a list, one per wall
    of every body; empty without walls or log)."""
    if not os.path.isfile(log):
        return []
    return [float(d) for d in re.findall(
        r"largest depth behind the wall \S+ \((\S+) of the patch's "
        r"shortest edge\)", open(log).read())]


def read_csv(path):
    return np.genfromtxt(path, delimiter=',', names=True)


def bar_axis(d):
    """The unit vector along d; exactly a coordinate axis when d lies
    within 1e-9 of one, so that a bar along x reads its probes' x columns
    unchanged (axial_probes)."""
    d = np.asarray(d, dtype=float)
    a = d / np.linalg.norm(d)
    k = int(np.argmax(np.abs(a)))
    if abs(abs(a[k]) - 1) < 1e-9:
        a = np.zeros(3)
        a[k] = 1.0 if d[k] > 0 else -1.0
    return a


def across(v, a):
    """The part of the vector v across the unit vector a (its length)."""
    v = np.asarray(v, dtype=float)
    return float(np.linalg.norm(v - np.dot(v, a) * a))


def bar_geometry(X, a):
    """A body's extent along the unit vector a (the axial coordinates of
    its ends, lo and hi), the largest distance of a point from the axis
    through its centre, and the area of its section across a (the convex
    hull of the points projected on the plane across a)."""
    s = X @ a
    lo, hi = float(s.min()), float(s.max())
    # a frame across a: for a coordinate axis the other two axes, in order
    k = int(np.argmin(np.abs(a)))
    e1 = np.zeros(3)
    e1[k] = 1.0
    e1 -= np.dot(e1, a) * a
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(a, e1)
    q = np.column_stack([X @ e1, X @ e2])
    centre = 0.5 * (q.min(axis=0) + q.max(axis=0))
    radius = float(np.sqrt(((q - centre)**2).sum(axis=1)).max())
    # the hull by Andrew's monotone chain, its area by the shoelace formula
    pts = sorted(set(map(tuple, q)))

    def half(points):
        chain = []
        for p in points:
            while len(chain) >= 2 and (
                    (chain[-1][0] - chain[-2][0]) * (p[1] - chain[-2][1])
                    - (chain[-1][1] - chain[-2][1]) * (p[0] - chain[-2][0])
                    <= 0):
                chain.pop()
            chain.append(p)
        return chain[:-1]
    hull = np.array(half(pts) + half(pts[::-1]))
    x, y = hull[:, 0], hull[:, 1]
    area = 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))
    return lo, hi, radius, float(area)


def axial_probes(P, a):
    """Probe histories along the unit vector a (a bar's axis), under the
    names of a bar along x: per probe k, 'vx<k>' the velocity along a,
    'ux<k>' the displacement along a, 'sxx<k>' the normal stress
    a.sigma.a; and 't'.  For a = (1 0 0) these are the x columns
    themselves, to the bit."""
    out = {'t': P['t']}
    k = 0
    while 'vx%d' % k in P.dtype.names:
        c = lambda n: P['%s%d' % (n, k)]
        out['vx%d' % k] = c('vx') * a[0] + c('vy') * a[1] + c('vz') * a[2]
        out['ux%d' % k] = c('ux') * a[0] + c('uy') * a[1] + c('uz') * a[2]
        out['sxx%d' % k] = (
            c('sxx') * a[0] * a[0] + c('syy') * a[1] * a[1]
            + c('szz') * a[2] * a[2]
            + 2 * (c('sxy') * a[0] * a[1] + c('syz') * a[1] * a[2]
                   + c('sxz') * a[0] * a[2]))
        k += 1
    return out


def axial_momentum(E, a):
    """A body's momentum along the unit vector a from its energy history."""
    return E['px'] * a[0] + E['py'] * a[1] + E['pz'] * a[2]


def save_history_plot(fig, what, summary, path='results/history.png'):
    """Title a probe-history figure with the case, what it shows and the
    run's size and wall time, and write it."""
    fig.suptitle('%s: %s (%d points, %.1f s wall)'
                 % (os.path.basename(os.getcwd()), what, summary['points'],
                    summary['wallTime']))
    fig.tight_layout()
    fig.savefig(path, dpi=90)


def print_summary(summary, width=24):
    """One line per entry: floats to 6 digits, lists space-separated."""
    for k, v in summary.items():
        if isinstance(v, list):
            v = ' '.join('%.6g' % x if isinstance(x, float) else str(x)
                         for x in v)
        elif isinstance(v, float):
            v = '%.6g' % v
        print('  %-*s %s' % (width, k, v))


def _foam_dictionary(args):
    # (OpenFOAM warns on stdout when PWD is not the working directory, as
    # after a chdir in the scripts that post-process a case; full precision:
    # by default it prints 6 digits, so a wall normal along (1 2 3) put the
    # bar's struck face 4e-7 behind the wall)
    return subprocess.run(['foamDictionary', '-precision', '17'] + args,
                          capture_output=True,
                          text=True, env=dict(os.environ, PWD=os.getcwd()))


def dict_entry(path, key, default=None, tool='svmbPost'):
    """The value of a dictionary entry as text (foamDictionary); the
    default where it is missing, or a stop naming the tool without one."""
    r = _foam_dictionary(['-entry', key, '-value', path])
    if r.returncode != 0:
        if default is None:
            fail(tool, 'no %s in %s' % (key, path))
        return default
    return r.stdout.strip()


def dict_keywords(path, key):
    """The keywords of a sub-dictionary (foamDictionary -keywords)."""
    return _foam_dictionary(['-keywords', '-entry', key, path]).stdout.split()


def elastic_moduli(path, tool='svmbPost'):
    """The type, shear and bulk moduli and the uniaxial-strain modulus
    lambda + 2 mu of the material in a solidProperties file (E and nu, or
    kappa and mu)."""
    kind = dict_entry(path, 'material/type', tool=tool)
    E = dict_entry(path, 'material/E', 'none', tool)
    if E != 'none':
        E = float(E)
        nu = float(dict_entry(path, 'material/nu', tool=tool))
        return (kind, E / (2 * (1 + nu)), E / (3 * (1 - 2 * nu)),
                E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)))
    mu = float(dict_entry(path, 'material/mu', tool=tool))
    kappa = float(dict_entry(path, 'material/kappa', tool=tool))
    return kind, mu, kappa, kappa + 4.0 * mu / 3.0


def uniaxial_material(path, refuse, tool='svmbPost'):
    """rho and the uniaxial-strain modulus lambda + 2 mu (a bar between
    symmetry sides) of an elastic material in a solidProperties file;
    refuse(message) for any other material."""
    kind = dict_entry(path, 'material/type', tool=tool)
    if kind not in ('linearElastic', 'neoHookean', 'mooneyRivlin'):
        refuse('the material of %s is %s, not an elastic one' % (path, kind))
    rho = float(dict_entry(path, 'material/rho', tool=tool))
    return rho, elastic_moduli(path, tool)[3]


def uniaxial_stress_curve(path, tool='svmbPost'):
    """The axial first Piola stress P11(lam) of an elastic material in
    uniaxial strain, F = diag(lam, 1, 1), as the solver evaluates it
    (src/materials): the deviatoric part of each model plus the volumetric
    stress, the Hugoniot pressure kappa (J - 1)/(1 - s (1 - J))^2 in
    compression where the material has one (kappa (J - 1) otherwise).  With
    shear stiffness and a Hugoniot the shock is not the one of
    U = c_p + s v: the deviatoric stress has its own curve."""
    kind, mu, kappa, _ = elastic_moduli(path, tool)
    s = float(dict_entry(path, 'material/hugoniot/s', '0', tool))
    xi = float(dict_entry(path, 'material/xi', '0', tool)) \
        if kind == 'mooneyRivlin' else 0.0

    def volumetric(J):
        if s > 0 and J < 1:
            return kappa * (J - 1) / (1 - s * (1 - J)) ** 2
        return kappa * (J - 1)

    def deviatoric_energy(lam):
        if kind == 'linearElastic':
            return 2.0 / 3.0 * mu * (lam - 1) ** 2
        if kind == 'neoHookean':
            return 0.5 * mu * (lam ** (-2.0 / 3.0) * (lam ** 2 + 2) - 3)
        zeta = 0.5 * (mu - 3 * np.sqrt(3.0) * xi)
        HH = 1 + 2 * lam ** 2
        return (zeta * lam ** (-2.0 / 3.0) * (lam ** 2 + 2)
                + xi * HH * np.sqrt(HH) / lam ** 2
                - 3 * (zeta + np.sqrt(3.0) * xi))

    def P11(lam):
        h = 1e-5 * lam
        dev = (deviatoric_energy(lam + h) - deviatoric_energy(lam - h)) \
            / (2 * h) if mu > 0 else 0.0
        return dev + volumetric(lam)
    return P11


def shock_jump(P11, rho, sigma):
    """The particle velocity jump of a compressive shock into material at
    rest that leaves the stress sigma < 0 behind it (jump conditions:
    sigma = -rho U dv, dv = U (1 - lam), sigma = P11(lam)): dv =
    sqrt(-sigma (1 - lam)/rho)."""
    lo, hi = 1e-3, 1.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if P11(mid) < sigma:
            lo = mid
        else:
            hi = mid
    lam = 0.5 * (lo + hi)
    return np.sqrt(max(-sigma * (1 - lam) / rho, 0.0))


def shock_plateau(P1, rho1, P2, rho2, v0):
    """Contact velocity (in Bar Two's frame) and stress of two bars whose
    impact at v0 sends a shock into each (Bar Two may be a rigid wall:
    P2 None, then the contact velocity is 0)."""
    def excess(sigma):
        dv = shock_jump(P1, rho1, sigma)
        if P2 is not None:
            dv += shock_jump(P2, rho2, sigma)
        return dv - v0
    lo = -1.0
    while excess(lo) < 0:
        lo *= 2
    hi = 0.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if excess(mid) > 0:
            lo = mid
        else:
            hi = mid
    sigma = 0.5 * (lo + hi)
    return v0 - shock_jump(P1, rho1, sigma), sigma
