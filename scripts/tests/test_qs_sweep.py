# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""The quasi-steady sweep's results of one point (flapfoam.studies.qs_sweep), on a
made-up joints.dat whose answers are known by hand."""

import numpy as np
import pytest

from flapfoam.studies.qs_sweep import point_results


def test_point_results_of_a_made_up_joints_table():
    # z = t^3, zDot = 3 t^2, x = -t, power_2 = t^2 (mean 1/3 on [0, 1],
    # trapezoidal), power_3 = 1
    t = np.linspace(0, 1, 2001)
    d = np.column_stack([t, t**3, 3*t**2, 0*t, -t, -1 + 0*t, 0*t,
                         t**2, t**2, 1 + 0*t, 1 + 0*t])
    r = point_results(d, "time q_0 qDot_0 qDdot_0 q_1 qDot_1 qDdot_1 tau_2"
                     " power_2 tau_3 power_3".split(), 0, 1, 10.0)
    assert r["meanClimbRate"] == pytest.approx(1, abs=1e-12)
    assert r["meanClimbAcceleration"] == pytest.approx(3, abs=1e-12)
    assert r["forceOverWeight"] == pytest.approx(1.3, abs=1e-12)
    assert r["meanDrift"] == pytest.approx(-1, abs=1e-12)
    assert r["meanPower_2"] == pytest.approx(1/3, abs=1e-6)
    assert r["meanPower"] == pytest.approx(4/3, abs=1e-6)
