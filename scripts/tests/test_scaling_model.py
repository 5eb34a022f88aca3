# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""The scaling bench's Python pieces on inputs whose answers are known:
flapfoam.bench.rank_tables (a couplingReport and an oversetRankReport table with
their extra lines, cellDist to cellDecomposition, neighbour ranks of a 2x2
mesh), flapfoam.scaling.model (an exact traffic fit, the step of a 2-rank
decomposition by hand, octree and stock, the values the busiest rank
receives per sweep, the step of an oversetRankReport, the shared
bandwidth) and flapfoam.scaling.validate (the committed model against both
16-core sessions of bench/scaling/measured, the second's medians over
rounds by flapfoam.bench.timed_rounds, its calibration reproduced)."""

import fnmatch

import numpy as np
import pytest

from flapfoam.bench import rank_tables

from flapfoam.scaling import model as scaling_model

from flapfoam.scaling import validate as scaling_validate
HEADER = "FoamFile { version 2.0; format ascii; class %s; object %s; }\n"
REPORT = """x: 2 ranks, 6 cells, 3 poses of "c", decomposition "d"
x: rank cells weight oversetWork processorFaces acceptors pairs remotePairs
x: 0 4 4 10 2 3 9 1
x: 1 2 2 6 2 1 3 2
x: total 6 6 16 4 4 12 3
x: imbalance cells 1.3333 weight 1.3333 remotePairShare 0.25
"""


def write(path, text):
    path.write_text(text)
    return str(path)


def test_report_rows(tmp_path):
    t = rank_tables.read_table(write(tmp_path / "log", REPORT), "x")
    assert [r["cells"] for r in t.rows] == [4, 2]
    assert t.total["remotePairs"] == 3


def test_report_info(tmp_path):
    t = rank_tables.read_table(write(tmp_path / "log", REPORT), "x")
    assert t.info["remotePairShare"] == 0.25
    assert t.info["cells"] == 1.3333


def test_cell_dist_to_cell_decomposition(tmp_path):
    dist = write(tmp_path / "cellDist", HEADER % ("volScalarField", "cellDist")
                 + "dimensions [0 0 0 0 0 0 0];\ninternalField nonuniform "
                 "List<scalar> 4(0 1 1 0);\nboundaryField {}\n")
    out = str(tmp_path / "cellDecomposition")
    rank_tables.cell_decomposition(dist, out)
    assert list(rank_tables.read_decomposition(out)) == [0, 1, 1, 0]


@pytest.fixture
def square(tmp_path):
    """2x2 cells 0 1 / 2 3: internal faces 0-1, 2-3, 0-2, 1-3."""
    mesh = tmp_path / "polyMesh"
    mesh.mkdir()
    write(mesh / "owner", HEADER % ("labelList", "owner") + "4(0 2 0 1)\n")
    write(mesh / "neighbour", HEADER % ("labelList", "neighbour")
          + "4(1 3 2 3)\n")
    return str(mesh)


def test_neighbour_ranks(square):
    nbr = rank_tables.neighbour_ranks(square, np.array([0, 1, 2, 2]))
    assert list(nbr) == [2, 2, 2]


def test_cell_order_gap(square):
    # one rank: gaps 1, 1, 2, 2; two ranks by rows: 1 each, by columns 1
    gaps = [list(rank_tables.cell_order_gap(square, np.array(d)))
            for d in ([0, 0, 0, 0], [0, 0, 1, 1], [0, 1, 0, 1])]
    assert gaps == [[1.5], [1.0, 1.0], [1.0, 1.0]]


def bw(own, total, p_sat=2.0):
    """B(n, N) by hand: sqrt((n^2 + (N/pSat)^2)/(1 + pSat^-2))."""
    return ((own*own + (total/p_sat)**2)/(1 + p_sat**-2))**0.5


def traffic_fit():
    rows = [(p, w, 5 + 7*(p - 1) + 3*w, 2 + (p - 1)) for p, w in
            ((2, 1), (2, 4), (4, 0), (8, 5), (16, 2))]
    return scaling_model.TrafficFit(rows)


def test_traffic_fit_exact():
    fit = traffic_fit()
    assert np.allclose(fit.bytes, [5, 7, 3])
    assert np.allclose(fit.messages, [2, 1, 0], atol=1e-9)
    assert fit.error.max() < 1e-12


def test_shared_bandwidth():
    # balanced, B(N/P, N) is S(P) N/P; a rank with 1.5x the mean cells at
    # 16 ranks (pSat 14.2): sqrt(1.5^2 + (16/14.2)^2)/sqrt(1 + 14.2^-2),
    # 1.8714 of the mean, not 1.5 S(16) = 2.25
    sb = scaling_model.shared_bandwidth
    assert abs(sb(100.0, 1600.0, 14.2)
               - 100*scaling_model.slowdown(16, 14.2)) < 1e-12
    assert abs(sb(1.5/16, 1.0, 14.2)*16 - 1.8714) < 1e-4


@pytest.fixture
def costs():
    """G(2) = 1.5 with growth 0.5; I1 = 100 iterations; pSat 2."""
    cal = scaling_model.Calibration(p_sat=2.0, c_iter=1e-5, growth=0.5,
                                    v_parallel=2e-3, b_stock=0.1,
                                    iterations=100.0)
    c = scaling_model.Costs((1e-6, 1e-9), (10, 2, 4), traffic_fit(), cal)
    c.c_cell, c.c_work, c.rbd = 1e-6, 1e-5, 0.01
    return c


@pytest.fixture
def table():
    return rank_tables.RankTable(
        columns=["cells", "processorFaces", "oversetWork", "remotePairs",
                 "acceptors", "pairs"],
        rows=[{"cells": 1000, "processorFaces": 50, "oversetWork": 100,
               "remotePairs": 10, "acceptors": 5, "pairs": 40},
              {"cells": 800, "processorFaces": 50, "oversetWork": 300,
               "remotePairs": 0, "acceptors": 7, "pairs": 60}])


# overset: rank 1's work 1e-5 B(300, 400) + vParallel + rank 0's traffic
# 1e-6 (2 + 1) + 1e-9 (5 + 7 + 3*10); rank 0 pimple: G (1e-6 B(1000, 1800)
# + 100 1e-5 1 + 1e-9 2 8 50)
OVERSET = 1e-5*bw(300, 400) + 2e-3 + 3e-6 + 42e-9
PIMPLE = 1.5*(1e-6*bw(1000, 1800) + 1e-3 + 800e-9)


def predict(costs, table):
    return scaling_model.predict(costs, scaling_model.Decomposition(
        table, [1, 1]))


def test_step_of_2_ranks(costs, table):
    step = predict(costs, table)
    assert abs(step["overset"] - OVERSET) < 1e-15
    assert abs(step["pimple"] - PIMPLE) < 1e-15
    assert abs(step["total"] - 0.01 - OVERSET - PIMPLE) < 1e-15


def test_stock_overset_of_2_ranks(costs, table):
    # bStock (P - 1) of the serial overset (1e-5 400) instead of vParallel
    costs.stencil = scaling_model.STOCK
    stock = predict(costs, table)["overset"]
    assert abs(stock - (OVERSET - 2e-3 + 0.1*4e-3)) < 1e-15


def test_overset_at_a_pose(costs, table):
    # the work's imbalance at a pose 1.8 (of the mean 200): 360 at a step;
    # 1.2 (240) is below the cycle's largest mean, 300
    peaks = []
    for at_pose in (1.8, 1.2):
        table.info["oversetWorkAtPose"] = at_pose
        peaks.append(predict(costs, table)["overset"])
    assert abs(peaks[0] - OVERSET - 1e-5*(bw(360, 400) - bw(300, 400))) \
        < 1e-15
    assert abs(peaks[1] - OVERSET) < 1e-15


def test_sweep_values_max_and_pimple_with_remote_donors(costs, table):
    # the busiest rank per sweep: faces + remote donor cells (50 + 30 on
    # rank 1); a report without remoteDonors: NaN.  PIMPLE with the
    # remote-stencil interfaces (1 rank each): rank 0 G (1e-6 B(1000,
    # 1800) + 100 1e-5 (1 + 1) + 1e-9 2 8 (50 + 8)), rank 1 less
    without = scaling_model.Decomposition(table, [1, 1]).sweep_values_max()
    table.columns += ["remoteDonors", "donorRanks"]
    for row, donors in zip(table.rows, (8, 30)):
        row["remoteDonors"], row["donorRanks"] = donors, 1
    d = scaling_model.Decomposition(table, [1, 1])
    assert d.sweep_values_max() == 80 and np.isnan(without)
    pimple = 1.5*(1e-6*bw(1000, 1800) + 2e-3 + 928e-9)
    assert abs(scaling_model.predict(costs, d)["pimple"] - pimple) < 1e-15


def test_step_of_an_overset_rank_report(costs):
    """A solver's oversetRankReport of 2 ranks as a decomposition: the
    neighbours from procPatches, remote donors from received, recvRanks;
    its step by hand with the counted iterations (110 of I1 100)."""
    names = ["cells", "procFaces", "procPatches", "acceptors", "remoteSlots",
             "received", "recvRanks"]
    report = rank_tables.RankTable(columns=names, rows=[
        dict(zip(names, (600, 40, 1, 10, 12, 5, 1))),
        dict(zip(names, (500, 40, 1, 20, 30, 9, 1)))])
    d = scaling_model.Decomposition.from_rank_report(report)
    costs.traffic = None
    step = scaling_model.predict(costs, d, iterations=110)
    # rank 0: 1.1 (1e-6 B(600, 1100) + 100 1e-5 2 + 1e-9 2 8 45); overset:
    # 1e-5 B(600, 1100) + vParallel (no stencil traffic)
    assert list(d.neighbours) == [1, 1] and list(d.remote_donors) == [5, 9]
    assert abs(step["pimple"] - 1.1*(1e-6*bw(600, 1100) + 2e-3 + 720e-9)) \
        < 1e-15
    assert abs(step["overset"] - (1e-5*bw(600, 1100) + 2e-3)) < 1e-15
    assert step["slowestRank"] == 0


# The committed 16-core measurements (bench/scaling/measured).  Runs of the
# first 40 s of the first session's coarse archive: their PIMPLE is
# 1.30-1.75x that of the same partition run later with the stock stencil
# (bitwise the same p solves); the model, which gives both the same PIMPLE,
# is 19-48 % below them (bench/scaling/results-validate.md)
EARLY = ("scaling-16core:coarse/octree-oversetGraph-np*",
         "scaling-16core:coarse/octree-hierarchical-np2")
NEW = "session2-round3"
ARCHIVES = scaling_validate.SESSIONS
ROUNDS = scaling_validate.ROUNDS[0]


@pytest.fixture(scope="module")
def runs():
    return scaling_validate.read_archives(ARCHIVES, rounds=[ROUNDS])


@pytest.fixture(scope="module")
def rows(runs):
    from flapfoam.scaling import validate as sv
    return sv.compare(runs, scaling_model.CALIBRATION)


def test_timed_rounds_of_the_committed_log():
    """flapfoam.bench.timed_rounds on the committed runTimed.log (rounds 1 and
    2): coarse scotch np16 the median of 0.1524 and 0.1339."""
    from flapfoam.bench import timed_rounds
    timed = timed_rounds.read_file(ROUNDS, ["coarse", "medium"])
    got = timed_rounds.medians(timed).get(
        ("coarse", "octree", "scotch", 16, False))
    assert len(timed) == 73 and got and got[1] == 2
    assert abs(got[0]["step"] - 0.14315) < 1e-9


def test_validate_medians_over_rounds(runs):
    """Medians of 3 rounds (2 where round 2 was skipped), the other
    session's runs untouched: coarse scotch np16 0.1339."""
    by = {r.name: r for r in runs}
    scotch = by.get(NEW + ":coarse/octree-scotch-np16")
    hier = by.get(NEW + ":medium/octree-hierarchical-np4")
    assert scotch and scotch.rounds == 3
    assert abs(scotch.measured["step"] - 0.1339) < 1e-9
    assert hier and hier.rounds == 2
    assert {r.rounds for r in runs if r.session == "scaling-16core"} == {1}


