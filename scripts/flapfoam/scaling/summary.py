# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""Table, model and charts of the scaling bench (bench/scaling/run).

    flapfoam scaling_summary -dir DIR -levels "fine ..." -countLevel L
        -countSteps N1 N2 -timeLevel L [-startup K] [-o PREFIX]

Reads what run left in DIR: the counted structure of every level
(DIR/<level>/structure/<method>-np<N>.report, .cellDecomposition), the
counted traffic of every level that has some (DIR/<level>/traffic/<run>-s<N>/
counts, the oversetRankReport of its log, its peak memory: the count level's
and any other counted with -countLevel), the timed runs
(DIR/<level>/timed/<run>-r<R>/postProcessing/stepTimers) and
DIR/pingPong.log; fits the model's costs (flapfoam.scaling.model) and writes
PREFIX.md (tables: structure, traffic, timed against the model, the
model's step per level, method, ranks and stencil, the goals
at 16-48 ranks) and the charts PREFIX-*.png (flapfoam.scaling.charts).
"""

import argparse
import glob
import os
import platform
import re
import time
from dataclasses import dataclass

import numpy as np

from flapfoam.errors import run_tool
from flapfoam.paths import project_path
from flapfoam.bench import rank_tables
from flapfoam.io import mpi_counts, step_timers
from flapfoam.scaling import charts as scaling_charts
from flapfoam.scaling import model as scaling_model
from flapfoam.scaling import report as scaling_report
from flapfoam.scaling import validate as scaling_validate

METHODS = ["simple", "hierarchical", "scotch", "metis", "oversetGraph"]
STENCILS = ["inverseDistance", "octreeInverseDistance"]
REPORT = "oversetCouplingsReport"


def read_structure(folder, base):
    """{(method, P): Decomposition} of a level's structure folder."""
    mesh = None
    out = {}
    for path in sorted(glob.glob(os.path.join(folder, "*-np*.report"))):
        m = re.match(r"(\w+)-np(\d+)\.report$", os.path.basename(path))
        table = rank_tables.read_table(path, REPORT)
        decomp = rank_tables.read_decomposition(
            path[:-len(".report")] + ".cellDecomposition")
        if mesh is None:
            mesh = os.path.join(base, "constant", "polyMesh")
        nbr = rank_tables.neighbour_ranks(mesh, decomp)
        out[(m.group(1), int(m.group(2)))] = \
            scaling_model.Decomposition(table, nbr)
    return out


def read_traffic(folder, n1, n2):
    """{(method, P, stencil): dict perStep (per rank: p2pBytes, p2pCalls,
    collectiveCalls), report (oversetRankReport table of the first
    update), memory (MiB, summed over the ranks)}; and the solver runs
    under the key ("solver", 2, stencil)."""
    out = {}
    for d in sorted(glob.glob(os.path.join(folder, "*-s%d" % n2))):
        m = re.match(r"(\w+)-np(\d+)-(\w+)-s%d$" % n2, os.path.basename(d))
        short = d[:-len("-s%d" % n2)] + "-s%d" % n1
        if not m or not os.path.isdir(os.path.join(short, "counts")):
            continue
        entry = {"perStep": mpi_counts.per_step(
            os.path.join(short, "counts"), n1, os.path.join(d, "counts"), n2)}
        log = os.path.join(d, "log.oversetMotionCheck")
        if os.path.isfile(log):
            entry["report"] = rank_tables.read_table(log, "oversetRankReport")
        with open(os.path.join(d, "memory")) as f:
            entry["memory"] = float(f.read().split()[0])
        out[(m.group(1), int(m.group(2)), m.group(3))] = entry
    return out


