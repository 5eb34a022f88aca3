# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
A planar chain of point masses on revolute joints, by Lagrange's equations
and scipy: the independent reference of the multibody integrators' order
(flapfoam.studies.integrator_order), written apart from the C++.

Joint j turns link j about y at the end of link j - 1 (joint 0 at the
origin); q_j is relative to link j - 1, so the absolute angle of link j
from the downward vertical is phi_j = q_0 + ... + q_j.  Link j is massless
with its point mass m_j at its end, a length L_j from its joint (the tree
of cases/doublePendulum).  With mu_jk the mass beyond links j and k
(sum of m_i, i >= max(j, k)), gravity g downwards:

    T = 1/2 sum_jk mu_jk L_j L_k cos(phi_j - phi_k) phiDot_j phiDot_k
    V = -g sum_j mu_jj L_j cos(phi_j)
    sum_k mu_jk L_j L_k (cos(phi_j - phi_k) phiDdot_k
                         + sin(phi_j - phi_k) phiDot_k^2)
        + g mu_jj L_j sin(phi_j) = Q_j   (absolute angles)

and in q (phi = S q, S lower triangular ones): S^T (M S qDdot + c) = tau.
Prescribed joints take their q, qDot, qDdot from a harmonic motion (the
imposedMotion type of that name); the free ones are solved for, with
tau = 0 on them.  DOP853 at rtol = atol = 1e-12.
"""

from dataclasses import dataclass, field
import math

import numpy as np
from scipy.integrate import solve_ivp


@dataclass(frozen=True)
class Harmonic:
    """q = offset + amplitude cos(2 pi frequency t + phase)."""
    amplitude: float
    frequency: float
    phase: float = 0.0
    offset: float = 0.0

    def __call__(self, t):
        w = 2*math.pi*self.frequency
        arg = w*t + self.phase
        return (self.offset + self.amplitude*math.cos(arg),
                -w*self.amplitude*math.sin(arg),
                -w*w*self.amplitude*math.cos(arg))


@dataclass
class Chain:
    """The chain: lengths and masses per link, the prescribed joints."""
    lengths: np.ndarray
    masses: np.ndarray
    g: float = 9.81
    prescribed: dict = field(default_factory=dict)

    def __post_init__(self):
        self.lengths = np.asarray(self.lengths, dtype=float)
        self.masses = np.asarray(self.masses, dtype=float)
        n = len(self.lengths)
        if len(self.masses) != n or n == 0:
            raise ValueError("lengths %d, masses %d: one of each a link"
                             % (n, len(self.masses)))
        self.free = [j for j in range(n) if j not in self.prescribed]
        self.fixed = sorted(self.prescribed)
        self._S = np.tril(np.ones((n, n)))
        tail = np.cumsum(self.masses[::-1])[::-1]
        j, k = np.meshgrid(range(n), range(n), indexing="ij")
        self._mu_ll = tail[np.maximum(j, k)]*np.outer(self.lengths,
                                                    self.lengths)
        self._gravity = self.g*tail*self.lengths

    def equations(self, q, q_dot):
        """The mass matrix M_q and the bias h_q (velocity products and
        gravity) in joint coordinates: M_q qDdot + h_q = tau."""
        phi, phi_dot = self._S @ q, self._S @ q_dot
        d = phi[:, None] - phi[None, :]
        M = self._mu_ll*np.cos(d)
        c = (self._mu_ll*np.sin(d)) @ phi_dot**2 + self._gravity*np.sin(phi)
        return self._S.T @ M @ self._S, self._S.T @ c

    def prescribed_state(self, t):
        """q, qDot, qDdot of the prescribed joints at t (arrays)."""
        rows = [self.prescribed[j](t) for j in self.fixed]
        return tuple(np.array([r[i] for r in rows]) for i in range(3))

    def accelerations(self, t, q, q_dot):
        """qDdot of every joint and tau of every joint (zero on the free
        ones) at the state, the prescribed joints at t."""
        M, h = self.equations(q, q_dot)
        q_ddot = np.zeros(len(q))
        f, p = self.free, self.fixed
        if p:
            q_ddot[p] = self.prescribed_state(t)[2]
        rhs = -h[f] - M[np.ix_(f, p)] @ q_ddot[p]
        q_ddot[f] = np.linalg.solve(M[np.ix_(f, f)], rhs)
        tau = M @ q_ddot + h
        tau[f] = 0.0
        return q_ddot, tau

    def full_state(self, t, y):
        """q, qDot of every joint from the free joints' y = (q_f, qDot_f)."""
        n, nf = len(self.lengths), len(self.free)
        q, q_dot = np.zeros(n), np.zeros(n)
        q[self.free], q_dot[self.free] = y[:nf], y[nf:]
        if self.fixed:
            qp, q_dot_p, _ = self.prescribed_state(t)
            q[self.fixed], q_dot[self.fixed] = qp, q_dot_p
        return q, q_dot

    def rhs(self, t, y):
        q, q_dot = self.full_state(t, y)
        q_ddot, _ = self.accelerations(t, q, q_dot)
        return np.concatenate([q_dot[self.free], q_ddot[self.free]])

    def energy(self, q, q_dot):
        """T + V, zero hanging at rest."""
        M, _ = self.equations(q, q_dot)
        phi = self._S @ q
        return 0.5*q_dot @ M @ q_dot \
            + float(self._gravity @ (1 - np.cos(phi)))

    def solve(self, q0, q_dot0, times):
        """q and qDot of every joint at the times (rows), from the free
        joints' q0, qDot0 at times[0] (the prescribed ones' entries of q0,
        qDot0 are ignored: their motions give them)."""
        times = np.asarray(times, dtype=float)
        y0 = np.concatenate([np.asarray(q0, float)[self.free],
                             np.asarray(q_dot0, float)[self.free]])
        sol = solve_ivp(self.rhs, (times[0], times[-1]), y0, t_eval=times,
                        method="DOP853", rtol=1e-12, atol=1e-12)
        if not sol.success:
            raise RuntimeError("chain reference: " + sol.message)
        states = [self.full_state(t, y) for t, y in zip(sol.t, sol.y.T)]
        return (np.array([s[0] for s in states]),
                np.array([s[1] for s in states]))
