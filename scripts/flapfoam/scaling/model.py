# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
A model of one time step of the drone cases per rank, from what a
decomposition gives each rank (counted: rankTables, mpiCounts, or the
solver's oversetRankReport) and costs measured on one machine (the
level's serial run, the ping-pong), with a few constants calibrated on
the timed runs of a 16-core machine (Calibration; bench/scaling/
results-validate.md says which runs fitted them and how far the model is
from every run).  A model, not a measurement:

    step = rbd + overset + max_r pimple_r

(timedOversetFvMesh waits for the slowest rank after the mesh update, so
the two parts are synchronised separately; rbd is serial, the same on
every rank), with, per rank r of P,

    pimple_r  = G(P) [cCell B(N_r, N) + cIter I1 (k_r + q_r)
                      + beta sBytes 8 (F_r + D_r)]
    overset   = cFix + cWork B(W_peak, W_total) + vParallel (octree, P > 1)
                + bStock (P - 1) (cFix + cWork W_total) (stock stencil)
                + max_r (alpha m_r + beta b_r)
    B(n, N)   = sqrt((n^2 + (N/pSat)^2)/(1 + pSat^-2))
    G(P)      = 1 + growth log2 P

- N_r cells, F_r processor faces, k_r neighbour ranks (processor
  patches), D_r the donor cells it receives from other ranks and q_r the
  ranks they come from (v1912's remote-stencil interfaces, exchanged in
  every linear-solver sweep like the processor faces); W_r overset work
  (couplingReport's oversetWork, or the cells where only the solver's
  oversetRankReport is at hand), W_peak the busiest rank's at a step;
- cCell, cWork: pimple and overset seconds per cell and per unit of
  overset work of the level's serial run; rbd the serial run's; I1 the
  serial run's pressure iterations per step (its log: 4 PBiCGStab
  solves); m_r, b_r the stencil's messages and bytes (TrafficFit, where
  counted); alpha, beta the ping-pong's; sBytes the sweeps per step;
- B(n, N): the time (in serial cells) of a rank with n of the N cells
  when the ranks share one socket's memory bandwidth: its own cells, n,
  while the socket keeps up, the socket's share of all cells, N/pSat,
  past pSat ranks (the two blended); balanced (n = N/P) it is n S(P),
  S(P) = sqrt((1 + (P/pSat)^2)/(1 + pSat^-2)), 1 at P = 1.  The
  bandwidth is spent on all the cells, not P times the busiest rank's:
  an imbalanced partition (simple: the busiest rank 1.4-1.5x the mean
  at 16 ranks) waits on its busiest rank at a less crowded socket.  On
  the pimple and the overset work alike;
- G(P): the pressure iterations per step, I1 G(P) (they grow as the
  DILU preconditioner acts on smaller blocks);
- cIter: seconds per interface (neighbour or remote-stencil rank) and
  pressure iteration: the halo exchanges of the sweeps and the boundary
  updates, waiting for the neighbour included (per sweep, two an
  iteration, 28-70x the ping-pong's alpha on the 16-core machine: not a
  latency, a calibrated cost);
- vParallel: the octree stencil's voxel exchange (patchVoxelExchange),
  the same on every level, 0 in serial; bStock: the stock
  inverseDistance's overset work per extra rank, a share of its serial
  overset (its search sends every rank's cells to every rank whose box
  overlaps: the part grows with P).