def read_timed(folder, startup):
    """{(method, P, stencil): {part: median over rounds of the per-run
    medians}} of a level's timed runs; method "serial" for P = 1; parts:
    rbd + overset + pimple (total less the rest of the step: writing the
    fields, which the model leaves out); split: the pimple column's
    (step_timers.pimple_split of the medians, None without it)."""
    groups = {}
    for d in sorted(glob.glob(os.path.join(folder, "*-r*"))):
        m = re.match(r"(\w+)-np(\d+)-(\w+)-r\d+$", os.path.basename(d))
        if not m or not os.path.isdir(os.path.join(d, "postProcessing")):
            continue
        columns, data = step_timers.read_input(
            os.path.join(d, "postProcessing", "stepTimers"), startup)
        med = {c: float(np.median(data[:, i])) for i, c in enumerate(columns)}
        parts = sum(data[:, columns.index(c)]
                    for c in ("rbd", "overset", "pimple"))
        med["parts"] = float(np.median(parts))
        groups.setdefault((m.group(1), int(m.group(2)), m.group(3)),
                          []).append(med)
    out = {}
    for k, g in groups.items():
        med = {c: float(np.median([r[c] for r in g]))
               for c in set.intersection(*(set(r) for r in g))}
        out[k] = dict({c: med[c] for c in
                       ("rbd", "overset", "pimple", "total", "parts")},
                      rounds=len(g), split=step_timers.pimple_split(med))
    return out


def pimple_traffic(traffic, structure):
    """(sMsg, sBytes, sReduce): the flow run minus the motion run (octree,
    hierarchical, 2 ranks), per step of rank 0: per interface (neighbour
    rank and remote-stencil rank), per value (processor face and remote
    donor cell), reductions."""
    stencil = "octreeInverseDistance"
    flow = traffic[("solver", 2, stencil)]["perStep"][0]
    motion = traffic[("hierarchical", 2, stencil)]["perStep"][0]
    d = structure[("hierarchical", 2)]
    return ((flow["p2pCalls"] - motion["p2pCalls"])
            / (d.neighbours[0] + d.donor_ranks[0]),
            (flow["p2pBytes"] - motion["p2pBytes"])
            / (8*(d.faces[0] + d.remote_donors[0])),
            flow["collectiveCalls"] - motion["collectiveCalls"])


def traffic_fit(data, stencil):
    """The stencil's TrafficFit from the counted runs of every level (every
    rank)."""
    rows = []
    for level, traffic in data["traffic"].items():
        structure = data["structure"][level]
        for (method, p, s), e in traffic.items():
            if s != stencil or (method, p) not in structure:
                continue
            d = structure[(method, p)]
            for r, step in enumerate(e["perStep"]):
                rows.append((p, d.pairs[r], step["p2pBytes"],
                             step["p2pCalls"]))
    return scaling_model.TrafficFit(rows)


def pimple_traffics(data, count_level):
    """{level: (sMsg, sBytes, sReduce)} of the levels with the flow and
    motion runs counted, and None: the count level's (for the others)."""
    out = {}
    for level, traffic in data["traffic"].items():
        try:
            out[level] = pimple_traffic(traffic, data["structure"][level])
        except KeyError:
            continue
    out[None] = out[count_level]
    return out


def serial_of(structure):
    """The serial decomposition of a level (cells, overset work, pairs
    from any of its reports' totals)."""
    d = next(iter(structure.values()))
    return scaling_model.serial_decomposition(
        d.cells.sum(), d.work.sum(), d.all_pairs.sum())


def serial_runs(data, stencil):
    """{level: (serial medians, serial decomposition)} of the levels with
    a timed serial run of the stencil and a counted structure."""
    return {lv: (timed[("serial", 1, stencil)], serial_of(data["structure"][lv]))
            for lv, timed in data["timed"].items()
            if ("serial", 1, stencil) in timed and lv in data["structure"]}


def fit_costs(data, stencil, level):
    """The stencil's Costs for LEVEL from LEVEL's serial run (or, without
    one, the time level's): cCell, rbd, and cWork (cFix 0: the serial runs
    of tiny, coarse and fine show no part of the overset work that stays
    fixed as the mesh grows, see the costs table).  The 2-rank runs only
    check the model: on this machine they share its 2 cores with the
    other jobs."""
    pimple = data["pimpleTraffic"]
    costs = scaling_model.Costs(data["machine"],
                               pimple.get(level, pimple[None]),
                               data["fits"][stencil])
    costs.stencil = stencil
    serial = serial_runs(data, stencil)
    t, d = serial.get(level, serial.get(data["timeLevel"]))
    costs.fit_overset([(t["overset"], d.work[0], 0.0)])
    costs.c_cell, costs.rbd = t["pimple"]/d.cells[0], t["rbd"]
    return costs


