# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam.checks.pimple_guard, the guard that chose the flow defaults: its
checks on made-up cycles with known answers (the margins, the smoothing,
which checks count for the verdict)."""

import numpy as np
import pytest

from flapfoam.checks import pimple_guard as pg
def cycles(cz_scale=1.0, cx_shift=0.0, z_shift=0.0, spike=0.0, cont=1.0,
           n=2001):
    """One cycle of 0.05 s: C_zI = 2 + sin, C_xI = cos (mean 0), z climbs
    1 mm over the cycle, x = 0; an optional single-step spike of C_zI."""
    t = np.linspace(0.0, 0.05, n)
    phase = 2*np.pi*t/0.05
    cz = cz_scale*(2.0 + np.sin(phase))
    cz[n//3] += spike
    return pg.Cycles(case="c", t=t, cx=np.cos(phase) + cx_shift, cz=cz,
                     x=np.zeros(n), z=1e-3*t/0.05 + z_shift, tq=t, t0=0.0,
                     t1=0.05, continuity=cont)


def by_name(checks):
    return {c.name: c for c in checks}


def test_a_run_against_itself_passes_at_zero():
    ref = cycles()
    checks = by_name(pg.guard(ref, cycles()))
    assert all(c.ok for c in checks.values())
    assert all(c.ratio == pytest.approx(0, abs=1e-12)
               for name, c in checks.items() if name != "continuity")
    assert checks["continuity"].ratio == pytest.approx(1)


def test_cycle_mean_margin_is_one_percent_of_the_larger_mean():
    ref = cycles()
    # C_zI's mean is 2, C_xI's 0: the scale is 2, 1 % of it 0.02; a C_zI
    # 0.5 % higher (mean 2.01) is half the allowed, 1.1 % higher fails
    half = by_name(pg.mean_checks(ref, cycles(cz_scale=1.005)))
    assert half["C_zI"].ratio == pytest.approx(0.5, rel=1e-6)
    over = by_name(pg.mean_checks(ref, cycles(cz_scale=1.011)))
    assert not over["C_zI"].ok
    # C_xI shifted by 0.01: half the allowed (the scale is C_zI's 2)
    assert by_name(pg.mean_checks(ref, cycles(cx_shift=0.01)))["C_xI"] \
        .ratio == pytest.approx(0.5, rel=1e-3)


def test_a_single_step_spike_is_informative_not_judged():
    ref = cycles()
    run = cycles(spike=0.5)               # 25 % of the range 2, one step
    checks = by_name(pg.guard(ref, run))
    assert checks["C_zI(t)"].ratio == pytest.approx(0.5/(0.03*2), rel=1e-6)
    assert not checks["C_zI(t)"].counts
    # averaged over 1 % of the cycle (20 steps) the spike is 1/20 as tall
    assert checks["C_zI(t) smoothed"].ok
    assert checks["C_zI(t) smoothed"].counts


def test_position_margin_is_one_percent_of_the_excursion():
    ref = cycles()
    # z's excursion is 1 mm: 5 um off is half the allowed, 20 um fails
    assert by_name(pg.position_checks(ref, cycles(z_shift=5e-6)))["z"] \
        .ratio == pytest.approx(0.5, rel=1e-6)
    assert not by_name(pg.position_checks(ref, cycles(z_shift=2e-5)))["z"].ok


def test_continuity_no_larger_than_the_reference():
    checks = by_name(pg.guard(cycles(cont=2.0), cycles(cont=2.5)))
    assert not checks["continuity"].ok
    assert checks["continuity"].ratio == pytest.approx(1.25)


def test_smoothed_is_the_window_mean_of_a_linear_function():
    t = np.linspace(0, 1, 101)
    c = 3*t + 1
    at = np.array([0.5, 0.2])
    assert pg.smoothed(t, c, at, 0.1) == pytest.approx(3*at + 1, abs=1e-12)
    # clipped at the ends: the mean over [0, 0.05]
    assert pg.smoothed(t, c, np.array([0.0]), 0.1) == \
        pytest.approx([1.075], abs=1e-12)
