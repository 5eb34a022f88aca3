# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam.studies.two_wing_flight: the two-wing flights' summary keys
from runs whose flight data are made here (known lateral states, a roll
growing at known rates, a known wall-clock and mesh), the files, and the
refusals."""

import json

import h5py
import numpy as np
import pytest

from flapfoam.errors import FlapFoamError
from flapfoam.studies import two_wing_flight as tw

F = 20.0


def make_run(folder, roll_rates=(0, 0, 0), y=0.0, wall=None, cells=None):
    """A run folder: 3 cycles, 100 rows a cycle, roll growing by
    roll_rates[k] deg over cycle k, y = y sin(2 pi f t), the wings'
    forces; a solver log and an owner note if wall and cells are given."""
    t = np.linspace(0, 3/F, 301)
    q = np.zeros((len(t), 10))
    q[:, 1] = y*np.sin(2*np.pi*F*t)
    ends = np.concatenate([[0], np.cumsum(roll_rates)])
    q[:, 5] = np.radians(np.interp(t*F, np.arange(4), ends))
    path = folder / "postProcessing" / "flightData" / "0"
    path.mkdir(parents=True)
    with h5py.File(path / "flightData.h5", "w") as h:
        h["time"], h["joints/q"] = t, q
        h["joints/qDot"] = np.gradient(q, t, axis=0)
        for w in tw.WINGS:
            h["bodies/%s/force" % w] = np.tile([1e-3, 0, 2e-2], (len(t), 1))
        h.attrs["nRanks"], h.attrs["level"] = 2, "tiny"
    if wall is not None:
        (folder / "log.overPimpleDyMFoam").write_text(
            "ExecutionTime = 1 s  ClockTime = %g s\n" % wall)
        (folder / "constant" / "polyMesh").mkdir(parents=True)
        (folder / "constant" / "polyMesh" / "owner").write_text(
            'note "nPoints:10 nCells:%d nFaces:10";\n' % cells)
    return str(folder)


def test_summary_keys_from_known_flights(tmp_path):
    cfd = make_run(tmp_path / "cfd", y=2e-4, wall=3600.0, cells=500000)
    qs = make_run(tmp_path / "qs")
    roll = make_run(tmp_path / "roll", roll_rates=(1, 3, 5))
    roll_qs = make_run(tmp_path / "rollQs", roll_rates=(1, 2, 4))
    out = tmp_path / "out"
    out.mkdir()
    (out / "summary.json").write_text('{"trim_iterations": 3, "cells": 1}')
    rc = tw.main([cfd, "-qs", qs, "-roll", roll, "-rollQs", roll_qs,
                  "-o", str(out)])
    s = json.loads((out / "summary.json").read_text())
    assert rc == 0
    # the other studies' keys kept, its own replaced
    assert s["trim_iterations"] == 3
    assert s["cells"] == 500000 and s["ranks"] == 2
    assert s["cycles_run"] == 3.0
    # 3600 s x 2 ranks / 3 cycles / 0.5 M cells = 1.33 core-h
    assert s["core_hours_per_cycle_per_million_cells"] == 1.33
    assert s["max_abs_lateral_qs"] == 0.0
    assert s["max_abs_y_m_cfd"] == pytest.approx(2e-4, rel=1e-3)
    assert s["max_abs_roll_deg_cfd"] == 0.0
    # y = 2e-4 sin: its bound reached in the first cycle; equal wings
    sym = s["symmetry_cfd_by_cycle"]
    assert sym["y_m"] == pytest.approx([2e-4]*3, rel=1e-3)
    assert sym["roll_deg"] == [0.0]*3
    assert sym["wing_lift_difference_percent"] == [0.0]*3
    # two wings of 2e-2 N each, every cycle, both flights
    assert s["wing_lift_n_by_cycle"]["cfd"] == pytest.approx([4e-2]*3)
    assert s["wing_lift_n_by_cycle"]["qs"] == pytest.approx([4e-2]*3)
    assert s["roll_rate_deg_per_cycle_cfd"] == pytest.approx([1, 3, 5])
    assert s["manoeuvre_rate_deg_per_cycle_cfd"] == pytest.approx(4.0)
    assert s["manoeuvre_rate_deg_per_cycle_qs"] == pytest.approx(3.0)
    for name in ("trajectory", "attitude", "wingForces", "manoeuvre"):
        assert (out / (name + ".png")).stat().st_size > 10000
    with h5py.File(out / "flightData.h5") as h:
        assert len(h["time"]) == 301


def test_not_a_two_wing_flight_is_refused(tmp_path):
    run = make_run(tmp_path / "cfd", wall=1.0, cells=10)
    with h5py.File(tmp_path / "cfd" / "postProcessing" / "flightData" / "0"
                   / "flightData.h5", "a") as h:
        del h["bodies/rightWing"]
    with pytest.raises(FlapFoamError, match="not a two-wing flight"):
        tw.read(run)


def test_roll_runs_go_together(tmp_path, capsys):
    with pytest.raises(SystemExit):
        tw.parse(["r", "-qs", "q", "-o", "o", "-roll", "x"])
    assert "-roll and -rollQs go together" in capsys.readouterr().err


def test_symmetry_by_cycle_bounds_and_lift_difference(tmp_path):
    # roll growing 1, 3, 5 deg a cycle: bounds 1, 4, 9 deg to each cycle's
    # end; the right wing lifting 1 % less: 200 (1 - 0.99) / 1.99 %
    run = make_run(tmp_path / "roll", roll_rates=(1, 3, 5))
    with h5py.File(tmp_path / "roll" / "postProcessing" / "flightData" / "0"
                   / "flightData.h5", "a") as h:
        h["bodies/rightWing/force"][:, 2] *= 0.99
    sym = tw.symmetry_by_cycle(tw.read(run), F)
    assert sym["roll_deg"] == pytest.approx([1, 4, 9])
    assert sym["yaw_deg"] == [0.0]*3
    assert sym["wing_lift_difference_percent"] == \
        pytest.approx([200*0.01/1.99]*3)


def test_wing_lift_by_cycle_takes_each_cycles_rows(tmp_path):
    # the left wing lifting k/100 N in cycle k (its first row at t = 0 is
    # no cycle's), the right 2e-2 N: cycle means 0.03, 0.04, 0.05 N
    run = make_run(tmp_path / "cfd")
    with h5py.File(tmp_path / "cfd" / "postProcessing" / "flightData" / "0"
                   / "flightData.h5", "a") as h:
        t = h["time"][:]
        h["bodies/leftWing/force"][:, 2] = \
            np.ceil(np.round(t*F, 9)).clip(1)/100
    lift = tw.wing_lift_by_cycle([("cfd", tw.read(run))], F)
    assert lift["cfd"] == pytest.approx([0.03, 0.04, 0.05])


def test_a_longer_qs_flight_is_drawn_over_the_cfd_cycles(tmp_path):
    cfd = tw.read(make_run(tmp_path / "cfd"))
    qs = tw.read(make_run(tmp_path / "qs"))
    qs.time = qs.time*2
    keep = tw.within(qs, cfd)
    assert keep.sum() == 151 and qs.time[keep][-1] == pytest.approx(3/F)