def fixed_overset(data, stencil):
    """cFix, cWork of the serial runs of all levels together (least
    squares, cFix >= 0): whether a part of the overset work does not
    shrink with the mesh."""
    costs = scaling_model.Costs(data["machine"], data["pimpleTraffic"][None],
                               data["fits"][stencil])
    costs.fit_overset([(t["overset"], d.work[0], 0.0)
                       for t, d in serial_runs(data, stencil).values()])
    return costs.c_fix, costs.c_work


def predictions(data):
    """{(level, method, P, stencil): step} of the model, P = 1 (method
    'serial') and every counted decomposition."""
    out = {}
    for level, structure in data["structure"].items():
        for stencil in data["stencils"]:
            costs = fit_costs(data, stencil, level)
            data["costs"][(level, stencil)] = costs
            out[(level, "serial", 1, stencil)] = scaling_model.predict(
                costs, serial_of(structure))
            for (method, p), d in structure.items():
                out[(level, method, p, stencil)] = \
                    scaling_model.predict(costs, d)
    return out


@dataclass
class Bench:
    """Where the bench's runs are (dir) and which of them to read: the
    levels tabulated, the level whose traffic was counted (over steps
    countSteps), the level timed (its first startup steps left out)."""
    dir: str
    levels: list
    count_level: str = "tiny"
    count_steps: tuple = (1, 3)
    time_level: str = "coarse"
    startup: int = 3


def load(bench):
    """Everything the tables and charts need (bench: a Bench)."""
    data = {"timeLevel": bench.time_level, "costs": {}}
    levels = sorted(set(bench.levels) | {bench.count_level, bench.time_level})
    data["structure"] = {
        lv: read_structure(os.path.join(bench.dir, lv, "structure"),
                           os.path.join(bench.dir, lv, "base"))
        for lv in levels
        if glob.glob(os.path.join(bench.dir, lv, "structure", "*.report"))}
    data["traffic"] = {
        lv: read_traffic(os.path.join(bench.dir, lv, "traffic"),
                         *bench.count_steps)
        for lv in data["structure"]
        if os.path.isdir(os.path.join(bench.dir, lv, "traffic"))}
    data["timed"] = {lv: read_timed(os.path.join(bench.dir, lv, "timed"),
                                    bench.startup) for lv in levels}
    data["machine"] = scaling_validate.read_ping_pong(
        os.path.join(bench.dir, "pingPong.log"))
    data["pimpleTraffic"] = pimple_traffics(data, bench.count_level)
    data["stencils"] = [s for s in STENCILS if any(
        k[2] == s for k in data["traffic"][bench.count_level])]
    data["fits"] = {s: traffic_fit(data, s) for s in data["stencils"]}
    data["fixedOverset"] = {s: fixed_overset(data, s)
                            for s in data["stencils"]}
    data["model"] = predictions(data)
    data["levels"] = [lv for lv in bench.levels if lv in data["structure"]]
    data["countLevel"] = bench.count_level
    return data


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("-dir", required=True)
    parser.add_argument("-levels", default="fine")
    parser.add_argument("-countLevel", dest="count_level", default="tiny")
    parser.add_argument("-countSteps", dest="count_steps", nargs=2, type=int,
                        default=[1, 3])
    parser.add_argument("-timeLevel", dest="time_level", default="coarse")
    parser.add_argument("-startup", type=int, default=3)
    parser.add_argument("-o", default=project_path("bench", "scaling",
                                                   "results"))
    args = parser.parse_args()
    data = load(Bench(args.dir, args.levels.split(), args.count_level,
                      tuple(args.count_steps), args.time_level, args.startup))
    lines = scaling_report.tables(data)
    lines += ["", "Machine: %s, %d CPUs, load average %s; %s." % (
        platform.node(), os.cpu_count(),
        " ".join("%.2f" % x for x in os.getloadavg()),
        time.strftime("%Y-%m-%d %H:%M"))]
    with open(args.o + ".md", "w") as f:
        f.write("\n".join(lines) + "\n")
    scaling_charts.write_all(data, args.o)
    print("summarise: wrote %s.md and %s-*.png" % (args.o, args.o))


if __name__ == "__main__":
    run_tool(main)
