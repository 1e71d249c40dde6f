#!/usr/bin/env bash
# The driver's half of tests/gui/gui_test.sh; runs inside xvfb-run (DISPLAY is set). Environment: VOXMOD_EXE,
# VOXMOD_SRC, VOXMOD_GUI_OUT.
set -euo pipefail

out=$VOXMOD_GUI_OUT
sed "s|@OUT@|$out|g" "$VOXMOD_SRC/tests/gui/drive.script" >"$out/drive.script"
"$VOXMOD_EXE" "$VOXMOD_SRC/models/featuretype.stl" --size 1280x800 --script "$out/drive.script" \
  >"$out/voxmod.log" 2>&1 &
pid=$!
checks=0

fail() {
  echo "FAIL: $*" >&2
  echo "--- voxmod log ($out/voxmod.log):" >&2
  cat "$out/voxmod.log" >&2 || true
  kill "$pid" 2>/dev/null || true
  exit 1
}
pass() {
  checks=$((checks + 1))
  echo "ok $checks - $*"
}

# Waits for a file voxmod writes, failing if voxmod exits first or 120 s pass.
wait_for() {
  local i
  for ((i = 0; i < 1200; ++i)); do
    [[ -s "$1" ]] && return 0
    kill -0 "$pid" 2>/dev/null || fail "voxmod exited before writing $(basename "$1")"
    sleep 0.1
  done
  fail "timed out waiting for $(basename "$1")"
}
get() { sed -n "s/^$2 = //p" "$1"; }
# A widget rectangle from a state file as "x0 y0 x1 y1" (integers, window pixels).
rect() {
  local r
  r=$(get "$1" "rect_$2")
  [[ -n "$r" ]] || fail "no rectangle '$2' in $(basename "$1")"
  awk '{printf "%d %d %d %d\n", $1, $2, $3, $4}' <<<"$r"
}
viewport_rect() { awk '{printf "%d %d %d %d\n", $1, $2, $1 + $3, $2 + $4}' <<<"$(get "$1" viewport)"; }
# The 3D view without its bottom line, which reads out the draw time (different in every frame).
viewport_picture_rect() { awk '{printf "%d %d %d %d\n", $1, $2, $1 + $3, $2 + $4 - 28}' <<<"$(get "$1" viewport)"; }

# Number of pixels that differ between two screenshots inside a rectangle "x0 y0 x1 y1" (ImageMagick AE metric:
# an exact count, no fuzz; llvmpipe renders the same input to the same pixels).
diff_pixels() {
  local a=$1 b=$2 x0 y0 x1 y1
  read -r x0 y0 x1 y1 <<<"$3"
  local geom="$((x1 - x0))x$((y1 - y0))+$x0+$y0"
  convert "$a" -crop "$geom" +repage "$out/crop_a.png"
  convert "$b" -crop "$geom" +repage "$out/crop_b.png"
  compare -metric AE "$out/crop_a.png" "$out/crop_b.png" null: 2>&1 || true
}
expect_differ() {  # a b rect min_pixels what
  local n
  n=$(diff_pixels "$1" "$2" "$3")
  ((n >= $4)) || fail "$5: expected at least $4 changed pixels, found $n ($(basename "$1") vs $(basename "$2"))"
  pass "$5 ($n pixels changed)"
}
expect_same() {  # a b rect what
  local n
  n=$(diff_pixels "$1" "$2" "$3")
  ((n == 0)) || fail "$4: expected identical pixels, found $n different ($(basename "$1") vs $(basename "$2"))"
  pass "$4 (identical)"
}

win=$(xdotool search --sync --name '^voxmod' | head -n 1)
[[ -n "$win" ]] || fail "no voxmod window"
pass "voxmod window $win is open"

move() { xdotool mousemove --window "$win" "$1" "$2"; sleep 0.15; }
click() {
  move "$1" "$2"
  xdotool mousedown 1
  sleep 0.15
  xdotool mouseup 1
  sleep 0.15
}
centre() { awk '{printf "%d %d\n", ($1 + $3) / 2, ($2 + $4) / 2}' <<<"$1"; }

# ---- 1. Drag the section slider from its grab to three quarters along, in steps, as a hand would.
wait_for "$out/01_state.txt"
s1="$out/01_state.txt"
n=$(get "$s1" section_length)
i1=$(get "$s1" section_index)
[[ "$(get "$s1" section_axis)" == z && "$i1" == 5 ]] || fail "script did not set section z 5"
read -r x0 y0 x1 y1 <<<"$(rect "$s1" section_slider)"
y=$(((y0 + y1) / 2))
# The grab of index 5 sits near the left end of the slider.
start_x=$((x0 + 6 + (x1 - x0 - 12) * i1 / (n - 1)))
end_x=$((x0 + (x1 - x0) * 3 / 4))
move "$start_x" "$y"
xdotool mousedown 1
for ((k = 1; k <= 10; ++k)); do
  move $((start_x + (end_x - start_x) * k / 10)) "$y"