Assumptions: one rank per core on one socket (B says nothing of two
sockets or of nodes); the work of a rank is proportional to its cells
and its overset work; halo bytes cost beta (they are negligible beside
cIter); the pressure iterations follow G(P), the same for every method;
no I/O.  What it cannot see: run-to-run changes of the machine (one
configuration's step moves by a median 1.15x, p90 1.37x, over three
rounds on the 16-core machine: compare it with medians over rounds), the
differences between sessions beyond their serial runs (the same
partition 1.14-1.29x slower against its serial run in one session than
in another), and the cell order of a rank's matrix.
"""

import dataclasses
import math

import numpy as np

from flapfoam.bench import rank_tables

STOCK = "inverseDistance"
OCTREE = "octreeInverseDistance"


@dataclasses.dataclass(frozen=True)
class Calibration:
    """The constants fitted to timed runs (see the module's docstring):
    pSat [ranks], cIter [s per interface and pressure iteration], growth
    [pressure iterations per doubling of the ranks, a share of the serial
    run's], vParallel [s], bStock [a share of the serial overset per extra
    rank], iterations (I1 where a level's serial iterations are unknown)."""
    p_sat: float
    c_iter: float
    growth: float
    v_parallel: float
    b_stock: float
    iterations: float = 91.2


# Fitted by flapfoam.scaling.validate.calibrate on CALIBRATION_RUNS (the
# hierarchical and scotch runs) of both sessions of bench/scaling/measured
# (16-core Xeon, one socket: scaling-16core-*.tar.gz, one round, and
# device-2026-11-26, the medians of three rounds); simple, metis and
# oversetGraph are held out (bench/scaling/results-validate.md).
CALIBRATION = Calibration(p_sat=14.2, c_iter=1.81e-05, growth=0.0598,
                          v_parallel=0.0245, b_stock=0.0953)
CALIBRATION_RUNS = ("*-hierarchical-*", "*-scotch-*")


def slowdown(ranks, p_sat):
    """S(P): a rank's compute time relative to serial when P ranks share
    the socket's memory bandwidth."""
    return math.sqrt((1 + (ranks/p_sat)**2)/(1 + p_sat**-2))


def shared_bandwidth(own, total, p_sat):
    """B(n, N): a rank's compute, in serial cells, with OWN of the TOTAL
    cells (or units of work) when all ranks share the socket's memory
    bandwidth (see the module's docstring); OWN may be an array."""
    return np.sqrt((np.square(own) + (total/p_sat)**2)/(1 + p_sat**-2))


def iteration_growth(ranks, growth):
    """G(P): pressure iterations per step relative to serial."""
    return 1 + growth*math.log2(ranks)


def least_squares(rows, values):
    """Coefficients of values ~ rows @ c (least squares)."""
    c, *_ = np.linalg.lstsq(np.asarray(rows, float),
                            np.asarray(values, float), rcond=None)
    return c


class TrafficFit:
    """Per-rank bytes and messages that a stencil sends per step:
    value = c0 + c1 (P - 1) + c2 remotePairs_r, fitted to counted rows
    (P, remotePairs_r, bytes, messages)."""

    def __init__(self, rows):
        if len(rows) < 3:
            raise ValueError("TrafficFit: %d counted rows, need 3"
                             % len(rows))
        x = [self.features(p, pairs) for p, pairs, _b, _m in rows]
        self.bytes = least_squares(x, [r[2] for r in rows])
        self.messages = least_squares(x, [r[3] for r in rows])
        fit = np.array([self.predict(p, pairs) for p, pairs, _b, _m in rows])
        measured = np.array([[r[2], r[3]] for r in rows])
        scale = np.maximum(measured.max(axis=0), 1)
        self.error = np.abs(fit - measured).max(axis=0)/scale

    @staticmethod
    def features(p, pairs):
        return [1.0, p - 1.0, pairs]

    def predict(self, p, pairs):
        """(bytes, messages) per step of a rank of P with PAIRS remote
        pairs (never negative)."""
        x = np.array(self.features(p, pairs))
        return max(x @ self.bytes, 0.0), max(x @ self.messages, 0.0)


class Costs:
    """The measured costs of one stencil (seconds): cCell, cFix, cWork,
    rbd, and the machine's alpha, beta; the PIMPLE traffic per step
    (sMsg, sBytes, sReduce: counted; sBytes enters the model) and the
    stencil's TrafficFit (None: no stencil traffic counted); stencil
    (STOCK or OCTREE), iterations (I1, None: unknown) and the
    Calibration."""

    def __init__(self, machine, pimple_traffic, traffic,
                 calibration=CALIBRATION):
        self.alpha, self.beta = machine
        self.s_msg, self.s_bytes, self.s_reduce = pimple_traffic
        self.traffic = traffic
        self.calibration = calibration
        self.stencil = OCTREE
        self.iterations = None
        self.c_cell = self.c_fix = self.c_work = self.rbd = 0.0

    def serial_iterations(self):
        """I1: the level's serial pressure iterations per step (the
        calibration's where unknown)."""
        return self.iterations or self.calibration.iterations

    def fit_overset(self, runs):
        """cFix, cWork from runs [(overset seconds, max_r W_r, modelled
        communication seconds)]: least squares with two runs or more (cFix
        at least 0), cWork alone from one."""
        if len(runs) == 1:
            t, w, c = runs[0]
            self.c_fix, self.c_work = 0.0, (t - c)/w
            return
        a = least_squares([[1.0, w] for _t, w, _c in runs],
                          [t - c for t, _w, c in runs])
        if a[0] < 0:
            a = [0.0, least_squares([[w] for _t, w, _c in runs],
                                    [t - c for t, _w, c in runs])[0]]
        self.c_fix, self.c_work = a[0], max(a[1], 0.0)


class Decomposition:
    """What a decomposition gives each rank (arrays, index = rank): cells,
    processorFaces, neighbours, oversetWork, remotePairs."""

    def __init__(self, table, neighbours):
        self.ranks = len(table.rows)
        col = {c: np.array([r[c] for r in table.rows]) for c in table.columns}
        self.cells = col["cells"]
        self.faces = col["processorFaces"]
        self.work = col["oversetWork"]
        self.pairs = col["remotePairs"]
        self.acceptors = col["acceptors"]
        self.all_pairs = col["pairs"]
        # donor cells on other ranks, each once, and the ranks they come
        # from (0 for a report without them)
        self.sweep_counted = "remoteDonors" in col
        none = np.zeros(self.ranks)
        self.remote_donors = col.get("remoteDonors", none)
        self.donor_ranks = col.get("donorRanks", none)
        self.neighbours = np.asarray(neighbours, float)
        self.info = table.info

    @classmethod
    def from_rank_report(cls, report):
        """The decomposition of a solver's oversetRankReport table
        (rankTables.read_table): cells, procFaces, procPatches (the
        neighbours), received and recvRanks (remote donor cells and
        their ranks), acceptors, remoteSlots (the remote pairs); the
        overset work taken as the cells (the report counts no work)."""
        rows = [{"cells": r["cells"], "processorFaces": r["procFaces"],
                 "oversetWork": r["cells"], "remotePairs": r["remoteSlots"],
                 "acceptors": r["acceptors"], "pairs": r["acceptors"],
                 "remoteDonors": r["received"], "donorRanks": r["recvRanks"]}
                for r in report.rows]
        table = rank_tables.RankTable(columns=list(rows[0]), rows=rows)
        return cls(table, [r["procPatches"] for r in report.rows])

    def work_peak(self):
        """The busiest rank's overset work at a step: the work's
        imbalance at a pose (oversetWorkAtPose) times its mean, at least
        the largest of the cycle's means (that alone for a report
        without it)."""
        at_pose = float(self.info.get("oversetWorkAtPose", 0.0))
        return max(float(self.work.max()), at_pose*float(self.work.mean()))

    def remote_pair_share(self):
        """Donor-acceptor pairs of the cycle with the donor on another
        rank, over all pairs."""
        return self.pairs.sum()/self.all_pairs.sum()

    def sweep_values_max(self):
        """The values the busiest rank receives per linear-solver sweep:
        processor faces plus remote donor cells (v1912's remote-stencil
        interfaces); NaN for a report without remoteDonors."""
        if not self.sweep_counted:
            return float("nan")
        return float((self.faces + self.remote_donors).max())

    def all_remote_acceptor_share(self):
        """Acceptors with every donor on another rank (the stock log's
        "remote") over all acceptors; NaN for a report without them."""
        return float(self.info.get("allRemoteAcceptorShare", float("nan")))

    def remote_acceptor_share(self):
        """Acceptors with a donor on another rank over all acceptors (the
        couplings' poses kept whole; NaN for a report without them)."""
        return float(self.info.get("remoteAcceptorShare", float("nan")))


def stencil_comm(costs, d):
    """Per rank: seconds of the stencil's messages per step (0 without a
    TrafficFit)."""
    out = []
    for pairs in d.pairs:
        b, m = costs.traffic.predict(d.ranks, pairs) \
            if d.ranks > 1 and costs.traffic is not None else (0.0, 0.0)
        out.append(costs.alpha*m + costs.beta*b)
    return np.array(out)


def pimple_ranks(costs, d, iterations=None):
    """Per rank: (pimple seconds, its halo part) of a step.  ITERATIONS:
    the pressure iterations per step where known (a measured run's), else
    I1 G(P)."""
    cal = costs.calibration
    i1 = costs.serial_iterations()
    grow = iterations/i1 if iterations else \
        iteration_growth(d.ranks, cal.growth)
    interfaces = d.neighbours + d.donor_ranks
    halo = grow*(i1*cal.c_iter*interfaces
                 + costs.beta*costs.s_bytes*8*(d.faces + d.remote_donors))
    work = grow*costs.c_cell*shared_bandwidth(d.cells, float(d.cells.sum()),
                                             cal.p_sat)
    return work + halo, halo


def overset_work(costs, d):
    """Seconds of the overset work of a step (no messages): the busiest
    rank's, with the shared bandwidth, plus the stencil's parallel
    part."""
    cal = costs.calibration
    t = costs.c_fix + costs.c_work*float(shared_bandwidth(
        d.work_peak(), float(d.work.sum()), cal.p_sat))
    if d.ranks > 1 and costs.stencil == STOCK:
        t += cal.b_stock*(d.ranks - 1)*(costs.c_fix
                                       + costs.c_work*float(d.work.sum()))
    elif d.ranks > 1:
        t += cal.v_parallel
    return t


def predict(costs, d, iterations=None):
    """The model's step of decomposition d: dict rbd, overset, pimple,
    total (seconds), oversetComm (the most of any rank) and pimpleComm
    (the halo of the slowest rank).  ITERATIONS: see pimple_ranks."""
    comm = stencil_comm(costs, d)
    pimple, halo = pimple_ranks(costs, d, iterations)
    p = int(np.argmax(pimple))
    step = {"rbd": costs.rbd, "oversetComm": float(comm.max()),
            "pimple": float(pimple[p]), "pimpleComm": float(halo[p]),
            "slowestRank": p}
    step["overset"] = overset_work(costs, d) + step["oversetComm"]
    step["total"] = step["rbd"] + step["overset"] + step["pimple"]
    return step


def serial_decomposition(n_cells, work, pairs):
    """The one-rank 'decomposition' of a mesh (for the serial step)."""
    table = rank_tables.RankTable(
        columns=["cells", "processorFaces", "oversetWork", "remotePairs",
                 "acceptors", "pairs"],
        rows=[{"cells": n_cells, "processorFaces": 0, "oversetWork": work,
               "remotePairs": 0, "acceptors": 0, "pairs": pairs}])
    return Decomposition(table, [0])


# The stencils of the timed runs' names
STENCILS = {"octree": OCTREE, "ID": STOCK}


def serial_costs(serial, cal):
    """The Costs of a level and stencil from its serial run (a
    scaling_validate Run: machine, decomposition, stencil, measured parts,
    iterations)."""
    costs = Costs(serial.machine, (0.0, 0.0, 0.0), None, cal)
    n = float(serial.decomposition.cells.sum())
    costs.stencil = STENCILS[serial.stencil]
    costs.c_cell = serial.measured["pimple"]/n
    costs.c_work = serial.measured["overset"]/n
    costs.rbd = serial.measured["rbd"]
    costs.iterations = serial.iterations
    costs.s_bytes = 2*serial.iterations  # two sweeps per BiCGStab iteration
    return costs
