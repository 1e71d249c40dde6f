#!/usr/bin/python3
"""Regenerates the tables of docs/performance.md on this machine.

usage: bench/tables.py [--build DIR] [--shared DIR] [--runs N] [--write] [TABLE ...]

  TABLE      which tables (default: all); `bench/tables.py --list` names them with their headings.
  --build    the build whose `voxmod` and `bench/*_bench` run (default build-rel, else build).
  --shared   the shared data (meshes), default ../shared.
  --runs     runs of each CLI command; the table gives the median (default 3).
  --write    replaces, in docs/performance.md, each table's "Command:" paragraph and its table (the lines from the
             heading to the table's last row) with the ones measured; the notes after the table stay as written.
             Only for the tables whose sections have the script's layout (WRITABLE); without it the sections are
             printed, to be merged by hand.

Each section says its command, this machine (CPU model, cores, memory) and the date. Google Benchmark programs run
with --benchmark_format=json; CLI commands with --json, under /usr/bin/time for wall time and peak memory. Nothing
is measured twice by hand: a figure in a table comes from what this script ran.
"""
import argparse
import datetime
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOC = os.path.join(ROOT, "docs", "performance.md")


class Bench:
    """What a table's rows need: the build, the shared meshes, a scratch folder, and the runners."""

    def __init__(self, build, shared, runs):
        self.build, self.shared, self.runs = build, shared, runs
        self.work = tempfile.mkdtemp(prefix="voxmod-bench-")
        self.voxmod = os.path.join(build, "voxmod")

    def mesh(self, name):
        return os.path.join(self.shared, "meshes", name)

    def scratch(self, name):
        return os.path.join(self.work, name)

    def gbench(self, program, filt, env=None, extra=()):
        """Google Benchmark results by name: real_time, cpu_time (ms) and the counters; with repetitions, the medians."""
        cmd = [os.path.join(self.build, "bench", program), "--benchmark_format=json", "--benchmark_filter=" + filt]
        out = subprocess.run(cmd + list(extra), env={**os.environ, **(env or {})}, check=True, capture_output=True,
                             text=True).stdout
        runs = json.loads(out)["benchmarks"]
        medians = {plain(r["run_name"]): r for r in runs if r.get("aggregate_name") == "median"}
        return medians or {plain(r["name"]): r for r in runs if r.get("run_type", "iteration") == "iteration"}

    def cli(self, args):
        """The median over the runs of a voxmod command with --json: (JSON of the median run, wall s, peak MiB)."""
        results = []
        for _ in range(self.runs):
            timing = self.scratch("time.txt")
            out = subprocess.run(["/usr/bin/time", "-f", "%e %M", "-o", timing, self.voxmod] + args + ["--json"],
                                 check=True, capture_output=True, text=True).stdout
            wall, kb = open(timing).read().split()[-2:]
            results.append((json.loads(out), float(wall), float(kb) / 1024))
        results.sort(key=lambda r: r[1])
        return results[len(results) // 2]



def plain(name):
    """A benchmark's name as registered: without the suffixes Google Benchmark adds (iterations:3, real_time, ...)."""
    return re.sub(r"/(iterations:\d+|repeats:\d+|threads:\d+|min_time:[\d.]+|process_time|real_time|manual_time)",
                  "", name)


def machine():
    info = {}
    for line in open("/proc/cpuinfo"):
        key, _, value = line.partition(":")
        info.setdefault(key.strip(), value.strip())
    mem = next(int(l.split()[1]) for l in open("/proc/meminfo") if l.startswith("MemTotal"))
    return (f"{info.get('model name', '?')} (family {info.get('cpu family', '?')}, model {info.get('model', '?')}), "
            f"{os.cpu_count()} cores, {mem / 2**20:.0f} GiB")


def ms(x):
    return f"{x:.1f}" if x < 100 else f"{x:.0f}"


def sec(x):
    return f"{x:.2f} s" if x < 10 else f"{x:.1f} s"


def table(header, rows):
    head = "| " + " | ".join(h.lstrip(">") for h in header) + " |"
    rule = "|" + "|".join("---:" if h.startswith(">") else "---" for h in header) + "|"
    return [head, rule] + ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]


# ---- The tables: each returns (heading, command paragraph, table lines). ----

