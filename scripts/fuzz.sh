#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan) and runs each for a bounded time.
# Usage: scripts/fuzz.sh [seconds per target, default 60]. Crashes are saved under build-fuzz/crashes/<target>/;
# turn each into a regression file under tests/data/ with the fix.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shared=${VOXMOD_SHARED_DIR:-../shared}
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVOXMOD_BUILD_FUZZ=ON \
  -DVOXMOD_BUILD_TESTS=OFF -DVOXMOD_BUILD_BENCH=OFF "-DVOXMOD_SANITIZE=address,undefined" >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target fuzz_stl fuzz_vxm fuzz_binvox fuzz_mesh_file fuzz_project

# Seed corpora: small shared meshes and reference grids, plus the malformed-file tests.
seed() {  # seed <target> <files...>
  local dir=build-fuzz/corpus/$1
  mkdir -p "$dir"
  shift
  for f in "$@"; do [[ -f $f ]] && cp -f "$f" "$dir/"; done
  return 0
}
seed stl models/*.stl tests/data/malformed/*.stl tests/data/quirks/*.stl $shared/meshes/two_disjoint_cubes.stl $shared/meshes/cube_axis_aligned.stl
seed binvox $shared/reference/*_r64.binvox tests/data/malformed/*.binvox tests/data/quirks/*.binvox tests/data/*.binvox
seed vxm tests/data/*.vxm tests/data/malformed/*.vxm tests/data/quirks/*.vxm
# fuzz_project reads each input as a .vxp file and as the manifest of a project with fixed grids: the manifest of
# those grids seeds it.
seed project tests/data/project/manifest.json
# fuzz_mesh_file reads the bytes after the first under the name that byte picks (tests/fuzz/fuzz_mesh_file.cpp):
# each seed is a file behind the byte of its format. The shared CAD corpus, and small files of tests/data/mesh.
seed_named() {  # seed_named <index of the name> <files...>
  local dir=build-fuzz/corpus/mesh_file index=$1
  mkdir -p "$dir"
  shift
  for f in "$@"; do
    [[ -f $f && $(stat -c %s "$f") -le 1048576 ]] || continue
    { printf "\\$(printf %03o "$index")"; cat "$f"; } >"$dir/$index-$(basename "$f")"
  done
  return 0
}
seed_named 0 tests/data/mesh/*.obj tests/data/malformed/*.obj $shared/meshes/cad/*.obj
seed_named 1 tests/data/mesh/*.ply tests/data/malformed/*.ply $shared/meshes/cad/*.ply
seed_named 2 tests/data/mesh/*.3mf tests/data/malformed/*.3mf $shared/meshes/cad/*.3mf $shared/meshes/cad/*.3MF
seed_named 3 tests/data/mesh/*.gltf
seed_named 4 tests/data/mesh/*.glb
seed_named 5 tests/data/mesh/*.off
seed_named 7 tests/data/mesh/*.step tests/data/malformed/*.step $shared/meshes/cad/screw.step
seed_named 8 tests/data/mesh/*.iges tests/data/malformed/*.iges

export LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp
fuzz_one() {  # fuzz_one <target>: fuzzes it for $seconds, its report in build-fuzz/fuzz_<target>.out; fails on a find
  local t=$1 timeout=10
  mkdir -p build-fuzz/crashes/$t
  # Under the fuzzer some malformed STEP files parse for tens of seconds (0.1 s in a release build): a longer timeout.
  [[ $t == mesh_file ]] && timeout=60
  if ! build-fuzz/tests/fuzz/fuzz_$t build-fuzz/corpus/$t -max_total_time="$seconds" -rss_limit_mb=2048 \
      -max_len=1048576 -timeout=$timeout -artifact_prefix=build-fuzz/crashes/$t/ -print_final_stats=1 2>build-fuzz/fuzz_$t.log; then
    { echo "fuzz_$t found a problem:"; tail -n 40 build-fuzz/fuzz_$t.log; } >build-fuzz/fuzz_$t.out
    return 1
  fi
  { echo "fuzz_$t: ${seconds}s"; grep -E 'DONE' build-fuzz/fuzz_$t.log | tail -n 1 || true; } >build-fuzz/fuzz_$t.out
}

# One fuzzer per core at a time (each runs on one thread).
targets=(stl vxm binvox mesh_file project)
status=0
running=0
for t in "${targets[@]}"; do
  if ((running >= $(nproc))); then
    wait -n || status=1
    ((running--))
  fi
  echo "fuzzing $t for ${seconds}s"
  fuzz_one "$t" &
  ((++running))
done
while ((running > 0)); do
  wait -n || status=1
  ((running--))
done
for t in "${targets[@]}"; do cat build-fuzz/fuzz_$t.out; done
exit $status
