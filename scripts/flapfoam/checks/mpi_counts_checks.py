# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Checks of the counts files of libflapFoamMPICounters.so for the
mpiCounters Alltest, one PASS/FAIL line each; exit status non-zero if one
fails (unit-tested: scripts/tests/test_mpi_counts_checks.py).

    flapfoam mpi_counts_checks probe DIR
                        the probe's counts (flapFoamMPICountersProbe),
                        exactly
    flapfoam mpi_counts_checks nonZero DIR NAME
                        both ranks sent point-to-point bytes and called
                        collectives
    flapfoam mpi_counts_checks steps FACES DESTS DIR:N DIR:N [DIR:N ...]
                        the same traffic in every step: per-step counts
                        (difference of the runs of N steps) equal between
                        consecutive pairs of runs and between the ranks,
                        whole, DESTS ranks sent to, and point-to-point bytes
                        a multiple of FACES doubles (the processor faces of
                        a rank)
"""

import argparse
import sys

from flapfoam.io import mpi_counts
from flapfoam.harness.checklist import Checks
from flapfoam.errors import run_tool

# What flapFoamMPICountersProbe sends (its header): rank -> function ->
# (calls, bytes, destinations); every other function has no call
PROBE = [
    {"MPI_Send": (4, 3*1000*8, 1),       # + one to MPI_PROC_NULL: 0 bytes
     "MPI_Bsend": (1, 100, 1),
     "MPI_Isend": (1, 10*4, 1),
     "MPI_Sendrecv": (1, 7*4, 1),
     "MPI_Allreduce": (2, 4*8 + 2*4, None),
     "MPI_Alltoall": (1, 2*4, None),
     "MPI_Alltoallv": (1, (1 + 2)*4, None),
     "MPI_Bcast": (1, 3*8, None),        # the root
     "MPI_Gatherv": (1, 1*8, None),
     "MPI_Barrier": (1, 0, None)},
    {"MPI_Isend": (3, 3*5*4, 1),         # one in the reversed communicator
     "MPI_Ssend": (1, 2*4, 1),
     "MPI_Sendrecv": (1, 7*4, 1),
     "MPI_Allreduce": (2, 4*8 + 2*4, None),
     "MPI_Alltoall": (1, 2*4, None),
     "MPI_Alltoallv": (1, (2 + 3)*4, None),
     "MPI_Bcast": (1, 0, None),
     "MPI_Gatherv": (1, 2*8, None),
     "MPI_Barrier": (1, 0, None)},
]
# And rank -> destination -> (calls, bytes), all point-to-point sends
# (Send, Bsend, Isend, Sendrecv; Isend, Ssend, Sendrecv)
PROBE_TO = [{1: (3 + 1 + 1 + 1, 3*1000*8 + 100 + 10*4 + 7*4)},
            {0: (3 + 1 + 1, 3*5*4 + 2*4 + 7*4)}]


def probe(check, directory):
    ranks = mpi_counts.read_counts(directory)
    check(len(ranks) == 2, "probe: 2 counts files (%d)" % len(ranks))
    for r, (counts, expected) in enumerate(zip(ranks, PROBE)):
        got = {name: (f["calls"], f["bytes"], f["destinations"])
               for name, f in counts["functions"].items() if f["calls"]}
        check(got == expected, "probe rank %d: calls, bytes, destinations "
              "of every MPI function as sent: %s" % (r, sorted(got.items())))
        to = {d: (t["calls"], t["bytes"]) for d, t in counts["to"].items()}
        check(to == PROBE_TO[r], "probe rank %d: destination: (calls, bytes)"
              " of all point-to-point sends (none to MPI_PROC_NULL) as sent:"
              " %s" % (r, to))


def non_zero(check, directory, name):
    for r, t in enumerate(mpi_counts.rank_totals(directory)):
        check(t["p2pBytes"] > 0 and t["collectiveCalls"] > 0,
              "%s rank %d: counts written, non-zero: %s" % (name, r, t))


def steps(check, faces, dests, runs):
    runs = [(r.rsplit(":", 1)[0], int(r.rsplit(":", 1)[1])) for r in runs]
    pairs = list(zip(runs, runs[1:]))
    first = mpi_counts.per_step(*pairs[0][0], *pairs[0][1])
    n = len(first)
    for (d1, n1), (d2, n2) in pairs[1:]:
        check(mpi_counts.per_step(d1, n1, d2, n2) == first,
              "%d ranks: per step, steps %d-%d = steps %d-%d"
              % (n, pairs[0][0][1], pairs[0][1][1], n1, n2))
    check(all(first[0] == t for t in first),
          "%d ranks: per step the same on every rank (symmetric): %s"
          % (n, first[0]))
    check(all(float(v).is_integer() for t in first for v in t.values()),
          "%d ranks: per step whole calls and bytes" % n)
    check(all(t["destinations"] == dests for t in first),
          "%d ranks: per step %d ranks sent to (the neighbours; over the "
          "whole run: %s)" % (n, dests, [t["destinations"] for t in
                                         mpi_counts.rank_totals(runs[0][0])]))
    halo = 8*faces
    check(all(t["p2pBytes"] > 0 and t["p2pBytes"] % halo == 0
              for t in first),
          "%d ranks: per step point-to-point bytes %d = %g x %d processor "
          "faces x 8" % (n, first[0]["p2pBytes"], first[0]["p2pBytes"]/halo,
                         faces))


def arguments(argv):
    p = argparse.ArgumentParser(prog="flapfoam mpi_counts_checks",
                                description=__doc__.split("\n\n")[0])
    sub = p.add_subparsers(dest="check", required=True)
    sub.add_parser("probe").add_argument("dir")
    one = sub.add_parser("nonZero")
    one.add_argument("dir")
    one.add_argument("name")
    many = sub.add_parser("steps")
    many.add_argument("faces", type=int)
    many.add_argument("dests", type=int)
    many.add_argument("runs", nargs="+", metavar="DIR:N")
    a = p.parse_args(argv)
    if a.check == "steps" and len(a.runs) < 2:
        many.error("at least two DIR:N")
    return a


def main(argv=None):
    a = arguments(argv)
    check = Checks()
    try:
        if a.check == "probe":
            probe(check, a.dir)
        elif a.check == "nonZero":
            non_zero(check, a.dir, a.name)
        else:
            steps(check, a.faces, a.dests, a.runs)
    except ValueError as err:
        check(False, "counts: %s" % err)
    return check.finish(None, None)


if __name__ == "__main__":
    sys.exit(run_tool(main))
