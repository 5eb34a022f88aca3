# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The cycle map of a drone case flown by the quasi-steady (QS) model: the
free joints' state at the start of a flapping cycle and the values of
kinematic parameters (ENTRY.KEY of the case's imposedMotion entries, e.g.
flapping.amplitude) to the state after each of N cycles, by
rigidBodySimulate -bodyLoad aerodynamics in a copy of the case's QS run
folder: the full multibody dynamics, not cycle-averaged, with the same
fixed time step and cycle length for every trial.  Used by flapfoam trim
and flapfoam floquet.

The state (StateLayout): every free joint's velocity qDot, and the
position q of every free rotation; the positions of free translations (Px,
Py, Pz) are left out (the dynamics do not depend on them: a trial starts
them at 0) and give the mean velocity over a cycle instead.  Scales (the
trim's residuals and the finite-difference steps are in these units): an
angle 1 rad, an angular rate 1 rad per cycle (1/T), a velocity g T (the
velocity a body gains in a cycle from a force equal to its weight, so a
velocity mismatch over a cycle in this unit is the mean force's mismatch
over the weight).  The trial's initial state is the multibody dictionary's
q and qDot (rigidBodySimulate reads them at a fresh start); the prescribed
joints take their motions' values.
"""

import itertools
import os
import shutil
import threading
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field

import numpy as np

from flapfoam.io import run_series
from flapfoam.io.foam_dict import read_foam_dict
from flapfoam.studies import qs_case
from flapfoam.studies.qs_case import StudyError, foam_dictionary

COEFFS = "eABAMeshMotionCoeffs"

# the keys of each imposedMotion type a trim may vary (the frequency is
# not one: the cycle length stays the same for every trial)
TRIM_KEYS = {"wang": ("amplitude", "offset", "phase", "K"),
             "harmonic": ("amplitude", "offset", "phase")}

ROTATIONS = ("Rx", "Ry", "Rz")


@dataclass
class MapSettings:
    """How the case is flown: the case folder, its variants (Allrun
    -variant), the fixed time step (None: the case's), the folder of the
    trials, how many run at a time, whether to keep their folders, and
    dictionary edits after the variants' (FILE, ENTRY, VALUE: Allrun
    -set; read_edits)."""
    case: str
    variants: list = field(default_factory=list)
    delta_t: float = None
    work_dir: str = "/tmp/flapFoam-cycleMap"
    np: int = 1
    keep: bool = False
    edits: list = field(default_factory=list)

    def edit_lines(self):
        """The edits of the variants, then the edits, as (FILE, ENTRY,
        VALUE)."""
        lines = []
        for v in self.variants:
            lines += read_edits(os.path.join(self.case, "variants", v))
        return lines + list(self.edits)


def read_edits(path):
    """[(FILE, ENTRY, VALUE)] of a file of dictionary edits in the format
    of a case variant: a line "FILE ENTRY VALUE" each (VALUE the rest of
    the line), # comments."""
    if not os.path.isfile(path):
        raise StudyError("%s: no such file of edits (allowed: a case variant"
                         "'s format, FILE ENTRY VALUE a line)" % path)
    edits = []
    with open(path) as f:
        for line in f:
            words = line.split(None, 2)
            if words and not words[0].startswith("#"):
                if len(words) < 3:
                    raise StudyError("%s: '%s': not allowed (FILE ENTRY"
                                     " VALUE)" % (path, line.strip()))
                edits.append((words[0], words[1], words[2].strip()))
    return edits


@dataclass
class Flight:
    """One trial: the state at the start and at the end of each cycle
    (rows: cycles + 1), the positions of the free translations there
    (rows x translations, starting at 0), its wall time and folder."""
    states: np.ndarray
    positions: np.ndarray
    seconds: float
    folder: str


class StateLayout:
    """The state vector of the free joints (module docstring): names,
    units, scales, and where each component sits in q and qDot."""

    def __init__(self, joints, period, g):
        self.free = [j for j in joints if j.motion is None]
        for j in self.free:
            if not (j.translation or j.type in ROTATIONS):
                raise StudyError("free joint q[%d] (body %s) of type %s:"
                                 " not supported (allowed: Px Py Pz Rx Ry"
                                 " Rz)" % (j.index, j.body, j.type))
        axes = [j.type[1] for j in self.free if j.translation]
        if len(set(axes)) != len(axes):
            raise StudyError("two free translations along one axis (%s):"
                             " not supported" % " ".join(axes))
        self.n_dof = len(joints)
        self.translations = [j for j in self.free if j.translation]
        self.parts = [("q", j) for j in self.free if not j.translation] + \
            [("qDot", j) for j in self.free]
        self.velocity_scale = abs(g)*period
        self.scales = np.array([1.0 if kind == "q" else
                                self.velocity_scale if j.translation else
                                1.0/period for kind, j in self.parts])

    @property
    def names(self):
        """q_2, qDot_0, ... in state order."""
        return ["%s_%d" % (kind, j.index) for kind, j in self.parts]

    @property
    def labels(self):
        """Each component with its body, joint and unit."""
        def unit(kind, j):
            base = "m" if j.translation else "rad"
            return base if kind == "q" else base + "/s"
        return ["%s_%d (%s %s) [%s]" % (kind, j.index, j.body, j.type,
                                        unit(kind, j))
                for kind, j in self.parts]

    def from_rows(self, q, q_dot):
        """The state vectors of rows of q and qDot (rows x nDoF)."""
        return np.stack([(q if kind == "q" else q_dot)[:, j.index]
                         for kind, j in self.parts], axis=-1)

    def to_q(self, x):
        """(q, qDot) of nDoF values for state x: the free translations
        at 0, the prescribed joints 0 (their motions set them)."""
        q, q_dot = np.zeros(self.n_dof), np.zeros(self.n_dof)
        for (kind, j), v in zip(self.parts, x):
            (q if kind == "q" else q_dot)[j.index] = v
        return q, q_dot


def check_variables(coeffs, names):
    """The imposedMotion entries of the variables ENTRY.KEY (StudyError
    naming the allowed ones for an unknown entry or key)."""
    motions = {n: e for n, e in coeffs.get("imposedMotion", {}).items()
               if isinstance(e, dict)}
    allowed = ["%s.%s" % (n, k) for n, e in motions.items()
               for k in TRIM_KEYS.get(e.get("type", [""])[0], ())]
    for name, _ in itertools.chain(*(qs_case.linked(g) for g in names)):
        if name not in allowed:
            raise StudyError("trim variable '%s': not allowed (ENTRY.KEY of"
                             " an imposedMotion entry; allowed: %s; the"
                             " frequency is fixed: the cycle stays the"
                             " same)" % (name, " ".join(allowed) or "none"))
    return motions


def dictionary_value(entry, key):
    """The number of key in an imposedMotion entry (0 where an optional
    key is absent)."""
    return float(entry.get(key, ["0"])[0])


class CycleMap:
    """The case's QS run folder of one cycle (its Allrun), made once; each
    trial a copy with the variables' values and the initial state filled
    in (placeholders), run by rigidBodySimulate for N cycles, a row of
    joints.dat at each cycle end."""

    def __init__(self, settings):
        self.settings = settings
        os.makedirs(settings.work_dir, exist_ok=True)
        options = list(itertools.chain(*(("-variant", v)
                                         for v in settings.variants)))
        options += list(itertools.chain(*(("-set",) + tuple(e)
                                          for e in settings.edits)))
        if settings.delta_t is not None:
            options += ["-deltaT", repr(settings.delta_t)]
        self.folder = qs_case.set_up(os.path.abspath(settings.case),
                                     os.path.join(settings.work_dir,
                                                  "template"), options)
        self.dict = os.path.join(self.folder, "constant", "dynamicMeshDict")
        self.control_dict = os.path.join(self.folder, "system",
                                         "controlDict")
        self.coeffs = read_foam_dict(self.dict)[COEFFS]
        if "controller" in self.coeffs:
            raise StudyError("%s: the case flies a controller (it changes"
                             " the kinematics from cycle to cycle): a cycle"
                             " map needs open-loop kinematics (a variant"
                             " without a controller)" % self.dict)
        self._read_time()
        with open(os.path.join(self.folder, "log.rigidBodySimulate")) as f:
            self.layout = StateLayout(qs_case.joint_map(f.read()),
                                      self.period, self.gravity())
        self.weight = self.mass()*abs(self.gravity())
        self.variables, self.values = [], np.zeros(0)
        self.text = self.control_text = None
        self._count = itertools.count()
        self._lock = threading.Lock()

    def _read_time(self):
        self.period = float(foam_dictionary("-entry", "endTime", "-value",
                                            self.control_dict))
        self.delta_t = float(foam_dictionary("-entry", "deltaT", "-value",
                                             self.control_dict))
        self.steps = int(round(self.period/self.delta_t))
        if abs(self.steps*self.delta_t - self.period) > 1e-9*self.period:
            raise StudyError("deltaT %g: not a whole number of steps in the"
                             " cycle of %g s (allowed: T/N)" % (self.delta_t,
                                                                 self.period))

    def gravity(self):
        """The z component of g (the drones fly in x-z)."""
        g = self.coeffs.get("g", ["(", "0", "0", "0", ")"])
        return float(g[3])

    def mass(self):
        """The total mass of the tree's bodies [kg]."""
        return sum(float(b.get("mass", ["0"])[0])
                   for b in self.coeffs.get("bodies", {}).values()
                   if isinstance(b, dict))

    def aerodynamics(self):
        """{wing: {key: number}} of the aerodynamics entry's numbers (the
        coefficients a result was found with)."""
        out = {}
        for name, e in self.coeffs.get("aerodynamics", {}).items():
            if isinstance(e, dict):
                out[name] = {k: float(v[0]) for k, v in e.items()
                             if len(v) == 1 and _number(v[0])}
        return out

    def initial_state(self):
        """The state of the dictionary's q and qDot (zero where absent)."""
        q, q_dot = (np.array([float(v) for v in self.coeffs[k][1:-1]])
                    if k in self.coeffs else np.zeros(self.layout.n_dof)
                    for k in ("q", "qDot"))
        return self.layout.from_rows(q[None, :], q_dot[None, :])[0]

    def prepare(self, variables=()):
        """The variables (ENTRY.KEY, checked; linked: ENTRY.KEY+-ENTRY2.KEY2,
        one value, negated after -, qs_case.linked) and their dictionary
        values (a linked variable's first entry's); placeholders in the
        template: trimVariable_<i> (trimVariableNeg_<i>), trimState_q,
        trimState_qDot; controlDict: a row every cycle, endTime
        trimEndTime, the flight data (if any) every step.  Once, before
        the first run."""
        motions = check_variables(self.coeffs, variables)
        self.variables = list(variables)
        firsts = [qs_case.linked(v)[0][0].split(".") for v in self.variables]
        self.values = np.array([dictionary_value(motions[entry], key)
                                for entry, key in firsts])
        qs_case.set_placeholders(
            self.dict, self.variables, lambda name: "%s/imposedMotion/%s"
            % (COEFFS, name.replace(".", "/")), "trimVariable")
        for key in ("q", "qDot"):
            foam_dictionary("-entry", "%s/%s" % (COEFFS, key), "-set",
                            "trimState_" + key, self.dict)
        foam_dictionary("-entry", "writeInterval", "-set", str(self.steps),
                        self.control_dict)
        self._flight_data_every_step()
        foam_dictionary("-entry", "endTime", "-set", "trimEndTime",
                        self.control_dict)
        with open(self.dict) as f:
            self.text = f.read()
        with open(self.control_dict) as f:
            self.control_text = f.read()

    def _flight_data_every_step(self):
        """The case's flightData function object (if it has one) samples
        every step: a cycle mean over its rows is then the trapezoidal
        rule on every step (on 20 rows a cycle the wing's force aliases:
        the two-wing hover's mean lift read 1.0002 of the weight)."""
        functions = read_foam_dict(self.control_dict).get("functions", {})
        if "flightData" not in functions:
            return
        for key in ("executeInterval", "writeInterval"):
            foam_dictionary("-entry", "functions/flightData/" + key, "-set",
                            "1", self.control_dict)

    def _write(self, folder, values, x0, cycles):
        """A trial's folder: the template's system/, the dictionary with
        the values and the state."""
        shutil.rmtree(folder, ignore_errors=True)
        os.makedirs(os.path.join(folder, "constant"))
        shutil.copytree(os.path.join(self.folder, "system"),
                        os.path.join(folder, "system"))
        q, q_dot = self.layout.to_q(x0)
        text = qs_case.fill_placeholders(self.text, "trimVariable", values)
        for key, v in (("q", q), ("qDot", q_dot)):
            text = text.replace("trimState_%s;" % key, "(%s);" % " ".join(
                repr(float(a)) for a in v))
        with open(os.path.join(folder, "constant", "dynamicMeshDict"),
                  "w") as f:
            f.write(text)
        with open(os.path.join(folder, "system", "controlDict"), "w") as f:
            f.write(self.control_text.replace(
                "trimEndTime;", "%r;" % (cycles*self.period)))

    def run(self, values, x0, cycles=1, flight_data=False):
        """The Flight of cycles from state x0 with the variables' values
        (flight_data: with the case's function objects, e.g. its flight
        data; else none); StudyError if rigidBodySimulate fails."""
        with self._lock:
            folder = os.path.join(self.settings.work_dir,
                                  "trial%05d" % next(self._count))
        self._write(folder, values, x0, cycles)
        rc, seconds = qs_case.simulate(
            folder, "log.rigidBodySimulate",
            () if flight_data else ("-noFunctionObjects",))
        if rc != 0:
            raise StudyError("rigidBodySimulate failed (exit %d) with %s ="
                             " %s from the state %s: see %s/"
                             "log.rigidBodySimulate" % (
                                 rc, self.variables, list(values), list(x0),
                                 folder))
        flight = self._read(folder, cycles, seconds)
        if not (self.settings.keep or flight_data):
            shutil.rmtree(folder)
        return flight

    def _read(self, folder, cycles, seconds):
        series = run_series.read(folder, tables="rigidBodySimulate")
        ends = np.arange(cycles + 1)*self.period
        rows = [int(np.argmin(abs(series.time - t))) for t in ends]
        if len(series.time) < cycles + 1 or \
                np.max(abs(series.time[rows] - ends)) > 0.5*self.delta_t:
            raise StudyError("%s: joints.dat lacks the cycle ends %s"
                             % (folder, list(ends)))
        q, q_dot = series.q[rows], series.q_dot[rows]
        positions = q[:, [j.index for j in self.layout.translations]]
        return Flight(self.layout.from_rows(q, q_dot), positions, seconds,
                      folder)

    def run_all(self, trials, cycles=1):
        """The Flights of trials [(values, x0)], settings.np at a time."""
        with ThreadPoolExecutor(max_workers=self.settings.np) as pool:
            return list(pool.map(lambda t: self.run(t[0], t[1], cycles),
                                 trials))

    def mean_velocity(self, flight):
        """The free translations' mean velocity over each cycle [m/s]."""
        return np.diff(flight.positions, axis=0)/self.period


def _number(word):
    try:
        float(word)
        return True
    except ValueError:
        return False


def cycle_mean_loads(folder, layout, weight):
    """{axis: cycle mean of the bodies' aerodynamic force along it over
    the weight} of a one-cycle run with flight data, for the axes of the
    free translations: the mean of its equally spaced rows after t = 0
    (the row at t = 0 has no load yet; on a periodic load the row at T
    stands for it, and the mean is the trapezoidal rule's: spectrally
    accurate)."""
    series = run_series.read(folder)
    later = series.time > series.time[0]
    total = sum(b.force[later] for b in series.bodies.values()
                if b.force is not None)
    mean = np.mean(total, axis=0)
    return {j.type[1]: float(mean["xyz".index(j.type[1])])/weight
            for j in layout.translations}