VOXELIZE_MESHES = ["featuretype", "plate_holes", "rocker_arm", "fandisk", "tray_bottom_ascii", "orion_capsule_ascii",
                   "stanford_bunny", "armadillo", "femur_right", "igea_refined_508k", "cycloidal_assembly",
                   "cube_axis_aligned", "cube_rotated_45z", "two_disjoint_cubes"]


def voxelize_table(b):
    """Voxelization speed and memory at R = 1000"""
    r = b.gbench("voxelize_bench", ".*")
    rows = []
    for m in VOXELIZE_MESHES:
        if f"load/{m}" not in r:
            continue
        load = r[f"load/{m}"]["real_time"]
        cells = [m, int(r[f"load/{m}"]["triangles"]), r[f"voxelize/{m}/128"]["label"], ms(load)]
        for res in (128, 256, 512, 1000):
            v, f = r[f"voxelize/{m}/{res}"], r[f"floor/{m}/{res}"]
            cells.append(f"{ms(v['cold_ms'])} / {ms(f['cold_ms'])}")
        v, f = r[f"voxelize/{m}/1000"], r[f"floor/{m}/1000"]
        base = v["grid_MiB"] + 36 * v["triangles"] / 2**20
        cells += [f"{(v['cold_ms'] - load) / f['cold_ms']:.2f}", f"{v['grid_MiB']:.1f}", f"{v['peak_MiB']:.1f}",
                  f"{v['peak_MiB'] / base:.2f}", f"{v['extra_MiB'] / base:.2f}"]
        rows.append(cells)
    head = ["mesh", ">triangles", "mode", ">load", "R = 128: voxelize / floor", "R = 256", "R = 512", "R = 1000",
            ">(voxelize - load) / floor at 1000", ">grid MiB", ">peak MiB", ">peak / (grid + mesh)",
            ">work's own / (grid + mesh)"]
    return ("Voxelization speed and memory at R = 1000",
            "Command: `bench/tables.py voxelize` (`voxelize_bench`, 2 threads). Times in ms, cold (median of five "
            "fresh processes); memory at R = 1000.", table(head, rows))


def assemblies_table(b):
    """Assemblies"""
    r = b.gbench("assembly_bench", ".*", extra=["--benchmark_repetitions=3", "--benchmark_report_aggregates_only=true"])
    rows = []
    for name, res in sorted(r.items()):
        rows.append([f"`{name}`", ms(res["real_time"]) + " ms", ms(res["cpu_time"]) + " ms"])
    return ("Assemblies", "Command: `bench/tables.py assemblies` (`assembly_bench`, 2 threads, median of three). "
            "CPU is both threads'.", table(["operation", ">wall", ">CPU"], rows))


def io_table(b):
    """STL loading and voxel files"""
    r = b.gbench("io_bench", ".*", extra=["--benchmark_min_time=1"])
    rows = []
    for name, res in r.items():
        rate = ""
        if "triangles/s" in res:
            rate = f"{res['triangles/s'] / 1e6:.2f} M triangles/s"
        if "file_bytes" in res:
            rate = f"file {res['file_bytes'] / 1e6:.2f} MB"
        rows.append([f"`{name}`", ms(res["real_time"]) + " ms", rate])
    return ("STL loading and voxel files", "Command: `bench/tables.py io` (`io_bench --benchmark_min_time=1`); CPU, "
            "one thread, files in memory.", table(["benchmark", ">time", "rate"], rows))


def analysis_table(b):
    """Analysis at R = 1000"""
    cols = {}
    for m in ("igea_refined_508k", "fandisk"):
        cols[m] = b.gbench("analysis_bench", ".*", env={"VOXMOD_BENCH_MESH": m})
    names = list(cols["fandisk"])
    rows = [[f"`{n}`"] + [f"{ms(cols[m][n]['real_time'])} / {ms(cols[m][n]['cpu_time'])}" if n in cols[m] else ""
                          for m in cols] for n in names]
    return ("Analysis at R = 1000", "Command: `bench/tables.py analysis` (`VOXMOD_BENCH_MESH=M analysis_bench`). "
            "Wall / CPU in ms.", table(["operation", "igea", "fandisk"], rows))


