#!/usr/bin/env bash
# GUI test: nothing lost. A window with an assembly whose parts were moved, turned, coloured and hidden is killed
# (SIGKILL) once it has autosaved; the next window offers to recover the work, and pressing Recover brings back the
# parts with their names, colours, visibility and placements, unsaved. Then a project saved with Save As (.vxp)
# reopens as it was saved.
#
#   recover_test.sh VOXMOD SOURCE_DIR OUT_DIR
#
# Exit codes: 0 pass, 1 fail, 77 skipped (no xvfb-run outside CI).
set -euo pipefail

voxmod=$1
src=$2
out=$3
if ! command -v xvfb-run >/dev/null 2>&1; then
  [[ "${CI:-}" == "true" ]] && { echo "FAIL: recover test needs xvfb-run (scripts/setup.sh installs it)" >&2; exit 1; }
  echo "SKIP: recover test needs xvfb-run" >&2
  exit 77
fi
rm -rf "$out"
mkdir -p "$out/autosave"
export VOXMOD_AUTOSAVE_DIR=$out/autosave VOXMOD_AUTOSAVE_SECONDS=0
checks=0
fail() {
  echo "FAIL: $*" >&2
  for f in "$out"/*.log; do echo "--- $f" >&2; tail -n 20 "$f" >&2; done
  exit 1
}
pass() {
  checks=$((checks + 1))
  echo "ok $checks - $*"
}
get() { sed -n "s/^$2 = //p" "$out/$1"; }
expect() {  # file key value
  local v
  v=$(get "$1" "$2")
  [[ "$v" == "$3" ]] || fail "$1: $2 is '$v', expected '$3'"
  pass "$1: $2 = $3"
}
run() {  # script-name: runs voxmod on $out/NAME.script (with @SRC@ and @OUT@ filled in) in the background
  sed -e "s|@SRC@|$src|g" -e "s|@OUT@|$out|g" >"$out/$1.script"
  xvfb-run -a -s "-screen 0 1400x900x24" "$voxmod" --size 1280x800 --script "$out/$1.script" >"$out/$1.log" 2>&1 &
}

# 1. Work on an assembly, then wait to be killed.
run work <<'SCRIPT'
open @SRC@/models/plate_holes.stl
voxelize 60
panel-parts
add-part @SRC@/models/plate_holes.stl
place-part 2 20 0 0 0 0 1
part-colour 2 0.1 0.9 0.2
part-visible 1 off
select-part 2
section x 7
wait 5
state @OUT@/work.txt
wait-file @OUT@/never 300
SCRIPT
for ((i = 0; i < 1200; ++i)); do
  [[ -s "$out/work.txt" ]] && break
  sleep 0.1
done
[[ -s "$out/work.txt" ]] || fail "the working window wrote no state"
autosave=$(get work.txt autosave_file)
[[ -n "$autosave" && -s "$autosave" ]] || fail "no autosave was written ('$autosave')"
pass "the working window autosaved to $(basename "$autosave")"
pid=$(get work.txt pid)
kill -KILL "$pid" || fail "no window to kill"
wait || true  # xvfb-run reaps the killed window and ends
[[ -s "$autosave" ]] || fail "the autosave did not outlive the kill"
pass "killed; the autosave stays"

# 2. The next window offers the work; Recover brings it back, unsaved.
run recover <<'SCRIPT'
wait 3
state @OUT@/offer.txt
press Recover
wait 3
state @OUT@/recovered.txt
exit
SCRIPT
wait $! || fail "the recovering window failed"
expect offer.txt autosave_orphans 1
expect recovered.txt autosave_orphans 0
expect recovered.txt parts 2
expect recovered.txt selected_parts 2
for key in selected_part selected_translation selected_turns filled dims section_axis section_index panel; do
  expect recovered.txt "$key" "$(get work.txt "$key")"
done
expect recovered.txt document plate_holes.stl
expect recovered.txt unsaved 1
[[ ! -e "$autosave" ]] || fail "the recovered autosave was left for another window to offer"
pass "the recovered autosave is now this window's"

# 3. A project saved with Save As reopens as it was saved, parts and look included.
run save <<'SCRIPT'
open @SRC@/models/plate_holes.stl
voxelize 60
panel-parts
add-part @SRC@/models/plate_holes.stl
place-part 2 20 0 0 0 0 1
part-colour 2 0.1 0.9 0.2
select-part 2
save-as @OUT@/scene.vxp
state @OUT@/saved.txt
exit
SCRIPT
wait $! || fail "the saving window failed"
run reopen <<'SCRIPT'
open @OUT@/scene.vxp
state @OUT@/reopened.txt
exit
SCRIPT
wait $! || fail "the reopening window failed"
for key in parts selected_parts selected_part selected_translation selected_turns filled dims panel; do
  expect reopened.txt "$key" "$(get saved.txt "$key")"
done
expect reopened.txt unsaved 0
echo "recover test: $checks checks passed"
