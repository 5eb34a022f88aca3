# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
References and models, in Python: the Wang kinematics of imposedMotion
(wang), the quasi-steady blade-element wing (quasi_steady), planar chains by
Lagrange's equations (chain_reference), the paper's wing (wing_geometry) and
the paper authors' controllers as flapFoam entries (authors_control).
"""
