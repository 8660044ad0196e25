#!/usr/bin/env python3
"""The closing figures of a solidVertexMBFoam log, for the benchmark scripts
(benchmarks/*/Allrun), which print them side by side:

    from svmbPost.solverLog import runFigures
    f = runFigures('log.solidVertexMBFoam')    # None if it did not finish

Keys: steps, wall (s), throughput (point-stage updates per second per
core), points, updates (point-stage updates: the multirate count, else two
stages of every point per step), work (in steps of every point), and
bytesPerPoint (None if the log has no peak-memory line).  (The figures of
<time>/uniform/runStatistics, svmbPost.run_statistics, count the wall time
since start-up and have no multirate counts.)"""
import re


def runFigures(path):
    """The figures of the log at path (see the module's docstring)."""
    with open(path) as f:
        text = f.read()
    fin = re.search(r'^Finished (\d+) steps in (\S+) s wall', text, re.M)
    thr = re.search(r'^Throughput: (\S+) .*\((\d+) points', text, re.M)
    if not fin or not thr:
        return None
    mem = re.search(r'^Peak memory: (\S+) MB, (\S+) bytes per point', text,
                    re.M)
    mr = re.search(r'^Multirate: (\d+) point-stage updates, the work of '
                   r'(\d+) steps', text, re.M)
    steps, points = int(fin.group(1)), int(thr.group(2))
    return {
        'steps': steps,
        'wall': float(fin.group(2)),
        'throughput': float(thr.group(1)),
        'points': points,
        'updates': int(mr.group(1)) if mr else 2*steps*points,
        'work': int(mr.group(2)) if mr else steps,
        'bytesPerPoint': float(mem.group(2)) if mem else None,
    }
