#!/usr/bin/python3
"""Outside judge of volume export (docs/file-format.md, "Volume files"): OpenVDB's own Python module (Debian's
python3-openvdb) reads voxmod's .vdb files, and must find a float fog volume named "voxels" whose transform puts
index (0, 0, 0) at the centre of voxel (0, 0, 0) with the voxel size as scale, whose active voxels are the filled
ones (count and bounding box), with the grid's dims and units in its metadata; thickness as a grid of its own,
active in every filled voxel, with the minimum and maximum voxmod reports.

usage: openvdb_volumes.py VOXMOD SOURCE_DIR WORK_DIR
Exit 0: all agree; 1: a mismatch or a failure; 77: skipped (python3-openvdb absent outside CI).
"""
import os
import sys

from judge_support import check, close, finish, skip_or_fail, use_voxmod, voxmod


try:
    import pyopenvdb as vdb
except ImportError:
    skip_or_fail("needs Debian's python3-openvdb (apt-get install python3-openvdb)")

def grid_named(path, name):
    grids, _ = vdb.readAll(path)
    matches = [g for g in grids if g.name == name]
    return matches[0] if matches else None


def judge_voxels(path, info, mass, name):
    g = grid_named(path, "voxels")
    check(g is not None and isinstance(g, vdb.FloatGrid), f"{name}: a FloatGrid named voxels")
    if g is None:
        return
    h = info["voxel_size"]
    centre0 = [o + 0.5 * h for o in info["origin"]]
    check(g.gridClass == "fog volume" and g.background == 0.0, f"{name}: fog volume, background 0")
    check(close(g.transform.indexToWorld((0, 0, 0)), centre0), f"{name}: index (0, 0, 0) at {centre0}")
    check(close(g.transform.voxelSize(), (h, h, h)), f"{name}: voxel size {g.transform.voxelSize()}")
    check(g.activeVoxelCount() == info["filled"], f"{name}: {g.activeVoxelCount()} active voxels")
    lo, hi = g.evalActiveVoxelBoundingBox()
    check(list(lo) == mass["bbox_min_ijk"] and list(hi) == mass["bbox_max_ijk"], f"{name}: active box {lo} {hi}")
    check(g.evalMinMax() == (1.0, 1.0), f"{name}: active values 1")
    check(list(g.metadata.get("dims", ())) == info["dims"], f"{name}: dims {g.metadata.get('dims')}")
    check(g.metadata.get("units") == info["units"], f"{name}: units {g.metadata.get('units')}")


def judge_thickness(path, t, info, name):
    g = grid_named(path, "thickness")
    check(g is not None and g.activeVoxelCount() == info["filled"], f"{name}: thickness in every filled voxel")
    if g is None:
        return
    lo, hi = g.evalMinMax()
    check(abs(lo - t["min"]) < 1e-5 * t["max"] and abs(hi - t["max"]) < 1e-5 * t["max"],
          f"{name}: thickness from {lo:.6g} to {hi:.6g}")


def main():
    exe, source, work = sys.argv[1:4]
    use_voxmod(exe)
    os.makedirs(work, exist_ok=True)
    for model in ["featuretype.stl", "plate_holes.stl"]:
        for res in (60, 150):
            name = f"{model} R={res}"
            vxm = os.path.join(work, f"{model}_{res}.vxm")
            voxmod("convert", os.path.join(source, "models", model), vxm, "--res", str(res), "--units", "mm")
            info, mass = voxmod("info", vxm), voxmod("mass", vxm)
            out = vxm[:-4] + ".vdb"
            voxmod("convert", vxm, out)
            judge_voxels(out, info, mass, f"{name} .vdb")
            t_vdb = vxm[:-4] + "_t.vdb"
            t = voxmod("thickness", vxm, "-o", t_vdb)
            judge_thickness(t_vdb, t, info, f"{name} .vdb")
    finish()


main()