done
xdotool mouseup 1
sleep 0.2
touch "$out/go_section"
wait_for "$out/02_state.txt"
s2="$out/02_state.txt"
i2=$(get "$s2" section_index)
expected=$(((n - 1) * 3 / 4))
tolerance=$(((n + 9) / 10))
((i2 != i1)) || fail "the slider drag did not move the section (index still $i1)"
((i2 >= expected - tolerance && i2 <= expected + tolerance)) ||
  fail "section index $i2 after dragging to 3/4 of the slider; expected about $expected of 0..$((n - 1))"
pass "slider drag moved the section from index $i1 to $i2 (expected about $expected)"
[[ "$(get "$s2" section_filled)" != "$(get "$s1" section_filled)" ]] ||
  fail "the section's filled count did not change ($(get "$s2" section_filled))"
pass "section filled voxels changed: $(get "$s1" section_filled) -> $(get "$s2" section_filled)"
expect_differ "$out/01_section_before.png" "$out/02_section_after.png" "$(rect "$s1" section_image)" 500 \
  "section image changed"
expect_differ "$out/01_section_before.png" "$out/02_section_after.png" "$(viewport_rect "$s1")" 500 \
  "3D cut-away changed"
expect_same "$out/01_section_before.png" "$out/02_section_after.png" "0 0 1280 20" "menu bar unchanged"

# ---- 2. Click "Peel one" twice.
wait_for "$out/03_state.txt"
s3="$out/03_state.txt"
[[ "$(get "$s3" peeled)" == 0 ]] || fail "model already peeled before the clicks"
read -r cx cy <<<"$(centre "$(rect "$s3" peel_one)")"
click "$cx" "$cy"
touch "$out/go_peel1"
wait_for "$out/04_state.txt"
[[ "$(get "$out/04_state.txt" peeled)" == 1 ]] || fail "one click on Peel one: peeled = $(get "$out/04_state.txt" peeled)"
click "$cx" "$cy"
touch "$out/go_peel2"
wait_for "$out/05_state.txt"
s5="$out/05_state.txt"
[[ "$(get "$s5" peeled)" == 2 ]] || fail "two clicks on Peel one: peeled = $(get "$s5" peeled)"
pass "two clicks on Peel one peeled 2 of $(get "$s5" layers) layers"
(($(get "$s5" filled) < $(get "$s3" filled))) || fail "peeling did not remove voxels"
pass "filled voxels $(get "$s3" filled) -> $(get "$s5" filled)"
expect_differ "$out/03_skin_before.png" "$out/05_skin_peel2.png" "$(viewport_rect "$s3")" 1000 "3D view after peeling"

# ---- 3. Click the X-ray mode buttons: Minimum, Maximum, then Total again.
wait_for "$out/06_state.txt"
s6="$out/06_state.txt"
[[ "$(get "$s6" xray_mode)" == total ]] || fail "X-ray did not start in total mode"
read -r mx my <<<"$(centre "$(rect "$s6" xray_min)")"
click "$mx" "$my"
touch "$out/go_xray_min"
wait_for "$out/07_state.txt"
s7="$out/07_state.txt"
[[ "$(get "$s7" xray_mode)" == min ]] || fail "clicking Minimum gave X-ray mode $(get "$s7" xray_mode)"
read -r mx my <<<"$(centre "$(rect "$s7" xray_max)")"
click "$mx" "$my"
touch "$out/go_xray_max"
wait_for "$out/08_state.txt"
s8="$out/08_state.txt"
[[ "$(get "$s8" xray_mode)" == max ]] || fail "clicking Maximum gave X-ray mode $(get "$s8" xray_mode)"
read -r mx my <<<"$(centre "$(rect "$s8" xray_total)")"
click "$mx" "$my"
touch "$out/go_xray_total"
wait_for "$out/09_state.txt"
s9="$out/09_state.txt"
[[ "$(get "$s9" xray_mode)" == total ]] || fail "clicking Total gave X-ray mode $(get "$s9" xray_mode)"
pass "X-ray mode buttons: total -> min -> max -> total"
image=$(rect "$s6" xray_image)
expect_differ "$out/06_xray_total.png" "$out/07_xray_min.png" "$image" 1000 "X-ray image total -> min"
expect_differ "$out/07_xray_min.png" "$out/08_xray_max.png" "$image" 1000 "X-ray image min -> max"
expect_differ "$out/08_xray_max.png" "$out/09_xray_total_again.png" "$image" 1000 "X-ray image max -> total"
expect_same "$out/06_xray_total.png" "$out/09_xray_total_again.png" "$image" "X-ray image total is reproducible"
expect_same "$out/06_xray_total.png" "$out/08_xray_max.png" "$(viewport_picture_rect "$s6")" \
  "3D view untouched by X-ray modes"

