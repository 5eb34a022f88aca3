# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
flapfoam.studies.trim on a closed-form model: a body in x-z with a
flapping thrust k a^2 (1 - cos w t) along its axis, tilted by the pitch
theta, linear drag d on each velocity, a pitching moment k a^2 (1 - cos w
t) b from the stroke offset b and pitch damping c.  Its periodic flights
are known: k a^2 = sqrt((g + d V)^2 + (d U)^2), tan theta = d U/(g + d V),
b = 0, and the start velocities U, V minus the lag of the first harmonic.
The trim (Newton with its finite-difference Jacobian, the same Problem as
on a drone case) must find them; a target beyond the amplitude's range
stops with the reachable range; the trimDict and its variables are
checked.
"""

import math
import re
import shutil

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from flapfoam.studies import trim
from flapfoam.paths import project_path
from flapfoam.studies.cycle_map import (CycleMap, Flight, MapSettings,
                                        StateLayout, check_variables,
                                        cycle_mean_loads)
from flapfoam.studies.qs_case import Joint, StudyError

G, K, D, C, I = 9.81, 20.0, 0.8, 3.0, 0.5
PERIOD = 0.05
OMEGA = 2*math.pi/PERIOD


class ClosedForm(CycleMap):
    """The model as a cycle map: the joints of the body-wing drone (heave
    Pz, surge Px, pitch Ry), so the state is (q_2, qDot_0, qDot_1,
    qDot_2); the variables flapping.amplitude a, flapping.offset b."""

    def __init__(self, values=(1.0, 0.05)):
        self.settings = MapSettings("", np=1)
        self.period = PERIOD
        self.delta_t = PERIOD/100
        self.layout = StateLayout([Joint(0, "heave", "Pz"),
                                   Joint(1, "surge", "Px"),
                                   Joint(2, "body", "Ry")], PERIOD, -G)
        self.variables = ["flapping.amplitude", "flapping.offset"]
        self.values = np.array(values)
        self.coeffs = {}        # no dictionary: no aerodynamics entry

    def initial_state(self):
        return np.zeros(4)

    def run(self, values, x0, cycles=1, flight_data=False):
        a, b = values

        def rhs(t, y):
            theta, w, u, q = y[:4]
            f = K*a*a*(1 - math.cos(OMEGA*t))
            return [q, f*math.cos(theta) - G - D*w, f*math.sin(theta) - D*u,
                    (f*b - C*q)/I, w, u]

        ts = np.arange(cycles + 1)*PERIOD
        y = solve_ivp(rhs, (0, ts[-1]), list(x0) + [0, 0], t_eval=ts,
                      method="DOP853", rtol=1e-12, atol=1e-14).y.T
        # positions in the order of the free translations: Pz, Px
        return Flight(y[:, :4], y[:, 4:], 0.0, "")


def exact(climb, forward):
    """(a, b, state) of the periodic flight of the mean velocity."""
    vertical, horizontal = G + D*climb, D*forward
    f = math.hypot(vertical, horizontal)
    theta = math.atan2(horizontal, vertical)
    lag = f*D/(D*D + OMEGA*OMEGA)
    return (math.sqrt(f/K), 0.0,
            np.array([theta, climb - lag*math.cos(theta),
                      forward - lag*math.sin(theta), 0.0]))


RANGES = {"flapping.amplitude": (0.3, 1.5), "flapping.offset": (-0.4, 0.4)}


def solved(target, ranges=RANGES):
    problem = trim.Problem(ClosedForm(), ranges, target)
    settings = trim.TrimSettings(None, target, tolerance=1e-10)
    return problem, trim.Newton(problem, settings).solve(problem.z0)


@pytest.mark.parametrize("climb,forward", [(0.0, 0.0), (0.3, 0.0),
                                           (0.0, 1.5)])
def test_trim_finds_the_closed_form_flight(climb, forward):
    """Hover, a climb at 0.3 m/s and forward flight at 1.5 m/s: the
    amplitude, the offset and the start state within 1e-8 of the closed
    form, the residual below 1e-10, in a few iterations."""
    problem, history = solved({"z": climb, "x": forward})
    a, b, x = exact(climb, forward)
    values, x0, _ = problem.split(history[-1].z)
    assert abs(values[0] - a) < 1e-8
    assert abs(values[1] - b) < 1e-8
    assert np.max(abs(x0 - x)) < 1e-8
    assert np.max(abs(history[-1].r)) < 1e-10
    assert len(history) - 1 <= 8


def test_out_of_reach_names_the_reachable_range():
    """A climb of 50 m/s needs an amplitude above the range's 1.5: the
    trim stops naming flapping.amplitude and the climb rates at the
    range's ends, (K a^2 - G)/D within 1e-4 (printed to 6 digits)."""
    problem = trim.Problem(ClosedForm(), RANGES, {"z": 50.0})
    settings = trim.TrimSettings(None, {"z": 50.0}, tolerance=1e-10)
    with pytest.raises(trim.BoundError) as error:
        trim.Newton(problem, settings).solve(problem.z0)
    message = trim.reachable(problem, settings, error.value)
    assert "flapping.amplitude" in message and "u_z" in message
    found = [float(v) for v in re.findall(r"([-\d.e+]+) m/s at", message)]
    for v, a in zip(found, RANGES["flapping.amplitude"]):
        assert abs(v - (K*a*a - G)/D) < 1e-4*max(1, abs(v))
    assert len(found) == 2


