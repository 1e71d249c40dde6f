#!/usr/bin/python3
"""Outside judge of the surface export (SPEC section 8): voxmod's STL surface of real meshes read by Debian's admesh,
which welds by position and repairs what it finds: nothing may need repair (no unconnected or backwards edges, no
degenerate facets, nothing added or removed) and the volume admesh measures is filled x h^3.

usage: admesh_surface.py VOXMOD SHARED_DIR WORK_DIR
Exit 0: every surface is clean; 1: a finding or a failure; 77: skipped (admesh or the shared meshes absent outside CI).
"""
import json
import os
import re
import shutil
import subprocess
import sys

from judge_support import skip_or_fail


voxmod, shared, work = sys.argv[1:4]
admesh = shutil.which("admesh")
if not admesh:
    skip_or_fail("needs Debian's admesh (apt-get install admesh)")
if not os.path.isdir(os.path.join(shared, "meshes")):
    skip_or_fail("no shared meshes at " + shared)
os.makedirs(work, exist_ok=True)

# (mesh, R): parts with edge and corner contacts at these resolutions, disjoint bodies, a scan.
CASES = [("rocker_arm.stl", 200), ("two_disjoint_cubes.stl", 50), ("featuretype.stl", 150),
         ("stanford_bunny.stl", 120), ("femur_right.stl", 90)]
failures = 0
for mesh, res in CASES:
    out = os.path.join(work, mesh.replace(".stl", "_surface.stl"))
    run = subprocess.run([voxmod, "convert", os.path.join(shared, "meshes", mesh), out, "--res", str(res), "--json"],
                         capture_output=True, text=True)
    if run.returncode != 0:
        print(f"FAIL {mesh}: voxmod convert exited {run.returncode}: {run.stderr.strip()}")
        failures += 1
        continue
    info = json.loads(run.stdout)
    report = subprocess.run([admesh, out], capture_output=True, text=True).stdout

    def number(label):
        m = re.search(re.escape(label) + r"\s*:\s*(-?[0-9.eE+-]+)", report)
        return float(m.group(1)) if m else None

    clean = {label: number(label) for label in
             ["Degenerate facets", "Edges fixed", "Facets removed", "Facets added", "Facets reversed",
              "Backwards edges", "Normals fixed"]}
    volume = number("Volume")
    bad = {k: v for k, v in clean.items() if v is None or v != 0}
    # admesh prints the volume with 6 decimals and STL holds float32 coordinates (about 1e-7 of the part's size
    # each): compare to within those and the split vertices' moves (each at most h^3 / 256)
    h3 = info["volume"] / max(1, info["filled"])
    tolerance = max(1e-6 + info["split_vertices"] / 256.0 * h3, 1e-5 * info["volume"])
    if volume is None or abs(volume - info["volume"]) > tolerance:
        bad["Volume"] = f"{volume} against filled x h^3 = {info['volume']}"
    status = "ok" if not bad else "FAIL"
    failures += bool(bad)
    print(f"{status} {mesh} R={res}: {info['triangles']} triangles, {info['split_vertices']} split vertices, "
          f"volume {volume}" + (f": {bad}" if bad else ""))
sys.exit(1 if failures else 0)