def early_and_rest(rows):
    early = [r for r in rows if any(fnmatch.fnmatch(r["run"], p)
                                    for p in EARLY)]
    return early, [r for r in rows if r not in early]


def test_validate_errors_of_the_committed_model(rows):
    """Its octree runs within 17 %, stock runs within 17 %, the first
    session's octree runs within 23 % but for EARLY (50 %)."""
    from flapfoam.scaling import validate as sv
    early, rest = early_and_rest(rows)
    worst = sv.largest_errors(rest, lambda r: (r["session"], r["stencil"]))
    assert len(rows) == 67 and len(early) == 5
    assert worst[(NEW, "octree")][0] < 0.17
    assert worst[("scaling-16core", "ID")][0] < 0.17
    assert worst[("scaling-16core", "octree")][0] < 0.23


def test_validate_early_runs(rows):
    from flapfoam.scaling import validate as sv
    early, _ = early_and_rest(rows)
    assert sv.largest_errors(early)[None][0] < 0.5


def test_validate_ranked_pairs(rows):
    """20 of the 26 pairs measured more than 15 % apart ranked as
    measured."""
    from flapfoam.scaling import validate as sv
    pairs = sv.ranked_pairs(rows)
    assert len(pairs) == 26 and sum(p[3] for p in pairs) >= 20


def test_calibrate_reproduces_the_committed_constants(runs):
    from flapfoam.scaling import validate as sv
    cal = sv.calibrate(runs)
    ref = scaling_model.CALIBRATION
    diff = {f: abs(getattr(cal, f)/getattr(ref, f) - 1)
            for f in ("p_sat", "c_iter", "growth", "v_parallel", "b_stock")}
    assert max(diff.values()) < 0.03, str(cal)
