# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Per-step tables of a run (joints.dat, bodies.dat of eABAMeshMotion or
rigidBodySimulate), joined over the start folders of a run and its
restarts, and the numeric time folders of a case.  numpy only.
"""

import glob
import os

import numpy as np

from flapfoam.errors import FlapFoamError


def read_table(path):
    """(columns, rows) of a joints.dat/bodies.dat file: the first comment
    line starting '# time' names the columns."""
    columns = None
    rows = []
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0] == "#":
                if columns is None and len(words) > 1 and words[1].lower() == "time":
                    columns = words[1:]
                continue
            rows.append([float(w) for w in words])
    if columns is None:
        raise FlapFoamError("plotRun: %s has no '# time ...' header" % path)
    data = np.array(rows, dtype=float).reshape(-1, len(columns))
    return columns, data


def time_value(name, default=None):
    """The time a folder's name stands for, or default if it is no
    number."""
    try:
        return float(name)
    except ValueError:
        return default


def start_folders(base):
    """Start-time folders of a postProcessing/<name> directory, in order."""
    if not os.path.isdir(base):
        return []
    found = [(time_value(d), os.path.join(base, d)) for d in os.listdir(base)]
    return sorted(f for f in found if f[0] is not None)


def joined_table(base, file_name, keep_earlier_at_start):
    """The rows of base/<t>/fileName of all start folders t joined: a later
    folder replaces the rows from its start time on; an earlier row at the
    start time is kept when keep_earlier_at_start (the later folder's row
    there dropped) or when the later folder has no row there (the
    flightData function object's tables write none at a restart)."""
    columns = None
    data = None
    for t0, folder in start_folders(base):
        path = os.path.join(folder, file_name)
        if not os.path.isfile(path):
            continue
        cols, rows = read_table(path)
        if columns is None:
            columns, data = cols, rows
            continue
        if cols != columns:
            raise FlapFoamError("plotRun: %s: columns differ from the first folder"
                                % path)
        eps = 1e-9*max(abs(t0), 1e-300) + 1e-15
        row_at_start = len(rows) > 0 and abs(rows[0, 0] - t0) <= eps
        if (keep_earlier_at_start or not row_at_start) and \
                np.any(np.abs(data[:, 0] - t0) <= eps):
            data = np.vstack([data[data[:, 0] <= t0 + eps],
                              rows[rows[:, 0] > t0 + eps]])
        else:
            data = np.vstack([data[data[:, 0] < t0 - eps], rows])
    return columns, data


def time_folders(case):
    """Numeric time folders of a case (float, path), in order."""
    out = [(time_value(os.path.basename(d)), d)
           for d in glob.glob(os.path.join(case, "[0-9]*"))]
    return sorted(f for f in out if f[0] is not None)

