# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Single-wing drone (SW) geometry: the semi-elliptical thin-plate wing of
Poletti et al. (docs/paper.md section 3, Table 1) and its analytic surface area.

Frame (phi = alpha = 0): flapping axis z through the origin, stroke plane x-y,
the wing spans +y from y = R0 (root) to y = R0 + R (tip), chord along x,
thickness along z.  The planform is symmetric about the pitch axis (the y
axis: x = 0, z = 0), so the leading and trailing edges are at
x = -c(r)/2 and x = +c(r)/2, with r = y - R0 and

    c(r) = c_r sqrt(1 - (r/R)^2),   c_r = 4 cbar/pi.

The planform is the half ellipse with semi-axes a = c_r/2 (x) and R (y),
centred on (0, R0); its edge is E(tau) = (a cos tau, R0 + R sin tau),
tau in [0, pi] (tau = pi: root leading edge, pi/2: tip, 0: root trailing
edge).  No truncation: the mesh follows the ellipse up to the tip.

The wing is a plate of thickness t: |z| <= t/2.  Its wetted surface
("wing" patch) = top + bottom (2 S) + the edge band of height t along the
curved edge (half the perimeter of the ellipse) and the straight root edge
(length c_r):

    A = 2 S + t (P/2 + c_r),   S = pi/4 c_r R = R cbar,
    P/2 = 2 R E(m),  m = 1 - (a/R)^2   (E: complete elliptic integral of
                                         the second kind, parameter m)
"""

import argparse
import math

import numpy as np

# Table 1 (SI units)
R = 0.05            # span [m]
R0 = 0.0225         # root offset from the flapping axis [m]
CBAR = 0.015        # mean chord [m]
THICKNESS = 0.00045 # plate thickness [m]
CROOT = 4.0*CBAR/math.pi   # root chord [m]
A = 0.5*CROOT       # semi-axis along x [m]


def chord(r):
    """Local chord c(r), r = distance from the root along the span."""
    r = np.asarray(r, dtype=float)
    return CROOT*np.sqrt(np.clip(1.0 - (r/R)**2, 0.0, None))


def planform_area():
    """S = pi/4 c_r R (= R cbar)."""
    return 0.25*math.pi*CROOT*R


def ellipe_m(m):
    """Complete elliptic integral of the second kind E(m) (parameter m),
    by the arithmetic-geometric mean (no scipy needed)."""
    a0, g0 = 1.0, math.sqrt(1.0 - m)
    s = 0.5*m
    p = 0.5
    while abs(a0 - g0) > 1e-16:
        a1 = 0.5*(a0 + g0)
        g1 = math.sqrt(a0*g0)
        c1 = 0.5*(a0 - g0)
        p *= 2.0
        s += p*c1*c1
        a0, g0 = a1, g1
    return (1.0 - s)*0.5*math.pi/a0


def half_perimeter():
    """Length of the curved (leading edge - tip - trailing edge) edge."""
    m = 1.0 - (A/R)**2
    return 2.0*R*ellipe_m(m)


def wing_area():
    """Analytic wetted area of the plate: 2 S + t (P/2 + c_r)."""
    return 2.0*planform_area() + THICKNESS*(half_perimeter() + CROOT)


def edge_point(tau):
    """Point E(tau) on the planform edge (x, y)."""
    tau = np.asarray(tau, dtype=float)
    return np.stack([A*np.cos(tau), R0 + R*np.sin(tau)], axis=-1)


def edge_normal(tau):
    """Outward unit normal of the planform edge at E(tau)."""
    tau = np.asarray(tau, dtype=float)
    n = np.stack([np.cos(tau)/A, np.sin(tau)/R], axis=-1)
    return n/np.linalg.norm(n, axis=-1, keepdims=True)


def radius_of_gyration():
    """R2 = sqrt(int_{R0}^{R0+R} c(r - R0) r^2 dr / S), r from the flapping
    axis (closed form; checked against radiusOfGyrationQuadrature)."""
    return math.sqrt(R0**2 + 8.0/(3.0*math.pi)*R0*R + 0.25*R**2)


def radius_of_gyration_quadrature(n=200001):
    """The same integral by the trapezoidal rule in tau, r = R0 + R sin(tau)
    (smooth integrand despite the square-root tip)."""
    tau = np.linspace(0.0, 0.5*math.pi, n)
    rho = R*np.sin(tau)
    w = chord(rho)*(R0 + rho)**2*R*np.cos(tau)
    integral = np.trapz(w, tau)
    return math.sqrt(integral/planform_area())


def pose_matrix(phi_deg, alpha_deg):
    """The wing's rotation at flapping angle phi (about z) and pitching
    angle alpha (about the pitch axis y), in degrees."""
    phi, alpha = np.radians(phi_deg), np.radians(alpha_deg)
    Rz = np.array([[np.cos(phi), -np.sin(phi), 0],
                   [np.sin(phi), np.cos(phi), 0], [0, 0, 1]])
    Ry = np.array([[np.cos(alpha), 0, np.sin(alpha)], [0, 1, 0],
                   [-np.sin(alpha), 0, np.cos(alpha)]])
    return Rz @ Ry


def summary():
    return {
        "R": R, "R0": R0, "cbar": CBAR, "thickness": THICKNESS,
        "rootChord": CROOT,
        "planformArea": planform_area(),
        "halfPerimeter": half_perimeter(),
        "wingAreaAnalytic": wing_area(),
    }


def main(argv=None):
    argparse.ArgumentParser(
        prog="flapfoam wing_geometry",
        description="Prints the single-wing drone's Table 1 geometry and "
                    "its analytic areas.").parse_args(argv)
    for k, v in summary().items():
        print("%-18s %.10g" % (k, v))


if __name__ == "__main__":
    main()
