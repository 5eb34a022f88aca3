# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam.io.run_series, the one reader of a run's time series: the flight
data and the tables (joints.dat, bodies.dat) on runs made here, the
tables joined over a restart, the tables read only where a run has no
flight data, and both paths giving the same columns of one run."""

import os

import h5py
import numpy as np
import pytest

from flapfoam.errors import FlapFoamError
from flapfoam.harness import synthetic_flight_data
from flapfoam.io import run_series
from flapfoam.paths import project_dir

XYZ = "xyz"


def motion(t):
    """A made-up run of 4 joints (joint 2 prescribed) and a wing: every
    series a smooth function of t, the first row's loads NaN."""
    q = np.column_stack([np.sin((k + 1)*100*t) + k for k in range(4)])
    d = {"time": t, "joints/q": q, "joints/qDot": 2*q, "joints/qDdot": 3*q,
         "joints/tau": np.cos(50*t)[:, None],
         "joints/power": np.sin(50*t)[:, None]}
    for k, name in enumerate(("position", "velocity", "angularVelocity",
                              "force", "moment")):
        d["bodies/wing/" + name] = np.column_stack(
            [np.cos((k + 1)*(c + 1)*40*t) for c in range(3)])
    d["bodies/wing/orientation"] = np.tile(np.eye(3).reshape(9),
                                           (len(t), 1))
    d["coefficients/wing"] = d["bodies/wing/force"]/7.0
    for name in ("force", "moment"):
        d["bodies/wing/" + name][0] = np.nan
    d["timers"] = np.column_stack([t, 2*t, 3*t, 6*t])
    return d


COLUMNS = {"joints/q": ["q_%d" % i for i in range(4)],
           "joints/tau": ["tau_2"], "joints/power": ["power_2"],
           "timers": ["rbd", "overset", "pimple", "total"]}


def write_flight_data(case, d, attrs=None, longer=()):
    """case/postProcessing/flightData/0/flightData.h5 of the series d (the
    datasets in longer one half-written row longer)."""
    folder = case / "postProcessing" / "flightData" / "0"
    folder.mkdir(parents=True)
    with h5py.File(folder / "flightData.h5", "w") as f:
        for name, v in d.items():
            f[name] = np.vstack([v, v[-1:]]) if name in longer else v
            if name in COLUMNS:
                f[name].attrs["columns"] = " ".join(COLUMNS[name])
        for k, v in (attrs or {}).items():
            f.attrs[k] = v


def write_tables(folder, d, digits=12):
    """joints.dat and bodies.dat of the series d as eABAMeshMotion writes
    them (digits significant digits)."""
    folder.mkdir(parents=True, exist_ok=True)
    fmt = "%%.%dg" % digits
    q, names, cols = d["joints/q"], ["time"], [d["time"]]
    for i in range(q.shape[1]):
        for kind in ("q", "qDot", "qDdot"):
            names.append("%s_%d" % (kind, i))
            cols.append(d["joints/" + kind][:, i])
    names += ["tau_2", "power_2"]
    cols += [d["joints/tau"][:, 0], d["joints/power"][:, 0]]
    np.savetxt(folder / "joints.dat", np.column_stack(cols), fmt=fmt,
               header=" ".join(names), comments="# ")
    names, cols = ["time"], [d["time"]]
    for letter, name in (("c", "position"), ("F", "force"),
                         ("M", "moment")):
        for c in range(3):
            names.append("wing:%s%s" % (letter, XYZ[c]))
            cols.append(d["bodies/wing/" + name][:, c])
    np.savetxt(folder / "bodies.dat", np.column_stack(cols), fmt=fmt,
               header=" ".join(names), comments="# ")


def tables_folder(case, name="eABAMeshMotion", start="0"):
    return case / "postProcessing" / name / start