def test_variant_lines_hold_the_trim():
    """The variant's lines set the variables and q, qDot (nDoF values,
    the free translations 0) to the trimmed numbers, every digit."""
    problem, history = solved({})
    result = trim.TrimResult(problem, history, {"z": 1.0, "x": 0.0})
    settings = trim.TrimSettings(MapSettings("", []))
    lines = trim.variant_lines(result, settings, ["header"])
    assert lines[0] == "# header"
    values, x0, _ = problem.split(result.z)
    amplitude = [line for line in lines if "flapping/amplitude" in line]
    assert float(amplitude[0].split()[-1]) == values[0]
    q = [line for line in lines if line.split()[1].endswith("/q")][0]
    assert [float(v) for v in q.split("(")[1].rstrip(")").split()] == \
        [0.0, 0.0, x0[0]]
    s = result.summary()
    assert s["trim_residual_state"] < 1e-10
    assert s["trim_residual_force_over_weight"] == 0.0


def test_trim_dict_is_checked(tmp_path):
    """An unknown entry, a range without min < max and an unknown
    variable are refused, naming what is allowed."""
    path = tmp_path / "trimDict"
    path.write_text("variables { flapping.amplitude (1 1.5); }\n"
                    "tolerance 1e-8;\n")
    with pytest.raises(StudyError, match="unknown entry 'tolerance'"
                       r" \(allowed: variables\)"):
        trim.read_trim_dict(str(path))
    path.write_text("variables { flapping.amplitude (1.5 1); }\n")
    with pytest.raises(StudyError, match="min < max"):
        trim.read_trim_dict(str(path))
    path.write_text("variables { flapping.amplitude (1 1.5);"
                    " stroke.offset (-0.3 0.3); }\n")
    assert trim.read_trim_dict(str(path)) == {
        "flapping.amplitude": (1.0, 1.5), "stroke.offset": (-0.3, 0.3)}
    coeffs = {"imposedMotion": {
        "flapping": {"type": ["wang"], "amplitude": ["1.3"]},
        "stroke": {"type": ["harmonic"], "amplitude": ["0"]}}}
    assert set(check_variables(coeffs, ["stroke.offset"])) == \
        {"flapping", "stroke"}
    with pytest.raises(StudyError, match="flapping.frequency': not allowed"
                       r" .*allowed: flapping.amplitude flapping.offset"
                       " flapping.phase flapping.K stroke.amplitude"
                       " stroke.offset stroke.phase"):
        check_variables(coeffs, ["flapping.frequency"])
    # linked: one value for mirrored entries, each member checked
    path.write_text("variables { flapping.amplitude+-stroke.amplitude"
                    " (1 1.5); }\n")
    assert trim.read_trim_dict(str(path)) == {
        "flapping.amplitude+-stroke.amplitude": (1.0, 1.5)}
    assert set(check_variables(
        coeffs, ["flapping.amplitude+-stroke.amplitude"])) == \
        {"flapping", "stroke"}
    with pytest.raises(StudyError, match="'stroke.frequency': not allowed"):
        check_variables(coeffs, ["flapping.amplitude+-stroke.frequency"])


@pytest.mark.skipif(shutil.which("rigidBodySimulate") is None,
                    reason="needs flapFoam's etc/bashrc (rigidBodySimulate)")
def test_two_wing_hover_mean_lift_is_the_weight(tmp_path):
    """The two-wing drone's hover (variants/hover, trimmed at deltaT
    1e-4): over one cycle the wings' mean force is the weight within
    1e-5 (measured 2.2e-6; sampled every 25th step, as the case writes
    its flight data, the mean read 1.0002) and nothing sideways."""
    cycle_map = CycleMap(MapSettings(project_path("cases", "twoWingDrone"),
                                     ["hover"], 1e-4, str(tmp_path), 1))
    cycle_map.prepare()
    flight = cycle_map.run(cycle_map.values, cycle_map.initial_state(), 1,
                           flight_data=True)
    loads = cycle_mean_loads(flight.folder, cycle_map.layout,
                             cycle_map.weight)
    assert abs(loads["z"] - 1) < 1e-5
    assert abs(loads["x"]) < 1e-6 and abs(loads["y"]) < 1e-12
