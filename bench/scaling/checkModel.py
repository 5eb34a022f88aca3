#!/usr/bin/python3
# License
#     This file is part of flapFoam, derived from OpenFOAM: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Checks of the scaling bench's Python pieces on inputs whose answers are
known (bench/scaling/Alltest runs it): flapfoam.rank_tables (a couplingReport
and an oversetRankReport table with their extra lines, cellDist to
cellDecomposition, neighbour ranks of a 2x2 mesh) and flapfoam.scaling_model
(an exact traffic fit, the step of a 2-rank decomposition by hand, octree
and stock, the values the busiest rank receives per sweep, the step of an
oversetRankReport, the shared bandwidth) and flapfoam.scaling_validate
(the committed model against both 16-core sessions of bench/scaling/
measured, the second's medians over rounds by flapfoam.timed_rounds, its
calibration reproduced).  PASS and FAIL lines; exit status 1 if one fails.

    bench/scaling/checkModel.py DIR      (DIR: a scratch folder)
"""

import fnmatch
import os
import sys

import numpy as np

from flapfoam import rank_tables, scaling_model

HERE = os.path.dirname(os.path.abspath(__file__))

HEADER = "FoamFile { version 2.0; format ascii; class %s; object %s; }\n"
REPORT = """x: 2 ranks, 6 cells, 3 poses of "c", decomposition "d"
x: rank cells weight oversetWork processorFaces acceptors pairs remotePairs
x: 0 4 4 10 2 3 9 1
x: 1 2 2 6 2 1 3 2
x: total 6 6 16 4 4 12 3
x: imbalance cells 1.3333 weight 1.3333 remotePairShare 0.25
"""
failed = []


def check(name, ok, detail=""):
    print("%s %s%s" % ("PASS" if ok else "FAIL", name,
                       (": " + detail) if detail else ""))
    if not ok:
        failed.append(name)


def write(path, text):
    with open(path, "w") as f:
        f.write(text)
    return path


def check_tables(tmp):
    t = rank_tables.read_table(write(os.path.join(tmp, "log"), REPORT), "x")
    check("report rows", [r["cells"] for r in t["rows"]] == [4, 2]
          and t["total"]["remotePairs"] == 3, str(t["rows"]))
    check("report info", t["info"]["remotePairShare"] == 0.25
          and t["info"]["cells"] == 1.3333, str(t["info"]))
    dist = write(os.path.join(tmp, "cellDist"),
                 HEADER % ("volScalarField", "cellDist")
                 + "dimensions [0 0 0 0 0 0 0];\ninternalField nonuniform "
                 "List<scalar> 4(0 1 1 0);\nboundaryField {}\n")
    out = os.path.join(tmp, "cellDecomposition")
    rank_tables.cell_decomposition(dist, out)
    ranks = rank_tables.read_decomposition(out)
    check("cellDist to cellDecomposition", list(ranks) == [0, 1, 1, 0],
          str(ranks))
    # 2x2 cells 0 1 / 2 3: internal faces 0-1, 2-3, 0-2, 1-3
    mesh = os.path.join(tmp, "polyMesh")
    os.makedirs(mesh, exist_ok=True)
    write(os.path.join(mesh, "owner"), HEADER % ("labelList", "owner")
          + "4(0 2 0 1)\n")
    write(os.path.join(mesh, "neighbour"), HEADER % ("labelList", "neighbour")
          + "4(1 3 2 3)\n")
    nbr = rank_tables.neighbour_ranks(mesh, np.array([0, 1, 2, 2]))
    check("neighbour ranks", list(nbr) == [2, 2, 2], str(nbr))
    # one rank: gaps 1, 1, 2, 2; two ranks by rows: 1 each, by columns 1
    gaps = [list(rank_tables.cell_order_gap(mesh, np.array(d)))
            for d in ([0, 0, 0, 0], [0, 0, 1, 1], [0, 1, 0, 1])]
    check("cell order gap", gaps == [[1.5], [1.0, 1.0], [1.0, 1.0]],
          str(gaps))


def bw(own, total, p_sat=2.0):
    """B(n, N) by hand: sqrt((n^2 + (N/pSat)^2)/(1 + pSat^-2))."""
    return ((own*own + (total/p_sat)**2)/(1 + p_sat**-2))**0.5


def check_model():
    rows = [(p, w, 5 + 7*(p - 1) + 3*w, 2 + (p - 1)) for p, w in
            ((2, 1), (2, 4), (4, 0), (8, 5), (16, 2))]
    fit = scaling_model.TrafficFit(rows)
    check("traffic fit exact", np.allclose(fit.bytes, [5, 7, 3])
          and np.allclose(fit.messages, [2, 1, 0], atol=1e-9)
          and fit.error.max() < 1e-12, "%s %s" % (fit.bytes, fit.messages))
    # balanced, B(N/P, N) is S(P) N/P; a rank with 1.5x the mean cells at
    # 16 ranks (pSat 14.2): sqrt(1.5^2 + (16/14.2)^2)/sqrt(1 + 14.2^-2),
    # 1.8714 of the mean, not 1.5 S(16) = 2.25
    sb = scaling_model.shared_bandwidth
    busy = sb(1.5/16, 1.0, 14.2)*16
    check("shared bandwidth", abs(sb(100.0, 1600.0, 14.2)
                                  - 100*scaling_model.slowdown(16, 14.2))
          < 1e-12 and abs(busy - 1.8714) < 1e-4, "%r" % busy)
    # G(2) = 1.5 with growth 0.5; I1 = 100 iterations; pSat 2
    cal = scaling_model.Calibration(pSat=2.0, cIter=1e-5, growth=0.5,
                                   vParallel=2e-3, bStock=0.1,
                                   iterations=100.0)
    costs = scaling_model.Costs((1e-6, 1e-9), (10, 2, 4), fit, cal)
    costs.cCell, costs.cWork, costs.rbd = 1e-6, 1e-5, 0.01
    table = {"columns": ["cells", "processorFaces", "oversetWork",
                         "remotePairs", "acceptors", "pairs"],
             "rows": [{"cells": 1000, "processorFaces": 50,
                       "oversetWork": 100, "remotePairs": 10,
                       "acceptors": 5, "pairs": 40},
                      {"cells": 800, "processorFaces": 50,
                       "oversetWork": 300, "remotePairs": 0,
                       "acceptors": 7, "pairs": 60}],
             "info": {}}
    step = scaling_model.predict(costs, scaling_model.Decomposition(table,
                                                                  [1, 1]))
    # overset: rank 1's work 1e-5 B(300, 400) + vParallel + rank 0's
    # traffic 1e-6 (2 + 1) + 1e-9 (5 + 7 + 3*10); rank 0 pimple: G (1e-6
    # B(1000, 1800) + 100 1e-5 1 + 1e-9 2 8 50)
    overset = 1e-5*bw(300, 400) + 2e-3 + 3e-6 + 42e-9
    pimple = 1.5*(1e-6*bw(1000, 1800) + 1e-3 + 800e-9)
    check("step of 2 ranks", abs(step["overset"] - overset) < 1e-15
          and abs(step["pimple"] - pimple) < 1e-15
          and abs(step["total"] - 0.01 - overset - pimple) < 1e-15, str(step))
    # the stock stencil: bStock (P - 1) of the serial overset (1e-5 400)
    # instead of vParallel
    costs.stencil = scaling_model.STOCK
    stock = scaling_model.predict(costs, scaling_model.Decomposition(
        table, [1, 1]))["overset"]
    costs.stencil = scaling_model.OCTREE
    check("stock overset of 2 ranks",
          abs(stock - (overset - 2e-3 + 0.1*4e-3)) < 1e-15, str(stock))
    # the work's imbalance at a pose 1.8 (of the mean 200): 360 at a step;
    # 1.2 (240) is below the cycle's largest mean, 300
    peaks = []
    for at_pose in (1.8, 1.2):
        table["info"]["oversetWorkAtPose"] = at_pose
        peaks.append(scaling_model.predict(
            costs, scaling_model.Decomposition(table, [1, 1]))["overset"])
    del table["info"]["oversetWorkAtPose"]
    check("overset at a pose", abs(peaks[0] - overset - 1e-5*(
        bw(360, 400) - bw(300, 400))) < 1e-15
        and abs(peaks[1] - overset) < 1e-15, str(peaks))
    # the busiest rank per sweep: faces + remote donor cells (50 + 30 on
    # rank 1); a report without remoteDonors: NaN.  PIMPLE with the
    # remote-stencil interfaces (1 rank each): rank 0 G (1e-6 B(1000,
    # 1800) + 100 1e-5 (1 + 1) + 1e-9 2 8 (50 + 8)), rank 1 less
    without = scaling_model.Decomposition(table, [1, 1]).sweep_values_max()
    table["columns"] += ["remoteDonors", "donorRanks"]
    for row, donors in zip(table["rows"], (8, 30)):
        row["remoteDonors"], row["donorRanks"] = donors, 1
    d = scaling_model.Decomposition(table, [1, 1])
    sweep = d.sweep_values_max()
    pimple = 1.5*(1e-6*bw(1000, 1800) + 2e-3 + 928e-9)
    step = scaling_model.predict(costs, d)
    check("sweep values max, PIMPLE with remote donors",
          sweep == 80 and np.isnan(without)
          and abs(step["pimple"] - pimple) < 1e-15,
          "%s, without the column %s; pimple %r" % (sweep, without,
                                                    step["pimple"]))
    check_rank_report(costs)


def check_rank_report(costs):
    """A solver's oversetRankReport of 2 ranks as a decomposition: the
    neighbours from procPatches, remote donors from received, recvRanks;
    its step by hand with the counted iterations (110 of I1 100)."""
    names = ["cells", "procFaces", "procPatches", "acceptors", "remoteSlots",
             "received", "recvRanks"]
    report = {"columns": names, "rows": [
        dict(zip(names, (600, 40, 1, 10, 12, 5, 1))),
        dict(zip(names, (500, 40, 1, 20, 30, 9, 1)))], "info": {}}
    d = scaling_model.Decomposition.from_rank_report(report)
    costs.traffic = None
    step = scaling_model.predict(costs, d, iterations=110)
    # rank 0: 1.1 (1e-6 B(600, 1100) + 100 1e-5 2 + 1e-9 2 8 45); overset:
    # 1e-5 B(600, 1100) + vParallel (no stencil traffic)
    pimple = 1.1*(1e-6*bw(600, 1100) + 2e-3 + 720e-9)
    overset = 1e-5*bw(600, 1100) + 2e-3
    check("step of an oversetRankReport", list(d.neighbours) == [1, 1]
          and list(d.remoteDonors) == [5, 9]
          and abs(step["pimple"] - pimple) < 1e-15
          and abs(step["overset"] - overset) < 1e-15
          and step["slowestRank"] == 0, str(step))


# runs of the first 40 s of the first session's coarse archive: their
# PIMPLE is 1.30-1.75x that of the same partition run later with the stock
# stencil (bitwise the same p solves); the model, which gives both the
# same PIMPLE, is 19-48 % below them (bench/scaling/results-validate.md)
EARLY = ("scaling-16core:coarse/octree-oversetGraph-np*",
         "scaling-16core:coarse/octree-hierarchical-np2")
NEW = "session2-round3"
MEASURED = os.path.join(HERE, "measured")
ARCHIVES = [os.path.join(MEASURED, f) for f in (
    "scaling-16core-coarse.tar.gz", "scaling-16core-medium.tar.gz",
    "device-2026-11-26/session2-round3.tar.gz")]
ROUNDS = os.path.join(MEASURED, "device-2026-11-26/session1/runTimed.log")


def check_rounds(runs):
    """flapfoam.timed_rounds on the committed runTimed.log (rounds 1 and
    2) and the medians over three rounds that validate reads: coarse
    scotch np16 0.1524, 0.1339 (the log) and 0.1243 (round 3)."""
    from flapfoam import timed_rounds
    timed = timed_rounds.read_file(ROUNDS, ["coarse", "medium"])
    table = timed_rounds.medians(timed)
    got = table.get(("coarse", "octree", "scotch", 16, False))
    check("timedRounds: runTimed.log's %d runs, coarse scotch np16 the "
          "median of 2 rounds" % len(timed), len(timed) == 73 and got
          and got[1] == 2 and abs(got[0]["step"] - 0.14315) < 1e-9,
          str(got))
    by = {r.name: r for r in runs}
    scotch = by.get(NEW + ":coarse/octree-scotch-np16")
    hier = by.get(NEW + ":medium/octree-hierarchical-np4")
    old = [r.rounds for r in runs if r.session == "scaling-16core"]
    check("validate -rounds: medians of 3 rounds (2 where round 2 was "
          "skipped), the other session's runs untouched",
          scotch and scotch.rounds == 3
          and abs(scotch.measured["step"] - 0.1339) < 1e-9
          and hier and hier.rounds == 2 and set(old) == {1},
          "%s %s %s" % (scotch and (scotch.rounds, scotch.measured["step"]),
                        hier and hier.rounds, set(old)))


def check_validate():
    """The committed model against the committed 16-core sessions (medians
    over rounds for the second): its octree runs within 17 %, stock runs
    within 17 %, the first session's octree runs within 23 % but for
    EARLY (50 %); 20 of the 26 pairs measured more than 15 % apart ranked
    as measured; calibrate on the committed set gives the committed
    constants (3 %)."""
    from flapfoam import scaling_validate as sv
    if not all(os.path.isfile(a) for a in ARCHIVES + [ROUNDS]):
        check("validate: the committed archives", False, str(ARCHIVES))
        return
    runs = sv.read_archives(ARCHIVES, rounds=[ROUNDS])
    check_rounds(runs)
    rows = sv.compare(runs, scaling_model.CALIBRATION)
    early = [r for r in rows if any(fnmatch.fnmatch(r["run"], p)
                                    for p in EARLY)]
    rest = [r for r in rows if r not in early]
    worst = sv.largest_errors(rest, lambda r: (r["session"], r["stencil"]))
    new, stock = worst[(NEW, "octree")][0], worst[("scaling-16core", "ID")][0]
    old = worst[("scaling-16core", "octree")][0]
    check("validate: %d runs; %s octree within 17 %%, stock within 17 %%, "
          "the first session's octree within 23 %%" % (len(rows), NEW),
          len(rows) == 67 and len(early) == 5 and new < 0.17
          and stock < 0.17 and old < 0.23, str(worst))
    check("validate: the %d early runs within 50 %%" % len(early),
          sv.largest_errors(early)[None][0] < 0.5,
          str(sv.largest_errors(early)))
    pairs = sv.ranked_pairs(rows)
    check("validate: pairs apart by more than the spread ranked as "
          "measured", len(pairs) == 26 and sum(p[3] for p in pairs) >= 20,
          "%d of %d" % (sum(p[3] for p in pairs), len(pairs)))
    cal = sv.calibrate(runs)
    ref = scaling_model.CALIBRATION
    diff = {f: abs(getattr(cal, f)/getattr(ref, f) - 1)
            for f in ("pSat", "cIter", "growth", "vParallel", "bStock")}
    check("calibrate reproduces the committed constants",
          max(diff.values()) < 0.03, str(cal))


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: checkModel.py DIR")
    os.makedirs(sys.argv[1], exist_ok=True)
    check_tables(sys.argv[1])
    check_model()
    check_validate()
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
