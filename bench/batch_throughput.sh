#!/usr/bin/env bash
# Batch throughput (docs/performance.md, "Batch"): the shared meshes voxelized to .binvox at R = 128 by a shell loop of
# `voxmod voxelize`, by `voxmod batch`, and by `voxmod batch` under `mpirun -np 1, 2, 3`. Each variant runs RUNS times
# (default 5) into a fresh directory; the median wall time is printed. Usage:
#   bench/batch_throughput.sh [VOXMOD] [MESH_DIR] [RES]
set -euo pipefail
voxmod=${1:-build/voxmod}
meshes=${2:-../shared/meshes}
res=${3:-128}
runs=${RUNS:-5}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
inputs=("$meshes"/*.stl)
mpirun_root=()
[[ $(id -u) -eq 0 ]] && mpirun_root=(--allow-run-as-root)

loop() {
  for m in "${inputs[@]}"; do "$voxmod" voxelize "$m" --res "$res" -o "$1/$(basename "${m%.*}").binvox" >/dev/null 2>&1; done
}
batch() { "$voxmod" batch "${inputs[@]}" -o "$1" --format binvox --res "$res" >/dev/null; }
batch_one() { "$voxmod" batch "${inputs[@]}" -o "$1" --format binvox --res "$res" --jobs 1 >/dev/null; }
mpi() {
  local np=$1
  shift
  mpirun "${mpirun_root[@]}" --oversubscribe -np "$np" "$voxmod" batch "${inputs[@]}" -o "$1" --format binvox \
    --res "$res" >/dev/null
}

# Median wall seconds of `runs` runs of "$@ DIR".
median() {
  local times=()
  for ((i = 0; i < runs; i++)); do
    local dir="$work/run$RANDOM$i"
    local t0 t1
    mkdir -p "$dir"
    t0=$(date +%s.%N)
    "$@" "$dir"
    t1=$(date +%s.%N)
    times+=("$(echo "$t1 - $t0" | bc)")
    rm -rf "$dir"
  done
  printf '%s\n' "${times[@]}" | sort -g | sed -n "$(((runs + 1) / 2))p"
}

echo "# $(date -u +%Y-%m-%dT%H:%MZ) $(nproc) cores, load: $(cut -d' ' -f1-3 /proc/loadavg), ${#inputs[@]} meshes, R = $res"
printf '%-28s %s\n' "shell loop of voxelize" "$(median loop)"
printf '%-28s %s\n' "voxmod batch" "$(median batch)"
printf '%-28s %s\n' "voxmod batch --jobs 1" "$(median batch_one)"
if command -v mpirun >/dev/null; then
  for np in 1 2 3; do printf '%-28s %s\n' "mpirun -np $np voxmod batch" "$(median mpi "$np")"; done
fi
