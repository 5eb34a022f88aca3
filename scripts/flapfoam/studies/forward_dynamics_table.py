# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The table of bench/forwardDynamics: the Google Benchmark JSON of
flapFoamBench-forwardDynamics (eABA and stock forward dynamics per tree,
aggregates over interleaved repetitions) as markdown:

    flapfoam forward_dynamics_table BENCHMARK.json > results.md
"""

import argparse
import json
import sys

from flapfoam.errors import FlapFoamError, run_tool

UNITS = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}


def aggregates(data):
    """({(tree, variant): {aggregate: value [ns], cv as a fraction}}, the
    trees, SW first) of the benchmark's aggregate rows."""
    agg = {}
    trees = []
    for b in data["benchmarks"]:
        if b.get("run_type") != "aggregate":
            continue
        tree, variant = b["run_name"].split("/")
        if tree not in trees:
            trees.append(tree)
        value = b["real_time"]
        if b["aggregate_name"] != "cv":
            value *= UNITS[b["time_unit"]]
        agg.setdefault((tree, variant), {})[b["aggregate_name"]] = value
    trees.sort(key=lambda t: (not t.startswith("SW"), t))
    return agg, trees


def row(tree, e, s):
    """A tree's row: medians (cv), their ratio, minima and their ratio."""
    text = "| %s | %.0f (%.0f %%) | %.0f (%.0f %%) | %.2f |" % (
        tree, e["median"], 100*e.get("cv", 0), s["median"],
        100*s.get("cv", 0), e["median"]/s["median"])
    if "min" in e and "min" in s:
        return text + " %.0f | %.0f | %.2f |" % (e["min"], s["min"],
                                                 e["min"]/s["min"])
    return text + " | | |"


def table(data):
    """The markdown lines of the benchmark's JSON (a dict)."""
    ctx = data["context"]
    agg, trees = aggregates(data)
    reps = next(b["repetitions"] for b in data["benchmarks"])
    lines = [
        "# Forward dynamics: time per call", "",
        "eABA: `eABAModel::forwardDynamics` with the wing's two revolute "
        "joints prescribed.  Stock: `rigidBodyModel::forwardDynamics` (ABA, "
        "every joint free) on the same model object and state.  Wall time "
        "per call over %d repetitions interleaved at random: median "
        "(coefficient of variation) and minimum." % reps, "",
        "| tree | eABA median [ns] | stock median [ns] | eABA/stock (median) "
        "| eABA min [ns] | stock min [ns] | eABA/stock (min) |",
        "|------|---:|---:|---:|---:|---:|---:|"]
    for tree in trees:
        e = agg.get((tree, "eABA"), {})
        s = agg.get((tree, "stock"), {})
        if "median" in e and "median" in s:
            lines.append(row(tree, e, s))
    lines += ["", "Machine: %d CPUs at %s MHz, load average %s; %s, %s.  "
              "(The benchmark library's own build type, %s, does not affect "
              "the timed code.)" % (
                  ctx.get("num_cpus", 0), ctx.get("mhz_per_cpu", "?"),
                  " ".join("%.2f" % x for x in ctx.get("load_avg", [])),
                  ctx.get("host_name", "?"), ctx.get("date", "?"),
                  ctx.get("library_build_type", "?"))]
    return lines


def main(argv=None):
    p = argparse.ArgumentParser(prog="flapfoam forward_dynamics_table",
                                description=__doc__.split("\n\n")[0])
    p.add_argument("json", metavar="BENCHMARK.json",
                   help="Google Benchmark's --benchmark_out file")
    path = p.parse_args(argv).json
    try:
        with open(path) as f:
            data = json.load(f)
    except (OSError, ValueError) as e:
        raise FlapFoamError("forward_dynamics_table: %s: %s" % (path, e))
    print("\n".join(table(data)))
    return 0


if __name__ == "__main__":
    sys.exit(run_tool(main))
