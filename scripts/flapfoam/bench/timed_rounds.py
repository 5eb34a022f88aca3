# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The timed runs of the scaling bench's portable stage (bench/scaling/
portable/runTimed) over several rounds and sessions, per level, method and
rank count: the median step of the rounds, the fastest method at each rank
count and every method against it (the decomposition the drone Allrun takes
by default must be within 5 % of the fastest).

Input: runTimed's summary tables, as it prints them at the end (its log) or
writes them (DIR/<level>/summary.txt): a header line "run rc end ...
step [s] rbd overset pimple", then one line per run, named
<stencil>-<method>-np<N>[-renumbered][-r<R>]; a log holds one table per
level, in the order of LEVELS; a summary.txt is one level's (its folder's
name).

    flapfoam timed_rounds [-levels "coarse medium"] [-o OUT.md]
        FILE...
"""

import argparse
import dataclasses
import os
import re
import sys

import numpy as np
from flapfoam.errors import run_tool

NAME = re.compile(r"^(\w+)-(\w+)-np(\d+)(-renumbered)?(?:-r(\d+))?$")
PARTS = ("step", "rbd", "overset", "pimple")


@dataclasses.dataclass(frozen=True)
class Timed:
    """One timed run of a summary table (seconds, medians over its steps)."""
    level: str
    stencil: str
    method: str
    ranks: int
    renumbered: bool
    parts: dict


def read_tables(text, levels):
    """The runs of the summary tables in TEXT, the k-th table of level
    LEVELS[k]; skipped runs (no step) left out."""
    runs, table = [], -1
    for line in text.splitlines():
        words = line.split()
        if words[:2] == ["run", "rc"]:
            table += 1
            continue
        if table < 0 or not words or not NAME.match(words[0]):
            continue
        if table >= len(levels):
            raise ValueError("more summary tables than levels %s" % levels)
        if words[1] != "0" or len(words) < 9:
            continue
        m = NAME.match(words[0])
        runs.append(Timed(levels[table], m.group(1), m.group(2),
                          int(m.group(3)), bool(m.group(4)),
                          dict(zip(PARTS, map(float, words[5:9])))))
    return runs


def read_file(path, levels):
    """The runs of a runTimed log (its tables in the order of LEVELS) or
    of a level's summary.txt (the level: its folder's name)."""
    with open(path) as f:
        text = f.read()
    if os.path.basename(path) == "summary.txt":
        levels = [os.path.basename(os.path.dirname(os.path.abspath(path)))]
    return read_tables(text, levels)


def medians(runs):
    """{(level, stencil, method, ranks, renumbered): (median parts over
    the rounds, rounds)}."""
    groups = {}
    for r in runs:
        key = (r.level, r.stencil, r.method, r.ranks, r.renumbered)
        groups.setdefault(key, []).append(r.parts)
    return {k: ({p: float(np.median([g[p] for g in v])) for p in PARTS},
                len(v))
            for k, v in groups.items()}


def against_fastest(table):
    """Rows (dicts) of the parallel runs of a medians() table: level,
    stencil, ranks, method, step, rounds, the fastest method at that
    level, stencil, ranks and renumbering, and the step over the
    fastest's."""
    fastest = {}
    for (lv, st, m, n, ren), (parts, _) in table.items():
        key = (lv, st, n, ren)
        if n > 1 and (key not in fastest or parts["step"]
                      < fastest[key][1]):
            fastest[key] = (m, parts["step"])
    rows = []
    for (lv, st, m, n, ren), (parts, rounds) in sorted(table.items()):
        if n < 2:
            continue
        best, step = fastest[(lv, st, n, ren)]
        rows.append(dict(level=lv, stencil=st, ranks=n, method=m,
                         renumbered=ren, rounds=rounds, parts=parts,
                         fastest=best, ratio=parts["step"]/step))
    return rows


def markdown(table, methods):
    """Lines of a markdown table per level: step [s] (rounds) of each
    method at each rank count, the fastest in bold, and each method's
    step over the fastest's."""
    rows = against_fastest(table)
    lines = []
    for lv, st, ren in sorted({(r["level"], r["stencil"], r["renumbered"])
                               for r in rows}):
        sub = [r for r in rows if (r["level"], r["stencil"],
                                   r["renumbered"]) == (lv, st, ren)]
        ranks = sorted({r["ranks"] for r in sub})
        serial = [v for k, v in table.items()
                  if k[:2] == (lv, st) and k[3] == 1 and k[4] == ren]
        lines += ["", "**%s, %s%s** (serial: %s)" % (
            lv, st, ", renumbered" if ren else "",
            "%.3f s (%d)" % (serial[0][0]["step"], serial[0][1])
            if serial else "-"), "",
            "| method | " + " | ".join("np %d" % n for n in ranks) + " |",
            "|---|" + "---:|"*len(ranks)]
        for m in methods:
            cells = []
            for n in ranks:
                r = [x for x in sub if x["method"] == m and x["ranks"] == n]
                cells.append(cell(r[0]) if r else "")
            if any(cells):
                lines.append("| %s | %s |" % (m, " | ".join(cells)))
    return lines


def cell(row):
    """step (rounds), bold where fastest, else +N % over the fastest."""
    step = "%.3f (%d)" % (row["parts"]["step"], row["rounds"])
    if row["ratio"] == 1.0:
        return "**%s**" % step
    return "%s +%.0f %%" % (step, 100*(row["ratio"] - 1))


def main(argv=None):
    p = argparse.ArgumentParser(
        prog="flapfoam timed_rounds",
        description=__doc__.split("\n\n")[1])
    p.add_argument("files", nargs="+", metavar="FILE")
    p.add_argument("-levels", default="coarse medium",
                   help="the levels of a log's tables, in order")
    p.add_argument("-methods", default="simple hierarchical scotch metis "
                   "oversetGraph", help="the table's rows, in order")
    p.add_argument("-o", metavar="OUT.md", help="also write the tables")
    args = p.parse_args(argv)
    runs = [r for f in args.files for r in read_file(f, args.levels.split())]
    if not runs:
        p.error("no timed runs in %s" % " ".join(args.files))
    lines = markdown(medians(runs), args.methods.split())
    print("\n".join(lines))
    if args.o:
        with open(args.o, "w") as f:
            f.write("\n".join(lines).lstrip("\n") + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(run_tool(main))
