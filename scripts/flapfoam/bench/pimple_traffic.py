# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The MPI traffic of a PIMPLE step per flow setting, counted: the table of
bench/pimple/run -count N1 N2.  Each setting ran twice from rest, N1 and N2
steps, under libflapFoamMPICounters.so (flapfoam.io.mpi_counts); the
difference divided by N2 - N1 is one step's traffic without the start-up.
Beside it, the pressure iterations of those steps (the longer run's solver
log, steps N1+1 to N2), and the messages and reductions per pressure
iteration.  Counted, exact: the same on any machine for the same
decomposition (oversubscribed runs count as well as real ones).

    flapfoam pimple_traffic DIR -count N1 N2 [-o OUT.md]

DIR holds the runs <level>-np<N>-<setting>-s<S> (S = N1, N2), each with
its counts/ folder and log.overPimpleDyMFoam.
"""

import argparse
import os
import re
import sys
from dataclasses import dataclass

import numpy as np

from flapfoam.errors import FlapFoamError, run_tool
from flapfoam.io import mpi_counts, solver_log

RUN = re.compile(r"^(\w+)-np(\d+)-([\w.+]+)-s(\d+)$")


@dataclass
class Traffic:
    """One setting's traffic of a step, per rank (mean and max over the
    ranks), and its pressure iterations."""
    level: str
    ranks: int
    setting: str
    p_iterations: float         # per step
    messages: tuple             # point-to-point calls: (mean, max)
    kbytes: tuple               # point-to-point kB: (mean, max)
    collectives: float          # collective calls (the same on every rank)

    def per_iteration(self, value):
        return value/self.p_iterations if self.p_iterations else float("nan")


def p_iterations(run, n1, n2):
    """Mean pressure iterations of steps n1+1 .. n2 of a run's log."""
    rows = solver_log.steps(run)
    if len(rows) < n2:
        raise FlapFoamError("%s: %d steps in its solver log, %d expected"
                            % (run, len(rows), n2))
    return float(np.mean(rows[n1:n2, 2]))


def traffic(folder, key, n1, n2):
    """The Traffic of one (level, ranks, setting) from its two runs."""
    level, ranks, setting = key
    runs = [os.path.join(folder, "%s-np%d-%s-s%d" % (level, ranks, setting, n))
            for n in (n1, n2)]
    try:
        steps = mpi_counts.per_step(os.path.join(runs[0], "counts"), n1,
                                    os.path.join(runs[1], "counts"), n2)
    except ValueError as err:
        raise FlapFoamError("pimple_traffic: %s" % err)
    calls = np.array([s["p2pCalls"] for s in steps])
    kbytes = np.array([s["p2pBytes"] for s in steps])/1e3
    return Traffic(level, ranks, setting, p_iterations(runs[1], n1, n2),
                   (float(calls.mean()), float(calls.max())),
                   (float(kbytes.mean()), float(kbytes.max())),
                   float(np.mean([s["collectiveCalls"] for s in steps])))


def read_folder(folder, n1, n2):
    """The Traffic of every (level, ranks, setting) with both runs, in the
    order of the folder's names."""
    keys = {}
    for name in sorted(os.listdir(folder)):
        m = RUN.match(name)
        if m and os.path.isdir(os.path.join(folder, name)):
            key = (m.group(1), int(m.group(2)), m.group(3))
            keys.setdefault(key, set()).add(int(m.group(4)))
    done = [k for k, s in keys.items() if {n1, n2} <= s]
    if not done:
        raise FlapFoamError("%s: no runs <level>-np<N>-<setting>-s%d and "
                            "-s%d" % (folder, n1, n2))
    return [traffic(folder, k, n1, n2) for k in done]


def table(rows, n1, n2):
    """The markdown lines of the table."""
    lines = [
        "MPI traffic of one step per rank, counted: runs of %d and %d steps "
        "under libflapFoamMPICounters.so, the difference over %d steps "
        "(mean and max over the ranks)." % (n1, n2, n2 - n1),
        "",
        "| level | ranks | setting | p iterations | messages mean | max "
        "| kB mean | max | collectives | messages per p iteration "
        "| collectives per p iteration |",
        "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(
            "| %s | %d | %s | %.1f | %.0f | %.0f | %.1f | %.1f | %.0f "
            "| %.1f | %.1f |"
            % (r.level, r.ranks, r.setting, r.p_iterations, r.messages[0],
               r.messages[1], r.kbytes[0], r.kbytes[1], r.collectives,
               r.per_iteration(r.messages[0]),
               r.per_iteration(r.collectives)))
    return lines


def main(argv=None):
    p = argparse.ArgumentParser(prog="flapfoam pimple_traffic",
                                description=__doc__.split("\n\n")[0])
    p.add_argument("dir")
    p.add_argument("-count", nargs=2, type=int, required=True,
                   metavar=("N1", "N2"))
    p.add_argument("-o", help="write the table here (else print it)")
    a = p.parse_args(argv)
    n1, n2 = a.count
    if not 0 < n1 < n2:
        raise FlapFoamError("-count %d %d: two step counts 0 < N1 < N2 are "
                            "allowed" % (n1, n2))
    text = "\n".join(table(read_folder(a.dir, n1, n2), n1, n2)) + "\n"
    if a.o:
        with open(a.o, "w") as fh:
            fh.write(text)
    print(text, end="")
    return 0


if __name__ == "__main__":
    sys.exit(run_tool(main))
