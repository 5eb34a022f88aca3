# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Checks of drone runs (used by the Alltests).  Each prints one
"PASS <name> <numbers>" or "FAIL <name> <numbers>" line; the exit status is
non-zero on failure.

    flapfoam check_run prescribed CASE [-tol 1e-12] [-tolTable 1e-11]
        The prescribed joints (imposedMotion entries of CASE/constant/
        dynamicMeshDict) against the analytic Wang motion at every step:
        q, qDot, qDdot from <time>/uniform/rigidBodyMotionState (17
        digits; a run written every step has one per step) and from every
        row of postProcessing/eABAMeshMotion/*/joints.dat (12 significant
        digits: its rounding alone is up to ~4e-12).  Error of derivative
        k: |sim - analytic| / (A omega^k), A the amplitude, omega = 2 pi f.

    flapfoam check_run timers CASE [-nStartup 2]
        stepTimers.dat and stepTimersRanks.dat (all start folders), the
        steps after the first nStartup of each file; four verdicts, each
        one condition and none a timing: the pimple split's columns
        present; a pressure solve with iterations in every step; the
        pimple* parts adding up to pimple; rbd + overset + pimple +
        preUpdate within total (the last two hold by construction, checked
        to the files' 6 digits, per rank: every row of a serial run, every
        rank's own means in parallel).  The closure of rbd + overset +
        pimple against total and the shares are reported on the last line,
        not checked: they depend on the machine's load.

    flapfoam check_run compare A B [-columns q_0,qDot_0,...] [-tol 1e-6]
                            [-rows last|all] [-state]
        joints.dat of case A against case B (rows matched by time).
        Relative difference of a value: |a - b| / max(|a|, |b|, floor) with
        floor = 1e-3 x the largest |value| of that column over A's rows, so
        that a quantity passing through zero at the compared instant is
        judged against its own scale rather than a vanishing denominator.
        -state also compares the last <time>/uniform/rigidBodyMotionState
        (17 digits; q, qDot, qDdot of every joint, same floor).

    flapfoam check_run initial CASE -q 2:0,3:0.785398163397 [-qDotSign 2:-1]
                             [-tol 1e-12]
        The first row of joints.dat: q_i = value (absolute difference) and
        the sign of qDot_i (e.g. -midStroke: phi(0) = 0 decreasing,
        alpha(0) = -45 deg).

    flapfoam check_run dictionary RUN GIVEN [-changed KEY ...]
        Every entry of the dictionary file GIVEN (the user's, e.g. the
        case's constant/dynamicMeshDict.eABA) holds the same value in RUN
        (the run folder's copy, rewritten by Allrun's foamDictionary
        edits): words equal, numbers equal as doubles (a rewrite at 6
        digits turns 1.3089969389957472 into 1.309); the KEYs (slash paths,
        e.g. eABAMeshMotionCoeffs/fluidLoad) are the entries Allrun was
        asked to change: present in RUN, not compared.

    flapfoam check_run rbs A B [-tol 1e-10]
        Every row of A's postProcessing/eABAMeshMotion/0/joints.dat against
        B's postProcessing/rigidBodySimulate/0/joints.dat (all columns, the
        same relative difference).
"""

import argparse
import math
import os
import re
import sys
from dataclasses import dataclass

import numpy as np

from flapfoam.harness import checklist as checks

from flapfoam.io import step_timers
from flapfoam.io.foam_dict import multibody_coeffs, read_foam_dict, read_state
from flapfoam.io import run_series
from flapfoam.io.tables import time_folders
from flapfoam.models.wang import imposed_joints
from flapfoam.errors import run_tool


# --------------------------------------------------------------------------

def report(ok, name, text):
    return checks.report(ok, "%s %s" % (name, text))


def states(case):
    """The rigidBodyMotionState of every time folder: list of dicts."""
    out = []
    for _, d in time_folders(case):
        p = os.path.join(d, "uniform", "rigidBodyMotionState")
        if os.path.isfile(p):
            out.append(read_state(p))
    return out


def joints(case, name="eABAMeshMotion"):
    """(columns, rows) of postProcessing/<name>/<start>/joints.dat joined
    over the start folders (flapfoam.io.run_series)."""
    return run_series.read(case, tables=name).joints_table()


def rel_diff(a, b, floor):
    return np.abs(a - b)/np.maximum(np.maximum(np.abs(a), np.abs(b)), floor)


def multibody_dict(case):
    return multibody_coeffs(os.path.join(case, "constant", "dynamicMeshDict"))


# --------------------------------------------------------------------------

def check_prescribed(case, name, tol, tol_table):
    """The prescribed joints against the analytic Wang motion (tol: the
    state files', tol_table: joints.dat's)."""
    imposed = imposed_joints(multibody_dict(case))
    if not imposed:
        return report(False, "prescribed", "no imposedMotion entries")

    def errors(t, q, q_dot, q_ddot, ev):
        w = 2.0*math.pi*ev.frequency
        qa, q_dot_a, q_ddot_a = ev(t)
        return (np.abs(q - qa)/ev.amplitude,
                np.abs(q_dot - q_dot_a)/(ev.amplitude*w),
                np.abs(q_ddot - q_ddot_a)/(ev.amplitude*w*w))

    # full-precision states
    sts = states(case)
    e_state = np.zeros(3)
    for s in sts:
        for qi, ev in imposed.items():
            e = errors(s["t"], s["q"][qi], s["qDot"][qi], s["qDdot"][qi],
                       ev)
            e_state = np.maximum(e_state, [float(x) for x in e])

    # every row of joints.dat
    cols, J = joints(case)
    c = {n: i for i, n in enumerate(cols)}
    e_table = np.zeros(3)
    for qi, ev in imposed.items():
        e = errors(J[:, 0], J[:, c["q_%d" % qi]], J[:, c["qDot_%d" % qi]],
                   J[:, c["qDdot_%d" % qi]], ev)
        e_table = np.maximum(e_table, [float(x.max()) for x in e])

    name = name or "prescribed"
    joints_named = "/".join("q_%d" % q for q in sorted(imposed))
    status = report(len(sts) > 0 and e_state.max() <= tol,
                    name + " state files",
                    "joints %s, %d rigidBodyMotionState files (17 digits): "
                    "max error q %.2e qDot %.2e qDdot %.2e (tol %g), error "
                    "= |sim - analytic|/(A omega^k)"
                    % (joints_named, len(sts), e_state[0], e_state[1],
                       e_state[2], tol))
    status |= report(e_table.max() <= tol_table, name + " joints.dat",
                     "joints %s, %d rows (12 digits): max error q %.2e qDot "
                     "%.2e qDdot %.2e (tol %g)"
                     % (joints_named, len(J), e_table[0], e_table[1],
                        e_table[2], tol_table))
    return status


# The identities the step timers hold by construction (the same clock
# readings, summed), checked to the files' 6 significant digits a value:
# the pimple* parts (timedOversetFvMesh's solves and interpolations, the
# fvOption pimpleTimers' laps, the function object's pimpleSync) add up to
# pimple; rbd + overset + pimple + preUpdate (disjoint stretches of the
# step) do not exceed total.  Both per rank: in a serial run every row,
# in parallel every rank's own means (stepTimersRanks.dat; the rows hold
# maxima over the ranks, from different ranks).  What the step's untimed
# rest is (total less the four) is reported, not checked: it is what the
# machine's load puts between two timers.
WRITTEN = 1e-6          # relative rounding of a written value (6 digits)
STEP_GROUPS = ("rbd", "overset", "pimple", "preUpdate")


def pimple_part_names(row):
    """The pimple* columns of a row that hold seconds (not pimple itself,
    not the counts)."""
    return [k for k in row if k.startswith("pimple") and k != "pimple"
            and not step_timers.is_count(k)]


def split_error(r):
    """|sum of the pimple* parts - pimple| of a row over its rounding
    bound (at most 1: the identity holds)."""
    parts = pimple_part_names(r)
    bound = WRITTEN*(r["pimple"] + sum(abs(r[k]) for k in parts)) + 1e-12
    return abs(sum(r[k] for k in parts) - r["pimple"])/bound


def cover_excess(r):
    """(rbd + overset + pimple + preUpdate - total) of a row over its
    rounding bound (at most 1: the four fit in the step)."""
    inside = sum(r[k] for k in STEP_GROUPS)
    return (inside - r["total"])/(WRITTEN*(inside + r["total"]) + 1e-12)


@dataclass
class TimerTables:
    """A run's step timers: the rows after the start-up steps (every
    start), the per-rank rows of every start, and the rows the identities
    are checked on (serial: the rows; parallel: the per-rank rows)."""
    rows: list
    ranks: list
    per_rank: list


def timer_tables(case, n_startup):
    """The TimerTables of a run (its stepTimers.dat of every start)."""
    files = step_timers.find_files(os.path.join(case, "postProcessing",
                                                "stepTimers"))
    rows, ranks = [], []
    for f in files:
        rows.extend(step_timers.read_file(f)[n_startup:])
        ranks.extend(step_timers.read_ranks(
            os.path.join(os.path.dirname(f), "stepTimersRanks.dat")))
    serial = all(len(step_timers.read_ranks(os.path.join(
        os.path.dirname(f), "stepTimersRanks.dat"))) <= 1 for f in files)
    return TimerTables(rows, ranks, rows + ranks if serial else ranks)


def timers_reported(tables):
    """What the step timers measured, for the record (no verdict): the
    closure of rbd + overset + pimple against total, the shares."""
    rows = tables.rows
    total = np.array([r["total"] for r in rows])
    parts = np.array([r["rbd"] + r["overset"] + r["pimple"] for r in rows])
    share = {k: np.mean([r[k] for r in rows])/total.mean()
             for k in ("rbd", "overset", "pimple")}
    return ("reported, not checked: 1 - mean(rbd+overset+pimple)/mean(total)"
            " %.2f %%, per-step max %.2f %%; mean total %.3g s/step, shares "
            "rbd %.2f %% overset %.1f %% pimple %.1f %%"
            % (100*abs(1.0 - parts.mean()/total.mean()),
               100*(np.abs(total - parts)/total).max(), total.mean(),
               100*share["rbd"], 100*share["overset"], 100*share["pimple"]))


def check_timers(case, name, n_startup):
    """The step timers of a run after n_startup start-up steps of each
    file: each verdict one condition, none a timing (see WRITTEN)."""
    name = name or "timers"
    t = timer_tables(case, n_startup)
    if not t.rows or not t.ranks:
        return report(False, name, "no steps after the start-up rows (%d) "
                      "or no stepTimersRanks.dat (%d rows)"
                      % (len(t.rows), len(t.ranks)))
    missing = [k for k in ("pimplePressureSolve", "pimpleMomentum",
                           "pimpleTurbulence", "pimpleSync", "pIterations1")
               if k not in t.rows[0]]
    status = report(not missing, name + " columns",
                    "%d steps, %d rank rows: the pimple split's columns "
                    "present%s" % (len(t.rows), len(t.ranks),
                                   ": missing " + " ".join(missing)
                                   if missing else ""))
    if missing:
        return status
    no_solve = [r["time"] for r in t.rows if r["pIterations1"] <= 0]
    status |= report(not no_solve, name + " pressure solves",
                     "a pressure solve with iterations in every step%s"
                     % (": none at t = %s" % no_solve[:3] if no_solve
                        else " (pIterations1 >= %d)"
                        % min(r["pIterations1"] for r in t.rows)))
    split = max(split_error(r) for r in t.per_rank)
    status |= report(split <= 1, name + " pimple split",
                     "the pimple* parts add up to pimple in %d %s: worst "
                     "%.2f of the 6-digit rounding bound (by construction)"
                     % (len(t.per_rank), "rows" if len(t.per_rank) >
                        len(t.ranks) else "ranks' means", split))
    cover = max(cover_excess(r) for r in t.per_rank)
    rest = min(r["total"] - sum(r[k] for k in STEP_GROUPS)
               for r in t.per_rank)
    status |= report(cover <= 1, name + " step cover",
                     "rbd + overset + pimple + preUpdate <= total in %d "
                     "%s (by construction; the least rest %.3g s, "
                     "%.2f of the rounding bound over it); %s"
                     % (len(t.per_rank), "rows" if len(t.per_rank) >
                        len(t.ranks) else "ranks' means", rest,
                        max(cover, 0.0), timers_reported(t)))
    return status


def match_rows(A, B):
    """Indices of rows of A and B with the same time."""
    ia, ib = [], []
    j = 0
    for i, t in enumerate(A[:, 0]):
        eps = 1e-9*max(abs(t), 1e-12)
        while j < len(B) and B[j, 0] < t - eps:
            j += 1
        if j < len(B) and abs(B[j, 0] - t) <= eps:
            ia.append(i)
            ib.append(j)
    return np.array(ia, dtype=int), np.array(ib, dtype=int)


@dataclass
class JointsComparison:
    """What checkCompare compares: joints.dat's columns (None: all), the
    relative tolerance, the rows ("last" or "all"), the last state files
    too (state)."""
    columns: list = None
    tol: float = 1e-6
    rows: str = "last"
    state: bool = False


def state_differences(a, b, ca, A):
    """{column: relative difference} of the last rigidBodyMotionState of
    runs a and b (17 digits; floors from a's joints.dat A, columns ca);
    None if they have none at a common last time."""
    sa, sb = states(a), states(b)
    if not sa or not sb or abs(sa[-1]["t"] - sb[-1]["t"]) > \
            1e-9*abs(sa[-1]["t"]):
        return None
    out = {}
    for key, pre in (("q", "q_"), ("qDot", "qDot_"), ("qDdot", "qDdot_")):
        for qi in range(len(sa[-1][key])):
            col = "%s%d" % (pre, qi)
            floor = 1e-3*np.abs(A[:, ca.index(col)]).max() + 1e-300
            out[col] = float(rel_diff(sa[-1][key][qi], sb[-1][key][qi],
                                     floor))
    return sa[-1]["t"], out


def check_compare(a, b, name, want):
    """joints.dat of run a against run b (want: a JointsComparison)."""
    ca, A = joints(a)
    cb, B = joints(b)
    cols = want.columns or ca[1:]
    ia, ib = match_rows(A, B)
    if len(ia) == 0:
        return report(False, name or "compare", "no common times")
    if want.rows == "last":
        if A[ia[-1], 0] != A[-1, 0] or B[ib[-1], 0] != B[-1, 0]:
            return report(False, name or "compare",
                          "last rows at different times (%g, %g)"
                          % (A[-1, 0], B[-1, 0]))
        ia, ib = ia[-1:], ib[-1:]
    worst = {}
    for col in cols:
        i, k = ca.index(col), cb.index(col)
        floor = 1e-3*np.abs(A[:, i]).max() + 1e-300
        worst[col] = float(rel_diff(A[ia, i], B[ib, k], floor).max())
    name = name or "compare"
    text = ", ".join("%s %.1e" % (k, v) for k, v in worst.items())
    max_rel = max(worst.values())
    status = report(max_rel <= want.tol, name + " joints.dat",
                    "%s rows (%d): max relative difference %.2e (tol %g): "
                    "%s" % (want.rows, len(ia), max_rel, want.tol, text))
    if not want.state:
        return status

    last = state_differences(a, b, ca, A)
    if last is None:
        return status | report(False, name + " state", "no "
                               "rigidBodyMotionState at a common last time")
    t, s_worst = last
    worst_key = max(s_worst, key=s_worst.get)
    return status | report(
        max(s_worst.values()) <= want.tol, name + " state",
        "last rigidBodyMotionState, t = %g (17 digits): max relative "
        "difference %.2e (%s; tol %g), q %s"
        % (t, s_worst[worst_key], worst_key, want.tol, " ".join(
            "%.1e" % v for k, v in s_worst.items() if k.startswith("q_"))))


def check_initial(case, name, q, qdot_sign, tol):
    """The first row of joints.dat: q ("i:value,...") within tol, the signs
    of qDot (qdot_sign "i:sign,...", or None)."""
    cols, J = joints(case)
    c = {n: i for i, n in enumerate(cols)}
    ok = True
    parts = []
    for item in q.split(","):
        qi, value = item.split(":")
        err = abs(J[0, c["q_" + qi]] - float(value))
        ok = ok and err <= tol
        parts.append("q_%s %.12g (expected %s, |diff| %.1e)"
                     % (qi, J[0, c["q_" + qi]], value, err))
    for item in (qdot_sign.split(",") if qdot_sign else []):
        qi, sign = item.split(":")
        v = J[0, c["qDot_" + qi]]
        ok = ok and v*float(sign) > 0
        parts.append("qDot_%s %.6g (sign %s)" % (qi, v, sign))
    return report(ok, name or "initial", "t = %g: %s (tol %g)"
                  % (J[0, 0], ", ".join(parts), tol))


def check_rbs(a, b, name, tol):
    """Every row of run a's eABAMeshMotion joints.dat against run b's
    rigidBodySimulate one (relative tol)."""
    ca, A = joints(a)
    cb, B = joints(b, "rigidBodySimulate")
    if ca != cb:
        return report(False, name or "rbs", "columns differ: %s / %s"
                      % (ca, cb))
    ia, ib = match_rows(A, B)
    if len(ia) != len(A) or len(ib) != len(B):
        return report(False, name or "rbs",
                      "rows do not align: %d eABAMeshMotion, %d "
                      "rigidBodySimulate, %d common" % (len(A), len(B),
                                                         len(ia)))
    worst, worst_col = 0.0, None
    for i, col in enumerate(ca[1:], start=1):
        floor = 1e-3*np.abs(A[:, i]).max() + 1e-300
        r = float(rel_diff(A[ia, i], B[ib, i], floor).max())
        if r > worst:
            worst, worst_col = r, col
    return report(worst <= tol, name or "rbs",
                  "%d rows x %d columns: max relative difference %.2e (%s) "
                  "(tol %g; eABAMeshMotion writes 12 digits)"
                  % (len(ia), len(ca) - 1, worst, worst_col, tol))


def dict_leaves(d, prefix=""):
    """(slash path, tokens) of every entry of a readFoamDict dict."""
    for k, v in d.items():
        if isinstance(v, dict):
            yield from dict_leaves(v, prefix + k + "/")
        else:
            yield prefix + k, v


def same_tokens(a, b):
    """Equal token lists: numbers as doubles, words as written."""
    if len(a) != len(b):
        return False
    for x, y in zip(a, b):
        try:
            if float(x) != float(y):
                return False
        except ValueError:
            if x != y:
                return False
    return True


def check_dictionary(run_file, given_file, name, changed):
    """Every entry of the user's dictionary given_file holds the same value
    in the run's copy run_file, but the changed keys (present there)."""
    given = dict(dict_leaves(read_foam_dict(given_file)))
    run = dict(dict_leaves(read_foam_dict(run_file)))
    changed = set(changed)
    bad = [k for k in sorted(given) if k not in changed and k != "FoamFile/note"
           and not same_tokens(given[k], run.get(k, []))]
    missing = sorted(changed - set(run))
    n_numbers = sum(1 for k in given if k not in changed for t in given[k]
                   if re.match(r"^[-+]?[0-9.]+([eE][-+]?[0-9]+)?$", t))
    text = ("%s: %d entries of %s (%d numbers) as given%s"
            % (run_file, len(given) - len(changed), given_file, n_numbers,
               ", changed as asked: " + " ".join(sorted(changed))
               if changed else ""))
    if bad or missing:
        text = ("%s: differ from %s: %s%s" % (
            run_file, given_file, "; ".join(
                "%s %s -> %s" % (k, " ".join(given[k]),
                                 " ".join(run.get(k, ["(none)"])))
                for k in bad[:5]),
            "; changed keys missing: " + " ".join(missing) if missing
            else ""))
    return report(not bad and not missing, name or "dictionary", text)


def main(argv=None):
    ap = argparse.ArgumentParser(
        description="Checks of single-wing drone runs (PASS/FAIL lines)")
    ap.add_argument("-name", default=None, help="name on the line")
    sub = ap.add_subparsers(dest="cmd", required=True)

    p = sub.add_parser("prescribed")
    p.add_argument("case")
    p.add_argument("-tol", type=float, default=1e-12)
    p.add_argument("-tolTable", dest="tol_table", type=float, default=1e-11)
    p.set_defaults(func=lambda a: check_prescribed(
        a.case, a.name, a.tol, a.tol_table))

    p = sub.add_parser("timers")
    p.add_argument("case")
    p.add_argument("-nStartup", dest="n_startup", type=int, default=2)
    p.set_defaults(func=lambda a: check_timers(a.case, a.name, a.n_startup))

    p = sub.add_parser("compare")
    p.add_argument("a")
    p.add_argument("b")
    p.add_argument("-columns", default=None)
    p.add_argument("-tol", type=float, default=1e-6)
    p.add_argument("-rows", choices=("last", "all"), default="last")
    p.add_argument("-state", action="store_true")
    p.set_defaults(func=lambda a: check_compare(
        a.a, a.b, a.name, JointsComparison(
            a.columns.split(",") if a.columns else None, a.tol, a.rows,
            a.state)))

    p = sub.add_parser("initial")
    p.add_argument("case")
    p.add_argument("-q", required=True)
    p.add_argument("-qDotSign", dest="q_dot_sign", default=None)
    p.add_argument("-tol", type=float, default=1e-12)
    p.set_defaults(func=lambda a: check_initial(
        a.case, a.name, a.q, a.q_dot_sign, a.tol))

    p = sub.add_parser("dictionary")
    p.add_argument("run")
    p.add_argument("given")
    p.add_argument("-changed", nargs="*", default=[])
    p.set_defaults(func=lambda a: check_dictionary(
        a.run, a.given, a.name, a.changed))

    p = sub.add_parser("rbs")
    p.add_argument("a")
    p.add_argument("b")
    p.add_argument("-tol", type=float, default=1e-10)
    p.set_defaults(func=lambda a: check_rbs(a.a, a.b, a.name, a.tol))

    args = ap.parse_args(argv)
    return args.func(args)


if __name__ == "__main__":
    sys.exit(run_tool(main))
