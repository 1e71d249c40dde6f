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
cmake --build build-fuzz -j "$(nproc)" --target fuzz_stl fuzz_vxm fuzz_binvox

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

status=0
for t in stl vxm binvox; do
  mkdir -p build-fuzz/crashes/$t
  echo "fuzzing $t for ${seconds}s"
  if ! build-fuzz/tests/fuzz/fuzz_$t build-fuzz/corpus/$t -max_total_time="$seconds" -rss_limit_mb=2048 \
      -max_len=1048576 -timeout=10 -artifact_prefix=build-fuzz/crashes/$t/ -print_final_stats=1 2>build-fuzz/fuzz_$t.log; then
    echo "fuzz_$t found a problem:"; tail -n 40 build-fuzz/fuzz_$t.log; status=1
  else
    grep -E 'DONE' build-fuzz/fuzz_$t.log | tail -n 1 || true
  fi
done
exit $status
