# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The per-step numbers of overPimpleDyMFoam's log: time, the last
continuity error ("sum local"), the pressure solves' iterations and the
CPU seconds of the step (the ExecutionTime increment); a run's logs joined
over its restarts.
"""

import glob
import math
import os
import re

import numpy as np

from flapfoam.io.tables import time_value

LOG = "log.overPimpleDyMFoam"


def read_log(path):
    """Per step of one solver log: (time, last 'sum local', p iterations,
    CPU seconds of the step: the ExecutionTime increment)."""
    rows = []
    time_re = re.compile(r"^Time = (\S+)")
    cpu = 0.0
    with open(path, errors="replace") as fh:
        for line in fh:
            m = time_re.match(line)
            if m:
                rows.append([float(m.group(1)), math.nan, 0, math.nan])
            elif not rows:
                continue
            elif "continuity errors : sum local" in line:
                rows[-1][1] = float(line.split("=")[1].split(",")[0])
            elif "Solving for p," in line:
                rows[-1][2] += int(line.rsplit(None, 1)[1])
            elif line.startswith("ExecutionTime"):
                now = float(line.split()[2])
                rows[-1][3], cpu = now - cpu, now
    return rows


def steps(case):
    """The steps of the run's solver logs (log.overPimpleDyMFoam and the
    restarts' log.overPimpleDyMFoam.<time>): a later log replaces the
    steps of the earlier ones from its first time on."""
    logs = [os.path.join(case, LOG)] + sorted(
        glob.glob(os.path.join(case, LOG + ".*")),
        key=lambda f: time_value(os.path.basename(f)[len(LOG) + 1:], 0.0))
    rows = []
    for path in logs:
        if not os.path.isfile(path):
            continue
        more = read_log(path)
        if more:
            rows = [r for r in rows if r[0] < more[0][0]] + more
    return np.array(rows) if rows else np.zeros((0, 4))
