# License
#     This file is part of flapFoam: free software
#     under the GNU General Public License v3 or later (COPYING).
"""
The ParaView side of flapfoam plot_flow: run by pvbatch (under
xvfb-run), not imported by the package.

    pvbatch pv_render.py FOAM TIME Q PREFIX CASETYPE

Reads an overset run (OpenFOAMReader: U, cellTypes, zoneID; the walls) at
TIME, keeps its calculated cells (cellTypes 0: no hole, no fringe, so the
overlapping zones are drawn once), computes the Q criterion of U and
writes PREFIX-Q.png (the walls and the Q = Q iso-surface coloured by the
speed) and PREFIX-mesh.png (the cells on the plane z = the body's centre,
holes and fringes left out, each zone a colour, the walls' outline).
Prints one line, "render:" and a JSON object: the time, the Q level, the
iso-surface's polygons, the largest Q, the walls' middle (z: the body's centre), their size,
the slice's cells.
"""

import json
import sys

from paraview.simple import (CellDatatoPointData, ColorBy, Contour,
                             CreateView, ExtractBlock, GetColorTransferFunction,
                             GetScalarBar,
                             Gradient, OpenFOAMReader, Render,
                             SaveScreenshot, Show, Slice, Text, Threshold)

WALLS = ("patch/body", "patch/leftWing", "patch/rightWing", "patch/wing")


def read(foam, time, case_type):
    """(the fluid's calculated cells, the walls, the body's wall (or the
    first wall's, if there is no body)) at time."""
    reader = OpenFOAMReader(FileName=foam)
    reader.CaseType = case_type
    reader.Decomposepolyhedra = 0
    walls = [w for w in WALLS if w in reader.MeshRegions.Available]
    reader.MeshRegions = ["internalMesh"] + walls
    reader.CellArrays = ["U", "cellTypes", "zoneID"]
    reader.UpdatePipeline(time)
    fluid = ExtractBlock(Input=reader, Selectors=["/Root/internalMesh"])
    calculated = Threshold(Input=fluid, Scalars=["CELLS", "cellTypes"],
                           LowerThreshold=-0.5, UpperThreshold=0.5)
    wall = ExtractBlock(Input=reader, Selectors=["/Root/boundary"])
    body = ExtractBlock(Input=reader, Selectors=["/Root/boundary/" + (
        "body" if "patch/body" in walls else walls[0][6:])])
    for f in (calculated, wall, body):
        f.UpdatePipeline(time)
    return calculated, wall, body


def bounds(source):
    """The data's bounds (xmin, xmax, ymin, ymax, zmin, zmax)."""
    return source.GetDataInformation().GetBounds()


def view(centre, distance, direction, up=(0, 0, 1)):
    """A white 1200 x 900 render view looking at centre along direction
    from distance away."""
    v = CreateView("RenderView")
    v.ViewSize = [1200, 900]
    if hasattr(v, "UseColorPaletteForBackground"):
        v.UseColorPaletteForBackground = 0
    v.Background = [1, 1, 1]
    v.OrientationAxesVisibility = 1
    v.OrientationAxesLabelColor = [0, 0, 0]
    v.CameraFocalPoint = centre
    v.CameraPosition = [c + distance*d for c, d in zip(centre, direction)]
    v.CameraViewUp = list(up)
    return v


def caption(v, text):
    """A black caption at the view's top left."""
    t = Text(Text=text)
    d = Show(t, v)
    d.WindowLocation = "Upper Left Corner"
    d.Color = [0, 0, 0]
    d.FontSize = 26


