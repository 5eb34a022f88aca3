# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam.models.chain_reference: the planar chain against known solutions."""

import math

import numpy as np
import pytest

from flapfoam.models.chain_reference import Chain, Harmonic


def test_double_pendulum_accelerations_match_the_lagrangian_reference():
    # Row 0 of cases/doublePendulum/reference/free.dat (doublePendulumReference,
    # the C++ Lagrangian): absolute theta1 = 1, theta2 = 0.5, theta2Dot = 3
    chain = Chain([0.1, 0.2], [0.5, 0.5])
    q_ddot, tau = chain.accelerations(0.0, np.array([1.0, -0.5]),
                                     np.array([0.0, 3.0]))
    assert q_ddot[0] == pytest.approx(-107.6979, abs=1e-4)
    assert q_ddot[0] + q_ddot[1] == pytest.approx(23.7411, abs=1e-4)
    assert np.all(tau == 0)


def test_small_swing_has_the_pendulum_period():
    L, g = 0.25, 9.81
    chain = Chain([L], [2.0], g=g)
    period = 2*math.pi*math.sqrt(L/g)
    q, _ = chain.solve([1e-4], [0.0], [0.0, period])
    assert q[-1, 0] == pytest.approx(1e-4, rel=1e-6)


def test_free_chain_conserves_energy():
    chain = Chain([0.1, 0.15, 0.1], [0.3, 0.5, 0.2])
    times = np.linspace(0, 1, 101)
    q, q_dot = chain.solve([0.3, 0.4, -0.4], [1.0, 0.0, -2.0], times)
    e = [chain.energy(a, b) for a, b in zip(q, q_dot)]
    assert max(abs(np.array(e) - e[0])) < 1e-9*e[0]


def test_prescribed_joint_follows_its_motion_and_gets_the_torque():
    drive = Harmonic(0.5, 2.0, -math.pi/2, 0.1)
    chain = Chain([0.1, 0.15, 0.1], [0.3, 0.5, 0.2], prescribed={1: drive})
    times = np.linspace(0, 0.5, 11)
    q, q_dot = chain.solve([0.3, 0.0, -0.4], [1.0, 0.0, -2.0], times)
    for t, qi, q_dot_i in zip(times, q, q_dot):
        assert (qi[1], q_dot_i[1]) == pytest.approx(drive(t)[:2], abs=1e-14)
    # The power of the drive's torque is the rate of the energy
    dt = 1e-6
    e = []
    for t in (0.25 - dt, 0.25 + dt):
        qs, q_dots = chain.solve([0.3, 0.0, -0.4], [1.0, 0.0, -2.0],
                                [0.0, t])
        e.append(chain.energy(qs[-1], q_dots[-1]))
    qm, q_dot_m = chain.solve([0.3, 0.0, -0.4], [1.0, 0.0, -2.0], [0.0, 0.25])
    _, tau = chain.accelerations(0.25, qm[-1], q_dot_m[-1])
    assert (e[1] - e[0])/(2*dt) == pytest.approx(tau[1]*q_dot_m[-1, 1],
                                                 rel=1e-5)


def test_harmonic_derivatives():
    h = Harmonic(0.7, 3.0, 0.2, -0.1)
    eps = 1e-6
    q, q_dot, q_ddot = h(0.13)
    assert (h(0.13 + eps)[0] - h(0.13 - eps)[0])/(2*eps) \
        == pytest.approx(q_dot, rel=1e-8)
    assert (h(0.13 + eps)[1] - h(0.13 - eps)[1])/(2*eps) \
        == pytest.approx(q_ddot, rel=1e-8)


def test_bad_chain_is_refused():
    with pytest.raises(ValueError, match="one of each a link"):
        Chain([0.1, 0.2], [0.5])
