#!/usr/bin/python3
"""Outside judge of the distance transform (docs/conventions.md, "Distance and thickness"): voxmod's distance field
of real meshes against SciPy's ndimage.distance_transform_edt of the same grid padded by one empty voxel.

usage: scipy_distance.py VOXMOD SHARED_DIR WORK_DIR
Exit 0: every voxel agrees; 1: a mismatch or a failure; 77: skipped (SciPy or the shared meshes absent outside CI).
"""
import os
import subprocess
import sys
import zlib

from judge_support import skip_or_fail


try:
    import numpy as np
    from scipy import ndimage
except ImportError:
    skip_or_fail("needs Debian's python3-scipy (apt-get install python3-scipy)")


def read_nrrd(path):
    """The NRRD files voxmod writes (float, gzip or raw, little-endian) as a numpy array indexed [z, y, x]."""
    data = open(path, "rb").read()
    head, _, body = data.partition(b"\n\n")
    fields = {}
    for line in head.decode().splitlines()[1:]:
        if ":" in line and not line.startswith("#"):
            key, _, value = line.partition(":")
            fields[key.strip()] = value.strip()
    sizes = [int(s) for s in fields["sizes"].split()]
    assert fields["type"] == "float" and fields["endian"] == "little", fields
    if fields["encoding"] == "gzip":
        body = zlib.decompress(body, 15 + 32)
    spacing = float(fields["space directions"].split(")")[0].strip("( ").split(",")[0])
    return np.frombuffer(body, dtype="<f4").reshape(sizes[2], sizes[1], sizes[0]), spacing


def main():
    voxmod, shared, work = sys.argv[1:4]
    meshes = ["rocker_arm.stl", "featuretype.stl", "stanford_bunny.stl", "plate_holes.stl"]
    if not all(os.path.exists(os.path.join(shared, "meshes", m)) for m in meshes):
        skip_or_fail("needs the shared meshes in " + os.path.join(shared, "meshes"))
    os.makedirs(work, exist_ok=True)
    failed = False
    for mesh in meshes:
        for res in (61, 128):
            out = os.path.join(work, f"{mesh}_{res}.nrrd")
            cmd = [voxmod, "thickness", os.path.join(shared, "meshes", mesh), "--res", str(res), "--mode", "vote",
                   "--distance", out, "--json"]
            run = subprocess.run(cmd, capture_output=True, text=True)
            if run.returncode != 0:
                print(f"FAIL: {' '.join(cmd)}: {run.stderr}", file=sys.stderr)
                failed = True
                continue
            ours, h = read_nrrd(out)
            filled = ours > 0  # every filled voxel is at least one voxel from the outside
            padded = np.pad(filled, 1, constant_values=False)
            theirs = ndimage.distance_transform_edt(padded)[1:-1, 1:-1, 1:-1] * h
            worst = float(np.max(np.abs(theirs - ours))) / h
            ok = worst < 1e-5
            failed |= not ok
            print(f"{'ok' if ok else 'FAIL'} - {mesh} R={res}: {int(filled.sum())} filled voxels, "
                  f"largest difference {worst:.2e} voxels")
    sys.exit(1 if failed else 0)


main()
