# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam.studies.gain_sweep's linked gains: one grid value for several
controller entries (the mirrored loops of two wings), negated after -."""

import math

import pytest

from flapfoam.studies import gain_sweep, qs_case
from flapfoam.studies.qs_sweep import SweepError, parse_grid


def a_template(names=(), text=None):
    t = object.__new__(gain_sweep.Template)
    t.bounds = {n: (-math.inf, math.inf)
                for n in ("leftOffset.yaw.Kp", "rightOffset.yaw.Kp",
                          "leftOffset.x.Kp", "rightOffset.x.Kp")}
    t.names, t.text = list(names), text
    return t


def test_linked_names_and_signs():
    assert qs_case.linked("leftOffset.x.Kp+-rightOffset.x.Kp") == \
        [("leftOffset.x.Kp", 1), ("rightOffset.x.Kp", -1)]
    assert qs_case.linked("leftOffset.yaw.Kp") == \
        [("leftOffset.yaw.Kp", 1)]


def test_a_linked_group_is_allowed_when_each_name_is():
    text = "leftOffset.yaw.Kp+rightOffset.yaw.Kp=0:4:3 leftOffset.x.Kp=-1"
    grid = parse_grid(text, a_template().allowed(text))
    assert grid["leftOffset.yaw.Kp+rightOffset.yaw.Kp"] == [0, 2, 4]
    bad = "leftOffset.yaw.Kp+rightOffset.yaw.Kd=1"
    with pytest.raises(SweepError, match="not allowed"):
        parse_grid(bad, a_template().allowed(bad))


def test_a_point_sets_each_linked_entry_with_its_sign(tmp_path):
    (tmp_path / "template" / "system").mkdir(parents=True)
    t = a_template(["leftOffset.x.Kp+-rightOffset.x.Kp"],
                   "left { Kp gainSweep_0; } right { Kp gainSweepNeg_0; }")
    t.folder = str(tmp_path / "template")
    t.write(str(tmp_path / "p0"), {"leftOffset.x.Kp+-rightOffset.x.Kp": 2.5})
    text = (tmp_path / "p0" / "constant" / "dynamicMeshDict").read_text()
    assert text == "left { Kp 2.5; } right { Kp -2.5; }"