def distance_table(b):
    """Distance and thickness"""
    rows = []
    for m, res in (("igea_refined_508k", 512), ("igea_refined_508k", 1000)):
        env = {"VOXMOD_BENCH_MESH": m, "VOXMOD_BENCH_R": str(res)}
        r = b.gbench("thickness_bench", "distance/0|thickness|hot_spots", env=env)
        d, t, h = r["distance/0"], r["thickness"], r["hot_spots"]
        rows.append([f"{m}, R = {res}", sec(d["real_time"] / 1e3), sec(t["real_time"] / 1e3) + " / " +
                     sec(t["cpu_time"] / 1e3), sec(h["real_time"] / 1e3)])
    return ("Distance and thickness", "Command: `bench/tables.py distance` (`VOXMOD_BENCH_MESH=M VOXMOD_BENCH_R=R "
            "thickness_bench --benchmark_filter='distance/0|thickness|hot_spots'`).",
            table(["part", ">exact distance transform", ">local thickness, wall / CPU", ">hot spots"], rows))


def printability_table(b):
    """Printability"""
    rows = []
    for mesh, res, orient in (("igea_refined_508k.stl", 1000, False), ("igea_refined_508k.stl", 256, True),
                              ("stanford_bunny.stl", 256, True), ("armadillo.stl", 256, True),
                              ("featuretype.stl", 256, True)):
        j, wall, peak = b.cli(["printcheck", b.mesh(mesh), "--res", str(res)] + (["--orient"] if orient else []))
        t = j.get("timings", j)
        rows.append([mesh[:-4], res, sec(wall), f"{peak:.0f} MiB", sec(t.get("support_s", 0)),
                     sec(t["orient_s"]) if orient and "orient_s" in t else ""])
    return ("Printability", "Command: `bench/tables.py printability` (`voxmod printcheck MESH --res R [--orient] "
            "--json` under `/usr/bin/time`, voxelizing included; `support_s`, `orient_s` from the JSON). No peer: the "
            "slicers that estimate support are not libraries in Debian.",
            table(["part", ">R", ">whole command", ">peak", ">support (one direction)", ">106 directions"], rows))


def casting_table(b):
    """Casting"""
    rows = []
    for res in (128, 300):
        j, wall, peak = b.cli(["casting", b.mesh("rocker_arm.stl"), "--units", "in", "--res", str(res), "--alloy",
                               "a356"])
        nx, ny, nz = j["box"]
        cells = nx * ny * nz
        rows.append([res, f"{nx} x {ny} x {nz} ({cells / 1e6:.1f} M)", j["steps"], sec(j["modulus_s"]),
                     sec(j["simulate_s"]), f"{j['simulate_s'] / (cells * j['steps']) * 1e9:.1f} ns", sec(wall),
                     f"{peak:.0f} MiB"])
    return ("Casting", "Command: `bench/tables.py casting` (`voxmod casting rocker_arm.stl --units in --res R "
            "--alloy a356 --json` under `/usr/bin/time`; the whole command includes voxelizing). No peer: no open "
            "solidification code is in Debian.",
            table([">R", "box (metal and sand)", ">steps", ">modulus", ">simulation", ">per cell and step",
                   ">whole command", ">peak"], rows))


def export_tables(b):
    """Surface export; Volume export"""
    vxm = b.scratch("igea1000.vxm")
    subprocess.run([b.voxmod, "voxelize", b.mesh("igea_refined_508k.stl"), "--res", "1000", "-o", vxm], check=True,
                   capture_output=True)
    surface, volume = [], []
    for ext in (".stl", ".ply"):
        j, wall, peak = b.cli(["convert", vxm, b.scratch("out" + ext)])
        t = j.get("timings", j)
        surface.append([f"`{ext}`", sec(t.get("surface_s", 0)), sec(t.get("write_s", 0)), sec(wall),
                        f"{peak:.0f} MiB", f"{os.path.getsize(b.scratch('out' + ext)) / 1e6:.0f} MB"])
    for ext in (".vdb", ".vti", ".nrrd", ".vox"):
        j, wall, peak = b.cli(["convert", vxm, b.scratch("out" + ext)])
        t = j.get("timings", j)
        volume.append([f"`{ext}`", sec(t.get("write_s", 0)), sec(wall), f"{peak:.0f} MiB",
                       f"{os.path.getsize(b.scratch('out' + ext)) / 1e6:.1f} MB"])
    return [("Surface export", "Command: `bench/tables.py surface` (`voxmod convert igea1000.vxm OUT --json`, igea "
             "at R = 1000, under `/usr/bin/time`).",
             table(["output", ">surface", ">written", ">wall", ">peak", ">file"], surface)),
            ("Volume export", "Command: `bench/tables.py surface` (`voxmod convert igea1000.vxm out.EXT --json`, "
             "igea at R = 1000; `write_s` from the JSON).",
             table(["format", ">write_s", ">wall", ">peak", ">file"], volume))]


