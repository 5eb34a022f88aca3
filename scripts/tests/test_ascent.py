# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""flapfoam.studies.ascent: the figures of a production ascent on small data made
here (cycle ends, the LEV table, the cost, the gaps to a model, the
wall-clock of the logs, the thinned flight data)."""

import h5py
import numpy as np
import pytest

from flapfoam.studies import ascent
def test_cycle_ends_are_the_values_at_k_over_f():
    t = np.linspace(0, 0.101, 1000)
    ends = ascent.at_cycle_ends(t, 3*t, 20.0)
    assert ends == pytest.approx([0.15, 0.3], abs=1e-12)


def lev_file(folder, rows):
    folder.mkdir(parents=True)
    with open(folder / "levStatistics.dat", "w") as fh:
        fh.write("# Leading-edge vortex of cellZone wing\n# Time volume "
                 "circulation nCells\n")
        for r in rows:
            fh.write("%.10g %.10g %.10g 7\n" % r)


def test_lev_rows_of_every_start_and_the_paper_phases(tmp_path):
    base = tmp_path / "postProcessing" / "lev"
    lev_file(base / "0", [(0.0125, 1, 1), (0.0375, 2.0, 4.0)])
    lev_file(base / "0.4", [(0.4875, 1.98, 3.68), (0.9375, 1.84, 3.6)])
    lev = ascent.lev_table(str(tmp_path))
    assert lev[:, 0] == pytest.approx([0.0125, 0.0375, 0.4875, 0.9375])
    vol, circ = ascent.lev_relative(lev, 20.0, [0.75, 9.75, 18.75])
    assert vol == [100.0, 99.0, 92.0] and circ == [100.0, 92.0, 90.0]
    # a missing phase is None; without the first, all are
    assert ascent.lev_relative(lev[:3], 20.0, [0.75, 9.75, 18.75])[0] == \
        [100.0, 99.0, None]
    assert ascent.lev_relative(lev[2:], 20.0, [0.75, 9.75])[1] == \
        [None, None]


def test_core_hours_of_the_paper_run_are_96():
    # 501k cells, 48 cores, 5 cycles in 5 h (hierarchical)
    assert ascent.core_hours(5*3600, 48, 5, 501e3) == \
        pytest.approx(95.8, abs=0.05)


def test_gaps_to_a_model_over_the_run():
    t = np.linspace(0, 1, 101)
    q = np.column_stack([0.8*t, -0.05*t])
    run = ascent.Flight(t, q, None, 20.0, {})
    model = ascent.Flight(t[::2], q[::2] + [0.1, 0.03], None, 20.0, {})
    dx, dz = ascent.max_gaps(run, model)
    assert (dx, dz) == pytest.approx((0.03, 0.1), abs=1e-12)


def test_wall_clock_sums_the_last_clock_of_every_log(tmp_path):
    (tmp_path / "previous").mkdir()
    for name, clocks in (("log.overPimpleDyMFoam", (1, 60)),
                         ("log.overPimpleDyMFoam.0.0375", (2, 30, 300)),
                         ("previous/log.overPimpleDyMFoam.0.0375", (5,))):
        (tmp_path / name).write_text("".join(
            "ExecutionTime = %d s  ClockTime = %d s\n" % (c, c)
            for c in clocks))
    assert ascent.wall_clock(str(tmp_path)) == 365


def test_thinned_copy_keeps_the_last_row_and_says_so(tmp_path):
    src, dst = tmp_path / "a.h5", tmp_path / "b.h5"
    n = 1001
    with h5py.File(src, "w") as f:
        f.create_dataset("time", data=np.arange(n)*1e-3)
        f.create_dataset("joints/q", data=np.ones((n, 5)))
        f.attrs["level"] = "tiny"
    k = ascent.thin_copy(str(src), str(dst), 48*100)
    with h5py.File(dst, "r") as f:
        assert k == 11 and f["time"][-1] == pytest.approx(1.0)
        assert len(f["time"]) == len(f["joints/q"]) == 92
        assert f.attrs["level"] == "tiny"
        assert f.attrs["thinning"] == "every 11-th row of 1001 (and the last)"
    assert ascent.thin_copy(str(src), str(dst), 1e9) == 1


def test_lift_peaks_of_each_half_of_the_whole_cycles():
    f = 20.0
    t = np.linspace(0, 2.5/f, 2501)         # 2.5 cycles, 1000 rows a cycle
    phase = (t*f) % 1
    cz = np.where(phase < 0.5, 3.0, 2.0)*np.sin(2*np.pi*phase)**2
    # the row of t_k holds the load of t_{k-1}
    c = np.zeros((len(t), 3))
    c[1:, 1] = cz[:-1]
    run = ascent.Flight(t, np.zeros((len(t), 3)), c, f, {})
    peaks = ascent.lift_peaks(run, [1, 2, 3])
    assert sorted(peaks) == [1, 2]            # cycle 3 is not whole
    for n in (1, 2):
        assert peaks[n] == pytest.approx([3.0, 2.0], abs=2e-3)


def test_wing_coefficients_plot_the_cfd_at_its_flow_times_and_the_qs(
        monkeypatch):
    t = np.linspace(0.0, 0.1, 11)
    c = np.column_stack([np.sin(40*np.pi*t), 2 + np.cos(40*np.pi*t), 0*t])
    run = ascent.Flight(t, np.zeros((11, 3)), c, 20.0, {})
    qs = ascent.Flight(t, np.zeros((11, 3)), 2*c, 20.0, {})
    shown = {}
    monkeypatch.setattr(ascent, "save",
                        lambda fig, out, name: shown.update(fig=fig, name=name))
    ascent.plot_coefficients(run, [("vacuum", qs, "--"), ("QS", qs, ":")],
                             "unused")
    assert shown["name"] == "wingCoefficients.png"
    for ax, i in zip(shown["fig"].axes, (0, 1)):
        lines = {ln.get_label(): ln for ln in ax.get_lines()
                 if not ln.get_label().startswith("_")}
        assert set(lines) == {"CFD", "QS"}       # no vacuum: it has no air
        np.testing.assert_allclose(lines["CFD"].get_xdata(), t[:-1]*20.0)
        np.testing.assert_allclose(lines["CFD"].get_ydata(), c[1:, i])
        np.testing.assert_allclose(lines["QS"].get_ydata(), 2*c[:, i])
