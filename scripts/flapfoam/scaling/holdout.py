# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The scaling model on sessions held out from every fit: for each session
of the measured archives, the constants calibrated on the other sessions'
runs alone (flapfoam.scaling.validate.calibrate, the committed set of
methods: hierarchical and scotch), then the model against every octree
run of the held-out session, which gives only its own machine figures
(the serial run of each level, the ping-pong).  What a new machine would
see of the model.

    flapfoam scaling_holdout [ARCHIVE ...] [-rounds FILE ...]
        [-levels "coarse medium"] [-o FILE]

ARCHIVE, -rounds, -levels: as flapfoam scaling_validate (default: the
committed 16-core sessions).  Prints per held-out session the constants
fitted without it, a line per run (measured, model, ratio) and
"model within X % of N measured runs (SESSION held out)"; with -o the
same as markdown.
"""

import argparse
import dataclasses
import statistics

from flapfoam.errors import FlapFoamError, run_tool
from flapfoam.scaling import model as scaling_model
from flapfoam.scaling import validate


@dataclasses.dataclass
class HeldOut:
    """One session held out: its name, the calibration fitted on the
    others, the rows of its octree runs (validate.compare)."""
    session: str
    calibration: scaling_model.Calibration
    rows: list

    def worst(self):
        return validate.largest_errors(self.rows)[None][0]

    def median(self):
        return statistics.median(abs(r["ratio"] - 1) for r in self.rows)

    def summary(self):
        return ("model within %.0f %% of %d measured runs (%s held out; "
                "median error %.0f %%)"
                % (100*self.worst(), len(self.rows), self.session,
                   100*self.median()))


def hold_out(runs, session):
    """The HeldOut of SESSION: calibrated on the other sessions' runs."""
    others = [r for r in runs if r.session != session]
    own = [r for r in runs if r.session == session and r.stencil == "octree"]
    if not others or not any(r.ranks > 1 for r in own):
        raise FlapFoamError("scaling_holdout: session %s: needs its own "
                            "parallel octree runs and another session's "
                            "to fit on" % session)
    cal = validate.rounded(validate.calibrate(others))
    return HeldOut(session, cal, validate.compare(own, cal))


def lines(held, markdown=False):
    """The report of one HeldOut: the constants, validate's line per run
    (markdown: a table), the summary."""
    c = held.calibration
    return ["held out %s: fitted on the other sessions: pSat %g, cIter %g, "
            "growth %g, vParallel %g, bStock %g"
            % (held.session, c.p_sat, c.c_iter, c.growth, c.v_parallel,
               c.b_stock), ""] \
        + validate.table_lines(held.rows, markdown) \
        + ["", held.summary(), ""]


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="flapfoam scaling_holdout", description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("archives", nargs="*")
    parser.add_argument("-rounds", nargs="+", metavar="FILE", default=[])
    parser.add_argument("-levels", default="coarse medium")
    parser.add_argument("-o", metavar="FILE")
    args = parser.parse_args(argv)
    if not args.archives:
        args.archives, args.rounds = validate.SESSIONS, \
            args.rounds or validate.ROUNDS
    runs = validate.read_archives(args.archives, rounds=args.rounds,
                                  level_names=args.levels.split())
    sessions = sorted({r.session for r in runs})
    if len(sessions) < 2:
        raise FlapFoamError("scaling_holdout: %d session(s) in the archives: "
                            "at least 2 needed" % len(sessions))
    held = [hold_out(runs, s) for s in sessions]
    for h in held:
        print("\n".join(lines(h)))
    if args.o:
        with open(args.o, "w") as fh:
            for h in held:
                fh.write("\n".join(lines(h, markdown=True)) + "\n")
    return 0


if __name__ == "__main__":
    run_tool(main)
