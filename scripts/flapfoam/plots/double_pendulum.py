# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Double pendulum figures (as in Poletti et al., section 4): the angles and
the drive torque from the eABA (each integrator) against the Lagrangian
reference, and their differences.

    doublePendulum.png      prescribed drive of joint 1
    doublePendulumFree.png  free pendulum (symplectic) against the reference

Reads the same files as flapfoam.checks.double_pendulum, in the case folder it
is run in or -case DIR (run ./Allrun first).
"""

import argparse
import os

import numpy as np

from flapfoam.checks import double_pendulum as compare
from flapfoam.plots.backend import pyplot
from flapfoam.errors import FlapFoamError, run_tool

plt = pyplot()

DEG = 180/np.pi
STYLE = {"Newmark": ("C0", "o"), "symplectic": ("C1", "s"),
         "CrankNicolson": ("C2", "^"), "free": ("C1", "s")}
# Newmark (0.5, 0.25) and Crank-Nicolson (0.5, 0.5) are the same update:
# draw Crank-Nicolson dashed over a wider Newmark line so both show
LINE = {"Newmark": dict(lw=2.5, alpha=0.6), "symplectic": dict(lw=1),
        "CrankNicolson": dict(lw=1, ls="--")}
TEX = {"theta1": r"\theta_1", "theta2": r"\theta_2"}


# error panels: key -> (y label, over max |reference| or not)
ERROR = {"theta2": (r"$|\theta_2 - \theta_{2,ref}|$ [rad]", False),
         "tau1": (r"$|\tau_1 - \tau_{1,ref}|$ / max $|\tau_{1,ref}|$", True)}


def error_panel(a, ref, runs, key):
    """|run - reference| of key (over max |reference| where ERROR says so),
    each integrator, with the acceptance limit and the end of its
    window."""
    ylabel, relative = ERROR[key]
    scale = np.abs(ref[key]).max() if relative else 1.0
    for name, e in runs.items():
        d = np.abs(e[key] - compare.on_times(ref, e["time"], key))
        a.semilogy(e["time"], np.maximum(d, 1e-16)/scale,
                   color=STYLE[name][0], label=name, **LINE[name])
    a.axhline(compare.TOL[key], color="r", ls=":", label="limit")
    a.axvline(compare.WINDOW[key], color="grey", ls=":")
    a.set_ylabel(ylabel)
    a.set_xlabel("t [s]")
    a.legend(fontsize=8)


def plot_prescribed(case, out):
    ref, _ = compare.read_reference("prescribed", case)
    runs = {i: compare.read_eaba(i, case) for i in compare.INTEGRATORS}

    fig, ax = plt.subplots(2, 2, figsize=(12, 8), sharex=True)
    a = ax[0, 0]
    a.plot(ref["time"], ref["theta1"]*DEG, "k-", lw=1,
           label=r"$\theta_1$ Lagrange")
    a.plot(ref["time"], ref["theta2"]*DEG, "k--", lw=1,
           label=r"$\theta_2$ Lagrange")
    for name, e in runs.items():
        c, m = STYLE[name]
        every = slice(None, None, 40)
        a.plot(e["time"][every], e["theta1"][every]*DEG, m, color=c, ms=3,
               mfc="none")
        a.plot(e["time"][every], e["theta2"][every]*DEG, m, color=c, ms=4,
               label=f"eABA {name}")
    a.set_ylabel("angle [deg]")
    a.set_title(r"angles from the vertical ($\theta_2$ absolute)")
    a.legend(fontsize=8)

    a = ax[0, 1]
    a.plot(ref["time"], ref["tau1"], "k-", lw=1, label="Lagrange")
    for name, e in runs.items():
        c, m = STYLE[name]
        every = slice(None, None, 40)
        a.plot(e["time"][every], e["tau1"][every], m, color=c, ms=4,
               label=f"eABA {name}")
    a.set_ylabel(r"$\tau_1$ [N m]")
    a.set_title("torque of the driven joint")
    a.legend(fontsize=8)

    error_panel(ax[1, 0], ref, runs, "theta2")
    error_panel(ax[1, 1], ref, runs, "tau1")

    fig.suptitle(r"Double pendulum, $\theta_1 = A\cos(2\pi f t) - A$, "
                 r"A = 57 deg, f = 2 Hz: eABA vs Lagrange")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


def plot_free(case, out):
    ref, p = compare.read_reference("free", case)
    e = compare.read_eaba("free", case)
    E = compare.energy(p, e["theta1"], e["theta2"], e["theta1Dot"],
                       e["theta2Dot"])

    fig, ax = plt.subplots(1, 2, figsize=(12, 4.5))
    a = ax[0]
    every = slice(None, None, 40)
    for k, ls in (("theta1", "-"), ("theta2", "--")):
        a.plot(ref["time"], ref[k]*DEG, "k" + ls, lw=1,
               label=rf"${TEX[k]}$ Lagrange")
        a.plot(e["time"][every], e[k][every]*DEG, "s", color="C1", ms=3,
               mfc="none" if k == "theta1" else None,
               label=rf"${TEX[k]}$ eABA symplectic")
    a.set_xlabel("t [s]")
    a.set_ylabel("angle [deg]")
    a.set_title("free double pendulum")
    a.legend(fontsize=8)

    a = ax[1]
    a.plot(e["time"], (E - E[0])/E[0], "C1", lw=1, label="eABA symplectic")
    a.plot(ref["time"], (ref["E"] - ref["E"][0])/ref["E"][0], "k", lw=1,
           label="Lagrange")
    a.set_xlabel("t [s]")
    a.set_ylabel(r"$(E - E_0)/E_0$")
    a.set_title("energy")
    a.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


def main(argv=None):
    p = argparse.ArgumentParser(prog="flapfoam plot_double_pendulum",
                                description=__doc__.split("\n\n")[0])
    p.add_argument("-case", default=compare.CASE,
                   help="the case folder (default: here)")
    case = p.parse_args(argv).case
    reference = os.path.join(case, "reference", "prescribed.dat")
    if not os.path.isfile(reference):
        raise FlapFoamError("plot_double_pendulum: no %s (run the case's "
                            "./Allrun first)" % reference)
    plot_prescribed(case, os.path.join(case, "doublePendulum.png"))
    plot_free(case, os.path.join(case, "doublePendulumFree.png"))


if __name__ == "__main__":
    run_tool(main)
