# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Counts files as libflapFoamMPICounters.so writes them, made up for the
tests of the readers of MPI counts."""

P2P = ["MPI_Send", "MPI_Bsend", "MPI_Ssend", "MPI_Rsend", "MPI_Isend",
       "MPI_Ibsend", "MPI_Issend", "MPI_Irsend", "MPI_Sendrecv",
       "MPI_Sendrecv_replace"]
COLL = ["MPI_Barrier", "MPI_Bcast", "MPI_Reduce", "MPI_Allreduce",
        "MPI_Gather", "MPI_Gatherv", "MPI_Scatter", "MPI_Scatterv",
        "MPI_Allgather", "MPI_Allgatherv", "MPI_Alltoall", "MPI_Alltoallv"]


def write_rank(folder, rank, n, functions, to):
    """A counts file: functions {name: (calls, bytes, destinations)}, to
    {rank: (calls, bytes)}."""
    lines = ["# flapFoam MPI counts", "rank %d" % rank, "nRanks %d" % n,
             "# function kind calls bytes destinations"]
    for name in P2P + COLL:
        c, b, d = functions.get(name, (0, 0, 0))
        kind = "p2p" if name in P2P else "collective"
        lines.append("%s %s %d %d %s" % (name, kind, c, b,
                                         d if kind == "p2p" else "-"))
    lines.append("# to rank calls bytes")
    lines += ["to %d %d %d" % (r, c, b) for r, (c, b) in to.items()]
    folder.mkdir(parents=True, exist_ok=True)
    (folder / ("rank%d" % rank)).write_text("\n".join(lines) + "\n")
