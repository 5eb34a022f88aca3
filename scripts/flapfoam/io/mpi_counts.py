# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The MPI counts of a run under libflapFoamMPICounters.so (src/mpiCounters:
calls and bytes per MPI function of each rank, in FLAPFOAM_MPI_COUNTS/rank<N>,
written at MPI_Finalize; what "bytes" means per function is in
src/mpiCounters/mpiCounters.H): read a folder into per-rank counts and
totals, and take the difference of two runs of N1 and N2 steps for the
traffic of one step.  Standard library only.

    flapfoam mpi_counts DIR                per-rank totals
    flapfoam mpi_counts DIR1 N1 DIR2 N2    per-rank totals per step
"""

import argparse
import os

from flapfoam.errors import FlapFoamError, run_tool

KINDS = ("p2p", "collective")
TOTALS = ("p2pCalls", "p2pBytes", "destinations", "collectiveCalls",
          "collectiveBytes")


def _int(fname, key, word):
    """A non-negative integer of a file, or ValueError naming it."""
    if not word.isdigit():
        raise ValueError("%s: %s: '%s' is not a non-negative integer"
                         % (fname, key, word))
    return int(word)


def read_rank(fname):
    """One rank's file: {"rank", "nRanks", "functions": {name: {"kind",
    "calls", "bytes", "destinations" (None for a collective)}}, "to":
    {destination rank: {"calls", "bytes"}} (point-to-point, all functions
    together)}."""
    counts = {"functions": {}, "to": {}}
    with open(fname) as f:
        for line in f:
            words = line.split()
            if not words or words[0].startswith("#"):
                continue
            if len(words) == 2 and words[0] in ("rank", "nRanks"):
                counts[words[0]] = _int(fname, words[0], words[1])
            elif len(words) == 5 and words[1] in KINDS:
                name, kind, calls, nbytes, dests = words
                counts["functions"][name] = {
                    "kind": kind,
                    "calls": _int(fname, name, calls),
                    "bytes": _int(fname, name, nbytes),
                    "destinations":
                        None if dests == "-" else _int(fname, name, dests)}
            elif len(words) == 4 and words[0] == "to":
                key = "to " + words[1]
                counts["to"][_int(fname, key, words[1])] = {
                    "calls": _int(fname, key, words[2]),
                    "bytes": _int(fname, key, words[3])}
            else:
                raise ValueError(
                    "%s: unknown line '%s' (allowed: 'rank N', 'nRanks N', "
                    "'MPI_name p2p|collective calls bytes destinations|-', "
                    "'to rank calls bytes')" % (fname, line.strip()))
    for key in ("rank", "nRanks"):
        if key not in counts:
            raise ValueError("%s: no '%s' line" % (fname, key))
    return counts


def read_counts(directory):
    """The counts of every rank of a run (list index = rank), checked: one
    file rank<N> for each of the nRanks ranks, all of the same run."""
    first = os.path.join(directory, "rank0")
    if not os.path.isfile(first):
        raise ValueError("%s: no MPI counts file (FLAPFOAM_MPI_COUNTS of a "
                         "run under libflapFoamMPICounters.so)" % first)
    ranks = [read_rank(first)]
    n = ranks[0]["nRanks"]
    for r in range(1, n):
        fname = os.path.join(directory, "rank%d" % r)
        if not os.path.isfile(fname):
            raise ValueError("%s: missing (rank0 says nRanks %d; a rank "
                             "that did not reach MPI_Finalize?)" % (fname, n))
        ranks.append(read_rank(fname))
    for r, c in enumerate(ranks):
        if c["rank"] != r or c["nRanks"] != n:
            raise ValueError("%s: rank %d of %d, expected rank %d of %d"
                             % (os.path.join(directory, "rank%d" % r),
                                c["rank"], c["nRanks"], r, n))
    return ranks


def totals(counts):
    """One rank's totals: calls and bytes of the point-to-point functions
    and of the collectives, and the number of ranks it sent to."""
    t = dict.fromkeys(TOTALS, 0)
    for f in counts["functions"].values():
        prefix = "p2p" if f["kind"] == "p2p" else "collective"
        t[prefix + "Calls"] += f["calls"]
        t[prefix + "Bytes"] += f["bytes"]
    t["destinations"] = sum(1 for d in counts["to"].values() if d["calls"])
    return t


def rank_totals(directory):
    """The totals of every rank of a run (list index = rank)."""
    return [totals(c) for c in read_counts(directory)]


def _minus(later, earlier, keys):
    """Dict of dicts: later minus earlier, key by key (absent: 0)."""
    zero = dict.fromkeys(keys, 0)
    return {name: dict(v, **{k: v[k] - earlier.get(name, zero)[k]
                             for k in keys})
            for name, v in later.items()}


def difference(later, earlier):
    """Counts of one rank of a longer run minus those of a shorter one:
    calls and bytes per function and per destination (whose calls then
    give the destinations of the extra steps; the per-function
    "destinations" stay the longer run's)."""
    return dict(later,
                functions=_minus(later["functions"], earlier["functions"],
                                 ("calls", "bytes")),
                to=_minus(later["to"], earlier["to"], ("calls", "bytes")))


def per_step(dir1, n1, dir2, n2):
    """Per-rank totals per step: (run of n2 steps - run of n1 steps) /
    (n2 - n1), which leaves out the start-up and the end of a run.  Values
    are floats, whole where the steps' traffic is the same; "destinations"
    is the number of ranks sent to in the extra steps (not divided)."""
    if n2 <= n1:
        raise ValueError("per_step: N2 (%s) must be larger than N1 (%s)"
                         % (n2, n1))
    short, long_ = read_counts(dir1), read_counts(dir2)
    if len(short) != len(long_):
        raise ValueError("per_step: %s has %d ranks, %s %d"
                         % (dir1, len(short), dir2, len(long_)))
    steps = []
    for a, b in zip(short, long_):
        t = totals(difference(b, a))
        steps.append({k: (v if k == "destinations" else v/(n2 - n1))
                      for k, v in t.items()})
    return steps


def _number(v):
    """A count as text: exact where whole."""
    return "%d" % v if float(v).is_integer() else "%.3f" % v


def _print(rows):
    print("rank " + " ".join(TOTALS))
    for r, t in enumerate(rows):
        print("%d %s" % (r, " ".join(_number(t[k]) for k in TOTALS)))


def main(argv=None):
    p = argparse.ArgumentParser(
        prog="flapfoam mpi_counts", usage="%(prog)s DIR | DIR1 N1 DIR2 N2",
        description="Per-rank MPI totals of a run, or per step from two "
                    "runs of N1 and N2 steps.")
    p.add_argument("runs", nargs="+", metavar="DIR")
    a = p.parse_args(argv)
    try:
        if len(a.runs) == 1:
            _print(rank_totals(a.runs[0]))
        elif len(a.runs) == 4 and a.runs[1].isdigit() and \
                a.runs[3].isdigit():
            _print(per_step(a.runs[0], int(a.runs[1]), a.runs[2],
                            int(a.runs[3])))
        else:
            p.error("DIR, or DIR1 N1 DIR2 N2 (N1, N2: steps)")
    except ValueError as err:
        raise FlapFoamError("mpi_counts: %s" % err)


if __name__ == "__main__":
    run_tool(main)
