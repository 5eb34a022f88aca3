# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The paper authors' flight controllers as flapFoam entries: their
`wangParametrization` entry of `motionType midStartControl_xzth_PD` or
`midStartControl_xzth_linearPD` (github polettiRomain/eABA,
wangParametrization.C; their keys) rewritten as three imposedMotion entries
and a `controller` (src/controllers, type PID) that apply the same laws:

    flapfoam authors_control DICT [-solver NAME] [-entry NAME]
        [-body NAME] [-blend B] [-o FILE]

DICT: their dynamicMeshDict (the model in solvers/NAME, the first with
`bodies` by default) or a flapFoam multibody dictionary.  Writes the
entries to paste in place of their ImposedMotion entry (stdout, or FILE).

Their scheme: at the end of every flapping cycle, from the body's z, x,
pitch and their rates, u = tanh(sum of gains x errors + bias) mapped onto
[min, max] sets the flapping amplitude (Aphi_min..Aphi_max), the
stroke-plane angle beta (a third prescribed joint: jointList (beta phi
alpha)) and the stroke offset (theta_min..theta_max).  The rewrite:
- amplitude: the wang flapping entry's `amplitude` (their phi is
  Aphi_PID asin(K sin 2 pi f t)/asin(K): the wang flapping waveform at
  phase -pi/2);
- beta: q_beta = -(their output): the stroke entry's `offset` over
  [-beta_max, -beta_min], the gains and bias negated;
- the offset: they scale the amplitude by (Aphi + off)/Aphi on the
  downstroke and (Aphi - off)/Aphi on the upstroke, i.e. the stroke spans
  -A(1 +- off/|Aphi|) .. A(1 -+ off/|Aphi|): a mean flapping angle of
  -sign(Aphi) off A/|Aphi|.  flapFoam sets the wang entry's `offset`
  (the mean angle) to -sign(Aphi) off: the same mean angle at A = |Aphi|,
  without their jump of qDot at mid-stroke;
- errors as in their code: PD: e_z = z - href, e_x = x - xref, e_theta =
  asin(E_xz) - thetaref (= -pitch - thetaref, E the global-to-body
  rotation) but its rate omega_y - thetadref; linearPD: e_z = -(z - href)
  (their z pointed down), e_theta = pitch - thetaref, and every loop sums
  the errors of all three (their cross gains Kpxz, Kdzx, ...).  Rates:
  the state's velocity (derivative state).  Their Kiz, Kix, Kitheta are
  read by their code and not used: not used here either.
- the measured body: their code's body index 3 (hard-coded), the third
  entry of `bodies` (override: -body); its centre of mass (theirs: the
  body origin; the same for their sphere);
- updates once per flapping cycle (theirs: abrupt changes at the cycle
  start; here blended over -blend cycles, default 0.25; 0: abrupt); the
  first cycle flies the dictionary's |Aphi|, beta 0 and offset 0.
