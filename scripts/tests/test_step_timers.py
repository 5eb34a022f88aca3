# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam.io.step_timers: the stepTimers.dat reader, restarts, the pimple
split."""

import numpy as np
import pytest

from flapfoam.io import step_timers
from flapfoam.errors import FlapFoamError


def timers_file(folder, rows, columns="time rbd overset pimple total"):
    folder.mkdir(parents=True)
    path = folder / "stepTimers.dat"
    path.write_text("# stepTimers\n# " + columns + "\n"
                    + "".join(" ".join(map(str, r)) + "\n" for r in rows))
    return path


def test_rows_after_start_up_joined_over_a_restart(tmp_path):
    base = tmp_path / "postProcessing" / "stepTimers"
    timers_file(base / "0", [(1, 0.1, 0.2, 1.0, 1.3), (2, 0.1, 0.2, 1.1, 1.4),
                             (3, 0.1, 0.2, 1.2, 1.5)])
    timers_file(base / "2", [(2, 0.1, 0.3, 2.0, 2.4), (3, 0.1, 0.3, 2.1, 2.5)])
    columns, data = step_timers.read_input(str(tmp_path), 0)
    assert columns == ["time", "rbd", "overset", "pimple", "total"]
    assert data[:, 0].tolist() == [1, 2, 3]
    assert data[:, 3].tolist() == [1.0, 2.0, 2.1]
    # one start-up row dropped in each file
    _, data = step_timers.read_input(str(tmp_path), 1)
    assert data[:, 0].tolist() == [2, 3]
    assert data[:, 3].tolist() == [1.1, 2.1]


def test_summary_and_ranks_files_are_not_timers_files(tmp_path):
    base = tmp_path / "postProcessing" / "stepTimers" / "0"
    timers_file(base, [(1, 0, 0, 1, 1)])
    (base / "stepTimersSummary.dat").write_text("# x\n")
    (base / "stepTimersRanks.dat").write_text(
        "# rank rbd pimple\n0 0.1 1.0\n1 0.2 0.9\n")
    assert [p.rsplit("/", 1)[1] for p in step_timers.find_files(
        str(tmp_path))] == ["stepTimers.dat"]
    ranks = step_timers.read_ranks(str(base / "stepTimersRanks.dat"))
    assert ranks == [{"rank": 0, "rbd": 0.1, "pimple": 1.0},
                     {"rank": 1, "rbd": 0.2, "pimple": 0.9}]
    assert step_timers.read_ranks(str(base / "absent.dat")) == []


def test_a_row_that_does_not_fit_its_header_stops(tmp_path):
    path = timers_file(tmp_path / "0", [(1, 0, 0, 1)])
    with pytest.raises(FlapFoamError, match="a row of 4 values under a header"
                       " of 5 columns"):
        step_timers.read_file(str(path))


def test_pimple_split_adds_up():
    row = {"pimple": 1.0, "pimpleMomentum": 0.1, "pimpleMomentumSolve": 0.05,
           "pimplePressure": 0.2, "pimplePressureSolve": 0.3,
           "pimpleTurbulence": 0.1, "pimpleOtherSolve": 0.02,
           "pimpleOversetInterpolate": 0.03, "pIterations1": 30,
           "pIterations2": 45, "pimpleInterpolations": 86}
    s = step_timers.pimple_split(row)
    assert s["momentum"] == pytest.approx(0.15)
    assert s["pressure"] == pytest.approx(0.5)
    assert s["pressureSolve"] == pytest.approx(0.3)
    assert s["turbulence"] == pytest.approx(0.12)
    assert s["rest"] == pytest.approx(1.0 - 0.15 - 0.5 - 0.12 - 0.03)
    assert s["pIterations"] == 75 and s["interpolations"] == 86
    assert step_timers.pimple_split({"pimple": 1.0}) is None
    assert step_timers.is_count("pIterations3")
    assert not step_timers.is_count("pimplePressure")


def test_chart_of_a_run_and_of_one_without_steps(tmp_path):
    from flapfoam.plots import step_timers as plot_step_timers
    from flapfoam.plots import plotting
    timers = tmp_path / "run" / "postProcessing" / "stepTimers"
    timers_file(timers / "0", [(t, 0.1, 0.2, 1.0, 1.3) for t in range(1, 6)])
    out = tmp_path / "plots"
    out.mkdir()
    assert plotting.step_timers_chart(str(tmp_path / "run"), str(out), "run") == 0
    assert (out / "stepTimers.png").stat().st_size > 1000
    # 2 rows: none after the 2 start-up steps
    short = tmp_path / "short"
    timers_file(short, [(1, 0.1, 0.2, 1.0, 1.3), (2, 0.1, 0.2, 1.0, 1.3)])
    with pytest.raises(ValueError, match="no steps after 2 start-up rows"):
        plot_step_timers.chart([str(short)], ["short"], 2,
                               plot_step_timers.Chart(str(tmp_path / "s.png")))


def test_chart_command_line(tmp_path):
    from flapfoam.plots import step_timers as plot_step_timers
    timers = tmp_path / "run"
    timers_file(timers, [(t, 0.1, 0.2, 1.0, 1.3) for t in range(1, 6)])
    out = tmp_path / "chart.png"
    plot_step_timers.main([str(timers), "-o", str(out), "-nStartup", "1",
                           "-l", "run", "-title", "a run"])
    assert out.stat().st_size > 1000
    with pytest.raises(SystemExit, match="no steps after 5 start-up rows"):
        plot_step_timers.main([str(timers), "-n", "5", "-o", str(out)])


def test_summary_is_a_tree_whose_parts_add_up(capsys):
    from flapfoam.io.step_timers import summary, tree_rows
    cols = ["time", "rbd", "overset", "pimple", "total", "oversetMovePoints",
            "oversetStencil", "oversetStencilDonors", "pimpleMomentum",
            "pimpleMomentumSolve", "pimplePressure", "pimplePressureSolve",
            "pimpleTurbulence", "pIterations1"]
    row = [1e-3, 0.1, 0.3, 1.0, 1.5, 0.2, 0.05, 0.1, 0.2, 0.1, 0.1, 0.4,
           0.1, 40]
    data = np.array([row, row])
    col = {c: data[:, i] for i, c in enumerate(cols)}
    rows = tree_rows(col)
    # each parent's children (rest included) add up to it
    for k, (depth, name, v) in enumerate(rows):
        kids = []
        for d2, _, v2 in rows[k + 1:]:
            if d2 <= depth:
                break
            if d2 == depth + 1:
                kids.append(v2[0])
        if kids:
            assert sum(kids) == pytest.approx(v[0], abs=1e-12), name
    names = [("  "*d + n) for d, n, _ in rows]
    assert "    move points" in names and "      stencil update" in names
    assert "        donors" in names and "    pressure" in names
    summary("run", cols, data, 2)
    out = capsys.readouterr().out
    assert "(the first 2 step(s) of each start left out: start-up)" in out
    assert "counts per step (mean): pIterations1 40" in out
    assert "pIterations1 " not in out.split("counts per step")[0]


def test_summary_of_a_run_without_flow_has_no_flow_rows(capsys):
    from flapfoam.io.step_timers import summary
    cols = ["time", "rbd", "overset", "pimple", "total"]
    data = np.array([[1e-5, 2e-5, 0.0, 1e-8, 5e-5]]*3)
    summary("qs", cols, data)
    out = capsys.readouterr().out
    assert "rbd" in out and "pimple" not in out and "overset" not in out
    assert "closure" not in out


def test_slowest_rank_tree_adds_up(capsys):
    """A parallel run's slowest rank (its own means): the pimple parts,
    the wait for the slowest rank among them, leave no rest; the move
    points hold the stencil update nested in them (overset's rest 0)."""
    from flapfoam.io.step_timers import slowest_rank_tree
    fast = {"rank": 0, "total": 1.0, "rbd": 0.01, "overset": 0.1,
            "oversetMovePoints": 0.04, "oversetStencil": 0.03,
            "oversetAddressing": 0.02, "oversetInterpolate": 0.01,
            "pimple": 0.8, "pimpleMomentum": 0.2, "pimplePressure": 0.3,
            "pimpleTurbulence": 0.1, "pimpleSync": 0.2, "preUpdate": 0.05}
    slow = dict(fast, rank=1, total=1.2, pimple=1.0, pimpleSync=0.0,
                pimplePressure=0.7)
    slowest_rank_tree("run", [fast, slow])
    out = capsys.readouterr().out.splitlines()
    assert out[0].startswith("run, rank 1 of 2 (the slowest")
    rests = [float(line.split()[1]) for line in out
             if line.split()[0] == "rest"]
    # move points' own time; overset's and pimple's rests: none
    assert rests == pytest.approx([0.04, 0, 0], abs=1e-12), out
