# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
Mesh generation: blockMeshDict writing and 1-D cell distributions
(block_mesh), the wing's component mesh and its levels (wing_mesh), the
background cube (background_mesh) and the command line of the cases'
meshGen.py (mesh_gen).
"""
