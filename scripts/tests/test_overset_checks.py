# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""The overset checkers of applications/test/overset
(flapfoam.checks.overset_cell_types, overset_motion, overset_rank_report)
on small runs written here: equal runs pass, a changed cell, force or
row fails, and the rank report's sums and counts are checked."""

import numpy as np
import pytest

from flapfoam.checks import overset_cell_types as cell_types
from flapfoam.checks import overset_motion as motion
from flapfoam.checks import overset_rank_report as rank_report
from flapfoam.errors import FlapFoamError

FIELD = """FoamFile { version 2.0; format ascii; class volScalarField;
    object cellTypes; }
dimensions [0 0 0 0 0 0 0];
internalField nonuniform List<scalar> %d (%s);
boundaryField { }
"""


def cell_types_run(folder, types, timers=None):
    """A run with cellTypes at t = 1e-05 and 2e-05 (types, the second
    time's last cell a hole), and stepTimers.dat rows."""
    for k, t in enumerate(("1e-05", "2e-05")):
        values = list(types) if k == 0 else list(types[:-1]) + [2]
        (folder / t).mkdir(parents=True)
        (folder / t / "cellTypes").write_text(
            FIELD % (len(values), " ".join(map(str, values))))
    if timers:
        dat = folder / "postProcessing" / "stepTimers" / "0"
        dat.mkdir(parents=True)
        dat.joinpath("stepTimers.dat").write_text(
            "# time oversetStencil oversetMovePoints overset total\n"
            + "".join("%g %g %g %g %g\n" % ((k*1e-5,) + row)
                      for k, row in enumerate(timers)))


def test_cell_types_equal_pass_a_changed_cell_fails(tmp_path, capsys):
    rows = [(9, 9, 9, 9)] + [(0.01, 0.02, 0.03, 0.1)]*3
    cell_types_run(tmp_path / "ref", [0, 0, 1, 1], rows)
    cell_types_run(tmp_path / "same", [0, 0, 1, 1], rows)
    cell_types_run(tmp_path / "other", [0, 1, 1, 1])
    args = ["-dir", str(tmp_path), "-reference", "ref", "ref", "same"]
    assert cell_types.main(args) == 0
    out = capsys.readouterr().out
    assert "PASS same: cellTypes match vs ref >= 1.000000 over 2 times" in out
    # the first step (9 s) is skipped: the medians of the others
    assert "0.01000" in out and "9.00000" not in out
    assert cell_types.main(args + ["other"]) == 1
    out = capsys.readouterr().out
    assert "match 0.750000  differing 1 0->1:1" in out
    assert "FAIL other: cellTypes match vs ref >= 0.750000" in out
    assert cell_types.main(args[:4] + ["-minMatch", "0.75", "other"]) == 0


def test_cell_types_missing_times_fail(tmp_path, capsys):
    cell_types_run(tmp_path / "ref", [0, 1])
    (tmp_path / "empty").mkdir()
    assert cell_types.main(["-dir", str(tmp_path), "-reference", "ref",
                            "empty"]) == 1
    assert "FAIL empty: no cellTypes at 1e-05" in capsys.readouterr().out
    assert cell_types.main(["-dir", str(tmp_path), "-reference", "empty",
                            "ref"]) == 1


def motion_run(folder, force_x=1.0, q_end=0.3):
    base = folder / "postProcessing" / "eABAMeshMotion" / "0"
    base.mkdir(parents=True)
    base.joinpath("bodies.dat").write_text(
        "# time wing:Fx wing:Fy wing:Fz\n"
        "0 0 0 1\n1e-05 %g 0 2\n2e-05 2 0 3\n" % force_x)
    base.joinpath("joints.dat").write_text(
        "# time q_0 qDot_0 q_1 qDot_1\n"
        "0 0 0 0 0\n1e-05 0.1 1 0.2 2\n2e-05 %g 2 0.4 3\n" % q_end)
    return str(folder)


