# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Check the per-rank overset report (Foam::oversetRankReport, the lines
"oversetRankReport: ..." that timedOversetFvMesh writes after the first
mesh update) in the solver logs of a serial and a parallel run of the same
case, for the stencils given (default: inverseDistance and
octreeInverseDistance).

    flapfoam overset_rank_report SERIAL PARALLEL [-stencils S...]

SERIAL/S and PARALLEL/S are cases with log.overPimpleDyMFoam (e.g.
applications/test/overset/compareMotion's -dir without and with -np;
applications/test/overset/checkRankReport runs them).
Checks, per stencil:
  - each log holds one report (rankReport's default: the first update),
    with one row per rank, total/max/mean rows equal to the sums, maxima
    and means of the rows, cellImbalance = max/mean of cells, remoteShare
    = remote/acceptors, remote = mixed + allRemote, haloBytes = 8
    procFaces;
  - serial: one row, nothing remote, no processor face, nothing sent;
  - parallel: the rows' cells add up to the serial cells and the acceptors
    to the serial acceptors; every processor face is seen from both sides
    (total procFaces even; with 2 ranks both rows equal); cells sent =
    cells received and send messages = receive messages over all ranks;
  - the stock inverseDistance: its own count of the same update ("interpolated
    : N (interpolated from local:a  mixed local/remote:b  remote:c)", which
    counts a donor slot >= nCells as remote) gives N = acceptors, a =
    acceptors - remote, b = mixed, c = allRemote (so the report, which
    sends each cell's rank through the stencil's map, and the slot order
    agree);
  - every other stencil: its rows equal the stock stencil's rows (the same
    donors: compareMotion checks that the stencils agree).
