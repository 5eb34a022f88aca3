# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam.plots.drone, the plots of the three drones: what they compute (the
reference values, the wing's coefficients at the load times, the cycle
means, the prescribed joints' error, the downstroke) and the figures of
each drone, on runs made here with the cases' dictionaries."""

import math
import os

import h5py
import numpy as np
import pytest

from flapfoam.errors import FlapFoamError
from flapfoam.io import run_series
from flapfoam.io.foam_dict import multibody_coeffs
from flapfoam.paths import project_dir
from flapfoam.plots import drone

F = 20.0                    # the drones' flapping frequency [Hz]
CASES = {"singleWing": ("singleWingDrone", 4, ("wing",)),
         "bodyWing": ("bodyWingDrone", 5, ("body", "wing")),
         "twoWing": ("twoWingDrone", 10, ("body", "leftWing", "rightWing"))}


def dictionary(name):
    return os.path.join(project_dir(), "cases", CASES[name][0], "constant",
                        "dynamicMeshDict.eABA")


def make_run(folder, name, cycles=2, steps=400):
    """A run of the drone name: its dictionary, and flight data whose
    prescribed joints follow the analytic motion exactly, heave and surge
    z = t, x = -t, each body's force (1, 0, 2 + sin 2 pi f t) N, its
    coefficients C_xI = 1, C_zI = 2 + sin, C_m = 0.5."""
    n_q, bodies = CASES[name][1:]
    (folder / "constant").mkdir(parents=True)
    (folder / "constant" / "dynamicMeshDict").write_text(
        open(dictionary(name)).read())
    t = np.linspace(0, cycles/F, steps + 1)
    q, q_dot = np.zeros((len(t), n_q)), np.zeros((len(t), n_q))
    q[:, 0], q[:, 1], q_dot[:, 0], q_dot[:, 1] = t, -t, 1, -1
    for qi, ev in drone.wang_joints(multibody_coeffs(
            dictionary(name))).items():
        q[:, qi], q_dot[:, qi], _ = ev(t)
    h5 = folder / "postProcessing" / "flightData" / "0"
    h5.mkdir(parents=True)
    wave = 2 + np.sin(2*math.pi*F*t)
    with h5py.File(h5 / "flightData.h5", "w") as f:
        f["time"], f["joints/q"], f["joints/qDot"] = t, q, q_dot
        f["joints/qDdot"] = 0*q
        for b in bodies:
            f["bodies/%s/position" % b] = np.column_stack([-t, 0*t, t])
            f["bodies/%s/velocity" % b] = np.column_stack([-1 + 0*t, 0*t,
                                                           1 + 0*t])
            f["bodies/%s/force" % b] = np.column_stack([1 + 0*t, 0*t, wave])
            f["bodies/%s/moment" % b] = np.zeros((len(t), 3))
            f["coefficients/%s" % b] = np.column_stack(
                [1 + 0*t, wave, 0.5 + 0*t])
    return str(folder)


def a_run(tmp_path, name):
    case = make_run(tmp_path / name, name)
    coeffs = multibody_coeffs(os.path.join(case, "constant",
                                           "dynamicMeshDict"))
    return drone.read_run(case, coeffs)


def test_reference_values_of_the_cases():
    # U_ref = 4 f A_phi R2 = 4.783 m/s (A_phi 75 deg, R2 45.67 mm), the
    # flapping joint 2 of SW and 3 of BW
    for name, flapping in (("singleWing", 2), ("bodyWing", 3)):
        ref = drone.reference_values(multibody_coeffs(dictionary(name)))
        assert ref.Uref == pytest.approx(4.783, abs=5e-4)
        assert ref.qref == pytest.approx(0.5*1.2*7.5e-4*ref.Uref**2,
                                         rel=1e-12)
        assert ref.f == F and ref.flapping == flapping
        assert sorted(ref.joints) == [flapping, flapping + 1]


def test_wing_coefficients_at_the_load_times(tmp_path):
    run = a_run(tmp_path, "singleWing")
    t, cx, cz = drone.wing_coefficients(run.series, run.ref.qref)
    # the load of the row of t_k, plotted at t_{k-1}
    assert np.array_equal(t, run.t[:-1])
    assert cx == pytest.approx(1/run.ref.qref, rel=1e-14)
    assert cz == pytest.approx((2 + np.sin(2*math.pi*F*run.t[1:]))
                               /run.ref.qref, rel=1e-14)


