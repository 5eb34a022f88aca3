# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam.scaling.holdout on the committed 16-core sessions: each held
out from the fit, its octree runs against the model calibrated on the
other (the figures bench/scaling/results-holdout.md states), and a
single session refused."""

import pytest

from flapfoam.errors import FlapFoamError
from flapfoam.scaling import holdout
from flapfoam.scaling import validate

SECOND = "session2-round3"
FIRST = "scaling-16core"


@pytest.fixture(scope="module")
def runs():
    return validate.read_archives(validate.SESSIONS,
                                  rounds=validate.ROUNDS)


def test_second_session_held_out(runs):
    """Fitted on the first session alone (pSat 11.5): the second's 38
    octree runs within 28 % (medium scotch and hierarchical at 16 ranks,
    optimistic about the first session's slower socket), median 6 %."""
    held = holdout.hold_out(runs, SECOND)
    assert len(held.rows) == 38
    assert abs(held.calibration.p_sat - 11.5) < 0.1
    assert 0.27 < held.worst() < 0.29 and held.median() < 0.07
    worst = max(held.rows, key=lambda r: abs(r["ratio"] - 1))
    assert worst["level"] == "medium" and worst["ranks"] == 16
    assert "model within 28 % of 38 measured runs" in held.summary()


def test_first_session_held_out(runs):
    """Fitted on the second session alone (pSat 19.6): the first's 17
    octree runs within 51 % (its early coarse runs, -43 %; medium
    hierarchical np 8 -27 %), median 19 %: the model too fast there."""
    held = holdout.hold_out(runs, FIRST)
    assert len(held.rows) == 17
    assert abs(held.calibration.p_sat - 19.6) < 0.2
    assert 0.49 < held.worst() < 0.53 and 0.17 < held.median() < 0.21
    assert all(r["ratio"] < 1 for r in held.rows)


def test_one_session_refused(runs):
    with pytest.raises(FlapFoamError, match="session nope"):
        holdout.hold_out([r for r in runs if r.session == SECOND], "nope")
