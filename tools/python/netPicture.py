"""A picture of a flexible barrier (mpm3dFoam's barrier type membrane) and
the flow at the peak load, for pvbatch without a display:

    xvfb-run -a pvbatch netPicture.py CASE BARRIER PNG

(tools/netPicture runs it so, and retries when two virtual displays clash).

The peak load is the largest resultant of the anchor forces
(postProcessing/BARRIER/<start>/anchorForces.dat: the sum over the anchor
groups and ropes, so that the ropes' pretensions, which pull the flank
anchors apart, cancel). The picture is taken at the write time nearest it:
the deformed net from VTK/BARRIER.vtk.series (legacy VTK, coloured by the
magnitude of its displacement, the ropes as lines) and the particles of
the cloud mpm3dCloud from CASE/case.foam (ParaView's OpenFOAM reader,
coloured by speed). The view looks at the net from downstream (+x), from
above and from the side. Prints the peak, the time shown and the picture's
name.
"""
import json
import os
import sys

from paraview import simple as pv

case, barrier, png = (os.path.abspath(a) for a in sys.argv[1:4])
barrier = os.path.basename(barrier)


def peakLoad():
    """Time and size of the largest resultant anchor force."""
    d = os.path.join(case, "postProcessing", barrier)
    path = os.path.join(d, sorted(os.listdir(d), key=float)[0], "anchorForces.dat")
    best = (0.0, 0.0)
    columns = []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                columns = line[1:].split()
                continue
            v = [float(x) for x in line.split()]
            # The forces [N], not a plane slice's per width
            F = [sum(x for name, x in zip(columns, v) if name.endswith(c)) for c in ("Fx", "Fy", "Fz")]
            size = (F[0]**2 + F[1]**2 + F[2]**2)**0.5
            if size > best[1]:
                best = (v[0], size)
    return best


def colourBy(show, field, preset, title, position):
    """Colour a shown source by the magnitude of a point field, with a
    scalar bar at a position of the view."""
    pv.ColorBy(show, ("POINTS", field, "Magnitude"))
    show.RescaleTransferFunctionToDataRange(True, False)
    lut = pv.GetColorTransferFunction(field)
    lut.ApplyPreset(preset, True)
    show.SetScalarBarVisibility(view, True)
    bar = pv.GetScalarBar(lut, view)
    bar.Title = title
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    bar.WindowLocation = "Any Location"
    bar.Position = position


tPeak, FPeak = peakLoad()
series = json.load(open(os.path.join(case, "VTK", barrier + ".vtk.series")))["files"]
shot = min(series, key=lambda e: abs(e["time"] - tPeak))
time = shot["time"]
print("Peak resultant anchor force %.4g N at t = %.4g s; picture at the write time %.4g s" % (FPeak, tPeak, time))

view = pv.GetActiveViewOrCreate("RenderView")
view.ViewSize = [1400, 900]
view.UseColorPaletteForBackground = 0
view.Background = [1, 1, 1]
view.OrientationAxesVisibility = 1
view.ViewTime = time

net = pv.LegacyVTKReader(FileNames=[os.path.join(case, "VTK", shot["name"])])
netShow = pv.Show(net, view)
netShow.SetRepresentationType("Surface With Edges")
netShow.EdgeColor = [0.25, 0.25, 0.25]
netShow.LineWidth = 2.0
colourBy(netShow, "displacement", "Viridis (matplotlib)", "net displacement [m]", [0.89, 0.05])

foam = os.path.join(case, "case.foam")
open(foam, "a").close()
flow = pv.OpenFOAMReader(FileName=foam)
flow.MeshRegions = ["lagrangian/mpm3dCloud"]
flow.CellArrays = []
flow.LagrangianArrays = ["U"]
flow.UpdatePipelineInformation()
flow.UpdatePipeline(time)
flowShow = pv.Show(flow, view)
flowShow.SetRepresentationType("Points")
flowShow.PointSize = 3.0
colourBy(flowShow, "U", "Inferno (matplotlib)", "flow speed [m/s]", [0.02, 0.05])

title = pv.Text(Text="%s: t = %.3g s, resultant anchor force %.3g kN (peak at %.3g s)"
                % (os.path.basename(case), time, FPeak / 1e3, tPeak))
titleShow = pv.Show(title, view)
titleShow.Color = [0, 0, 0]
titleShow.FontSize = 14
titleShow.WindowLocation = "Upper Center"

# From downstream, above and beside the net, centred on it
(x0, x1, y0, y1, z0, z1) = net.GetDataInformation().GetBounds()
centre = [(x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2]
size = max(x1 - x0, y1 - y0, z1 - z0)
view.CameraFocalPoint = centre
view.CameraPosition = [centre[0] + 2.2 * size, centre[1] - 1.6 * size, centre[2] + 1.2 * size]
view.CameraViewUp = [0, 0, 1]
view.CameraViewAngle = 30
pv.Render(view)
pv.SaveScreenshot(png, view, ImageResolution=[1400, 900])
print("Wrote " + os.path.relpath(png, case))