PASS/FAIL lines; exit status 1 if a check fails.
"""

import argparse
import os
import re
import sys
from dataclasses import dataclass

from flapfoam.bench import rank_tables
from flapfoam.harness.checklist import Checks
from flapfoam.errors import run_tool

PREFIX = "oversetRankReport"
STOCK = "inverseDistance"
ANALYSIS = re.compile(
    r"interpolated : (\d+) \(interpolated from local:(\d+)\s+"
    r"mixed local/remote:(\d+)\s+remote:(\d+)\)")


@dataclass
class RankReport:
    """One oversetRankReport: its title's time, stencil and ranks, the
    columns, a row per rank and the total, max and mean rows ({column:
    count}, integers but the means), the cell imbalance, the remote share
    and the stock stencil's last count line before it (interpolated, local,
    mixed, remote; None if there is none)."""
    time: float
    stencil: str
    ranks: int
    columns: list
    rows: list
    total: dict
    max: dict
    mean: dict
    cell_imbalance: float
    remote_share: float
    analysis: tuple = None


def read_reports(log):
    """The RankReports of a log (read by flapfoam.bench.rank_tables)."""
    analyses = []
    for i, line in enumerate(open(log, errors="replace")):
        m = ANALYSIS.search(line)
        if m:
            analyses.append((i, tuple(int(x) for x in m.groups())))
    reports = []
    for t in rank_tables.read_tables(log, PREFIX):
        info = t.info
        before = [a for i, a in analyses if i < t.line]
        counts = [{k: int(v) for k, v in row.items()} for row in t.rows]
        reports.append(RankReport(
            time=info.get("time"), stencil=info.get("stencil"),
            ranks=int(info.get("ranks", 0)), columns=t.columns,
            rows=counts,
            total={k: int(v) for k, v in (t.total or {}).items()},
            max={k: int(v) for k, v in (t.max or {}).items()}, mean=t.mean,
            cell_imbalance=info.get("cellImbalance"),
            remote_share=info.get("remoteShare"),
            analysis=before[-1] if before else None))
    return reports


def close(a, b):
    return abs(a - b) <= 1e-6*max(1.0, abs(b))


def check_table(c, name, r):
    """The derived rows and figures of one report"""
    rows, cols = r.rows, r.columns
    total = {k: sum(row[k] for row in rows) for k in cols}
    largest = {k: max(row[k] for row in rows) for k in cols}
    mean = {k: total[k]/len(rows) for k in cols}
    share = total["remote"]/total["acceptors"] if total["acceptors"] else 0
    c(len(rows) == r.ranks
      and r.total == total and r.max == largest
      and all(close(r.mean[k], mean[k]) for k in cols)
      and close(r.cell_imbalance, largest["cells"]/mean["cells"])
      and close(r.remote_share, share)
      and all(row["remote"] == row["mixed"] + row["allRemote"]
              and row["haloBytes"] == 8*row["procFaces"]
              for row in rows),
      "%s: %d rows, total/max/mean rows, cellImbalance %g, "
      "remoteShare %g, remote = mixed + allRemote, haloBytes = 8 "
      "procFaces" % (name, len(rows), r.cell_imbalance,
                     r.remote_share))


def one_report(c, name, case):
    log = os.path.join(case, "log.overPimpleDyMFoam")
    reports = read_reports(log) if os.path.isfile(log) else []
    if not c(len(reports) == 1, "%s: one report in %s (found %d)"
             % (name, log, len(reports))):
        return None
    check_table(c, name, reports[0])
    return reports[0]


def check_stock(c, name, r):
    t = r.total
    a = r.analysis
    c(a == (t["acceptors"], t["acceptors"] - t["remote"], t["mixed"],
            t["allRemote"]),
      "%s: the stencil's own count (interpolated, local, mixed, "
      "remote) %s = the report's %s"
      % (name, a, (t["acceptors"], t["acceptors"] - t["remote"],
                   t["mixed"], t["allRemote"])))


def check_runs(c, stencil, serial, parallel):
    nothing = ["remote", "mixed", "allRemote", "remoteSlots", "procFaces",
               "procPatches", "sent", "received", "sendRanks", "recvRanks"]
    s = serial.total
    c(serial.ranks == 1 and all(s[k] == 0 for k in nothing),
      "%s serial: one row, %s all 0"
      % (stencil, " ".join(nothing)))
    p = parallel.total
    faces = [row["procFaces"] for row in parallel.rows]
    c(p["cells"] == s["cells"] and p["acceptors"] == s["acceptors"],
      "%s -np %d: cells %s add up to the serial %d, acceptors %s to "
      "the serial %d"
      % (stencil, parallel.ranks,
         "+".join(str(row["cells"]) for row in parallel.rows),
         s["cells"],
         "+".join(str(row["acceptors"]) for row in parallel.rows),
         s["acceptors"]))
    c(p["procFaces"] % 2 == 0
      and (len(faces) != 2 or faces[0] == faces[1])
      and p["sent"] == p["received"]
      and p["sendRanks"] == p["recvRanks"],
      "%s -np %d: processor faces %s (each seen from both sides), "
      "cells sent %d = received, messages %d = received"
      % (stencil, parallel.ranks, faces, p["sent"],
         p["sendRanks"]))
    print("  %s -np %d: remote acceptors %d of %d (mixed %d, all remote %d, "
          "remote slots %d), share %.4f, cell imbalance %.4f"
          % (stencil, parallel.ranks, p["remote"], p["acceptors"],
             p["mixed"], p["allRemote"], p["remoteSlots"],
             parallel.remote_share, parallel.cell_imbalance))


def main(argv=None):
    ap = argparse.ArgumentParser(prog="flapfoam overset_rank_report",
                                 description=__doc__.split("\n\n")[0])
    ap.add_argument("serial")
    ap.add_argument("parallel")
    ap.add_argument("-stencils", nargs="+",
                    default=[STOCK, "octreeInverseDistance"])
    a = ap.parse_args(argv)
    c = Checks()
    reports = {}
    for stencil in a.stencils:
        serial = one_report(c, stencil + " serial",
                           os.path.join(a.serial, stencil))
        parallel = one_report(c, stencil + " parallel",
                             os.path.join(a.parallel, stencil))
        if not (serial and parallel):
            continue
        check_runs(c, stencil, serial, parallel)
        if stencil == STOCK:
            check_stock(c, stencil + " serial", serial)
            check_stock(c, stencil + " parallel", parallel)
        reports[stencil] = parallel
    if STOCK in reports:
        for stencil, r in reports.items():
            if stencil != STOCK:
                c(r.rows == reports[STOCK].rows,
                  "%s parallel: every row equals %s's"
                  % (stencil, STOCK))
    return c.finish(None, None)


if __name__ == "__main__":
    sys.exit(run_tool(main))
