# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam.studies.grid_study: Celik's Richardson extrapolation and GCI."""

import math

import pytest

from flapfoam.studies.grid_study import Level, Richardson, richardson, table


def synthetic(h, exact=2.0, c=0.5, p=1.6):
    return exact + c*h**p


def test_exact_power_law_gives_its_order_and_limit():
    h1, h2, h3 = 1.0, 1.4, 2.1          # unequal ratios
    r = Richardson((synthetic(h1), synthetic(h2), synthetic(h3)),
                   h2/h1, h3/h2)
    assert r.p == pytest.approx(1.6, rel=1e-9)
    assert r.extrapolated == pytest.approx(2.0, rel=1e-12)
    assert not r.oscillatory
    e21 = abs(synthetic(h2) - synthetic(h1))/synthetic(h1)
    assert r.gci == pytest.approx(1.25*e21/(1.4**1.6 - 1), rel=1e-9)
    assert r.error(synthetic(h1)) == pytest.approx(0.25, rel=1e-9)


def test_oscillatory_convergence_is_flagged():
    r = Richardson((1.0, 1.1, 0.8), 1.5, 1.5)
    assert r.oscillatory
    assert math.isfinite(r.p) and r.p > 0


def test_levels_out_of_order_are_refused():
    with pytest.raises(ValueError, match="coarsest first"):
        Richardson((1.0, 1.1, 1.2), 1.0, 1.5)


def test_table_of_three_levels():
    levels = []
    for name, n in (("tiny", 1000), ("coarse", 3000), ("medium", 9000)):
        lv = Level("/runs/" + name, n)
        lv.values = {k: synthetic(lv.h*10, exact=v) for k, v in
                     (("C_zI", 2.0), ("C_xI", 0.03), ("z", -5.0),
                      ("x", 4.0), ("C_M", 0.1), ("C_M_rms", 0.3))}
        levels.append(lv)
    text = table(levels)
    assert "| cells | 1000 | 3000 | 9000 |" in text
    assert richardson(levels, "z").extrapolated == pytest.approx(-5.0)
    assert "| mean C_zI | " in text and "1.60 | 2 |" in text
