# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""The markdown tables of the scaling bench (flapfoam.scaling.summary's data): the
counted structure, the counted traffic, the model's costs, the model
against the timed runs, the model's step per method and ranks, and the
goals set for oversetGraph at 16-48 ranks."""

METHODS = ["simple", "hierarchical", "scotch", "metis", "oversetGraph"]
SHORT = {"inverseDistance": "ID", "octreeInverseDistance": "octree"}
GOAL_RANKS = (16, 32, 48)


def _keys(structure):
    """(method, P) of a level in the order of METHODS, then P."""
    return sorted(structure, key=lambda k: (METHODS.index(k[0]), k[1]))


def structure_table(level, structure):
    lines = [
        "", "### Counted structure: SW %s (%d cells; oversetCouplingsReport, "
        "means over the cycle's poses)" % (
            level, next(iter(structure.values())).cells.sum()), "",
        "| method | ranks | cells max/mean | processor faces | vs scotch "
        "| neighbours max | overset work max/mean | at a pose | acceptors "
        "| remote pair share | remote acceptor share | sweep values max "
        "| vs scotch |",
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for method, p in _keys(structure):
        d = structure[(method, p)]
        scotch = structure.get(("scotch", p))
        ratio = "%.2f" % (d.faces.sum()/scotch.faces.sum()) \
            if scotch is not None else "-"
        sweep = d.sweep_values_max()
        sweep_ratio = "%.2f" % (sweep/scotch.sweep_values_max()) \
            if scotch is not None else "-"
        lines.append("| %s | %d | %.3f | %d | %s | %d | %.2f | %.2f | %d "
                     "| %.1f %% | %.1f %% | %.0f | %s |"
                     % (method, p, d.cells.max()/d.cells.mean(),
                        d.faces.sum(), ratio, d.neighbours.max(),
                        d.work.max()/d.work.mean(),
                        d.work_peak()/d.work.mean(), d.acceptors.sum(),
                        100*d.remote_pair_share(),
                        100*d.remote_acceptor_share(), sweep, sweep_ratio))
    lines += ["", "Overset work max/mean: of the means over the cycle; at "
              "a pose: the busiest rank's at a step (the imbalance at a kept "
              "pose, a mean over them: the model's W_peak). Sweep values "
              "max: what the busiest rank receives per linear-solver sweep, "
              "processor faces plus the donor cells on other ranks (each "
              "once: v1912 puts them in the matrix as remote-stencil "
              "interfaces, in the model's halo)."]
    return lines


def traffic_table(data):
    lines = [
        "", "### Counted traffic: SW %s, motion and stencil only "
        "(oversetMotionCheck), per step and rank" % data["countLevel"], "",
        "Per step: the difference of two runs (libflapFoamMPICounters.so); "
        "remote acceptors: oversetRankReport of the first update (acceptors "
        "with a donor on another rank); memory: peak resident, summed over "
        "the ranks.", "",
        "| method | ranks | stencil | bytes max [MB] | bytes mean [MB] | "
        "messages max | remote acceptors | peak memory [MiB] |",
        "|---|---:|---|---:|---:|---:|---:|---:|"]
    traffic = data["traffic"][data["countLevel"]]
    keys = sorted((k for k in traffic if k[0] in METHODS),
                  key=lambda k: (k[2], METHODS.index(k[0]), k[1]))
    for method, p, stencil in keys:
        e = traffic[(method, p, stencil)]
        b = [s["p2pBytes"] for s in e["perStep"]]
        m = [s["p2pCalls"] for s in e["perStep"]]
        share = e["report"].info.get("remoteShare", float("nan")) \
            if "report" in e else float("nan")
        lines.append("| %s | %d | %s | %.3f | %.3f | %.0f | %.1f %% | %.0f |"
                     % (method, p, SHORT[stencil], max(b)/1e6,
                        sum(b)/len(b)/1e6, max(m), 100*share, e["memory"]))
    lines += ["", "PIMPLE (a flow run minus a motion run, octree, "
              "hierarchical, 2 ranks, per step; the model uses a level's own "
              "where counted, else the count level's):"]
    for level, (s_msg, s_bytes, s_reduce) in sorted(
            (k, v) for k, v in data["pimpleTraffic"].items() if k):
        lines.append("%s %.0f halo messages per neighbour, %.0f sweeps of 8 "
                     "bytes per processor face, %.0f reductions;"
                     % (level, s_msg, s_bytes, s_reduce))
    return lines


def traffic_check_table(data):
    """Traffic counted on levels other than the count level against the
    fit (per step, the rank that sends most)."""
    lines = ["", "### Counted traffic on other levels against the fit "
             "(per step, the rank that sends most)", "",
             "| level | method | ranks | stencil | bytes counted [MB] | fit "
             "[MB] | messages counted | fit | peak memory [MiB] |",
             "|---|---|---:|---|---:|---:|---:|---:|---:|"]
    for level, traffic in sorted(data["traffic"].items()):
        if level == data["countLevel"]:
            continue
        for (method, p, stencil), e in sorted(traffic.items()):
            d = data["structure"][level].get((method, p))
            if d is None or stencil not in data["fits"]:
                continue
            fit = [data["fits"][stencil].predict(p, x) for x in d.pairs]
            lines.append("| %s | %s | %d | %s | %.3f | %.3f | %.0f | %.0f | "
                         "%.0f |" % (
                             level, method, p, SHORT[stencil],
                             max(r["p2pBytes"] for r in e["perStep"])/1e6,
                             max(b for b, _m in fit)/1e6,
                             max(r["p2pCalls"] for r in e["perStep"]),
                             max(m for _b, m in fit), e["memory"]))
    return lines


def costs_table(data):
    alpha, beta = data["machine"]
    lines = [
        "", "### The model's costs (measured here)", "",
        "One message alpha = %.2e s, one byte beta = %.2e s (pingPong.c, 2 "
        "ranks). Traffic fit per rank and step (every counted rank of every "
        "level): value = c0 + c1 (P - 1) + c2 remotePairs. The serial runs of all levels together: "
        "overset = cFix + cWork W with %s." % (alpha, beta, "; ".join(
            "%s cFix %.3f s, cWork %.2f us" % (SHORT[s], c[0], 1e6*c[1])
            for s, c in sorted(data["fixedOverset"].items()))), "",
        "| level | stencil | cCell [us] | cFix [s] | cWork [us] | rbd [s] | "
        "bytes c0, c1, c2 | messages c0, c1, c2 | fit max error (bytes, "
        "messages) |",
        "|---|---|---:|---:|---:|---:|---|---|---|"]
    for (level, stencil), c in sorted(data["costs"].items()):
        f = c.traffic
        lines.append(
            "| %s | %s | %.2f | %.4f | %.2f | %.4f | %s | %s | %.0f %%, "
            "%.0f %% |" % (level, SHORT[stencil], 1e6*c.c_cell, c.c_fix,
                           1e6*c.c_work, c.rbd,
                           ", ".join("%.3g" % x for x in f.bytes),
                           ", ".join("%.3g" % x for x in f.messages),
                           100*f.error[0], 100*f.error[1]))
    return lines


def check_table(data):
    level = data["timeLevel"]
    lines = [
        "", "### The model against the timed runs (SW %s, medians)" % level, "",
        "Measured step: rbd + overset + pimple (the step timers' total "
        "less the rest: writing the fields every step, which the model "
        "leaves out); 2 ranks share this machine's 2 cores with the other "
        "jobs running on it.", "",
        "| method | ranks | stencil | rounds | measured step [s] | "
        "model [s] | error | measured overset [s] | model | measured pimple "
        "[s] | model | total with writing [s] |",
        "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for lv in [level] + [x for x in data["timed"] if x != level]:
        for (method, p, stencil), t in sorted(data["timed"][lv].items()):
            m = data["model"].get((lv, method, p, stencil))
            if m is None:
                continue
            lines.append(
                "| %s%s | %d | %s | %d | %.3f | %.3f | %+.0f %% | %.3f | "
                "%.3f | %.3f | %.3f | %.3f |" % (
                    method, "" if lv == level else " (%s)" % lv, p,
                    SHORT[stencil], t["rounds"], t["parts"], m["total"],
                    100*(m["total"]/t["parts"] - 1), t["overset"],
                    m["overset"], t["pimple"], m["pimple"], t["total"]))
    return lines


def split_table(data):
    """Where the timed runs' pimple goes (runs with the pimpleTimers
    fvOption)."""
    rows = [(lv, key, t) for lv in data["timed"]
            for key, t in sorted(data["timed"][lv].items()) if t.get("split")]
    if not rows:
        return []
    lines = [
        "", "### Where pimple goes (the timed runs, medians)", "",
        "momentum = assembly + solve, pressure = the correctors (of which "
        "the solves), turbulence = `correct()` + its solves, the overset "
        "interpolations inside PIMPLE (calls a step), pressure iterations "
        "a step; the maxima over the ranks (per rank: stepTimersRanks.dat)."
        , "",
        "| level | method | ranks | stencil | pimple [s] | momentum | "
        "pressure (solves) | turbulence | interpolate (calls) | p iterations "
        "|", "|---|---|---:|---|---:|---:|---:|---:|---:|---:|"]
    for lv, (method, p, stencil), t in rows:
        s = t["split"]
        lines.append(
            "| %s | %s | %d | %s | %.3f | %.3f | %.3f (%.3f) | %.3f | %.3f "
            "(%.0f) | %.0f |" % (
                lv, method, p, SHORT[stencil], t["pimple"], s["momentum"],
                s["pressure"], s["pressureSolve"], s["turbulence"],
                s["interpolate"], s["interpolations"], s["pIterations"]))
    return lines


def model_table(data, level):
    model = data["model"]
    ranks = sorted({p for (lv, _m, p, _s) in model if lv == level and p > 1})
    lines = [
        "", "### Model: a step of SW %s [s] (a model, not a measurement)"
        % level, "",
        "| stencil | method | " + " | ".join("%d" % p for p in ranks)
        + " | overset share at %d | efficiency at %d |" % (ranks[-1],
                                                          ranks[-1]),
        "|---|---|" + "---:|"*(len(ranks) + 2)]
    for stencil in data["stencils"]:
        t1 = model[(level, "serial", 1, stencil)]["total"]
        for method in METHODS:
            row = [model.get((level, method, p, stencil)) for p in ranks]
            if not any(row):
                continue
            last = row[-1] or {"overset": float("nan"),
                               "total": float("nan")}
            lines.append("| %s | %s | %s | %.0f %% | %.0f %% |" % (
                SHORT[stencil], method,
                " | ".join("%.3f" % r["total"] if r else "-" for r in row),
                100*last["overset"]/last["total"],
                100*t1/(ranks[-1]*last["total"])))
    return lines


def goals(data, level):
    """The goals of part 3 for oversetGraph at 16-48 ranks."""
    st, model = data["structure"][level], data["model"]
    lines = ["", "### Goals at 16-48 ranks, oversetGraph, SW %s" % level, "",
             "Remote share: acceptors with a donor on another rank (the "
             "couplings' poses kept whole); all remote: every donor on "
             "another rank (the stock log's `remote`); pairs: donor-acceptor "
             "pairs of the cycle; sweep values: what the busiest rank "
             "receives per linear-solver sweep (processor faces and remote "
             "donor cells).", "",
             "| ranks | remote acceptor share <= 20 % | (all remote) | "
             "(remote pair share) | cells max/mean <= 1.05 | processor faces "
             "<= 1.2 x scotch | (sweep values vs scotch) | step (octree) "
             "within 5 % of the best | step (ID) within 5 % of the best |",
             "|---:|---|---|---|---|---|---|---|---|"]
    for p in GOAL_RANKS:
        d, s = st.get(("oversetGraph", p)), st.get(("scotch", p))
        if d is None or s is None:
            continue
        cells = [_best(model, level, p, x) for x in
                 ("octreeInverseDistance", "inverseDistance")]
        lines.append("| %d | %s | %.1f %% | %.1f %% | %s | %s | %.2f x "
                     "| %s | %s |" % (
                         p, _mark(d.remote_acceptor_share(), 0.2, "%.1f %%",
                                  100),
                         100*d.all_remote_acceptor_share(),
                         100*d.remote_pair_share(),
                         _mark(d.cells.max()/d.cells.mean(), 1.05, "%.3f"),
                         _mark(d.faces.sum()/s.faces.sum(), 1.2, "%.2f x"),
                         d.sweep_values_max()/s.sweep_values_max(),
                         cells[0], cells[1]))
    octree = model.get((level, "oversetGraph", 48, "octreeInverseDistance"))
    if octree:
        lines += ["", "Octree overset share of a step at 48 ranks "
                  "(oversetGraph, model): %.1f %% (goal <= 15 %%)."
                  % (100*octree["overset"]/octree["total"])]
    return lines


def _best(model, level, p, stencil):
    steps = {m: model[(level, m, p, stencil)]["total"] for m in METHODS
             if (level, m, p, stencil) in model}
    if "oversetGraph" not in steps:
        return "-"
    best = min(steps, key=steps.get)
    ratio = steps["oversetGraph"]/steps[best]
    return "%s %.3f s (best %s %.3f s, %.2f x)" % (
        "yes" if ratio <= 1.05 else "NO", steps["oversetGraph"], best,
        steps[best], ratio)


def _mark(value, limit, fmt, scale=1):
    return ("yes " if value <= limit else "NO ") + fmt % (scale*value)


def tables(data):
    lines = ["# Scaling bench: where a step goes from 2 to 48 ranks", "",
             "`bench/scaling/run` (docs/benches.md). Counted: exact "
             "figures of each decomposition (structure, traffic); timed: "
             "this 2-core machine; model: `scripts/flapfoam/scaling/model.py`"
             " (its assumptions are in its header)."]
    for level in data["levels"]:
        lines += goals(data, level)
        lines += model_table(data, level)
    lines += check_table(data)
    lines += split_table(data)
    lines += costs_table(data)
    lines += traffic_table(data)
    lines += traffic_check_table(data)
    for level in sorted(data["structure"]):
        lines += structure_table(level, data["structure"][level])
    return lines
