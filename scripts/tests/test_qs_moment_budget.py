# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam qs_moment_budget's parts on made-up series: the added inertia
and damping recovered from a moment built with them; a moment that is not
proportional to the pitch motion is not explained."""

import numpy as np
import pytest

from flapfoam.studies import qs_moment_budget as mb


def test_added_inertia_recovered():
    t = np.linspace(0, 0.1, 500)
    rate = 40*np.cos(2*np.pi*20*t)
    acc = -40*2*np.pi*20*np.sin(2*np.pi*20*t)
    moment = -7e-9*acc - 1e-7*rate
    r2, inertia, damping = mb.added_inertia(moment, (rate, acc),
                                            np.full(len(t), 2e-4))
    assert r2 == pytest.approx(1, abs=1e-12)
    assert inertia == pytest.approx(7e-9, rel=1e-9)
    assert damping == pytest.approx(1e-7, rel=1e-9)


def test_a_moment_of_another_frequency_is_not_explained():
    t = np.linspace(0, 0.1, 500)
    rate = np.cos(2*np.pi*20*t)
    acc = -2*np.pi*20*np.sin(2*np.pi*20*t)
    moment = np.cos(2*np.pi*60*t)
    r2, _, _ = mb.added_inertia(moment, (rate, acc), np.ones(len(t)))
    assert r2 < 1e-2
