"""Run by ParaView's own Python (`pvbatch`; tests/test_paraview.py): opens a result's two XDMF sidecars,
prints what ParaView read as one JSON line, and renders the wall and the fluid at the last snapshot.
usage: pvbatch paraview_check.py RESULT_STEM OUT.png"""
import json
import sys

from paraview import simple

stem, png = sys.argv[1], sys.argv[2]
view = simple.CreateRenderView()
view.ViewSize = [800, 600]
view.Background = [1, 1, 1]
read = {}
for kind in ("wall", "fluid"):
    reader = simple.OpenDataFile(f"{stem}.{kind}.xdmf")
    times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
    reader.UpdatePipeline(times[-1])
    info = reader.GetDataInformation()
    read[kind] = {"points": info.GetNumberOfPoints(), "cells": info.GetNumberOfCells(), "times": len(times),
                  "arrays": sorted(reader.PointData.keys())}
    shown = simple.Show(reader, view)
    if kind == "wall":
        shown.Representation = "Surface With Edges"
        shown.Opacity = 0.4
    else:
        shown.Representation = "Points"
        shown.PointSize = 4
        simple.ColorBy(shown, ("POINTS", "pressure"))
view.ViewTime = times[-1]
simple.ResetCamera(view)
simple.SaveScreenshot(png, view, ImageResolution=[800, 600])
print("PARAVIEW_READ " + json.dumps(read))
