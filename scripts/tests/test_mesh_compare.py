# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam.studies.mesh_compare on two made-up runs whose cycle means are
known: RUN's loads and pitch 2 % above REF's, the same irregular
steps; the cycles both hold, and more refused."""

import math

import numpy as np
import pytest

from flapfoam.errors import FlapFoamError
from flapfoam.studies import mesh_compare
from flight_files import write_run


def made_up(case, scale, cycles):
    rng = np.random.default_rng(1)       # the same steps in both runs
    t = np.concatenate(([0], np.cumsum(rng.uniform(2e-4, 6e-4, 4000))))
    # the cycle ends are rows of both: each cycle's rows the same in both
    t = np.union1d(t[t < cycles*0.05 - 1e-6], 0.05*np.arange(cycles + 1))
    n = len(t)
    wave = np.sin(2*math.pi*20*t)
    q = np.column_stack([0*t, 0*t, scale*0.01*t])
    force = scale*np.column_stack([0.004*wave + 0.001, 0*t,
                                   0.02 + 0.01*wave])
    moment = scale*np.column_stack([0*t, 1e-5 + 1e-6*wave, 0*t])
    force[0] = moment[0] = np.nan
    return write_run(case, {"time": t, "joints/q": q,
                            "bodies/body/force": force/2,
                            "bodies/body/moment": moment/2,
                            "bodies/wing/force": force/2,
                            "bodies/wing/moment": moment/2},
                     {"joints/q": "q_0 q_1 q_2"})


def test_the_cycle_differences_in_percent(tmp_path):
    ref = mesh_compare.per_cycle(made_up(tmp_path / "a", 1.0, 3), 0.05, 2)
    run = mesh_compare.per_cycle(made_up(tmp_path / "b", 1.02, 5), 0.05, 2)
    rows = mesh_compare.compare(ref, run)
    assert len(rows["Fz_N"]) == 3           # the cycles both hold
    for q in ("Fz_N", "Fx_N", "My_Nm", "pitch_deg"):
        for k, (a, b, p) in enumerate(rows[q]):
            assert p == pytest.approx(2.0, abs=1e-9), (q, k)
    # the harmonic's mean over a cycle is 0: F_z's mean is 0.02 N
    assert rows["Fz_N"][0][0] == pytest.approx(0.02, rel=1e-4)
    assert rows["pitch_deg"][1][0] == pytest.approx(
        math.degrees(0.01*0.1), rel=1e-9)
    with pytest.raises(FlapFoamError, match="3 whole cycles in common"):
        mesh_compare.compare(ref, run, cycles=4)
