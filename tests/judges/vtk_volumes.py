#!/usr/bin/python3
"""Outside judge of volume export (docs/file-format.md, "Volume files"): VTK's own readers (Debian's python3-vtk9)
read voxmod's .vti and .nrrd files, and must find the same dims, spacing, origin (the centre of voxel (0, 0, 0)),
filled count and units as voxmod reports for the grid; thickness and distance fields must hold a value in every
filled voxel, with the minimum and maximum voxmod reports.

usage: vtk_volumes.py VOXMOD SOURCE_DIR WORK_DIR
Exit 0: all agree; 1: a mismatch or a failure; 77: skipped (python3-vtk9 absent outside CI).
"""
import os
import sys

from judge_support import check, close, finish, skip_or_fail, use_voxmod, voxmod


try:
    import numpy as np
    # The readers' own modules, not the umbrella `vtk` package: importing that one also loads Debian's MPI modules,
    # whose factory replaces vtkNrrdReader by vtkPNrrdReader, which fails without an MPI controller.
    from vtkmodules.vtkIOImage import vtkNrrdReader
    from vtkmodules.vtkIOXML import vtkXMLImageDataReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
except ImportError:
    skip_or_fail("needs Debian's python3-vtk9 and python3-numpy (apt-get install python3-vtk9 python3-numpy)")

def read(path):
    reader = vtkXMLImageDataReader() if path.endswith(".vti") else vtkNrrdReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def judge_grid(path, info, name):
    image = read(path)
    h = info["voxel_size"]
    centre0 = [o + 0.5 * h for o in info["origin"]]
    check(list(image.GetDimensions()) == info["dims"], f"{name}: dims {list(image.GetDimensions())}")
    check(close(image.GetSpacing(), [h, h, h]), f"{name}: spacing {image.GetSpacing()}")
    check(close(image.GetOrigin(), centre0), f"{name}: origin {image.GetOrigin()} (centre of voxel 0, 0, 0)")
    values = vtk_to_numpy(image.GetPointData().GetScalars())
    filled = int(np.count_nonzero(values))
    check(filled == info["filled"] and set(np.unique(values)) <= {0, 1}, f"{name}: {filled} filled voxels, 0/1")
    if path.endswith(".vti"):
        units = image.GetFieldData().GetAbstractArray("units")
        check(units is not None and units.GetValue(0) == info["units"], f"{name}: units {info['units']}")


def judge_field(path, array, stats, filled, name):
    image = read(path)
    data = image.GetPointData().GetArray(array) if path.endswith(".vti") else image.GetPointData().GetScalars()
    values = vtk_to_numpy(data)
    inside = values[values > 0]
    check(inside.size == filled, f"{name}: {inside.size} voxels hold a {array}")
    lo, hi = float(inside.min()), float(inside.max())
    check(abs(lo - stats[0]) < 1e-5 * stats[1] and abs(hi - stats[1]) < 1e-5 * stats[1],
          f"{name}: {array} from {lo:.6g} to {hi:.6g}")


def main():
    exe, source, work = sys.argv[1:4]
    use_voxmod(exe)
    os.makedirs(work, exist_ok=True)
    for model in ["featuretype.stl", "plate_holes.stl"]:
        for res in (60, 150):
            name = f"{model} R={res}"
            vxm = os.path.join(work, f"{model}_{res}.vxm")
            voxmod("convert", os.path.join(source, "models", model), vxm, "--res", str(res), "--units", "mm")
            info = voxmod("info", vxm)
            for ext in (".vti", ".nrrd"):
                out = vxm[:-4] + ext
                voxmod("convert", vxm, out)
                judge_grid(out, info, f"{name} {ext}")
            t_vti, d_nrrd = vxm[:-4] + "_t.vti", vxm[:-4] + "_d.nrrd"
            t = voxmod("thickness", vxm, "-o", t_vti, "--distance", d_nrrd)
            judge_field(t_vti, "thickness", (t["min"], t["max"]), info["filled"], f"{name} thickness .vti")
            judge_field(d_nrrd, "distance", (info["voxel_size"], t["distance_max"]), info["filled"],
                        f"{name} distance .nrrd")
    finish()


main()
