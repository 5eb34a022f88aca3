# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""bench/forwardDynamics' table (flapfoam.studies.forward_dynamics_table) of a
made-up Google Benchmark JSON."""

from flapfoam.studies import forward_dynamics_table as fdt
def bench(name, aggregate, value, unit="ns"):
    return {"run_name": name, "run_type": "aggregate", "repetitions": 10,
            "aggregate_name": aggregate, "real_time": value,
            "time_unit": unit}


DATA = {
    "context": {"num_cpus": 2, "mhz_per_cpu": 2400, "load_avg": [0.5, 0.25],
                "host_name": "h", "date": "d", "library_build_type": "release"},
    "benchmarks": [
        bench("BW/eABA", "median", 2.0, "us"), bench("BW/eABA", "cv", 0.05),
        bench("BW/stock", "median", 1000.0), bench("BW/stock", "cv", 0.1),
        bench("SW/eABA", "median", 900.0), bench("SW/eABA", "min", 850.0),
        bench("SW/stock", "median", 600.0), bench("SW/stock", "min", 500.0),
        {"run_name": "SW/eABA", "run_type": "iteration", "repetitions": 10,
         "real_time": 1e9, "time_unit": "ns"}]}


def test_rows_sw_first_in_nanoseconds():
    lines = fdt.table(DATA)
    rows = [x for x in lines if x.startswith("| SW") or x.startswith("| BW")]
    assert rows == ["| SW | 900 (0 %) | 600 (0 %) | 1.50 | 850 | 500 | 1.70 |",
                    "| BW | 2000 (5 %) | 1000 (10 %) | 2.00 | | | |"]
    assert "over 10 repetitions" in lines[2]
    assert lines[-1].startswith("Machine: 2 CPUs at 2400 MHz, load average"
                                " 0.50 0.25; h, d.")
