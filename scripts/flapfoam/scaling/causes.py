# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Why one partition's PIMPLE costs more than another's at the same ranks:
the measured gap split cause by cause with the calibrated model
(flapfoam.scaling.model, runs of flapfoam.scaling.validate).

For a run A against a reference B (the same level, stencil and ranks),
the model's PIMPLE of the slowest rank,

    pimple = (I/I1) [cCell B(N, Ntotal) + cIter I1 (k + q)
                     + beta sBytes 8 (F + D)]

goes from B's inputs to A's one at a time, in this order: cells N (the
slowest rank's: imbalance included), pressure iterations I (counted in
the logs), interfaces k + q (neighbour ranks and remote-stencil ranks),
halo values F + D (processor faces and remote donor cells received).
Each step's change is that cause's share; the measured gap less their sum
is what the model does not explain.  The twin: the same partition run
with the other stencil, whose PIMPLE is the same arithmetic (the two
stencils give the same donors; the p residuals of the two logs agree
bitwise), so its gap measures what is the partition's and what is the
run's.
"""

import numpy as np

from flapfoam.scaling import model as scaling_model
CAUSES = ("cells", "iterations", "interfaces", "halo bytes")
TWIN = {"octree": "ID", "ID": "octree"}


def slowest_inputs(run, step):
    """The model's slowest rank's inputs: cells, iterations, interfaces,
    halo values (the iterations: the run's counted ones)."""
    d, r = run.decomposition, step["slowestRank"]
    return [float(d.cells[r]), run.iterations,
            float(d.neighbours[r] + d.donor_ranks[r]),
            float(d.faces[r] + d.remote_donors[r])]


def rank_pimple(costs, total, x):
    """The model's PIMPLE of one rank of a decomposition of TOTAL cells
    with inputs X (see slowest_inputs)."""
    cal = costs.calibration
    i1 = costs.serial_iterations()
    cells, iterations, interfaces, values = x
    return iterations/i1*(
        costs.c_cell*scaling_model.shared_bandwidth(cells, total, cal.p_sat)
        + i1*cal.c_iter*interfaces
        + costs.beta*costs.s_bytes*8*values)


def attribute(a, b, costs):
    """{cause: seconds} of run A's model PIMPLE over B's, cause by cause
    (CAUSES, in order)."""
    xa = slowest_inputs(a, scaling_model.predict(costs, a.decomposition,
                                                a.iterations))
    x = slowest_inputs(b, scaling_model.predict(costs, b.decomposition,
                                               b.iterations))
    out = {}
    total = float(a.decomposition.cells.sum())
    for i, cause in enumerate(CAUSES):
        before = rank_pimple(costs, total, x)
        x[i] = xa[i]
        out[cause] = rank_pimple(costs, total, x) - before
    return out


def gaps(runs, cal):
    """Rows (dict) of every parallel run against the run of the same
    level, stencil and ranks with the smallest measured PIMPLE: run,
    reference, measured gap, the causes' seconds, unexplained, the
    measured gap of pimpleOversetInterpolate and the twins' gap."""
    serial = {r.group: r for r in runs if r.ranks == 1}
    by = {(r.session, r.level, r.stencil, r.method, r.ranks): r
          for r in runs}
    rows = []
    for a in runs:
        group = [r for r in runs if r.ranks == a.ranks > 1
                 and r.group == a.group]
        if not group or a.group not in serial:
            continue
        b = min(group, key=lambda r: r.measured["pimple"])
        costs = scaling_model.serial_costs(serial[a.group], cal)
        row = {"run": a.name, "method": a.method, "reference": b.method,
               "ranks": a.ranks,
               "gap": a.measured["pimple"] - b.measured["pimple"],
               "interpolate": a.measured["pimpleOversetInterpolate"]
               - b.measured["pimpleOversetInterpolate"]}
        row.update(attribute(a, b, costs))
        row["unexplained"] = row["gap"] - sum(row[c] for c in CAUSES)
        ta = by.get((a.session, a.level, TWIN[a.stencil], a.method,
                     a.ranks))
        tb = by.get((a.session, a.level, TWIN[a.stencil], b.method,
                     a.ranks))
        row["twinGap"] = ta.measured["pimple"] - tb.measured["pimple"] \
            if ta and tb else float("nan")
        rows.append(row)
    return rows


def feature_rows(runs):
    """Per parallel run: the measured PIMPLE and its twin's, pressure
    iterations, and per rank (max; cells also max/mean): cells, faces,
    neighbours, remote donors received, their ranks, halo bytes."""
    by = {(r.session, r.level, r.stencil, r.method, r.ranks): r
          for r in runs}
    out = []
    for r in runs:
        if r.ranks < 2:
            continue
        d = r.decomposition
        twin = by.get((r.session, r.level, TWIN[r.stencil], r.method,
                       r.ranks))
        out.append("| %s | %.3f | %s | %.3f | %.1f | %d (%.3f) | %d | %d | "
                   "%d | %d | %d |" % (
                       r.name, r.measured["pimple"],
                       "%.3f" % twin.measured["pimple"] if twin else "-",
                       r.measured["pimpleOversetInterpolate"],
                       r.iterations, d.cells.max(),
                       d.cells.max()/d.cells.mean(), d.faces.max(),
                       d.neighbours.max(), d.remote_donors.max(),
                       d.donor_ranks.max(), 8*d.faces.max()))
    return out


def report(runs, cal):
    """Markdown lines: the gaps table and the per-run inputs."""
    lines = [
        "## PIMPLE of each method against the fastest at the same ranks",
        "",
        "Seconds per step (measured medians; causes from the calibrated "
        "model `%s`, slowest rank, the runs' own pressure iterations). "
        "twin gap: the same two partitions run with the other stencil "
        "(the same PIMPLE arithmetic)." % (cal,), "",
        "| run | against | measured gap | " + " | ".join(CAUSES)
        + " | unexplained | of it pimpleOversetInterpolate | twin gap |",
        "|---|---|" + "---:|"*(len(CAUSES) + 4)]
    for row in gaps(runs, cal):
        if row["reference"] == row["method"]:
            continue
        lines.append("| %s | %s | %.3f | %s | %.3f | %.3f | %s |" % (
            row["run"], row["reference"], row["gap"],
            " | ".join("%+.3f" % row[c] for c in CAUSES),
            row["unexplained"], row["interpolate"],
            "-" if np.isnan(row["twinGap"]) else "%.3f" % row["twinGap"]))
    lines += [
        "", "## Inputs per run", "",
        "| run | pimple [s] | twin's pimple [s] | pimpleOversetInterpolate "
        "[s] | p iterations per step | cells max (max/mean) | procFaces "
        "max | procPatches max | received max | recvRanks max | "
        "haloBytes max |",
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    return lines + feature_rows(runs)
