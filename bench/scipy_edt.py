#!/usr/bin/python3
"""SciPy's exact distance transform on the grid of a voxmod distance field, for the side-by-side figures in
docs/performance.md ("Distance and thickness").

usage: /usr/bin/python3 bench/scipy_edt.py DISTANCE.nrrd
  DISTANCE.nrrd from `voxmod thickness PART --distance DISTANCE.nrrd` (filled voxels are those with a distance > 0).
Prints the filled voxel count, SciPy's time for distance_transform_edt of the grid padded by one empty voxel (the
definition voxmod follows), the peak memory SciPy allocated for it (tracemalloc: numpy reports its arrays), and the
largest difference from voxmod's field in voxels.
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


ours, h = read_nrrd(sys.argv[1])
padded = np.pad(ours > 0, 1, constant_values=False)
tracemalloc.start()
t0 = time.perf_counter()
edt = ndimage.distance_transform_edt(padded)
seconds = time.perf_counter() - t0
_, peak = tracemalloc.get_traced_memory()
tracemalloc.stop()
worst = float(np.max(np.abs(edt[1:-1, 1:-1, 1:-1] - ours / h)))
print(f"filled {int(padded.sum())}, grid {padded.shape[2] - 2} x {padded.shape[1] - 2} x {padded.shape[0] - 2}: "
      f"scipy distance_transform_edt {seconds:.2f} s, peak {peak / 2**30:.2f} GiB allocated; "
      f"largest difference from voxmod {worst:.2e} voxels")