def batch_table(b):
    """Batch: a dataset at R = 128"""
    script = os.path.join(ROOT, "bench", "batch_throughput.sh")
    out = subprocess.run([script, b.voxmod, os.path.join(b.shared, "meshes"), "128"], check=True,
                         capture_output=True, text=True, env={**os.environ, "RUNS": str(max(b.runs, 3))}).stdout
    rows, loop = [], None
    for line in out.splitlines():
        if line.startswith("#"):
            continue
        name, wall = line.rsplit(None, 1)
        loop = loop or float(wall)
        rows.append([name, sec(float(wall)), f"{loop / float(wall):.1f}x"])
    return ("Batch: a dataset at R = 128", "Command: `bench/tables.py batch` (`bench/batch_throughput.sh`: the "
            "shared meshes to `.binvox`, median wall of the runs).", table(["method", ">wall", ">vs loop"], rows))


def render_table(b):
    """Point rendering"""
    r = b.gbench("render_bench", ".*")
    rows = [[f"`{n}`", ms(x["real_time"]) + " ms", ms(x["cpu_time"]) + " ms", f"{x.get('points', 0) / 1e3:.0f} k"]
            for n, x in r.items()]
    return ("Point rendering", "Command: `bench/tables.py render` (`render_bench`, EGL surfaceless, 1280 x 720).",
            table(["case", ">wall", ">process CPU", ">points"], rows))


def gib(mib):
    return f"{mib / 1024:.2f} GiB" if mib >= 1024 else f"{mib:.0f} MiB"


