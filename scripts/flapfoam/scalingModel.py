# License
#     This file is part of flapFoam, derived from OpenFOAM: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
A model of one time step of the drone cases per rank, from what a
decomposition gives each rank (counted: rankTables, mpiCounts) and costs
measured on one machine (bench/scaling).  A model, not a measurement:

    step = rbd + overset + max_r pimple_r

(timedOversetFvMesh waits for the slowest rank after the mesh update, so
the two parts are synchronised separately; rbd is serial, the same on
every rank), with, per rank r of P,

    overset   = cFix + cWork W_peak + max_r (alpha m_r + beta b_r)
    pimple_r  = cCell N_r + alpha sMsg (k_r + q_r) + beta sBytes 8 (F_r + D_r)
                + alpha sReduce 2 ceil(log2 P)

- N_r cells, F_r processor faces, k_r neighbour ranks, W_r overset work
  (fringe, donors, hole-cut candidates: couplingReport's oversetWork, a
  mean over the poses of a cycle); W_peak the busiest rank's at a step:
  max(max_r W_r, oversetWorkAtPose mean_r W_r), with couplingReport's
  oversetWorkAtPose the imbalance of the work at a pose (acceptors and
  donors, a mean over the kept poses; the busiest rank changes with the
  pose, so this is above the imbalance of the cycle's means; max_r W_r
  for a report without it); D_r the donor cells on other ranks its
  acceptors use and q_r the ranks they come from (couplingReport's
  remoteDonors, donorRanks: v1912's dynamicOversetFvMesh puts them in the
  matrix as remote-stencil interfaces, exchanged every linear-solver
  sweep like the processor faces; 0 for a report without them);
- m_r, b_r: the messages and bytes that the stencil sends per step
  (motion and stencil only), from the traffic fit (TrafficFit: counted at
  some (method, P) on one level, fitted against P - 1 and the rank's
  remote donor-acceptor pairs);
- sMsg, sBytes, sReduce: halo exchanges per interface (neighbour rank or
  remote-stencil rank), sweeps by bytes (per face or remote donor) and
  reductions of one PIMPLE step (counted: a flow run minus a motion run,
  2 ranks);
- cCell, cWork: pimple and overset seconds per cell and per unit of
  overset work of the level's serial run; cFix: overset work that every
  rank repeats whatever its share (e.g. search-box voxels, the same on
  every level): 0 where the serial runs of several levels show none;
  alpha, beta: one message and one byte between two ranks (ping-pong).

Assumptions: the work of a rank is proportional to its cells and its
overset work; halo traffic per step does not depend on the level (the
same solver settings); one message costs alpha + bytes beta whatever the
ranks (no contention: a lower bound on a network); no I/O.
"""

import math

import numpy as np


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
    (sMsg, sBytes, sReduce) and the stencil's TrafficFit."""

    def __init__(self, machine, pimple_traffic, traffic):
        self.alpha, self.beta = machine
        self.sMsg, self.sBytes, self.sReduce = pimple_traffic
        self.traffic = traffic
        self.cCell = self.cFix = self.cWork = self.rbd = 0.0

    def fit_overset(self, runs):
        """cFix, cWork from runs [(overset seconds, max_r W_r, modelled
        communication seconds)]: least squares with two runs or more (cFix
        at least 0), cWork alone from one."""
        if len(runs) == 1:
            t, w, c = runs[0]
            self.cFix, self.cWork = 0.0, (t - c)/w
            return
        a = least_squares([[1.0, w] for _t, w, _c in runs],
                          [t - c for t, _w, c in runs])
        if a[0] < 0:
            a = [0.0, least_squares([[w] for _t, w, _c in runs],
                                    [t - c for t, _w, c in runs])[0]]
        self.cFix, self.cWork = a[0], max(a[1], 0.0)


class Decomposition:
    """What a decomposition gives each rank (arrays, index = rank): cells,
    processorFaces, neighbours, oversetWork, remotePairs."""

    def __init__(self, table, neighbours):
        self.ranks = len(table["rows"])
        col = {c: np.array([r[c] for r in table["rows"]])
               for c in table["columns"]}
        self.cells = col["cells"]
        self.faces = col["processorFaces"]
        self.work = col["oversetWork"]
        self.pairs = col["remotePairs"]
        self.acceptors = col["acceptors"]
        self.allPairs = col["pairs"]
        # donor cells on other ranks, each once, and the ranks they come
        # from (0 for a report without them)
        self.sweepCounted = "remoteDonors" in col
        none = np.zeros(self.ranks)
        self.remoteDonors = col.get("remoteDonors", none)
        self.donorRanks = col.get("donorRanks", none)
        self.neighbours = np.asarray(neighbours, float)
        self.info = table["info"]

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
        return self.pairs.sum()/self.allPairs.sum()

    def sweep_values_max(self):
        """The values the busiest rank receives per linear-solver sweep:
        processor faces plus remote donor cells (v1912's remote-stencil
        interfaces); NaN for a report without remoteDonors."""
        if not self.sweepCounted:
            return float("nan")
        return float((self.faces + self.remoteDonors).max())

    def all_remote_acceptor_share(self):
        """Acceptors with every donor on another rank (the stock log's
        "remote") over all acceptors; NaN for a report without them."""
        return float(self.info.get("allRemoteAcceptorShare", float("nan")))

    def remote_acceptor_share(self):
        """Acceptors with a donor on another rank over all acceptors (the
        couplings' poses kept whole; NaN for a report without them)."""
        return float(self.info.get("remoteAcceptorShare", float("nan")))


def stencil_comm(costs, d):
    """Per rank: seconds of the stencil's messages per step."""
    out = []
    for pairs in d.pairs:
        b, m = costs.traffic.predict(d.ranks, pairs) if d.ranks > 1 \
            else (0.0, 0.0)
        out.append(costs.alpha*m + costs.beta*b)
    return np.array(out)


def predict(costs, d):
    """The model's step of decomposition d: dict rbd, overset, pimple,
    total (seconds), oversetComm (the most of any rank) and pimpleComm
    (of the slowest rank)."""
    comm = stencil_comm(costs, d)
    reduce = 2*math.ceil(math.log2(d.ranks)) if d.ranks > 1 else 0
    halo = costs.alpha*(costs.sMsg*(d.neighbours + d.donorRanks)
                        + costs.sReduce*reduce) \
        + costs.beta*costs.sBytes*8*(d.faces + d.remoteDonors)
    pimple = costs.cCell*d.cells + halo
    p = int(np.argmax(pimple))
    step = {"rbd": costs.rbd, "oversetComm": float(comm.max()),
            "pimple": float(pimple[p]), "pimpleComm": float(halo[p])}
    step["overset"] = costs.cFix + costs.cWork*d.work_peak() \
        + step["oversetComm"]
    step["total"] = step["rbd"] + step["overset"] + step["pimple"]
    return step


def serial_decomposition(n_cells, work, pairs):
    """The one-rank 'decomposition' of a mesh (for the serial step)."""
    table = {"columns": ["cells", "processorFaces", "oversetWork",
                         "remotePairs", "acceptors", "pairs"],
             "rows": [{"cells": n_cells, "processorFaces": 0,
                       "oversetWork": work, "remotePairs": 0,
                       "acceptors": 0, "pairs": pairs}],
             "info": {}}
    return Decomposition(table, [0])
