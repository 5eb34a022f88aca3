# License
#     This file is part of flapFoam, derived from OpenFOAM: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Checks of the counts files of libflapFoamMPICounters.so for Alltest, one
PASS/FAIL line each; exit status non-zero if one fails.

    checkCounts.py probe DIR          the probe's counts, exactly
    checkCounts.py nonZero DIR NAME   both ranks sent point-to-point bytes and
                                      called collectives
    checkCounts.py steps FACES DIR:N DIR:N DIR:N
                                      the same traffic in every step: per-step
                                      counts (difference of the runs of N
                                      steps) equal between the pairs of runs
                                      and between the ranks, whole, and the
                                      point-to-point bytes a multiple of
                                      FACES doubles (the processor faces)
"""

import sys

from flapfoam import mpiCounts
from flapfoam.checks import Checks

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


def probe(check, directory):
    ranks = mpiCounts.read_counts(directory)
    check(len(ranks) == 2, "probe: 2 counts files (%d)" % len(ranks))
    for r, (counts, expected) in enumerate(zip(ranks, PROBE)):
        got = {name: (f["calls"], f["bytes"], f["destinations"])
               for name, f in counts["functions"].items() if f["calls"]}
        check(got == expected, "probe rank %d: calls, bytes, destinations "
              "of every MPI function as sent: %s" % (r, sorted(got.items())))
        check(counts["destinations"] == 1, "probe rank %d: 1 destination "
              "over all point-to-point sends (%d)"
              % (r, counts["destinations"]))


def non_zero(check, directory, name):
    for r, t in enumerate(mpiCounts.rank_totals(directory)):
        check(t["p2pBytes"] > 0 and t["collectiveCalls"] > 0,
              "%s rank %d: counts written, non-zero: %s" % (name, r, t))


def steps(check, faces, runs):
    (d1, n1), (d2, n2), (d3, n3) = [(r.rsplit(":", 1)[0],
                                     int(r.rsplit(":", 1)[1])) for r in runs]
    first = mpiCounts.per_step(d1, n1, d2, n2)
    second = mpiCounts.per_step(d2, n2, d3, n3)
    check(first == second, "per step, steps %d-%d = steps %d-%d: %s"
          % (n1, n2, n2, n3, first))
    check(all(first[0] == t for t in first),
          "per step: the same on every rank (symmetric halves)")
    check(all(float(v).is_integer() for t in first for v in t.values()),
          "per step: whole calls and bytes")
    halo = 8*faces
    check(all(t["p2pBytes"] > 0 and t["p2pBytes"] % halo == 0
              for t in first),
          "per step: point-to-point bytes %d = %g x %d processor faces x 8"
          % (first[0]["p2pBytes"], first[0]["p2pBytes"]/halo, faces))


def main(argv):
    check = Checks()
    try:
        if argv[:1] == ["probe"] and len(argv) == 2:
            probe(check, argv[1])
        elif argv[:1] == ["nonZero"] and len(argv) == 3:
            non_zero(check, argv[1], argv[2])
        elif argv[:1] == ["steps"] and len(argv) == 5:
            steps(check, int(argv[1]), argv[2:])
        else:
            sys.exit(__doc__)
    except ValueError as err:
        check(False, "counts: %s" % err)
    return check.finish(None, None)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