def q_view(calculated, walls, level, time, geometry):
    """The Q iso-surface coloured by the speed, the walls grey: PNG."""
    centre, size, prefix = geometry
    points = CellDatatoPointData(Input=calculated)
    grad = Gradient(Input=points, ScalarArray=["POINTS", "U"],
                    ComputeQCriterion=1, QCriterionArrayName="Q")
    iso = Contour(Input=grad, ContourBy=["POINTS", "Q"], Isosurfaces=[level])
    iso.ComputeScalars = 0
    iso.UpdatePipeline(time)
    v = view(centre, 2.4*size, (0.55, -0.65, 0.52))
    v.ViewTime = time
    d = Show(walls, v)
    d.DiffuseColor = [0.55, 0.55, 0.55]
    d.ColorArrayName = ["POINTS", ""]
    s = Show(iso, v)
    ColorBy(s, ("POINTS", "U", "Magnitude"))
    s.RescaleTransferFunctionToDataRange(True)
    s.SetScalarBarVisibility(v, True)
    lut = GetColorTransferFunction("U")
    lut.ApplyPreset("Viridis (matplotlib)", True)
    bar = GetScalarBar(lut, v)
    bar.Title, bar.ComponentTitle = "speed [m/s]", ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    caption(v, "t = %g s: Q = %g 1/s^2, coloured by the speed; the calculated"
            " cells of every zone" % (time, level))
    Render(v)
    SaveScreenshot(prefix + "-Q.png", v)
    grad.UpdatePipeline(time)
    q_range = grad.PointData["Q"].GetRange() \
        if "Q" in grad.PointData.keys() else (0.0, 0.0)
    return iso.GetDataInformation().GetNumberOfCells(), q_range[1]


def cut(source, centre, time):
    """The plane z = centre's z through source, cells kept whole."""
    plane = Slice(Input=source)
    plane.SliceType = "Plane"
    plane.SliceType.Origin = centre
    plane.SliceType.Normal = [0, 0, 1]
    if hasattr(plane, "Triangulatetheslice"):
        plane.Triangulatetheslice = 0
    plane.UpdatePipeline(time)
    return plane


def mesh_view(calculated, walls, time, geometry):
    """The calculated cells on the plane through the body's centre normal
    to z (the stroke plane at rest: the wings along their span), each zone a colour, with their edges, and the walls' outline
    on it: PNG; the slice's cells."""
    centre, size, prefix = geometry
    plane = cut(calculated, centre, time)
    v = view(centre, 2.8*size, (0, 0, 1), (1, 0, 0))
    v.ViewTime = time
    s = Show(plane, v)
    s.SetRepresentationType("Surface With Edges")
    ColorBy(s, ("CELLS", "zoneID"))
    s.RescaleTransferFunctionToDataRange(True)
    GetColorTransferFunction("zoneID").ApplyPreset("Set1", True)
    d = Show(cut(walls, centre, time), v)
    d.DiffuseColor = d.AmbientColor = [0, 0, 0]
    d.ColorArrayName = ["POINTS", ""]
    d.LineWidth = 3
    caption(v, "t = %g s: cells on z = %.4g m, a colour a zone, no holes or"
            " fringes, walls black" % (time, centre[2]))
    Render(v)
    SaveScreenshot(prefix + "-mesh.png", v)
    return plane.GetDataInformation().GetNumberOfCells()


def main(argv):
    foam, time, level, prefix, case_type = argv[1:6]
    time, level = float(time), float(level)
    calculated, walls, body = read(foam, time, case_type)
    b = bounds(walls)
    size = max(b[1] - b[0], b[3] - b[2], b[5] - b[4])
    middle = [(b[0] + b[1])/2, (b[2] + b[3])/2, (b[4] + b[5])/2]
    b = bounds(body)
    centre = [(b[0] + b[1])/2, (b[2] + b[3])/2, (b[4] + b[5])/2]
    geometry = ([middle[0], middle[1], centre[2]], size, prefix)
    polygons, q_max = q_view(calculated, walls, level, time, geometry)
    cells = mesh_view(calculated, walls, time, geometry)
    print("render: " + json.dumps({
        "time": time, "q": level, "isoPolygons": polygons, "qMax": q_max,
        "centre": geometry[0], "wallsSize": size, "sliceCells": cells}))


if __name__ == "__main__":
    main(sys.argv)