"""

import argparse
import math
import sys

from flapfoam.io.foam_dict import read_foam_dict
from flapfoam.errors import FlapFoamError, run_tool

TYPES = ("midStartControl_xzth_PD", "midStartControl_xzth_linearPD")
LIMITS = {"amplitude": ("Aphi_min", "Aphi_max"),
          "beta": ("beta_min", "beta_max"),
          "offset": ("theta_min", "theta_max")}
# Their gains per output loop and error: (Kp key, Kd key) of z, x, theta
GAINS = {"amplitude": {"z": ("Kpz", "Kdz"), "x": ("Kpxz", "Kdxz"),
                       "theta": ("Kpthz", "Kdthz"), "bias": "biasz"},
         "beta": {"x": ("Kpx", "Kdx"), "z": ("Kpzx", "Kdzx"),
                  "theta": ("Kpthx", "Kdthx"), "bias": "biasx"},
         "offset": {"theta": ("Kptheta", "Kdtheta"), "z": ("Kpzth", "Kdzth"),
                    "x": ("Kpxth", "Kdxth"), "bias": "biasth"}}
# PD: the loops without cross terms or (beta, offset) bias
PD_USES = {"amplitude": ("z", "bias"), "beta": ("x",), "offset": ("theta",)}


def fail(msg):
    raise FlapFoamError("authors_control: " + msg)


def find_model(d, solver):
    """The sub-dictionary with `bodies`: solvers/<solver> or the top."""
    if "bodies" in d:
        return d, "the top level"
    if "eABAMeshMotionCoeffs" in d:
        return d["eABAMeshMotionCoeffs"], "eABAMeshMotionCoeffs"
    solvers = d.get("solvers", {})
    names = [n for n, s in solvers.items()
             if isinstance(s, dict) and "bodies" in s]
    if solver is not None:
        if solver not in names:
            fail("-solver %s: not a sub-dictionary of solvers with bodies"
                 " (those: %s)" % (solver, " ".join(names) or "none"))
        return solvers[solver], "solvers/" + solver
    if not names:
        fail("no model (a dictionary with bodies) at the top level, in"
             " eABAMeshMotionCoeffs or in solvers")
    return solvers[names[0]], "solvers/" + names[0]


def find_entry(model, where, name):
    motions = model.get("ImposedMotion", model.get("imposedMotion", {}))
    found = [n for n, e in motions.items() if isinstance(e, dict)
             and e.get("motionType", [""])[0].strip('"') in TYPES]
    if name is not None:
        if name not in found:
            fail("-entry %s: not an entry of motionType %s in %s"
                 % (name, " or ".join(TYPES), where))
        found = [name]
    if len(found) != 1:
        fail("%s: %d entries of motionType %s (-entry NAME chooses)"
             % (where, len(found), " or ".join(TYPES)))
    return found[0], motions[found[0]]


def number(entry, key, entry_name):
    if key not in entry:
        fail("entry %s: key %s missing (their code reads it)"
             % (entry_name, key))
    try:
        return float(entry[key][0])
    except ValueError:
        fail("entry %s: %s %s is not a number"
             % (entry_name, key, " ".join(entry[key])))


class authors_entry:
    """Their controller entry's values and the flapFoam loops they make."""

    def __init__(self, name, entry, body):
        self.name = name
        self.entry = entry
        self.body = body
        self.kind = entry["motionType"][0].strip('"')
        self.joints = [int(j) for j in entry.get("jointList", [])
                       if j not in "()"]
        if len(self.joints) != 3:
            fail("entry %s: jointList %s: three joints (beta phi alpha)"
                 " are needed by %s" % (name, " ".join(
                     entry.get("jointList", [])), self.kind))
        self.v = lambda key: number(entry, key, name)
        self.sign = -1.0 if self.v("Aphi") < 0 else 1.0

    def terms(self, loop, n):
        """The terms (dict text) of a loop whose output is n x theirs."""
        v, gains, linear = self.v, GAINS[loop], self.kind.endswith("linearPD")
        uses = gains.keys() if linear else PD_USES[loop]
        out = []
        for q in ("z", "x", "theta"):
            if q not in uses:
                continue
            kp, kd = (v(k) for k in gains[q])
            sp, rsp = {"z": ("href", "hdref"), "x": ("xref", "xdref"),
                       "theta": ("thetaref", "thetadref")}[q]
            sp, rsp = v(sp), v(rsp)
            if q == "z" and linear:          # e_z = -(z - href)
                kp, kd = -kp, -kd
            if q == "theta" and not linear:  # e = -pitch - thetaref
                kp, sp = -kp, -sp
            quantity, comp = (("orientation", "y") if q == "theta"
                              else ("position", q))
            out.append("%s { body %s; quantity %s; component %s;"
                       " setPoint %.17g; rateSetPoint %.17g;"
                       " Kp %.17g; Kd %.17g; }"
                       % (q, self.body, quantity, comp, sp, rsp,
                          n*kp, n*kd))
        bias = v(gains["bias"]) if "bias" in uses else 0.0
        return out, n*bias

    def loop(self, loop):
        """(name, text) of one controller loop."""
        lo, hi = (self.v(k) for k in LIMITS[loop])
        n = {"amplitude": 1.0, "beta": -1.0, "offset": -self.sign}[loop]
        entry, parameter = {"amplitude": ("flapping", "amplitude"),
                            "beta": ("stroke", "offset"),
                            "offset": ("flapping", "offset")}[loop]
        if n < 0:
            lo, hi = -hi, -lo
        if not lo < hi:
            fail("entry %s: %s %g and %s %g: min < max is needed"
                 % (self.name, LIMITS[loop][0], lo, LIMITS[loop][1], hi))
        terms, bias = self.terms(loop, n)
        return ("%s\n{\n    entry %s; parameter %s; saturation tanh;\n"
                "    min %.17g; max %.17g; bias %.17g;\n    terms\n    {\n"
                "        %s\n    }\n}" % (loop, entry, parameter, lo, hi, bias,
                                          "\n        ".join(terms)))

    def text(self, blend):
        v, (b, p, a) = self.v, self.joints
        pi = math.pi
        motions = (
            "imposedMotion\n{\n"
            "    stroke { type harmonic; joint %d; amplitude 0;"
            " frequency %.17g; offset 0; }\n"
            "    flapping { type wang; joint %d; waveform flapping;"
            " amplitude %.17g; frequency %.17g; K %.17g; phase %.17g; }\n"
            "    pitching { type wang; joint %d; waveform pitching;"
            " amplitude %.17g; frequency %.17g; K %.17g; phase %.17g;"
            " offset %.17g; }\n}\n"
            % (b, v("fphi"), p, abs(v("Aphi")), v("fphi"), v("Kphi"), -pi/2,
               a, -v("Aalpha"), v("falpha"), v("Kalpha"), pi/2, v("Aalpha")))
        loops = "\n".join(self.loop(k) for k in ("amplitude", "beta",
                                                   "offset"))
        loops = "\n".join("        " + l if l else l
                          for l in loops.splitlines())
        return ("// From the paper authors' entry %s (motionType %s):"
                " flapfoam authors_control\n%s"
                "controller\n{\n    type PID; update cycle;"
                " cycleOf flapping; blend %.17g; log on;\n    loops\n    {\n"
                "%s\n    }\n}\n" % (self.name, self.kind, motions, blend,
                                    loops))


