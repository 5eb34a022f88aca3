# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""plot_control's metrics of a controlled quantity's error, on made-up
errors whose answers are known by hand."""

import math

import numpy as np

from flapfoam.plots.control import error_metrics


def test_metrics_of_made_up_errors():
    # e = 0.1 exp(-3 t): in a band of 0.01 from t = ln(10)/3 = 0.768 s
    t = np.linspace(0, 2, 201)
    e = 0.1*np.exp(-3*t)
    m = error_metrics(t, e, 0.01, 1.0)
    after = e[100:]
    assert m["settlingTime"] == t[77]
    assert m["inBand"] == 1
    assert abs(m["maxAbsError"] - 0.1*math.exp(-3.0)) < 1e-17
    assert abs(m["meanError"] - after.mean()) < 1e-15
    assert abs(m["rmsError"] - math.sqrt((after**2).mean())) < 1e-15
    # -e + 0.02 t^4: out of the band again at the end
    late = error_metrics(t, -e + 0.02*t**4, 0.01, 1.0)
    assert late["settlingTime"] == math.inf and late["inBand"] == 0
    # 0.001: never out
    never = error_metrics(t, 0.001 + 0*t, 0.01, 1.0)
    assert never["settlingTime"] == 0 and never["inBand"] == 1


def test_summary_keys_named_by_what_they_measure():
    from types import SimpleNamespace as NS
    from flapfoam.plots.control import summary_keys
    terms = [NS(label="height.z", quantity="position", component=2),
             NS(label="pitch.theta", quantity="orientation", component=1)]
    run = NS(name="a", terms=terms)
    rows = [{"run": "a", "quantity": "height.z", "maxAbsError": 0.002},
            {"run": "a", "quantity": "pitch.theta",
             "maxAbsError": math.pi/180},
            {"run": "b", "quantity": "height.z", "maxAbsError": 9.0}]
    keys = summary_keys(rows, run, 0.5, "cfd")
    assert keys == {"closed_loop_settle_s_cfd": 0.5,
                    "closed_loop_max_abs_dz_m_cfd": 0.002,
                    "closed_loop_max_abs_pitch_deg_cfd": 1.0}
    assert "closed_loop_max_abs_dz_m" in summary_keys(rows, run, 0.5)
