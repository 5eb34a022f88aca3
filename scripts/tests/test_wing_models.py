# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""The quasi-steady reference's blade elements (flapfoam.models.quasi_steady), the
wing's geometry and the mesh levels (wingGeometry, wingMesh)."""

import math

import numpy as np
import pytest

from flapfoam.models import wing_geometry as geo
from flapfoam.mesh.background_mesh import BACKGROUND, background_cell_size
from flapfoam.models.quasi_steady import Wing
from flapfoam.mesh.wing_mesh import LEVELS


def wing(**extra):
    entry = {"length": ["0.05"], "nStrips": ["400"],
             "chordDistribution": ["semiElliptic"], "meanChord": ["0.015"],
             "span": ["(", "0", "1", "0", ")"],
             "chord": ["(", "1", "0", "0", ")"],
             "root": ["(", "0", "0.0225", "0", ")"], "rho": ["1.2"]}
    entry.update({k: [v] for k, v in extra.items()})
    return Wing(entry)


def test_strips_cover_the_semi_elliptic_planform():
    w = wing()
    assert w.area.sum() == pytest.approx(geo.planform_area(), rel=1e-4)
    assert geo.planform_area() == pytest.approx(geo.R*geo.CBAR, rel=1e-15)


def test_no_force_at_rest_in_still_air():
    F, M = wing().force(np.eye(3), np.zeros(3), np.zeros(3), np.zeros(3))
    assert np.all(F == 0) and np.all(M == 0)


def test_flow_along_the_chord_is_pure_drag_cd0():
    w = wing(CD0="0.4")
    U = 3.0
    # the wing moves along -chord: the air comes along +chord
    F, _ = w.force(np.eye(3), np.zeros(3), np.array([-U, 0, 0]), np.zeros(3))
    q = 0.5*1.2*U**2*w.area.sum()
    assert F[0] == pytest.approx(0.4*q, rel=1e-12)
    assert abs(F[1]) < 1e-15 and abs(F[2]) < 1e-15


def test_lift_at_45_degrees_is_normal_to_the_flow_and_scales_with_u2():
    w = wing(CL="1.2", CD0="0.4", CD1="1.0")
    v = np.array([-1.0, 0, -1.0])/math.sqrt(2)       # air from 45 deg
    F1, _ = w.force(np.eye(3), np.zeros(3), v, np.zeros(3))
    F2, _ = w.force(np.eye(3), np.zeros(3), 2*v, np.zeros(3))
    assert F2 == pytest.approx(4*F1, rel=1e-12)
    q = 0.5*1.2*w.area.sum()
    drag = F1 @ (-v)
    lift = np.linalg.norm(F1 - drag*(-v))
    assert lift == pytest.approx(1.2*q, rel=1e-12)          # CL sin(2 alpha)
    assert drag == pytest.approx((0.4 + 1.0)*q, rel=1e-12)  # CD0 + CD1


def test_radius_of_gyration_closed_form_equals_quadrature():
    assert geo.radius_of_gyration() == pytest.approx(
        geo.radius_of_gyration_quadrature(), rel=1e-8)


def test_levels_refine_in_order():
    order = ["tiny", "coarse", "medium", "fine", "finePlus"]
    h = [background_cell_size(LEVELS[n], BACKGROUND) for n in order]
    assert all(a > b for a, b in zip(h, h[1:]))
    assert h[1] == pytest.approx(0.3/(12*2**3))           # coarse: 3.13 mm
    for key in ("n_s", "n_l", "n_c"):
        counts = [getattr(LEVELS[n], key) for n in order]
        assert counts == sorted(counts)
    ds = [LEVELS[n].ds_e for n in order]
    assert ds == sorted(ds, reverse=True)


def test_mesh_components_in_merge_order(tmp_path, capsys):
    from flapfoam.mesh import mesh_gen
    summary = tmp_path / "meshGen.json"
    summary.write_text('{"components": [{"name": "wing"}, {"name": "body",'
                       ' "post": ["sphereMesh.py", "-map"]},'
                       ' {"name": "background", "post": []}]}')
    assert mesh_gen.components(str(summary)) == [
        ("wing", []), ("body", ["sphereMesh.py", "-map"]),
        ("background", [])]
    assert mesh_gen.main(["components", str(summary)]) == 0
    assert capsys.readouterr().out == \
        "wing\nbody sphereMesh.py -map\nbackground\n"


def test_a_margin_given_replaces_the_levels():
    # the two-wing drone's tiny wing components: 18 mm, not the level's
    # 1 cbar (15 mm); the cells the planform needs grow with it
    from flapfoam.mesh import mesh_gen
    from flapfoam.mesh.wing_mesh import COMPONENT
    base = mesh_gen.build("tiny", COMPONENT)
    wide = mesh_gen.build("tiny", COMPONENT, margin=18e-3)
    assert base.comp.margin == pytest.approx(LEVELS["tiny"].margin)
    assert wide.comp.margin == 18e-3 and wide.lev.margin == 18e-3
    assert wide.winfo["cellsPlanned"] > base.winfo["cellsPlanned"]
    assert LEVELS["tiny"].margin == pytest.approx(geo.CBAR)   # unchanged


def test_parameters_by_their_file_names():
    from flapfoam.mesh.parameters import camel, file_entries
    assert camel("n_ref") == "nRef" and camel("core_frac") == "coreFrac"
    assert file_entries(LEVELS["coarse"]) == dict(
        nS=24, nL=5, nC=5, nT=2, dsE=0.4e-3, q=1.25, N0=12, nRef=3)
    assert list(file_entries(LEVELS["tiny"]))[-2:] == ["nBuffer", "margin"]
    assert file_entries(BACKGROUND)["finalMargin"] == 1
