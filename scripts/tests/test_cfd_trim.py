# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam.studies.cfd_trim: the loop on a made-up linear "CFD" whose
Jacobian differs from the QS one it is corrected with (it converges, to
the made-up trim, in the runs the contraction says; a CFD whose pitch
answers the other way does not, and stops at -maxRuns); the residuals of a
made-up run known in closed form."""

import math

import numpy as np
import pytest

from flapfoam.studies import cfd_trim
from flapfoam.studies.cfd_trim import Problem, Run, Settings
from flight_files import write_run

J_QS = np.array([[1.3, -0.1], [0.02, 0.55], [0.03, 3.1]])
TRIM = np.array([1.30, -0.02])


def made_up(monkeypatch, j_cfd):
    """fly(): the QS runs (qs-*) answer with J_QS about the start, the
    CFD runs with j_cfd about TRIM (residuals in the scaled units, the
    pitch's in deg a cycle)."""
    s = Settings(dir="/nonexistent", max_runs=8)
    problem = Problem(["flapping.amplitude", "flapping.offset"],
                      [(0.8, 1.55), (-0.4, 0.4)], [1.266, -0.0088])
    monkeypatch.setattr(cfd_trim, "problem_of", lambda s: problem)
    monkeypatch.setattr(cfd_trim.os, "makedirs", lambda *a, **k: None)
    unscale = np.array([1, 1, s.pitch_tolerance/s.force_tolerance])

    def fly(s, problem, values, k, model):
        j, about = (J_QS, np.array(problem.start)) if k.startswith("qs") \
            else (j_cfd, TRIM)
        r = j @ (np.array(values) - about)*unscale
        return Run(list(values), [float(x) for x in r], k, 0.0)

    monkeypatch.setattr(cfd_trim, "fly", fly)
    return s


def test_a_mismatched_jacobian_converges_to_the_cfd_trim(monkeypatch):
    # the CFD lifts 30 % more and pitches 20 % less than the QS model
    s = made_up(monkeypatch, J_QS*np.array([[1.3], [1.0], [0.8]]))
    problem = cfd_trim.cfd_trim(s, report=lambda line: None)
    keys = cfd_trim.summary(s, problem)
    assert keys["cfd_trim_converged"]
    assert 2 <= keys["cfd_trim_runs"] <= 5
    assert keys["cfd_trim_force_residual_over_weight"] <= s.force_tolerance
    assert abs(keys["cfd_trim_pitch_change_deg_per_cycle"]) \
        <= s.pitch_tolerance
    # the QS Jacobian, by differences of the made-up QS runs
    assert problem.jacobian == pytest.approx(J_QS, rel=1e-9)


def test_a_cfd_that_answers_the_other_way_stops_at_max_runs(monkeypatch):
    s = made_up(monkeypatch, J_QS*np.array([[1.0], [-1.0], [-1.0]]))
    problem = cfd_trim.cfd_trim(s, report=lambda line: None)
    assert len(problem.runs) == s.max_runs
    assert not cfd_trim.summary(s, problem)["cfd_trim_converged"]
    # every step stays inside the trimDict's ranges
    for run in problem.runs:
        for v, (lo, hi) in zip(run.values, problem.ranges):
            assert lo <= v <= hi


DICT = """eABAMeshMotionCoeffs
{
    g (0 0 -9.81);
    bodies
    {
        body { type rigidBody; parent root; mass 0.0015;
               inertia (6e-6 0 0 6e-6 0 6e-6); }
        wing { type rigidBody; parent body; mass 0.00015;
               inertia (1e-8 0 0 2e-9 0 1e-8); }
    }
    imposedMotion { flapping { type harmonic; joint 1; frequency 20; } }
}
"""


def test_the_residuals_of_a_made_up_run(tmp_path):
    """The fluid forces 1.05 W and 0.01 W with a flapping harmonic, the
    body pitching at 0.3 deg a cycle: the residuals to round-off."""
    (tmp_path / "constant").mkdir()
    (tmp_path / "constant" / "dynamicMeshDict").write_text(DICT)
    weight = 0.00165*9.81
    t = np.linspace(0, 0.15, 1501)
    n = len(t)
    wave = np.sin(2*math.pi*20*t)
    theta = np.radians(0.3*20*t)
    R = np.zeros((n, 9))
    R[:, 0] = R[:, 8] = np.cos(theta)
    R[:, 2], R[:, 6] = np.sin(theta), -np.sin(theta)
    rows = {"time": t, "joints/q": np.zeros((n, 2)),
            "bodies/body/force": np.column_stack(
                [0.01*weight + 0*t, 0*t, 0.5*weight + 0*t]),
            "bodies/body/orientation": R,
            "bodies/wing/force": np.column_stack(
                [0.3*weight*wave, 0*t, 0.55*weight*(1 + wave)]),
            "bodies/wing/orientation": R}
    for name in ("bodies/body/force", "bodies/wing/force"):
        rows[name][0] = np.nan
    write_run(tmp_path, rows, {"joints/q": "q_0 q_1"})
    r = cfd_trim.residuals(str(tmp_path), Settings(dir=""))
    assert r == pytest.approx([0.05, 0.01, 0.3], abs=1e-9)
    assert cfd_trim.finished(str(tmp_path), Settings(dir=""))
    assert not cfd_trim.finished(str(tmp_path), Settings(dir="", cycles=4))