def test_flight_data_into_the_dataclass(tmp_path):
    d = motion(np.linspace(0, 1e-3, 11))
    # a killed run's half-written row: every dataset but time one longer
    write_flight_data(tmp_path, d, {"case": "sw", "model": "CFD"},
                      longer=[k for k in d if k != "time"])
    s = run_series.read(str(tmp_path))
    assert s.from_flight_data and s.source.endswith("0/flightData.h5")
    assert len(s.time) == 11 and s.attrs == {"case": "sw", "model": "CFD"}
    for name, f in (("q", "q"), ("qDot", "q_dot"), ("qDdot", "q_ddot"),
                    ("tau", "tau"), ("power", "power")):
        assert np.array_equal(getattr(s, f), d["joints/" + name])
    assert s.prescribed == [2]
    wing = s.bodies["wing"]
    assert np.array_equal(wing.angular_velocity,
                          d["bodies/wing/angularVelocity"])
    assert np.array_equal(wing.orientation, d["bodies/wing/orientation"])
    assert np.array_equal(wing.coefficients, d["coefficients/wing"])
    assert np.isnan(wing.force[0]).all() and np.isfinite(wing.force[1:]).all()
    assert s.other["timers"][0] == COLUMNS["timers"]
    # arrays() names every series as the file does: nothing lost or added
    assert sorted(s.arrays()) == sorted(d)
    assert all(np.array_equal(v, d[k], equal_nan=True)
               for k, v in s.arrays().items())


def test_the_synthetic_flight_data_read_as_the_generator_wrote_it(tmp_path):
    (tmp_path / "constant").mkdir()
    src = os.path.join(project_dir(), "cases", "singleWingDrone",
                       "constant", "dynamicMeshDict.eABA")
    (tmp_path / "constant" / "dynamicMeshDict").write_text(open(src).read())
    synthetic_flight_data.main([str(tmp_path), "-CL", "1.7", "-CD0", "0.25",
                                "-CD1", "2.3", "-cycles", "0.1",
                                "-dt", "1e-4"])
    s = run_series.read(str(tmp_path))
    wing = s.bodies["wing"]
    assert len(s.time) == 51 and s.q is None and list(s.bodies) == ["wing"]
    # velocity the rate of position (central differences: O(dt^2) ~ 1e-6
    # of the largest speed), the orientation a rotation (R R^T = I)
    rate = np.gradient(wing.position, s.time, axis=0)[1:-1]
    v = wing.velocity[1:-1]
    assert np.max(np.abs(rate - v)) <= 1e-3*np.max(np.abs(v))
    R = wing.orientation.reshape(-1, 3, 3)
    assert np.max(np.abs(R @ R.transpose(0, 2, 1) - np.eye(3))) < 1e-12
    assert np.isnan(wing.force[0]).all() and wing.moment is None


def test_tables_into_the_dataclass(tmp_path):
    d = motion(np.linspace(0, 1e-3, 11))
    write_tables(tables_folder(tmp_path), d, digits=17)
    s = run_series.read(str(tmp_path))
    assert not s.from_flight_data and s.starts == [0.0]
    assert s.source.endswith("eABAMeshMotion")
    for name, f in (("q", "q"), ("qDot", "q_dot"), ("qDdot", "q_ddot"),
                    ("tau", "tau"), ("power", "power")):
        assert np.array_equal(getattr(s, f), d["joints/" + name])
    wing = s.bodies["wing"]
    for name in ("position", "force", "moment"):
        assert np.array_equal(getattr(wing, name), d["bodies/wing/" + name],
                              equal_nan=True)
    assert wing.velocity is None and wing.coefficients is None
    assert s.prescribed == [2] and s.attrs == {} and s.other == {}
    # the table rebuilt column for column as the file has it
    columns, rows = s.joints_table()
    with open(tables_folder(tmp_path) / "joints.dat") as fh:
        assert columns == fh.readline().split()[1:]
    assert np.array_equal(rows, np.loadtxt(tables_folder(tmp_path)
                                           / "joints.dat"))


def test_restart_folders_joined(tmp_path):
    t = np.linspace(0, 1e-3, 11)
    first, second = motion(t), motion(t)
    for k in second:
        second[k] = second[k] + 1.0         # the restart's values differ
    # the first start ran to 1e-3, the restart starts from 5e-4 (its first
    # row at its start time): joints.dat takes the restart's row at 5e-4,
    # bodies.dat keeps the first start's (the load of the step that ended
    # there), later rows are the restart's
    write_tables(tables_folder(tmp_path), first)
    restart = {k: v[5:] for k, v in second.items()}
    restart["time"] = t[5:]
    write_tables(tables_folder(tmp_path, start="0.0005"), restart)
    s = run_series.read(str(tmp_path))
    assert s.starts == [0.0, 0.0005]
    assert s.time == pytest.approx(t, abs=1e-15)
    assert s.q[:5] == pytest.approx(first["joints/q"][:5], rel=1e-11)
    assert s.q[5:] == pytest.approx(second["joints/q"][5:], rel=1e-11)
    force = s.bodies["wing"].force
    assert force[5] == pytest.approx(first["bodies/wing/force"][5],
                                     rel=1e-11)
    assert force[6:] == pytest.approx(second["bodies/wing/force"][6:],
                                      rel=1e-11)