# ---- 3b. The Thickness panel: a click on the first hot spot moves the section through its voxel.
wait_for "$out/09t_state.txt"
st="$out/09t_state.txt"
hs=$(get "$st" hot_spot_1)
[[ -n "$hs" ]] || fail "no hot spot listed in the Thickness panel"
read -r hx hy hz <<<"$hs"
axis=$(get "$st" section_axis)
read -r lx0 ly0 lx1 ly1 <<<"$(rect "$st" hot_spot_list)"
click $((lx0 + 30)) $((ly0 + 30)) # the first row, under the header
touch "$out/go_hot_spot"
wait_for "$out/09u_state.txt"
su="$out/09u_state.txt"
case $axis in x) want=$hx ;; y) want=$hy ;; *) want=$hz ;; esac
[[ "$(get "$su" section_index)" == "$want" ]] ||
  fail "clicking hot spot 1 at ($hs) left the section at $axis = $(get "$su" section_index), expected $want"
[[ "$(get "$su" panel)" == thickness ]] || fail "clicking a hot spot left the Thickness panel for $(get "$su" panel)"
pass "clicking hot spot 1 moved the section to $axis = $want (was $(get "$st" section_index))"
if [[ "$want" != "$(get "$st" section_index)" ]]; then
  expect_differ "$out/09t_thickness.png" "$out/09u_hot_spot.png" "$(rect "$st" thickness_image)" 200 \
    "thickness section image after the click"
fi

# ---- 4. Drag in the 3D view: the camera orbits.
wait_for "$out/10_state.txt"
s10="$out/10_state.txt"
read -r vx0 vy0 vx1 vy1 <<<"$(viewport_rect "$s10")"
cx=$(((vx0 + vx1) / 2))
cy=$(((vy0 + vy1) / 2))
move "$cx" "$cy"
xdotool mousedown 1
for ((k = 1; k <= 8; ++k)); do move $((cx + 15 * k)) $((cy + 5 * k)); done
xdotool mouseup 1
move $((vx0 + 5)) $((vy0 + 5))
touch "$out/go_orbit"
wait_for "$out/11_state.txt"
s11="$out/11_state.txt"
[[ "$(get "$s11" view_yaw)" != "$(get "$s10" view_yaw)" ]] || fail "dragging in the 3D view did not orbit"
pass "orbit by mouse: yaw $(get "$s10" view_yaw) -> $(get "$s11" view_yaw), pitch $(get "$s10" view_pitch) -> $(get "$s11" view_pitch)"
expect_differ "$out/10_model.png" "$out/11_orbited.png" "$(viewport_rect "$s10")" 1000 "3D view after orbiting"

# ---- 5. Keyboard: Ctrl+Z undoes the last peel (the shortcut comes from the action table).
move $((vx0 + 20)) $((vy0 + 60))
xdotool key ctrl+z
touch "$out/go_undo"
wait_for "$out/12_state.txt"
[[ "$(get "$out/12_state.txt" peeled)" == 1 ]] || fail "Ctrl+Z left peeled = $(get "$out/12_state.txt" peeled), expected 1"
pass "Ctrl+Z undid the second peel"

# ---- 6. Ctrl+Q with unsaved changes: the prompt appears; Cancel keeps the window; Ctrl+Q again and Discard quits.
xdotool key ctrl+q
touch "$out/go_quit"
wait_for "$out/13_state.txt"
s13="$out/13_state.txt"
[[ "$(get "$s13" unsaved_prompt)" == 1 && "$(get "$s13" unsaved)" == 1 ]] || fail "Ctrl+Q did not ask about unsaved changes"
pass "Ctrl+Q with unsaved changes opened the prompt"
read -r cx cy <<<"$(centre "$(rect "$s13" prompt_cancel)")"
click "$cx" "$cy"
touch "$out/go_cancel"
wait_for "$out/14_state.txt"
[[ "$(get "$out/14_state.txt" unsaved_prompt)" == 0 ]] || fail "Cancel did not close the prompt"
kill -0 "$pid" 2>/dev/null || fail "the window closed although Cancel was clicked"
pass "Cancel kept the window open"
sleep 0.5  # the script has ended; the window now waits for events like any session
read -r dx dy <<<"$(centre "$(rect "$s13" prompt_discard)")"
# Without a state file to say when the prompt is up, try a few times (a slow frame can delay it).
for ((attempt = 0; attempt < 5; ++attempt)); do
  move $((vx0 + 20)) $((vy0 + 60))
  xdotool key ctrl+q
  sleep 1
  click "$dx" "$dy"
  for ((k = 0; k < 20; ++k)); do
    kill -0 "$pid" 2>/dev/null || break 2
    sleep 0.1
  done
done
kill -0 "$pid" 2>/dev/null && fail "Ctrl+Q and Discard did not close the window"
wait "$pid" || fail "voxmod exited with status $?"
pass "Ctrl+Q, Discard: voxmod exited cleanly"
echo "gui test passed: $checks checks; screenshots in $out"
