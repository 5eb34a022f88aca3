# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The cycle-to-cycle modes of a flown flight (a CFD run), identified from
its states at the cycle ends, against the Floquet modes of a quasi-steady
trim (flapfoam floquet's PREFIX.json): is a CFD flight's swing of pitch
and forward speed the QS model's unstable mode?

    flapfoam flight_modes RUN -floquet PREFIX.json [-period T]
        [-from 1,2,3,5] [-pitch 2] [-speed 1] [-o PREFIX] [-summary FILE]

RUN: a run folder or a flightData.h5 (e.g. cases/bodyWingDrone/results/
ascent-20cycles/flightData.h5).  The states of the Floquet file (q_2,
qDot_0, ...) at the cycle ends t = k T (T: -period, default the Floquet
file's cycle), interpolated.  Identified from each start cycle of -from
(the first cycles hold the flow's start from rest) to the end, by least
squares:

    pitch alone   theta_k+1 = a1 theta_k + a2 theta_k-1 + c (theta: q of
                  -pitch): mu the roots of mu^2 - a1 mu - a2
    all states    x_k+1 = A x_k + b: mu the eigenvalues of A

(the constants c, b: the flight is not trimmed, its kinematics push it
steadily; A, the flight's cycle map, is in PREFIX.json, comparable with
the Floquet file's monodromy matrix).  Per identification and start, the
mu of largest |mu|: a
complex one is an oscillation of period 2 pi/|arg mu| cycles; it doubles in
ln 2/ln|mu| cycles.  Then the test of a set of modes on the flight: the
least-squares fit of every state at once, x_k = c + sum_i a_i mu_i^k v_i
(mu_i, v_i the modes' multipliers and eigenvectors; c and the a_i free;
the states weighed by the Floquet scales), with the flight's own modes (all
states, the first start) and with the QS trim's (its monodromy matrix):
the rms error of the pitch [deg] and of the speed (qDot of -speed) [m/s].
-o PREFIX: PREFIX.json, PREFIX.png (the cycle-end pitch and speed with both
fits; the multipliers of the flight, of the QS trim and of a hovering
bumblebee, Sun & Xiong 2005: period 50 wingbeats, doubling in 15.6);
-summary FILE: the key flight_modes merged in.  numpy, h5py, matplotlib.
"""

import argparse
import json
import math
import os
import shutil
import sys
import tempfile
from dataclasses import dataclass

import numpy as np

from flapfoam.errors import run_tool
from flapfoam.io import run_series
from flapfoam.studies.qs_case import StudyError, write_summary

# Sun & Xiong 2005 (J Exp Biol 208:447), hovering bumblebee: the unstable
# oscillatory mode's period and doubling time in wingbeats
BUMBLEBEE = (50.0, 15.6)


def read_series(path):
    """The RunSeries of a run folder, or of a bare flightData.h5 (read by
    the run reader through a temporary run folder that links it)."""
    if os.path.isdir(path):
        return run_series.read(path)
    if not os.path.isfile(path):
        raise StudyError("%s: no run folder or flightData.h5" % path)
    folder = tempfile.mkdtemp(prefix="flapFoam-flightModes-")
    try:
        start = os.path.join(folder, "postProcessing", "flightData", "0")
        os.makedirs(start)
        os.symlink(os.path.abspath(path),
                   os.path.join(start, "flightData.h5"))
        return run_series.read(folder)
    finally:
        shutil.rmtree(folder)


def cycle_ends(series, period, names):
    """Rows k = 0 ... of the states names (q_i, qDot_i) at t = k period,
    over the whole cycles of the run."""
    n = int(math.floor((series.time[-1] - series.time[0])/period + 1e-6))
    t = series.time[0] + period*np.arange(n + 1)
    columns = []
    for name in names:
        kind, index = name.split("_")
        values = series.q if kind == "q" else series.q_dot
        columns.append(np.interp(t, series.time, values[:, int(index)]))
    return np.column_stack(columns)


def pitch_alone(theta):
    """mu (2 roots) of theta_k+1 = a1 theta_k + a2 theta_k-1 + c."""
    A = np.column_stack([theta[1:-1], theta[:-2], np.ones(len(theta) - 2)])
    a1, a2, _ = np.linalg.lstsq(A, theta[2:], rcond=None)[0]
    return np.roots([1.0, -a1, -a2]).astype(complex)


def cycle_matrix(x):
    """A of x_k+1 = A x_k + b (rows x_k), least squares."""
    X = np.hstack([x[:-1], np.ones((len(x) - 1, 1))])
    return np.linalg.lstsq(X, x[1:], rcond=None)[0][:-1].T


def all_states(x):
    """(mu, V): the eigenvalues and eigenvectors of A of x_k+1 = A x_k +
    b (rows x_k)."""
    return np.linalg.eig(cycle_matrix(x))


def describe(mu):
    """{multiplier, modulus, period_cycles, doubling_cycles, grows} of the
    mu of largest |mu| (arg > 0 of a pair)."""
    top = complex(max(mu, key=lambda m: (abs(m), np.angle(m))))
    angle = abs(np.angle(top))
    growth = math.log(abs(top))
    return {"multiplier": [top.real, top.imag], "modulus": abs(top),
            "period_cycles": 2*math.pi/angle if angle > 1e-9 else None,
            "doubling_cycles": math.log(2)/abs(growth) if growth else None,
            "grows": bool(abs(top) > 1)}


def identify(states, starts, pitch):
    """{method: {start: describe(...)}} of the cycle-end states (pitch:
    the pitch's column)."""
    out = {"pitch alone": {}, "all states": {}}
    for s in starts:
        if not 1 <= s <= len(states) - 3*states.shape[1]:
            raise StudyError("-from %d: not allowed (1 ... %d: at least %d"
                             " cycle ends after it; the run has %d)" % (
                                 s, len(states) - 3*states.shape[1],
                                 3*states.shape[1], len(states)))
        out["pitch alone"][s] = describe(pitch_alone(states[s:, pitch]))
        A = cycle_matrix(states[s:])
        out["all states"][s] = dict(describe(np.linalg.eigvals(A)),
                                    matrix=A.tolist())
    return out


def modal_fit(states, mu, V, scales):
    """The fit x_k = c + sum_i a_i mu_i^k v_i (k = 0 ...; a complex pair's
    two a_i conjugate) of the rows states, weighed by 1/scales: the fitted
    rows."""
    k = np.arange(len(states))
    n = states.shape[1]
    columns = [np.kron(np.ones(len(k)), np.eye(n)[j]) for j in range(n)]
    for m, v in zip(mu, V.T):
        if m.imag < 0:
            continue
        p = np.outer(m**k, v).ravel()
        columns += [p.real] + ([-p.imag] if m.imag > 0 else [])
    A = np.column_stack(columns)
    w = np.tile(1.0/np.asarray(scales), len(k))
    a = np.linalg.lstsq(A*w[:, None], states.ravel()*w, rcond=None)[0]
    return (A @ a).reshape(states.shape)


@dataclass
class Comparison:
    """A flight's cycle-end states (names, scales), the identified modes,
    and the modal fits {label: (start, fitted rows)}."""
    names: list
    scales: np.ndarray
    states: np.ndarray
    found: dict
    fits: dict

    def errors(self, pitch, speed):
        """{label: (rms pitch error [deg], rms speed error [m/s])}."""
        out = {}
        for label, (s, fit) in self.fits.items():
            e = self.states[s:] - fit
            out[label] = (math.degrees(math.sqrt(np.mean(e[:, pitch]**2))),
                          math.sqrt(np.mean(e[:, speed]**2)))
        return out


def compare(states, floquet, starts, pitch):
    """The Comparison of the cycle-end states with the Floquet file's
    modes."""
    scales = np.array(floquet["floquet_state_scales"])
    found = identify(states, starts, pitch)
    s = min(starts)
    mu, V = all_states(states[s:])
    flight_label = "flight's modes (all states, from cycle %d)" % s
    qs_mu, qs_V = np.linalg.eig(np.array(floquet["floquet_monodromy"]))
    fits = {flight_label: (s, modal_fit(states[s:], mu, V, scales)),
            "QS trim's Floquet modes": (s, modal_fit(states[s:], qs_mu, qs_V,
                                                     scales))}
    return Comparison(floquet["floquet_states"], scales, states, found, fits)


def line(name, d):
    period = d["period_cycles"]
    return ("%s: mu %.4f %+.4fi, |mu| %.4f: %s, %s in %.3g cycles" % (
        name, d["multiplier"][0], d["multiplier"][1], d["modulus"],
        "period %.3g cycles" % period if period else "not oscillatory",
        "doubles" if d["grows"] else "halves", d["doubling_cycles"]))


def plot(path, comparison, columns, qs):
    """The cycle-end pitch and speed (columns) with the modal fits; the
    multipliers of the flight, the QS trim and the bumblebee."""
    from flapfoam.plots.backend import pyplot
    plt = pyplot()
    fig, axes = plt.subplots(1, 3, figsize=(16, 4.8))
    c = comparison
    k = np.arange(len(c.states))
    errors = c.errors(*columns)
    for ax, col, unit, factor in ((axes[0], columns[0], "deg", 180/math.pi),
                                  (axes[1], columns[1], "m/s", 1.0)):
        ax.plot(k, factor*c.states[:, col], "ko", label="flight")
        for label, (s, fit) in c.fits.items():
            e = errors[label][0 if col == columns[0] else 1]
            ax.plot(k[s:], factor*fit[:, col], "-",
                    label="%s: rms %.2g %s" % (label, e, unit))
        ax.set_xlabel("cycle")
        ax.set_ylabel("%s at the cycle end [%s]" % (c.names[col], unit))
        ax.legend(fontsize=7)
    multipliers(axes[2], c.found, qs)
    for ax in axes:
        ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def multipliers(ax, found, qs):
    """The complex plane: the flight's identified mu, the QS trim's, the
    bumblebee's unstable pair, the unit circle."""
    a = np.linspace(0, 2*np.pi, 400)
    ax.plot(np.cos(a), np.sin(a), "k-", lw=0.8)
    for method, marker in (("pitch alone", "o"), ("all states", "s")):
        m = np.array([v["multiplier"] for v in found[method].values()])
        ax.plot(m[:, 0], m[:, 1], marker, mfc="none",
                label="flight, %s (from cycles %s)" % (
                    method, ",".join(str(s) for s in found[method])))
    q = np.array(qs)
    ax.plot(q[:, 0], q[:, 1], "x", ms=9, mew=2, label="QS trim (Floquet)")
    period, doubling = BUMBLEBEE
    b = 2**(1/doubling)*np.exp(2j*np.pi/period)
    ax.plot([b.real, b.real], [b.imag, -b.imag], "^",
            label="bumblebee (Sun & Xiong 2005)")
    ax.set_xlim(0.8, 1.15)
    ax.set_ylim(-0.3, 0.3)
    ax.set_aspect("equal")
    ax.set_xlabel("Re mu")
    ax.set_ylabel("Im mu")
    ax.legend(fontsize=7)
    ax.set_title("multipliers per cycle")


def arguments(argv):
    parser = argparse.ArgumentParser(
        prog="flapfoam flight_modes", description=__doc__.split("\n\n")[0])
    parser.add_argument("run", help="a run folder or a flightData.h5")
    parser.add_argument("-floquet", required=True, metavar="PREFIX.json")
    parser.add_argument("-period", type=float)
    parser.add_argument("-pitch", type=int, default=2,
                        help="q index of the pitch (default 2)")
    parser.add_argument("-speed", type=int, default=1,
                        help="q index of the forward translation (default 1)")
    parser.add_argument("-from", dest="starts", default="1,2,3,5")
    parser.add_argument("-o", metavar="PREFIX")
    parser.add_argument("-summary", metavar="FILE")
    args = parser.parse_args(argv)
    try:
        args.starts = [int(s) for s in args.starts.split(",")]
    except ValueError:
        parser.error("-from %s: not allowed (cycle numbers, e.g. 1,2,3)"
                     % args.starts)
    if args.period is not None and not args.period > 0:
        parser.error("-period %g: not allowed (> 0)" % args.period)
    return args


def column(names, name, option):
    if name not in names:
        raise StudyError("%s: not allowed (%s is not a state of the Floquet"
                         " file: %s)" % (option, name, " ".join(names)))
    return names.index(name)


def main(argv=None):
    args = arguments(argv)
    try:
        with open(args.floquet) as f:
            floquet = json.load(f)
        names = floquet["floquet_states"]
        columns = (column(names, "q_%d" % args.pitch, "-pitch"),
                   column(names, "qDot_%d" % args.speed, "-speed"))
        period = args.period or floquet["floquet_period_s"]
        states = cycle_ends(read_series(args.run), period, names)
        c = compare(states, floquet, args.starts, columns[0])
        for method, by_start in c.found.items():
            for s, d in by_start.items():
                print("flight_modes: %s" % line("%s, from cycle %d" % (
                    method, s), d))
        for m in floquet["floquet_modes"]:
            print("flight_modes: %s" % line("QS trim (Floquet)", m))
        errors = c.errors(*columns)
        for label, (e_pitch, e_speed) in errors.items():
            print("flight_modes: fitted with the %s: rms %.3g deg (pitch),"
                  " %.3g m/s (speed)" % (label, e_pitch, e_speed))
        result = {"run": args.run, "floquet": args.floquet,
                  "period_s": period, "identified": c.found,
                  "fit_rms_pitch_deg_speed_m_per_s": errors}
        if args.o:
            with open(args.o + ".json", "w") as f:
                json.dump(dict(result, states=names,
                               cycle_end_states=states.tolist()), f,
                          indent=1)
            plot(args.o + ".png", c, columns, floquet["floquet_multipliers"])
            print("flight_modes: wrote %s.json, %s.png" % (args.o, args.o))
        if args.summary:
            write_summary(args.summary, {"flight_modes": result})
    except (StudyError, OSError, KeyError) as e:
        sys.exit("flight_modes: %s" % e)


if __name__ == "__main__":
    run_tool(main)
