#!/usr/bin/python3
"""SciPy's exact distance transform on the grid of a voxmod distance field, for the side-by-side figures in
docs/performance.md ("Distance and thickness").

usage: /usr/bin/python3 bench/scipy_edt.py DISTANCE.nrrd | GRID.binvox
  DISTANCE.nrrd from `voxmod thickness PART --distance DISTANCE.nrrd` (filled voxels are those with a distance > 0),
  or a grid from `voxmod convert PART.vxm GRID.binvox` (timing only: cropped to its filled voxels' bounding box,
  the box voxmod's transform works on).
Prints the filled voxel count, SciPy's time for distance_transform_edt of the grid padded by one empty voxel (the
definition voxmod follows), the peak memory SciPy allocated for it (tracemalloc: numpy reports its arrays), and, for a
distance field, the largest difference from voxmod's in voxels.
"""
import sys
import time
import tracemalloc
import zlib

import numpy as np
from scipy import ndimage


def read_nrrd(path):
    data = open(path, "rb").read()
    head, _, body = data.partition(b"\n\n")
    fields = dict(
        (k.strip(), v.strip()) for k, _, v in (l.partition(":") for l in head.decode().splitlines()[1:]) if v)
    sizes = [int(s) for s in fields["sizes"].split()]
    if fields["encoding"] == "gzip":
        body = zlib.decompress(body, 15 + 32)
    spacing = float(fields["space directions"].split(")")[0].strip("( ").split(",")[0])
    return np.frombuffer(body, dtype="<f4").reshape(sizes[2], sizes[1], sizes[0]), spacing


def read_binvox(path):
    data = open(path, "rb").read()
    head, _, body = data.partition(b"data\n")
    dims = [int(v) for v in head.split(b"dim")[1].split(b"\n")[0].split()]
    pairs = np.frombuffer(body, dtype=np.uint8).reshape(-1, 2)
    return np.repeat(pairs[:, 0].astype(bool), pairs[:, 1]).reshape(dims)


if sys.argv[1].endswith(".binvox"):
    ours, h = None, 1.0
    grid = read_binvox(sys.argv[1])
    # The filled voxels' bounding box, as voxmod's transform works on: SciPy's best case on the same voxels.
    nz = [np.flatnonzero(grid.any(axis=tuple(a for a in range(3) if a != k))) for k in range(3)]
    grid = grid[nz[0][0]:nz[0][-1] + 1, nz[1][0]:nz[1][-1] + 1, nz[2][0]:nz[2][-1] + 1]
    padded = np.pad(grid, 1, constant_values=False)
else:
    ours, h = read_nrrd(sys.argv[1])
    padded = np.pad(ours > 0, 1, constant_values=False)
tracemalloc.start()
t0 = time.perf_counter()
edt = ndimage.distance_transform_edt(padded)
seconds = time.perf_counter() - t0
_, peak = tracemalloc.get_traced_memory()
tracemalloc.stop()
worst = float(np.max(np.abs(edt[1:-1, 1:-1, 1:-1] - ours / h))) if ours is not None else float("nan")
print(f"filled {int(padded.sum())}, grid {padded.shape[2] - 2} x {padded.shape[1] - 2} x {padded.shape[0] - 2}: "
      f"scipy distance_transform_edt {seconds:.2f} s, peak {peak / 2**30:.2f} GiB allocated; "
      f"largest difference from voxmod {worst:.2e} voxels")