def test_restart_without_a_row_at_its_start_keeps_the_earlier_one(tmp_path):
    # the flightData function object's tables: a restart writes its first
    # row after its start time; the first start's row there stays
    t = np.linspace(0, 1e-3, 11)
    d = motion(t)
    write_tables(tables_folder(tmp_path), {k: v[:6] for k, v in d.items()})
    write_tables(tables_folder(tmp_path, start="0.0005"),
                 {k: v[6:] for k, v in d.items()})
    s = run_series.read(str(tmp_path))
    assert s.time == pytest.approx(t, abs=1e-15)
    assert s.q == pytest.approx(d["joints/q"], rel=1e-11)


def test_tables_only_where_the_run_has_no_flight_data(tmp_path):
    t = np.linspace(0, 1e-3, 11)
    flight, tables = motion(t), motion(t)
    tables["joints/q"] = tables["joints/q"] + 5.0
    write_flight_data(tmp_path, flight)
    write_tables(tables_folder(tmp_path), tables)
    case = str(tmp_path)
    s = run_series.read(case)
    assert s.from_flight_data
    assert np.array_equal(s.q, flight["joints/q"])
    # the tables on request, and on their own once the file is gone
    asked = run_series.read(case, tables="eABAMeshMotion")
    assert asked.q == pytest.approx(tables["joints/q"], rel=1e-11)
    os.remove(tmp_path / "postProcessing" / "flightData" / "0" /
              "flightData.h5")
    assert run_series.read(case).q == pytest.approx(tables["joints/q"],
                                                    rel=1e-11)


def test_rigid_body_simulate_tables_when_there_are_no_others(tmp_path):
    d = motion(np.linspace(0, 1e-3, 11))
    write_tables(tables_folder(tmp_path, "rigidBodySimulate"), d, 15)
    s = run_series.read(str(tmp_path))
    assert s.source.endswith("rigidBodySimulate")
    assert s.q_ddot == pytest.approx(d["joints/qDdot"], rel=1e-14)


def test_both_paths_give_the_same_columns_of_one_run(tmp_path):
    # one run writing both, the tables with 12 significant digits: every
    # column of joints.dat and bodies.dat equal to 12 digits (relative to
    # the column's largest value), the same column names
    d = motion(np.linspace(0, 1e-3, 101))
    write_flight_data(tmp_path, d)
    write_tables(tables_folder(tmp_path), d, digits=12)
    h = run_series.read(str(tmp_path))
    j = run_series.read(str(tmp_path), tables="eABAMeshMotion")
    (hc, H), (jc, J) = h.joints_table(), j.joints_table()
    assert hc == jc and H.shape == J.shape == (101, 1 + 3*4 + 2)
    scale = np.abs(H).max(axis=0)
    assert np.max(np.abs(H - J)/scale) < 1e-11
    for name in ("position", "force", "moment"):
        a = getattr(h.bodies["wing"], name)[1:]
        b = getattr(j.bodies["wing"], name)[1:]
        assert np.max(np.abs(a - b)/np.abs(a).max(axis=0)) < 1e-11
    assert set(j.arrays()) < set(h.arrays())


def test_a_run_without_either_names_what_it_looked_for(tmp_path):
    with pytest.raises(FlapFoamError, match="no .*/eABAMeshMotion/<time>/"
                       "joints.dat or .*bodies.dat and no postProcessing/"
                       "flightData"):
        run_series.read(str(tmp_path))
    folder = tables_folder(tmp_path)
    folder.mkdir(parents=True)
    (folder / "joints.dat").write_text("# time q_0 speed\n0 1 2\n")
    with pytest.raises(FlapFoamError, match="columns speed: not allowed"):
        run_series.read(str(tmp_path))