def main(argv=None):
    ap = argparse.ArgumentParser(
        prog="flapfoam authors_control",
        description="The paper authors' midStartControl_xzth_PD / _linearPD"
        " entry as flapFoam imposedMotion entries and a PID controller.")
    ap.add_argument("dict")
    ap.add_argument("-solver")
    ap.add_argument("-entry")
    ap.add_argument("-body")
    ap.add_argument("-blend", type=float, default=0.25)
    ap.add_argument("-o")
    args = ap.parse_args(argv)
    if not 0 <= args.blend <= 1:
        fail("-blend %g: allowed 0 to 1 (a fraction of the cycle)"
             % args.blend)
    try:
        d = read_foam_dict(args.dict)
    except OSError as e:
        fail("cannot read %s: %s" % (args.dict, e))
    model, where = find_model(d, args.solver)
    name, entry = find_entry(model, where, args.entry)
    bodies = [b for b, e in model["bodies"].items() if isinstance(e, dict)]
    body = args.body
    if body is None:
        if len(bodies) < 3:
            fail("%s: fewer than 3 bodies: their code measures body index"
                 " 3; name the body with -body" % where)
        body = bodies[2]
    elif body not in bodies:
        fail("-body %s: not a body of %s (bodies: %s)"
             % (body, where, " ".join(bodies)))
    text = authors_entry(name, entry, body).text(args.blend)
    if args.o:
        with open(args.o, "w") as f:
            f.write(text)
    else:
        sys.stdout.write(text)


if __name__ == "__main__":
    run_tool(main)
