"""Post-processing helpers shared by tutorials and tests (one place):
reading OpenFOAM ASCII point fields and mesh points, reading the solver's
CSV monitors.  Import with  sys.path.insert(0, os.environ['SVMB_PROJECT'] + '/etc')."""
import re
import numpy as np

_NUM = r'[-+0-9.eE]+'


def read_points(path):
    """Mesh points (N x 3) from constant/[region/]polyMesh/points."""
    return read_vector_list(open(path).read())


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
    """Internal values of an ASCII point field (scalar: N, vector: N x 3,
    tensor: N x 9, symmTensor: N x 6)."""
    text = open(path).read()
    i = text.index('internalField')
    head = text[i:i + 200]
    if 'uniform' in head and 'nonuniform' not in head:
        raise ValueError('uniform field ' + path)
    m = re.search(r'nonuniform\s+List<(\w+)>\s*(\d+)\s*\(', text[i:])
    kind, n = m.group(1), int(m.group(2))
    body = text[i + m.end():]
    body = body[:body.index('\n)')]
    if kind == 'scalar':
        return np.array(body.split(), dtype=float)
    return np.array(re.findall(_NUM, body), dtype=float).reshape(n, -1)


def read_csv(path):
    return np.genfromtxt(path, delimiter=',', names=True)
