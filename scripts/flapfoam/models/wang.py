# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Analytic Wang kinematics of the imposedMotion entries of a multibody
dictionary (foamDict.readFoamDict).  numpy only.
"""

import math

import numpy as np


def wang_motion(entry):
    """Analytic Wang kinematics of an imposedMotion entry (type wang):
    flapping q = offset + A/asin(K) asin(K cos(theta)),
    pitching q = offset + A/tanh(K) tanh(K sin(theta)),
    theta = 2 pi f t + phase.  Returns f(t) -> (q, qDot, qDdot)."""
    if entry["type"][0] != "wang":
        raise ValueError("imposedMotion entry of type %s, not wang"
                         % entry["type"][0])
    waveform = entry["waveform"][0]
    A = float(entry["amplitude"][0])
    f = float(entry["frequency"][0])
    K = float(entry["K"][0])
    phase = float(entry.get("phase", ["0"])[0])
    offset = float(entry.get("offset", ["0"])[0])
    w = 2.0*math.pi*f

    def evaluate(t):
        theta = w*np.asarray(t, dtype=float) + phase
        c, s = np.cos(theta), np.sin(theta)
        if waveform == "flapping":
            S = A/math.asin(K)
            u, du, ddu = K*c, -K*w*s, -w*w*K*c
            one = 1.0 - u*u
            q = offset + S*np.arcsin(u)
            q_dot = S*du/np.sqrt(one)
            q_ddot = S/np.sqrt(one)*(ddu + u*du*du/one)
        else:
            S = A/math.tanh(K)
            v, dv, ddv = K*s, K*w*c, -w*w*K*s
            th = np.tanh(v)
            sech2 = 1.0/np.cosh(v)**2
            q = offset + S*th
            q_dot = S*dv*sech2
            q_ddot = S*sech2*(ddv - 2.0*th*dv*dv)
        return q, q_dot, q_ddot

    evaluate.amplitude = A
    evaluate.frequency = f
    evaluate.waveform = waveform
    return evaluate


def named_joints(coeffs, wanted):
    """{joint index: wang evaluator, its name the entry's} of the
    imposedMotion entries for which wanted(entry)."""
    joints = {}
    for name, entry in coeffs.get("imposedMotion", {}).items():
        if isinstance(entry, dict) and "joint" in entry and wanted(entry):
            ev = wang_motion(entry)
            ev.name = name
            joints[int(entry["joint"][0])] = ev
    return joints


def imposed_joints(coeffs):
    """{joint index: wang evaluator} of the imposedMotion entries."""
    return named_joints(coeffs, lambda entry: True)


def wang_joints(coeffs):
    """{joint index: wang evaluator} of the imposedMotion entries of type
    wang (other types skipped)."""
    return named_joints(
        coeffs, lambda entry: entry.get("type", [""])[0] == "wang")
