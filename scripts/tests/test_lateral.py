# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam.checks.lateral, the two-wing drone's lateral states: the mean
rate of each whole cycle of a made-up angle."""

import math

import numpy as np

from flapfoam.checks.lateral import cycle_rates


def test_cycle_rates_of_a_steady_roll():
    # 2 deg a cycle at 20 Hz, plus a flapping wobble that each cycle
    # starts and ends at the same phase: each whole cycle's mean rate is 2
    f = 20.0
    t = np.linspace(0, 0.1625, 651)          # 3.25 cycles: 3 whole ones
    angle = np.radians(2*f*t + 0.5*np.sin(2*math.pi*f*t))
    rates = cycle_rates(t, angle, f)
    assert [k for k, _ in rates] == [1, 2, 3]
    assert max(abs(r - 2) for _, r in rates) < 1e-12