def test_cycle_means_of_a_sine_about_two(tmp_path):
    run = a_run(tmp_path, "bodyWing")
    c = run.series.bodies["wing"].coefficients[1:]
    cycles, overall = drone.cycle_means(run, (c[:, 0], c[:, 1]),
                                        drone.body_centre(run)[:2])
    # uniform steps over whole periods: the sine's mean is 0 to round-off;
    # x = -t, z = t at each cycle's end
    assert [k for k, *_ in cycles] == [1, 2]
    for k, cx, cz, x, z in cycles:
        assert (cx, cz) == pytest.approx((1, 2), abs=1e-12)
        assert (x, z) == pytest.approx((-k/F, k/F), abs=1e-15)
    assert overall == pytest.approx((1, 2, 2), abs=1e-12)
    # half a cycle: no whole cycle
    run.series.time = run.series.time/4
    assert drone.cycle_means(run, (c[:, 0], c[:, 1]),
                             drone.body_centre(run)[:2]) == ([], None)


def test_the_range_clipped_for_spikes_not_for_a_quiet_body():
    t = np.linspace(0, 1, 201)
    wing = (np.cos(2*math.pi*t), 2 + np.sin(2*math.pi*t))
    body = (0*t, 0*t)
    # a body without load beside the wing: nothing clipped
    assert drone.clip_range({"wing": wing, "body": body}) is None
    # the impulsive start: one step of 1e3 on the wing; the range shown
    # holds every other value (-1 to 3) and its median +- 10 scaled
    # absolute deviations (median 1, deviation 1: about -14 to 16), not
    # the spike
    spiked = (wing[0], wing[1].copy())
    spiked[1][1] = 1e3
    lo, hi = drone.clip_range({"wing": spiked, "body": body})
    assert -20 < lo < -1 and 3 < hi < 20


def test_prescribed_joints_error_over_the_amplitude(tmp_path):
    run = a_run(tmp_path, "singleWing")
    out = str(tmp_path / "plots")
    os.makedirs(out)
    assert drone.prescribed_joints(run, out) < 1e-15
    # 1e-3 rad off on the pitching joint (amplitude 45 deg)
    run.series.q[7, 3] += 1e-3
    assert drone.prescribed_joints(run, out) == \
        pytest.approx(1e-3/(math.pi/4), rel=1e-9)


def test_downstroke_is_the_flapping_joints_rate(tmp_path):
    for name, qi in (("singleWing", 2), ("bodyWing", 3)):
        run = a_run(tmp_path, name)
        rate = drone.downstroke(run)
        assert np.array_equal(rate, run.series.q_dot[:-1, qi])
        # phi decreases for half of each cycle
        assert np.mean(rate < 0) == pytest.approx(0.5, abs=0.01)


def test_each_drone_its_figures_and_numbers(tmp_path, capsys):
    common = ["trajectory", "forceCoefficients", "prescribedJoints"]
    for name, extra in (("singleWing", []),
                        ("bodyWing", ["bodyPitch", "wingPitchingMoment"]),
                        ("twoWing", ["attitude"])):
        case = make_run(tmp_path / name, name)
        # the drone found from the dictionary: a body named leftWing, body
        assert drone.main(["-case", case]) == 0
        out = capsys.readouterr().out
        pngs = sorted(os.listdir(os.path.join(case, "plots")))
        assert pngs == sorted(p + ".png" for p in common + extra)
        assert "max |q - analytic|/amplitude = 0\n" in out
        assert "final x = -0.1 m, z = 0.1 m, xDot = -1, zDot = 1 m/s" in out
        assert "400 rows after the first (the written steps), t = 0 ... 0.1 s"\
            " (2 cycles)" in out


def test_the_two_wing_drones_attitude(tmp_path, capsys):
    case = make_run(tmp_path / "tw", "twoWing")
    assert drone.main(["-case", case, "-o", str(tmp_path / "p")]) == 0
    # q_1 = -t is the two-wing drone's y; yaw, pitch, roll follow no motion
    assert "final yaw 0, pitch 0, roll 0 deg, y -0.1 m" in \
        capsys.readouterr().out


def test_a_body_wing_run_without_its_coefficients_writes_nothing(tmp_path):
    case = make_run(tmp_path / "bw", "bodyWing")
    s = run_series.read(case)
    os.remove(s.source)
    write = tmp_path / "bw" / "postProcessing" / "eABAMeshMotion" / "0"
    write.mkdir(parents=True)
    columns, rows = s.joints_table()
    np.savetxt(write / "joints.dat", rows, header=" ".join(columns),
               comments="# ")
    with pytest.raises(FlapFoamError, match="no coefficients/wing"):
        drone.main(["-case", case, "-drone", "bodyWing"])
    assert not os.path.exists(os.path.join(case, "plots"))
