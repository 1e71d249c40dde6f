#!/usr/bin/env bash
# GUI test: the window's real widgets pressed and typed into with the pointer and keys as ImGui sees them (the
# harness's press, type and press-all, script.h), with an assembly loaded and then one model, under whatever
# sanitizer the build has. Checks that:
#   - a Boolean of two selected parts pressed in the Parts panel makes the new part, selected, at its own placement
#     (the panel drew on from the assembly before it: a part past its end);
#   - typing 2 into the new part's X field moves it 2 model units in X, and nothing else;
#   - a move no grid could hold is refused with a message and changes nothing;
#   - the Print panel finds a sealed void, turns the build direction, searches the directions and waits for a face
#     to be clicked when its buttons are pressed;
#   - the Casting panel asks for units, simulates, places a feeder on the part's top and simulates with it;
#   - every button, field, toggle, list row and combo of every panel is pressed and the window goes on;
#   - clicks in the Thickness panel's picture pick voxels to measure, snapped to the material's edge.
#
#   press_test.sh VOXMOD SOURCE_DIR OUT_DIR
#
# Exit codes: 0 pass, 1 fail, 77 skipped (no xvfb-run outside CI).
set -euo pipefail

voxmod=$1
src=$2
out=$3
if ! command -v xvfb-run >/dev/null 2>&1; then
  [[ "${CI:-}" == "true" ]] && { echo "FAIL: press test needs xvfb-run (scripts/setup.sh installs it)" >&2; exit 1; }
  echo "SKIP: press test needs xvfb-run" >&2
  exit 77
fi
rm -rf "$out"
mkdir -p "$out"
# run_script NAME LOG: tests/gui/NAME.script with @SRC@ and @OUT@ filled in, its output in OUT/LOG.
run_script() {
  sed -e "s|@SRC@|$src|g" -e "s|@OUT@|$out|g" "$src/tests/gui/$1.script" >"$out/$1.script"
  if ! xvfb-run -a -s "-screen 0 1400x900x24" "$voxmod" --size 1280x800 --script "$out/$1.script" >"$out/$2" 2>&1; then
    echo "FAIL: voxmod did not finish $1.script" >&2
    tail -n 40 "$out/$2" >&2
    exit 1
  fi
}
run_script press voxmod.log
run_script measure measure.log

checks=0
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
get() { sed -n "s/^$2 = //p" "$out/$1"; }
expect() {  # file key value
  local v
  v=$(get "$1" "$2")
  [[ "$v" == "$3" ]] || fail "$1: $2 is '$v', expected '$3'"
  checks=$((checks + 1))
  echo "ok $checks - $1: $2 = $3"
}

expect after_boolean.txt parts 4
expect after_boolean.txt selected_parts 4
expect after_boolean.txt selected_translation "0 0 0"
expect after_boolean.txt selected_turns "0 0 0"
h=$(get after_boolean.txt voxel_size)
tx=$(python3 -c "print(round(2 / $h))")
((tx > 0)) || fail "a voxel of $h is larger than the move of 2"
expect after_move.txt selected_translation "$tx 0 0"
expect after_refusal.txt selected_translation "$tx 0 0"
expect after_refusal.txt selected_turns "0 0 1"
grep -q "expected error: .*more than the" "$out/voxmod.log" || fail "the absurd move was not refused with a message"

# The section at an angle shows its plane's facts (and its widgets are pressed below).
grep -q "^rect_X@normal = " "$out/oblique.txt" || fail "the section at an angle shows no normal fields"
grep -q "^rect_section_offset = " "$out/oblique.txt" || fail "the section at an angle shows no offset slider"
# Through (2,3,1), (20,3,4), (2,15,6): the normal (18,0,3) x (0,12,5) = (-36,-90,216), made unit with its largest
# component positive; the 3D view draws the cut face.
expect through.txt section_oblique 1
awk '/^section_normal = /{ ok = ($3 + 0.1521 < 0.001 && $3 + 0.1521 > -0.001 && $4 + 0.3801 < 0.001 &&
  $4 + 0.3801 > -0.001 && $5 - 0.9123 < 0.001 && $5 - 0.9123 > -0.001) } END { exit !ok }' "$out/through.txt" ||
  fail "the section through three picked voxels has the wrong normal: $(grep section_normal "$out/through.txt")"
awk '/^cut_points = /{ exit !($3 > 0) }' "$out/through.txt" || fail "the 3D view shows no cut face at an angle"

