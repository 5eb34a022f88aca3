# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
flapfoam.studies.floquet: the monodromy matrix by central differences and
the Floquet modes of a linear time-periodic system whose multipliers are
known in closed form; on the trimmed body-wing hover (variants/hover,
rigidBodySimulate: needs flapFoam's etc/bashrc), a kick along the most
unstable mode grows per cycle as its multiplier says.
"""

import math
import shutil

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.linalg import expm

from flapfoam.paths import project_path
from flapfoam.studies import flight_modes, floquet
from flapfoam.studies.cycle_map import CycleMap, MapSettings

# x' = A(t) x, A = P B P^-1 + P' P^-1 with P of period T: x(t) = P(t)
# exp(B t) P(0)^-1 x(0), so the monodromy is P(0) exp(B T) P(0)^-1 and the
# multipliers are the eigenvalues of exp(B T): exp(0.1 +- 1i), exp(-0.5),
# exp(0.02)
T = 1.0
B = np.array([[0.1, 1.0, 0.0, 0.0],
              [-1.0, 0.1, 0.0, 0.0],
              [0.0, 0.0, -0.5, 0.3],
              [0.0, 0.0, 0.0, 0.02]])
W = 2*math.pi/T


def factors(t):
    """R, D, N of P = R D N and their derivatives (closed form)."""
    c, s = math.cos(W*t), math.sin(W*t)
    R = np.array([[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
    dR = W*np.array([[-s, -c, 0, 0], [c, -s, 0, 0], [0, 0, 0, 0],
                     [0, 0, 0, 0]])
    D = np.diag([1.0, 1.0 + 0.3*s, 1.0 + 0.2*c, 1.5 - 0.4*s])
    dD = W*np.diag([0.0, 0.3*c, -0.2*s, -0.4*c])
    N, dN = np.eye(4), np.zeros((4, 4))
    N[3, 0], dN[3, 0] = 0.5*s, 0.5*W*c
    return (R, D, N), (dR, dD, dN)


def P(t):
    (R, D, N), _ = factors(t)
    return R @ D @ N


def P_dot(t):
    (R, D, N), (dR, dD, dN) = factors(t)
    return dR @ D @ N + R @ dD @ N + R @ D @ dN


def A(t):
    Pi = np.linalg.inv(P(t))
    return P(t) @ B @ Pi + P_dot(t) @ Pi


def one_cycle(points):
    return [solve_ivp(lambda t, x: A(t) @ x, (0, T), p, method="DOP853",
                      rtol=1e-12, atol=1e-14).y[:, -1] for p in points]


def exact_multipliers():
    mu = np.linalg.eigvals(expm(B*T))
    return sorted(mu, key=lambda m: (-abs(m), -np.angle(m)))


def test_monodromy_of_a_periodic_system_is_exact():
    """Central differences of the one-cycle map: the monodromy P(0)
    exp(BT) P(0)^-1 within 1e-8, the multipliers within 1e-6."""
    x = np.array([0.3, -0.2, 0.1, 0.05])
    M = floquet.monodromy(one_cycle, x, 1e-3*np.ones(4))
    exact = P(0) @ expm(B*T) @ np.linalg.inv(P(0))
    assert np.max(abs(M - exact)) < 1e-8
    modes = floquet.modes(M, np.ones(4))
    for m, mu in zip(modes, exact_multipliers()):
        assert abs(m.multiplier - mu) < 1e-6


def test_mode_periods_and_doubling_times():
    """The complex pair exp(0.1 +- 1i): period 2 pi cycles, doubles in
    ln 2/0.1; exp(-0.5) halves in ln 2/0.5 and does not oscillate; the
    unstable one is the pair (largest |mu|); each within 1e-6."""
    M = floquet.monodromy(one_cycle, np.zeros(4), 1e-2*np.ones(4))
    modes = floquet.modes(M, np.ones(4))
    pair, slow, stable = modes[0], modes[2], modes[3]
    assert abs(pair.period_cycles - 2*math.pi) < 1e-6
    assert abs(pair.doubling_cycles - math.log(2)/0.1) < 1e-5
    assert abs(modes[1].multiplier - pair.multiplier.conjugate()) < 1e-9
    assert abs(slow.doubling_cycles - math.log(2)/0.02) < 1e-3
    assert stable.period_cycles is None
    assert abs(stable.doubling_cycles - math.log(2)/0.5) < 1e-6
    result = floquet.Floquet(np.zeros(4), 0.0, M, modes, list("abcd"),
                             np.ones(4), 1e-2)
    assert result.unstable() is pair
    keys = floquet.summary(result)
    assert abs(keys["unstable_mode_period_cycles"] - 2*math.pi) < 1e-6
    assert len(keys["floquet_multipliers"]) == 4


def test_modal_coordinate_of_a_kick_grows_by_its_multiplier():
    """A kick along Re(v) of the pair: its modal coordinate is multiplied
    by mu each cycle (the linear system: within 1e-8)."""
    M = floquet.monodromy(one_cycle, np.zeros(4), 1e-2*np.ones(4))
    mode = floquet.modes(M, np.ones(4))[0]
    states = [1e-3*np.real(mode.vector)]
    for _ in range(3):
        states.append(one_cycle([states[-1]])[0])
    c = floquet.modal_coordinates(M, np.array(states), 0)
    assert np.max(abs(c[1:]/c[:-1] - mode.multiplier)) < 1e-8


def test_states_a_mode_moves():
    """The eigenvector in the scaled states, largest component 1: a
    matrix that only couples state 0 to 1 moves those two."""
    M = np.diag([1.2, 0.5, 0.4])
    M[1, 0] = 0.7
    top = floquet.modes(M, np.array([1.0, 2.0, 1.0]))[0]
    states = top.states(["a", "b", "c"])
    # v = (1, 1) in SI: (0.7/(1.2 - 0.5) = 1); scaled (1, 0.5)
    assert [s[0] for s in states] == ["a", "b"]
    assert abs(states[1][1] - 0.5) < 1e-12


@pytest.mark.skipif(shutil.which("rigidBodySimulate") is None,
                    reason="needs flapFoam's etc/bashrc (rigidBodySimulate)")
def test_bw_hover_kick_grows_as_its_multiplier(tmp_path):
    """The body-wing drone's hover (variants/hover, trimmed): one cycle
    brings it back within 1e-9 (scaled); its most unstable mode grows
    (|mu| > 1), and a kick of 1e-4 along it grows each of 3 cycles by mu
    within 1 %."""
    cycle_map = CycleMap(MapSettings(project_path("cases", "bodyWingDrone"),
                                     ["hover"], None, str(tmp_path), 2))
    cycle_map.prepare()
    result = floquet.analyse(cycle_map, 1e-5)
    assert result.mismatch < 1e-9, "variants/hover is not a periodic" \
        " flight of the case's dictionary: trim it again (docs/trim.md)"
    mu = result.modes[0].multiplier
    assert abs(mu) > 1
    ratios, _ = floquet.kick(cycle_map, result, 1e-4, 3)
    assert np.max(abs(ratios - mu))/abs(mu) < 0.01


def test_flight_modes_identify_a_known_map():
    """Cycle ends of x_k+1 = A x_k + b (2 states, a growing oscillation
    mu = 1.08 exp(+-0.2i)): both identifications give mu within 1e-9; the
    modal fit with A's modes is exact (1e-12), with other modes not."""
    mu = 1.08*np.exp(0.2j)
    A = np.array([[mu.real, -mu.imag], [mu.imag, mu.real]])
    A = np.array([[1.0, 0.0], [0.5, 2.0]]) @ A @ np.linalg.inv(
        np.array([[1.0, 0.0], [0.5, 2.0]]))
    x = [np.array([0.01, 0.0])]
    for _ in range(20):
        x.append(A @ x[-1] + np.array([0.002, -0.001]))
    states = np.array(x)
    found = flight_modes.identify(states, [1, 3], 0)
    for method in found.values():
        for d in method.values():
            assert abs(complex(*d["multiplier"]) - mu) < 1e-9
            assert abs(d["period_cycles"] - 2*math.pi/0.2) < 1e-6
    true_mu, true_V = np.linalg.eig(A)
    fit = flight_modes.modal_fit(states, true_mu, true_V, np.ones(2))
    assert np.max(abs(fit - states)) < 1e-12
    wrong = flight_modes.modal_fit(states, np.array([1.07, 0.9]),
                                   np.eye(2), np.ones(2))
    assert np.max(abs(wrong - states)) > 1e-3
