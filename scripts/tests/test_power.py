# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam power on a made-up run whose numbers are known in closed form:
a joint power of mean P0 plus a harmonic, a body climbing at a constant
speed (its potential energy grows at m g c), irregular steps; the window
checked against the run's whole cycles."""

import json
import math

import numpy as np
import pytest

from flapfoam.studies import power
from flight_files import write_run
from flapfoam.studies.qs_case import StudyError

DICT = """eABAMeshMotionCoeffs
{
    g (0 0 -9.81);
    bodies
    {
        link { type masslessBody; parent root; }
        wing { type rigidBody; parent link; mass 0.002;
               inertia (1e-6 0 0 2e-6 0 3e-6); }
    }
    imposedMotion
    {
        flapping { type harmonic; joint 1; frequency 20; amplitude 1.1; }
    }
    aerodynamics
    {
        wing { type quasiSteady; body wing; root (0 0.02 0); span (0 1 0);
               length 0.05; rho 1.2; }
    }
}
"""
P0, CLIMB, F, A, MASS = 0.08, 0.05, 20.0, 1.1, 0.002


def made_up_run(case, cycles=6):
    """A run of a climbing wing: 2 joints (Pz free, the flapping Rz
    prescribed), steps of irregular length, the first row's loads NaN."""
    (case / "constant").mkdir(parents=True)
    (case / "constant" / "dynamicMeshDict").write_text(DICT)
    rng = np.random.default_rng(1)
    dt = rng.uniform(2e-5, 6e-5, size=int(cycles/F/4e-5) + 10)
    t = np.concatenate(([0], np.cumsum(dt)))
    t = np.append(t[t < cycles/F - 1e-6], cycles/F)
    flap = A*np.sin(2*math.pi*F*t)
    q = np.column_stack([CLIMB*t, flap])
    p = P0 + 0.3*np.sin(4*math.pi*F*t)
    p[0] = np.nan
    n = len(t)
    rows = {"time": t, "joints/q": q, "joints/qDot": 0*q,
            "joints/qDdot": 0*q, "joints/tau": p[:, None],
            "joints/power": p[:, None],
            "bodies/wing/position": np.column_stack([0*t, 0*t, CLIMB*t]),
            "bodies/wing/velocity": np.tile([0, 0, CLIMB], (n, 1)),
            "bodies/wing/angularVelocity": np.tile([0, 0, 2.0], (n, 1)),
            "bodies/wing/orientation": np.tile(np.eye(3).reshape(9), (n, 1))}
    write_run(case, rows, {"joints/q": "q_0 q_1", "joints/power": "power_1",
                           "joints/tau": "tau_1"})
    return case


def test_the_numbers_of_a_climbing_wing(tmp_path):
    run = str(made_up_run(tmp_path / "run"))
    r = power.power(run, power.Window(1, 5, None))
    assert r["cycles"] == [1, 5] and r["period_s"] == pytest.approx(1/F)
    # the harmonic's mean over whole cycles is 0 (trapezoids: to 1e-4)
    assert r["power_w"] == pytest.approx(P0, rel=1e-4)
    assert r["power_w_per_kg"] == pytest.approx(P0/MASS, rel=1e-4)
    assert r["energy_change_w"] == pytest.approx(MASS*9.81*CLIMB, rel=1e-3)
    assert r["aero_power_w"] == pytest.approx(P0 - MASS*9.81*CLIMB,
                                              rel=1e-3)
    assert r["stroke_amplitude_rad"] == pytest.approx(2*A, rel=1e-4)
    area = 2*A*0.07**2/2
    assert r["disk_area_m2"] == pytest.approx(area, rel=1e-4)
    ideal = math.sqrt((MASS*9.81)**3/(2*1.2*area))
    assert r["ideal_power_w"] == pytest.approx(ideal, rel=1e-4)
    assert r["figure_of_merit"] == pytest.approx(
        ideal/(P0 - MASS*9.81*CLIMB), rel=1e-3)
    # each cycle's mean is the harmonic's P0 too
    assert len(r["cycle_power_w_per_kg"]) == 4
    assert r["cycle_power_w_per_kg"] == pytest.approx([P0/MASS]*4, rel=1e-3)
    # no store: the mean of max(p, 0) of P0 + 0.3 sin
    x = np.linspace(0, 2*math.pi, 200001)
    positive = np.mean(np.maximum(P0 + 0.3*np.sin(x), 0))
    assert r["power_positive_w_per_kg"] == pytest.approx(positive/MASS,
                                                         rel=1e-3)


def test_the_radius_option_sets_the_disk(tmp_path):
    run = str(made_up_run(tmp_path / "run"))
    r = power.power(run, power.Window(0, None, None), radius=0.1)
    assert r["cycles"] == [0, 6]
    assert r["disk_area_m2"] == pytest.approx(2*A*0.01/2, rel=1e-4)


def test_a_window_past_the_run_and_a_missing_entry_are_refused(tmp_path):
    run = str(made_up_run(tmp_path / "run"))
    with pytest.raises(StudyError, match="holds 6 whole cycles"):
        power.power(run, power.Window(2, 7, None))
    with pytest.raises(StudyError, match="no imposedMotion entry stroke"):
        power.power(run, power.Window(0, 1, None), flapping="stroke")


def test_the_command_writes_the_summary_key(tmp_path, capsys):
    run = str(made_up_run(tmp_path / "run"))
    summary = tmp_path / "summary.json"
    power.main([run, "-from", "1", "-summary", str(summary), "-label", "qs"])
    assert "FM" in capsys.readouterr().out
    keys = json.loads(summary.read_text())
    assert keys["power_qs"]["cycles"] == [1, 6]
    assert keys["power_w_per_kg_qs"] == keys["power_qs"]["power_w_per_kg"]
    assert keys["figure_of_merit_qs"] == keys["power_qs"]["figure_of_merit"]
    with pytest.raises(SystemExit):
        power.main([run, "-summary", str(summary)])       # no -label


def test_the_plot_draws_each_run(tmp_path, capsys):
    run = str(made_up_run(tmp_path / "run"))
    png = tmp_path / "power.png"
    power.main([run, run, "-from", "1", "-plot", str(png)])
    assert "wrote" in capsys.readouterr().out
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert png.stat().st_size > 10000