# The Print panel: the block's void found, -z pressed turns the build direction (the void's floor then hangs), the
# search lists the six axes and 100 more directions, and "Lay a face on the plate" waits for a click.
expect print.txt print_direction "+z"
expect print.txt print_cavities 1
expect print_down.txt print_direction "-z"
expect print_down.txt print_cavities 1
expect print_orient.txt print_orientations 106
expect print_lay.txt print_lay_face 1
up=$(get print.txt print_support_volume)
down=$(get print_down.txt print_support_volume)
python3 -c "import sys; sys.exit(0 if abs($up - 256) < 5 and abs($down - 256) < 5 else 1)" ||
  fail "the void's 8 x 8 x 4 mm needs 256 mm^3 of support either way up, not $up and $down"
checks=$((checks + 1))
echo "ok $checks - support $up mm^3 up, $down mm^3 down"

# The Casting panel: the block without units says so and is simulated once they are chosen; "Place a feeder" waits for
# a click; the feeder placed on the top is a part (undone, done again) and is simulated with the block.
grep -q "^rect_Model units@prompt = " "$out/casting_units.txt" || fail "the Casting panel offers no units for a unitless part"
grep -q "^rect_Model units@prompt = " "$out/units_prompt.txt" || fail "the Model panel does not ask a unitless file's units"
expect units_prompt.txt units model
expect casting.txt units mm
expect units_remembered.txt units mm
grep -q "^rect_Model units@prompt = " "$out/units_remembered.txt" && fail "the Model panel asks for units it knows"
expect casting.txt casting_run_feeders 0
expect casting.txt casting_sound 0
expect casting_placing.txt casting_placing_feeder 1
expect casting_feeder.txt casting_feeders 1
expect casting_feeder.txt casting_run_feeders 1
expect casting_feeder.txt parts 2
expect casting_undo.txt casting_feeders 0
[[ -n "$(get casting.txt casting_solidification_s)" ]] || fail "the casting was not simulated"

# The view buttons over the view: +X turned it, the cube's +Z face looked from +Z, Ortho made it orthographic.
expect view_x.txt view_yaw 90
expect view_x.txt view_pitch 0
expect view_cube.txt view_yaw 0
expect view_cube.txt view_pitch 0
expect view_cube.txt view_projection perspective
expect view_ortho.txt view_projection orthographic
expect thickness_zoom.txt section_zoom 2
expect thickness_zoom.txt panel thickness
# Clicks in the thickness picture: column 1 snapped to the cube's edge voxel, column 20 as it is; both in row 20
# from the top of 40 (up index 19), at the section z = 20.
expect measure.txt section_length 40
expect measure.txt measure_picks "0,19,20 20,19,20"

# The "(?)" beside the casting's modulus opened Help > Terms at "Modulus", every term listed.
expect terms.txt help_term modulus
for term in modulus isolated niyama suspect-voxels core; do
  grep -q "^rect_term $term = " "$out/terms.txt" || fail "Help > Terms does not list $term"
done
checks=$((checks + 1))

# Every panel pressed, with the assembly and with one model: 18 rounds, each with more than the 3D view's buttons.
rounds=$(grep -c "^press-all: pressed" "$out/voxmod.log")
((rounds == 18)) || fail "expected 18 press-all rounds, found $rounds"
while read -r n; do
  ((n > 8)) || fail "a press-all round pressed only $n widgets"
done < <(sed -n 's/^press-all: pressed \([0-9]*\) widgets.*/\1/p' "$out/voxmod.log")
total=$(awk '/^press-all: pressed/ { n += $3 } END { print n }' "$out/voxmod.log")
checks=$((checks + 1))
echo "ok $checks - $total widgets pressed over $rounds rounds, the window still up"
expect end.txt has_model 1

# No text cut off in any state the scripts looked at (every panel, the assembly and one model): a glyph drawn past
# its window's, child's or table cell's edge (app/clipped_text.h). Units go in a column's header, not each cell.
states=0
for f in "$out"/*.txt; do
  name=$(basename "$f")
  n=$(get "$name" clipped_text)
  [[ -n "$n" ]] || continue
  states=$((states + 1))
  ((n == 0)) || fail "$name: $n lines of text cut off: $(grep '^clipped_in' "$f" | head -n 3 | tr '\n' ';')"
done
((states > 20)) || fail "only $states states say what text was cut off"
checks=$((checks + 1))
echo "ok $checks - no text cut off in $states states"
echo "press test: $checks checks passed"