def streamed_table(b):
    """Grids larger than memory: streamed voxelization and reading in windows"""
    rows = []
    for res, limit in ((2048, None), (2048, "512M"), (4096, None), (4096, "512M"), (8192, None)):
        vxm = b.scratch(f"igea{res}.vxm")
        extra = ["--memory-limit", limit] if limit else []
        j, wall, peak = b.cli(["voxelize", b.mesh("igea_refined_508k.stl"), "--res", str(res), "-o", vxm] + extra)
        nx, _, nz = j["dims"]
        reads = (["info"], ["mass"], ["section", "--axis", "z", "--index", str(nz // 2)],
                 ["section", "--axis", "x", "--index", str(nx // 2)], ["xray", "--axis", "z", "--mode", "max"])
        cells = [f"{res} ({' x '.join(str(d) for d in j['dims'])}; `.vxm` {os.path.getsize(vxm) / 2**20:.1f} MiB)",
                 ("streamed, " + (limit or "default limit")) if j.get("streamed") else "in memory",
                 f"{sec(wall)}, {gib(peak)}"]
        for read in reads:
            out = [b.scratch("read.png")] if read[0] in ("section", "xray") else []
            _, w, pk = b.cli([read[0], vxm] + read[1:] + (["-o"] + out if out else []) + extra)
            cells.append(f"{sec(w)}, {gib(pk)}")
        os.remove(vxm)
        rows.append(cells)
    return ("Grids larger than memory: streamed voxelization and reading in windows",
            "Command: `bench/tables.py streamed` (`voxmod voxelize igea_refined_508k.stl --res R -o igea.vxm --json "
            "[--memory-limit 512M]`, then `info`, `mass`, `section --axis z|x` (the middle index), `xray --axis z "
            "--mode max` on the file with the same limit, under `/usr/bin/time`). Wall, peak resident.",
            table(["R (dims; `.vxm`)", "how", ">voxelize", ">info", ">mass", ">section z", ">section x",
                   ">xray z max"], rows))


def parts_move_table(b):
    """The window: moving a part of the cycloidal drive"""
    r = b.gbench("parts_move_bench", ".*", env={"VOXMOD_BENCH_R": "1000"})
    rows = [[n.split("/")[-1], ms(x["real_time"]) + " ms", ms(x["placePart_ms"]) + " ms",
             ms(x["syncRenderers_ms"]) + " ms", int(x["parts"])] for n, x in r.items()]
    return ("The window: moving a part of the cycloidal drive",
            "Command: `bench/tables.py parts-move` (`VOXMOD_BENCH_R=1000 parts_move_bench`, EGL, llvmpipe): part N "
            "of the drive's bodies moved a voxel along X and back, mean of 4 moves, the frame's drawing left out.",
            table([">part", ">whole move", ">placePart (new state, union)", ">syncRenderers", ">parts"], rows))


def cad_table(b):
    """CAD input: a STEP assembly opened, tessellated and voxelized at R = 500"""
    rows = []
    for cad in ("as1-oc-214.stp", "box_sides.STEP"):
        r = b.gbench("cad_bench", ".*", env={"VOXMOD_BENCH_CAD": cad}, extra=["--benchmark_min_time=1"])
        read, tess = r["BM_CadRead"], r["BM_CadTessellate"]
        vox, whole = r["BM_CadVoxelize"], r["BM_CadOpenTessellateVoxelize"]
        j, wall, peak = b.cli(["voxelize", os.path.join(b.shared, "meshes", "cad", cad), "--res", "500", "-o",
                               b.scratch("cad.vxm")])
        rows.append([f"{cad} ({' x '.join(str(d) for d in j['dims'])})", int(read["solids"]),
                     ms(read["real_time"]) + " ms", ms(tess["real_time"]) + " ms", f"{int(tess['triangles']):,}",
                     ms(vox["real_time"]) + " ms", ms(whole["real_time"]) + " ms", sec(wall), f"{peak:.0f} MiB"])
    return ("CAD input: a STEP assembly opened, tessellated and voxelized at R = 500",
            "Command: `bench/tables.py cad` (`VOXMOD_BENCH_CAD=FILE cad_bench --benchmark_min_time=1`; the CLI: "
            "`voxmod voxelize cad/FILE --res 500 -o x.vxm --json` under `/usr/bin/time`). Wall time.",
            table(["file", ">solids", ">read + heal", ">tessellate", ">triangles", ">voxelize", ">all three",
                   ">CLI wall", ">CLI peak"], rows))


def report_table(b):
    """The report"""
    out = b.scratch("r.html")
    j, wall, peak = b.cli(["report", b.mesh("rocker_arm.stl"), "--res", "300", "--units", "mm", "--min-wall", "0.02",
                           "--material", "aluminium", "-o", out])
    rows = [["rocker_arm, R = 300", sec(j["report_s"]), sec(wall), f"{peak:.0f} MiB",
             f"{os.path.getsize(out) / 1e3:.0f} kB"]]
    return ("The report", "Command: `bench/tables.py report` (`voxmod report rocker_arm.stl --res 300 --units mm "
            "--min-wall 0.02 --material aluminium -o r.html --json` under `/usr/bin/time`; `report_s`: the analyses, "
            "the pictures and the page). No peer.",
            table(["part", ">report_s", ">whole command", ">peak", ">page"], rows))


def window_script(b, script, args=()):
    """A window run under Xvfb with a script: (its output, peak resident MiB)."""
    path = b.scratch("run.script")
    open(path, "w").write(script)
    timing = b.scratch("time.txt")
    cmd = ["/usr/bin/time", "-f", "%e %M", "-o", timing, "xvfb-run", "-a", "-s", "-screen 0 1280x800x24", b.voxmod,
           *args, "--size", "1280x800", "--script", path]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    return out, float(open(timing).read().split()[-1]) / 1024


def peel_table(b):
    """The window: peel to core at R = 4096"""
    script = (f"open {b.mesh('rocker_arm.stl')}\nvoxelize 4096\nstate {b.scratch('model.txt')}\npanel-skin\n"
              f"peel-core\nstate {b.scratch('peeled.txt')}\nexit\n")
    t0 = datetime.datetime.now()
    _, peak = window_script(b, script)
    wall = (datetime.datetime.now() - t0).total_seconds()
    state = dict(l.split(" = ", 1) for l in open(b.scratch("peeled.txt")).read().splitlines() if " = " in l)
    rows = [[state.get("dims", "?").replace(" ", " x "), state.get("layers", "?"), state.get("peeled", "?"), sec(wall), gib(peak)]]
    return ("The window: peel to core at R = 4096",
            "Command: `bench/tables.py peel` (the window under Xvfb with a script: `open rocker_arm.stl`, "
            "`voxelize 4096`, `panel-skin`, `peel-core`; the whole run under `/usr/bin/time`). The window refuses "
            "skin layers when the bound plus the model exceeds 80% of physical memory.",
            table(["grid", ">skin layers", ">peeled", ">whole run (voxelize, depth map, peel)", ">peak"], rows))


def slider_table(b):
    """The window: dragging the section slider"""
    sweep = open(os.path.join(ROOT, "tests", "gui", "bench_section_sweep.script")).read()
    out, _ = window_script(b, sweep, [b.mesh("igea_refined_508k.stl")])
    rows = []
    for line in out.splitlines():
        m = re.match(r"sweep (\w): (\d+) frames, (.*?) voxels, (\d+) surface points .* lod (\w+): mean ([\d.]+) ms, "
                     r"median [\d.]+ ms, ([\d.]+) fps", line)
        if m:
            rows.append([f"along {m[1].upper()}, {m[3]}, {int(m[4]) / 1e3:.0f} k points, lod {m[5]}", m[2],
                         m[6] + " ms", m[7]])
    return ("The window: dragging the section slider",
            "Command: `bench/tables.py slider` (`voxmod igea_refined_508k.stl --size 1280x800 --script "
            "tests/gui/bench_section_sweep.script` under Xvfb: one section per frame; llvmpipe).",
            table(["sweep", ">frames", ">frame mean", ">frames per second"], rows))


# The tables whose sections in docs/performance.md have the layout the script writes (--write replaces only these;
# the others' sections carry more: rows of other tools, targets, a second machine, and are merged by hand).
WRITABLE = {"casting"}

TABLES = {"voxelize": voxelize_table, "streamed": streamed_table, "batch": batch_table,
          "assemblies": assemblies_table, "parts-move": parts_move_table, "io": io_table, "cad": cad_table,
          "analysis": analysis_table, "distance": distance_table, "printability": printability_table,
          "casting": casting_table, "report": report_table, "surface": export_tables, "peel": peel_table,
          "render": render_table, "slider": slider_table}


def replace_section(doc, heading, paragraph, lines):
    """The doc with the lines from `## heading` to its first table's last row replaced."""
    start = doc.index(f"## {heading}")
    rows = [i for i in range(start + 1, len(doc)) if doc[i].startswith("|")]
    if not rows:
        raise SystemExit(f"docs/performance.md: no table under '## {heading}'")
    end = rows[0]
    while end + 1 < len(doc) and doc[end + 1].startswith("|"):
        end += 1
    return doc[:start + 1] + wrap(paragraph) + [""] + lines + doc[end + 1:]


def wrap(text, width=118):
    out, line = [], ""
    for word in text.split(" "):
        if line and len(line) + 1 + len(word) > width:
            out.append(line)
            line = word
        else:
            line = f"{line} {word}" if line else word
    return out + [line]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("tables", nargs="*")
    ap.add_argument("--build", default=next((d for d in ("build-rel", "build") if os.path.isdir(os.path.join(
        ROOT, d))), "build"))
    ap.add_argument("--shared", default=os.path.join(ROOT, "..", "shared"))
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--write", action="store_true")
    ap.add_argument("--list", action="store_true")
    args = ap.parse_args()
    if args.list:
        for k, f in TABLES.items():
            print(f"{k:14} {f.__doc__}")
        return
    unknown = [t for t in args.tables if t not in TABLES]
    if unknown:
        raise SystemExit(f"bench/tables.py: no table {', '.join(unknown)} (there are {', '.join(TABLES)})")
    unwritable = [t for t in args.tables or list(TABLES) if t not in WRITABLE]
    if args.write and unwritable:
        raise SystemExit(f"bench/tables.py: --write replaces only {', '.join(sorted(WRITABLE))}: the sections of "
                         f"{', '.join(unwritable)} hold more than the script measures; print them and merge by hand")
    b = Bench(os.path.join(ROOT, args.build), args.shared, args.runs)
    stamp = f" Measured on {machine()}, {datetime.date.today().isoformat()}."
    doc = open(DOC).read().split("\n")
    try:
        for name in args.tables or list(TABLES):
            got = TABLES[name](b)
            for heading, paragraph, lines in got if isinstance(got, list) else [got]:
                if args.write:
                    doc = replace_section(doc, heading, paragraph + stamp, lines)
                else:
                    print("\n".join([f"## {heading}"] + wrap(paragraph + stamp) + [""] + lines + [""]))
    finally:
        shutil.rmtree(b.work, ignore_errors=True)
    if args.write:
        tmp = DOC + ".tmp"
        open(tmp, "w").write("\n".join(doc))
        os.replace(tmp, DOC)


if __name__ == "__main__":
    sys.exit(main())
