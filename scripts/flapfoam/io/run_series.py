# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
A run's time series, read in one place into one dataclass (RunSeries):
time; q, qDot, qDdot of every joint; tau and power of the prescribed
joints; each body's centre of mass position, its velocity, the angular
velocity, the orientation, the fluid force and moment and the
coefficients; the run's attributes.

    read(case)              the run's flight data
                            (postProcessing/flightData/<start>/flightData.h5,
                            flapfoam.io.flight_data: restarts append to it),
                            or, only for a run without one, its tables
                            joints.dat and bodies.dat of
                            postProcessing/eABAMeshMotion/<start> (else
                            rigidBodySimulate's)
    read(case, tables=NAME) the tables of postProcessing/NAME/<start>,
                            flight data or not (a check of those files)

The tables of the start folders of a run and its restarts are joined in
time order (flapfoam.io.tables.joined_table): a restart's joints.dat
replaces the earlier rows from its start time on; bodies.dat keeps the
earlier row at a start (its load is that of the step that ended there).
Rows that joints.dat has and bodies.dat not yet (a killed run) are
dropped, as load() drops a half-written row of the flight data.  The
tables hold the position, force and moment of the bodies (12 significant
digits from eABAMeshMotion, 15 from rigidBodySimulate); what they lack is
None.  The loads of the row of time t_k are those of the step to t_k,
computed from the flow at t_{k-1}.  numpy; h5py for the flight data.
"""

import os
from dataclasses import dataclass, field

import numpy as np

from flapfoam.errors import FlapFoamError
from flapfoam.io import flight_data
from flapfoam.io.tables import joined_table, start_folders

# the folders whose tables read() takes where a run has no flight data
TABLE_FOLDERS = ("eABAMeshMotion", "rigidBodySimulate")

# (joints.dat column prefix and flight data dataset of joints/, field)
JOINT_SERIES = (("q", "q"), ("qDot", "q_dot"), ("qDdot", "q_ddot"))
PRESCRIBED_SERIES = (("tau", "tau"), ("power", "power"))

# flight data dataset of bodies/<body>/: field of Body
BODY_SERIES = {"position": "position", "velocity": "velocity",
               "angularVelocity": "angular_velocity",
               "orientation": "orientation", "force": "force",
               "moment": "moment"}

# bodies.dat column <body>:<letter><x|y|z>: field of Body
BODY_COLUMNS = {"c": "position", "F": "force", "M": "moment"}


@dataclass
class Body:
    """One body's rows, global frame (None: not in the source): the centre
    of mass position and velocity, the angular velocity, the orientation
    (body to global, row-major: 9 columns), the fluid force and moment
    (bodies.dat: about the body's centre of mass; the flight data: about
    the centre of mass of its coefficients' momentAbout body, e.g. the
    body-wing drone's wing about the body's), and C_xI, C_zI, C_m (flight
    data only)."""
    position: np.ndarray = None
    velocity: np.ndarray = None
    angular_velocity: np.ndarray = None
    orientation: np.ndarray = None
    force: np.ndarray = None
    moment: np.ndarray = None
    coefficients: np.ndarray = None


@dataclass
class RunSeries:
    """A run's rows: time (rows); q, q_dot, q_ddot (rows x joints);
    tau, power (rows x prescribed joints, the q index of each column in
    prescribed); bodies ({name: Body}); the flight data's attributes and
    its other datasets (other: {name: (columns, rows)}, e.g. timers,
    control); the file or folder read (source) and the start times of
    the run and its restarts (starts: its table folders')."""
    time: np.ndarray
    q: np.ndarray = None
    q_dot: np.ndarray = None
    q_ddot: np.ndarray = None
    tau: np.ndarray = None
    power: np.ndarray = None
    prescribed: list = field(default_factory=list)
    bodies: dict = field(default_factory=dict)
    attrs: dict = field(default_factory=dict)
    other: dict = field(default_factory=dict)
    source: str = ""
    starts: list = field(default_factory=list)

    @property
    def from_flight_data(self):
        return self.source.endswith(".h5")

    def joints_table(self):
        """(columns, rows) as joints.dat has them: time, then q_i qDot_i
        qDdot_i of each joint, then tau_i power_i of each prescribed
        one (the series the run has)."""
        columns, rows = ["time"], [self.time[:, None]]
        present = [(name, getattr(self, f)) for name, f in JOINT_SERIES
                   if getattr(self, f) is not None]
        for i in range(present[0][1].shape[1] if present else 0):
            for name, v in present:
                columns.append("%s_%d" % (name, i))
                rows.append(v[:, i:i + 1])
        for k, qi in enumerate(self.prescribed):
            for name, f in PRESCRIBED_SERIES:
                if getattr(self, f) is not None:
                    columns.append("%s_%d" % (name, qi))
                    rows.append(getattr(self, f)[:, k:k + 1])
        return columns, np.hstack(rows)

    def arrays(self):
        """{dataset: rows} named as in the flight data (time, joints/q,
        bodies/wing/force, coefficients/wing, timers, ...): the series
        the run has."""
        out = {"time": self.time}
        for name, f in JOINT_SERIES + PRESCRIBED_SERIES:
            if getattr(self, f) is not None:
                out["joints/" + name] = getattr(self, f)
        for b, body in self.bodies.items():
            for name, f in BODY_SERIES.items():
                if getattr(body, f) is not None:
                    out["bodies/%s/%s" % (b, name)] = getattr(body, f)
            if body.coefficients is not None:
                out["coefficients/" + b] = body.coefficients
        out.update({k: v for k, (_, v) in self.other.items()})
        return out


def table_base(case, tables):
    return os.path.join(case, "postProcessing", tables)


def table_folder(case):
    """The first of TABLE_FOLDERS that holds a start folder, or None."""
    return next((t for t in TABLE_FOLDERS
                 if start_folders(table_base(case, t))), None)


def read(case, tables=None):
    """The run's RunSeries: its flight data, else the tables of the first
    of TABLE_FOLDERS it has; with tables, those of
    postProcessing/<tables>."""
    if tables is not None:
        return from_tables(case, tables)
    path = flight_data.find(case)
    if path is not None:
        return from_flight_data(case, path)
    return from_tables(case, table_folder(case) or TABLE_FOLDERS[0],
                       " and no postProcessing/flightData/<time>/"
                       "flightData.h5")


def from_flight_data(case, path):
    """The RunSeries of the run's flightData.h5 (path)."""
    try:
        attrs, data, columns = flight_data.load(case, with_columns=True)
    except (OSError, KeyError) as e:
        raise FlapFoamError("%s: cannot read: %s" % (path, e))
    if "time" not in data:
        raise FlapFoamError("%s: no time dataset" % path)
    s = RunSeries(time=data.pop("time"), attrs=attrs, source=path)
    for name, f in JOINT_SERIES + PRESCRIBED_SERIES:
        setattr(s, f, data.pop("joints/" + name, None))
    s.prescribed = [int(c.split("_")[1])
                    for c in columns.get("joints/tau", [])]
    for name in sorted(data):
        parts = name.split("/")
        if parts[0] == "bodies" and len(parts) == 3 and \
                parts[2] in BODY_SERIES:
            setattr(s.bodies.setdefault(parts[1], Body()),
                    BODY_SERIES[parts[2]], data.pop(name))
        elif parts[0] == "coefficients" and len(parts) == 2:
            s.bodies.setdefault(parts[1], Body()).coefficients = \
                data.pop(name)
    s.other = {k: (columns.get(k, []), v) for k, v in data.items()}
    tables = table_folder(case)
    s.starts = [t for t, _ in start_folders(table_base(case, tables))] \
        if tables else []
    return s


def from_tables(case, tables, missing=""):
    """The RunSeries of the joints.dat and bodies.dat of
    postProcessing/<tables>/<start> (missing: what else the error says
    the run lacks)."""
    base = table_base(case, tables)
    jcols, J = joined_table(base, "joints.dat", keep_earlier_at_start=False)
    bcols, B = joined_table(base, "bodies.dat", keep_earlier_at_start=True)
    if jcols is None and bcols is None:
        raise FlapFoamError("no %s/<time>/joints.dat or %s/<time>/bodies.dat"
                            "%s" % (base, base, missing))
    if jcols is not None and bcols is not None:
        n = min(len(J), len(B))
        J, B = J[:n], B[:n]
        eps = 1e-9*np.abs(J[:, 0]) + 1e-15
        if np.any(np.abs(J[:, 0] - B[:, 0]) > eps):
            raise FlapFoamError("%s: joints.dat and bodies.dat have rows at"
                                " other times" % base)
    s = RunSeries(time=(J if J is not None else B)[:, 0], source=base,
                  starts=[t for t, _ in start_folders(base)])
    if jcols is not None:
        joint_columns(s, jcols, J, base)
    if bcols is not None:
        s.bodies = body_columns(bcols, B, base)
    return s


def joint_columns(s, columns, rows, where):
    """s's joint series from joints.dat's columns and rows."""
    index = {c: i for i, c in enumerate(columns)}
    known = {"time"}
    nq = sum(1 for c in columns if c.startswith("q_"))
    for name, f in JOINT_SERIES:
        names = ["%s_%d" % (name, i) for i in range(nq)]
        if all(c in index for c in names) and nq:
            setattr(s, f, rows[:, [index[c] for c in names]])
            known.update(names)
    s.prescribed = [int(c[4:]) for c in columns if c.startswith("tau_")]
    for name, f in PRESCRIBED_SERIES:
        names = ["%s_%d" % (name, i) for i in s.prescribed]
        if all(c in index for c in names) and names:
            setattr(s, f, rows[:, [index[c] for c in names]])
            known.update(names)
    unknown = [c for c in columns if c not in known]
    if unknown:
        raise FlapFoamError("%s/<time>/joints.dat: columns %s: not allowed "
                            "(time, then q_i qDot_i qDdot_i of each joint "
                            "i = 0, 1, ..., tau_i power_i of each "
                            "prescribed one)" % (where, " ".join(unknown)))


def body_columns(columns, rows, where):
    """{body: Body} of bodies.dat's columns (<body>:cx, ..., :Fx, ...,
    :Mx, ...) and rows."""
    index = {c: i for i, c in enumerate(columns)}
    bodies = {}
    for c in columns[1:]:
        body, _, kind = c.partition(":")
        if kind[:1] not in BODY_COLUMNS or kind[1:] not in ("x", "y", "z"):
            raise FlapFoamError("%s/<time>/bodies.dat: column %s: not "
                                "allowed (<body>:cx|cy|cz|Fx|Fy|Fz|Mx|My|Mz)"
                                % (where, c))
        names = ["%s:%s%s" % (body, kind[0], x) for x in "xyz"]
        if not all(n in index for n in names):
            raise FlapFoamError("%s/<time>/bodies.dat: %s without all of %s"
                                % (where, c, " ".join(names)))
        setattr(bodies.setdefault(body, Body()), BODY_COLUMNS[kind[0]],
                rows[:, [index[n] for n in names]])
    return bodies
