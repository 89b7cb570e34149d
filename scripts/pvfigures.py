"""Pictures of a run with ParaView: the von Mises stress (cell data), the
damage and the contact status (point data) on the deformed body, and the
deformed mesh, for any run's solution.pvd, at chosen times, as PNG files.

Run by scripts/pvfigures under ParaView's pvbatch (or pvpython). A starting
point to edit: each picture is one function call below, with ParaView's
Python names (paraview.simple), so that a trace from ParaView's GUI can be
pasted in beside them.

  scripts/pvfigures results/paper_fig1/solution.pvd
  scripts/pvfigures RUN/solution.pvd --times 0.5 1 --warp 10 --out pictures
"""
import argparse
import os
import sys

from paraview import simple as pv

# The fields pictured where a run has them: (name, association, title).
FIELDS = [("von_mises", "CELLS", "von Mises stress [Pa]"),
          ("damage", "POINTS", "damage zeta"),
          ("contact_status", "POINTS", "contact status (1 stick, 2 slip, "
           "3 separated)")]


def arguments():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("pvd", help="the run's solution.pvd")
    p.add_argument("--times", type=float, nargs="*",
                   help="times to picture (default: the last output); the "
                   "output nearest to each is taken")
    p.add_argument("--warp", type=float, default=1.0,
                   help="factor on the displacement of the deformed body "
                   "(default 1, true scale)")
    p.add_argument("--out", help="folder of the PNG files (default: a "
                   "folder 'pictures' beside the .pvd file)")
    p.add_argument("--size", default="1200x800", help="pixels, WxH")
    p.add_argument("--edges", action="store_true",
                   help="draw the cells' edges on the field pictures too "
                   "(a mesh that adapts during the run)")
    return p.parse_args()


def nearest(available, wanted):
    return min(available, key=lambda t: abs(t - wanted))


def picture(view, source, field, association, title, path, edges=False):
    """Colour the deformed body by one field and save the view."""
    display = pv.Show(source, view)
    display.SetRepresentationType("Surface With Edges" if edges else "Surface")
    pv.ColorBy(display, (association, field))
    display.RescaleTransferFunctionToDataRange(True, False)
    display.SetScalarBarVisibility(view, True)
    pv.GetScalarBar(pv.GetColorTransferFunction(field), view).Title = title
    pv.SaveScreenshot(path, view, ImageResolution=view.ViewSize)
    pv.Hide(source, view)


def mesh_picture(view, source, path):
    """The deformed mesh: its cells' edges on a plain surface."""
    display = pv.Show(source, view)
    display.SetRepresentationType("Surface With Edges")
    pv.ColorBy(display, None)
    pv.SaveScreenshot(path, view, ImageResolution=view.ViewSize)
    pv.Hide(source, view)


def main():
    a = arguments()
    if not os.path.isfile(a.pvd):
        sys.exit(f"pvfigures: no such file: {a.pvd}")
    out = a.out or os.path.join(os.path.dirname(os.path.abspath(a.pvd)),
                                "pictures")
    os.makedirs(out, exist_ok=True)
    width, height = (int(v) for v in a.size.split("x"))

    reader = pv.PVDReader(FileName=a.pvd)
    try:
        steps = [float(t) for t in reader.TimestepValues]
    except TypeError:  # a single output
        steps = [float(reader.TimestepValues)]
    times = [nearest(steps, t) for t in (a.times or [steps[-1]])]
    warp = pv.WarpByVector(Input=reader)
    warp.Vectors = ["POINTS", "displacement"]
    warp.ScaleFactor = a.warp

    view = pv.CreateView("RenderView")
    view.ViewSize = [width, height]
    view.OrientationAxesVisibility = 0
    present = {("CELLS", n) for n in reader.CellData.keys()} | \
              {("POINTS", n) for n in reader.PointData.keys()}
    bounds = reader.GetDataInformation().GetBounds()
    flat = abs(bounds[5] - bounds[4]) < 1e-12 * max(1.0, abs(bounds[1]))
    for t in times:
        view.ViewTime = t
        pv.Show(warp, view)
        view.ResetCamera()
        if not flat:
            view.ApplyIsometricView()
            view.ResetCamera()
        pv.Hide(warp, view)
        for field, association, title in FIELDS:
            if (association, field) in present:
                path = os.path.join(out, f"{field}_t{t:g}.png")
                picture(view, warp, field, association, title, path,
                        a.edges)
                print(path)
        path = os.path.join(out, f"mesh_t{t:g}.png")
        mesh_picture(view, warp, path)
        print(path)


if __name__ == "__main__":
    main()