def test_motion_equal_pass_and_changes_fail(tmp_path, capsys):
    ref = motion_run(tmp_path / "ref")
    assert motion.main([ref, motion_run(tmp_path / "same")]) == 0
    out = capsys.readouterr().out
    assert "PASS same wing force vs ref, 3 rows" in out
    assert "PASS same trajectory vs ref, 3 rows" in out
    # the force 1.1 against 1: 0.1 of max|F| (sqrt(13))
    force = motion_run(tmp_path / "force", force_x=1.1)
    assert motion.main([ref, force]) == 1
    assert "FAIL force wing force" in capsys.readouterr().out
    assert motion.main([ref, force, "-forceTol", "0.028"]) == 0
    assert motion.main([ref, motion_run(tmp_path / "q", q_end=0.31)]) == 1
    assert "FAIL q trajectory" in capsys.readouterr().out
    with pytest.raises(FlapFoamError, match="no .*/eABAMeshMotion/<time>"
                       "/bodies.dat"):
        motion.main([ref, str(tmp_path)])


COLUMNS = ("cells acceptors remote mixed allRemote remoteSlots procFaces "
           "procPatches sent received sendRanks recvRanks haloBytes").split()


def report_lines(stencil, rows):
    """The lines of one oversetRankReport as timedOversetFvMesh writes
    them."""
    tag = "oversetRankReport: "
    total = [sum(c) for c in zip(*rows)]
    cells = [r[0] for r in rows]
    lines = [tag + "time 1e-05 stencil %s ranks %d" % (stencil, len(rows)),
             tag + "rank " + " ".join(COLUMNS)]
    lines += [tag + "%d %s" % (k, " ".join(map(str, r)))
              for k, r in enumerate(rows)]
    lines += [tag + "total " + " ".join(map(str, total)),
              tag + "max " + " ".join(str(max(c)) for c in zip(*rows)),
              tag + "mean " + " ".join(str(s/len(rows)) for s in total),
              tag + "cellImbalance %.17g remoteShare %.17g"
              % (max(cells)/(sum(cells)/len(rows)),
                 total[2]/total[1] if total[1] else 0)]
    return lines


def rank_runs(tmp_path, parallel_rows, stock_count):
    serial = [(100, 10) + (0,)*11]
    for name, rows in (("serial", serial), ("parallel", parallel_rows)):
        for stencil in ("inverseDistance", "octreeInverseDistance"):
            case = tmp_path / name / stencil
            case.mkdir(parents=True)
            count = ["interpolated : %d (interpolated from local:%d  mixed "
                     "local/remote:%d  remote:%d)" % stock_count[name]]
            case.joinpath("log.overPimpleDyMFoam").write_text(
                "\n".join(count + report_lines(stencil, rows)) + "\n")
    return str(tmp_path / "serial"), str(tmp_path / "parallel")


PARALLEL = [(60, 6, 2, 1, 1, 3, 5, 1, 4, 4, 1, 1, 40),
            (40, 4, 1, 1, 0, 1, 5, 1, 4, 4, 1, 1, 40)]


def test_rank_report_consistent_runs_pass(tmp_path, capsys):
    runs = rank_runs(tmp_path, PARALLEL, {"serial": (10, 10, 0, 0),
                                          "parallel": (10, 7, 2, 1)})
    assert rank_report.main(list(runs)) == 0
    out = capsys.readouterr().out
    assert "FAIL" not in out
    assert "inverseDistance -np 2: cells 60+40 add up to the serial 100" \
        in out
    assert "octreeInverseDistance parallel: every row equals" in out


def test_rank_report_inconsistent_runs_fail(tmp_path, capsys):
    rows = [PARALLEL[0], PARALLEL[1][:6] + (4,) + PARALLEL[1][7:12] + (32,)]
    runs = rank_runs(tmp_path, rows, {"serial": (10, 10, 0, 0),
                                      "parallel": (10, 8, 1, 1)})
    assert rank_report.main(list(runs)) == 1
    out = capsys.readouterr().out
    # 5 + 4 processor faces: one seen from one side only
    assert "FAIL inverseDistance -np 2: processor faces [5, 4]" in out
    assert "FAIL inverseDistance parallel: the stencil's own count" in out
