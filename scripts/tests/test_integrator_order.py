# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam.studies.integrator_order: the systems' references and the verdicts
(the runs themselves: applications/test/integratorOrder/Alltest)."""

import math

import numpy as np
import pytest

from flapfoam.studies import integrator_order as io
def combination(errors, system="doublePendulum"):
    return io.Combination(io.SYSTEMS[system], "Newmark", "1", errors)


def test_second_order_errors_pass():
    c = combination((1.6e-5, 4e-6, 1e-6))
    assert c.orders() == pytest.approx([2.0, 2.0])
    assert c.failures() == []
    assert c.line().startswith("PASS doublePendulum Newmark nIter 1")


def test_first_order_errors_fail_with_the_order():
    c = combination((8e-6, 4e-6, 2e-6))
    assert c.failures() == ["order 1.00 < 1.8"]
    assert c.line().startswith("FAIL")


def test_pendulum_error_limit_at_the_largest_step():
    c = combination((4e-5, 1e-5, 2.5e-6))
    assert c.failures() == ["error 4e-05 rad > 2e-05 at deltaT 0.0001"]
    # no limit on the drone
    assert combination((4e-5, 1e-5, 2.5e-6), "singleWingDrone").failures() \
        == []


def test_round_off_errors_pass_whatever_their_ratio():
    c = combination((3e-12, 4e-12, 2e-12))
    assert c.failures() == []
    assert combination((1e-6, 0.0, 0.0)).orders()[1] == math.inf


def test_table_has_a_row_per_combination():
    text = io.table([combination((1.6e-5, 4e-6, 1e-6)),
                     combination((8e-6, 4e-6, 2e-6))])
    rows = text.splitlines()
    assert len(rows) == 4
    assert rows[2].endswith("| 2.00 | 2.00 | PASS |")
    assert rows[3].endswith("| 1.00 | 1.00 | FAIL |")


def test_pendulum_chains_read_from_the_dictionaries():
    chain, q0, q_dot0 = io.chain_of(io.SYSTEMS["doublePendulum"])
    assert list(chain.lengths) == [0.1, 0.2]
    assert list(chain.masses) == [0.5, 0.5]
    assert chain.free == [1] and chain.fixed == [0]
    assert chain.prescribed[0](0.0)[0] == pytest.approx(0.0, abs=1e-15)
    assert list(q0) == [0, 0] and list(q_dot0) == [0, 0]

    chain, q0, q_dot0 = io.chain_of(io.SYSTEMS["threeLink"])
    assert list(chain.lengths) == [0.1, 0.15, 0.1]
    assert chain.free == [0, 2]
    assert list(q0) == [0.3, 0.1, -0.4]
    # the state file's middle entries are its motion's at t = 0
    assert chain.prescribed[1](0.0)[:2] == pytest.approx(
        (q0[1], q_dot0[1]), abs=1e-12)


def test_reference_rows_at_the_write_times():
    system = io.SYSTEMS["doublePendulum"]
    times, values = io.reference(system)
    assert len(times) == 1001 and times[-1] == pytest.approx(1.0)
    assert values.shape == (1001, 2)
    # the drive: theta1 = A cos(4 pi t) - A
    A = 0.9948376736367679
    assert values[:, 0] == pytest.approx(A*np.cos(4*np.pi*times) - A,
                                         abs=1e-13)


def test_staggered_loads_are_expected_first_order():
    system = "singleWingDroneStaggered"
    assert combination((8e-6, 4e-6, 2e-6), system).failures() == []
    assert combination((1.6e-5, 4e-6, 1e-6), system).failures() \
        == ["orders 2.00 2.00, not within 0.8-1.2"]
