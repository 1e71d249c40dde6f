#!/usr/bin/env bash
# GUI test of files and errors in the real window under Xvfb (no mouse needed): broken, missing and foreign files
# each raise an error dialog naming the file, and the window carries on; save, undo / redo, re-open and the
# section / X-ray / view exports work. Usage and exit codes as gui_test.sh.
set -euo pipefail

voxmod=$1
src=$2
out=$3

missing=()
for tool in xvfb-run xauth identify; do command -v "$tool" >/dev/null 2>&1 || missing+=("$tool"); done
if ((${#missing[@]} > 0)); then
  msg="gui test needs ${missing[*]} (scripts/setup.sh installs them)"
  [[ "${CI:-}" == "true" ]] && { echo "FAIL: $msg" >&2; exit 1; }
  echo "SKIP: $msg" >&2
  exit 77
fi

rm -rf "$out"
mkdir -p "$out"
export XDG_CONFIG_HOME="$out/config"
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
get() { sed -n "s/^$2 = //p" "$1"; }

# Bad inputs, each broken in its own way.
head -c 1000 "$src/models/featuretype.stl" >"$out/truncated.stl"  # binary STL cut short
printf 'hello, this is not a mesh\n' >"$out/text.stl"
printf 'VXM?garbage' >"$out/garbage.vxm"
sed -e "s|@OUT@|$out|g" -e "s|@SRC@|$src|g" "$src/tests/gui/files.script" >"$out/files.script"

status=0
xvfb-run -a -s "-screen 0 1280x800x24" "$voxmod" --size 1280x800 --script "$out/files.script" \
  >"$out/voxmod.log" 2>&1 || status=$?
cat "$out/voxmod.log"
((status == 0)) || fail "voxmod exited with status $status"

grep -q "expected error: .*truncated.stl.*truncated" "$out/voxmod.log" || fail "the truncated STL's error does not name it"
grep -q "expected error: .*missing.stl" "$out/voxmod.log" || fail "the missing file's error does not name it"
echo "ok - errors name the file and the problem"
[[ "$(get "$out/01_state.txt" errors)" == 4 ]] || fail "expected 4 error dialogs queued, found $(get "$out/01_state.txt" errors)"
[[ "$(get "$out/01_state.txt" has_model)" == 0 ]] || fail "a broken file produced a model"
echo "ok - four bad files gave four error dialogs and no model"

s2="$out/02_state.txt" s3="$out/03_state.txt" s4="$out/04_state.txt" s5="$out/05_state.txt"
[[ "$(get "$s2" unsaved)" == 0 && "$(get "$s2" peeled)" == 1 ]] || fail "after save: unsaved=$(get "$s2" unsaved)"
[[ "$(get "$s3" unsaved)" == 1 && "$(get "$s3" peeled)" == 0 ]] || fail "undo did not restore the unpeeled model"
[[ "$(get "$s4" unsaved)" == 0 && "$(get "$s4" peeled)" == 1 ]] || fail "redo did not return to the saved model"
echo "ok - save marks the model saved; undo / redo move away from and back to it"
[[ -n "$(get "$s2" filled)" && "$(get "$s5" filled)" == "$(get "$s2" filled)" && "$(get "$s5" dims)" == "$(get "$s2" dims)" ]] ||
  fail "re-opened part.vxm differs: $(get "$s5" dims) / $(get "$s5" filled) vs $(get "$s2" dims) / $(get "$s2" filled)"
[[ "$(get "$s5" unsaved)" == 0 ]] || fail "a freshly opened file counts as unsaved"
echo "ok - part.vxm re-opens with the same $(get "$s5" filled) voxels"
for f in section.png xray.png view.png xray.csv xray.nrrd surface.stl surface.3mf smooth.ply part.vdb thickness.vti \
  depth.vti 01_error_dialog.png 02_reopened.png; do
  [[ -s "$out/$f" ]] || fail "$f was not written"
done
head -n 1 "$out/xray.csv" | grep -q "^u,v,thickness_voxels" || fail "xray.csv has no header"
# the surface is a binary STL of whole triangles: 84 bytes of header and count, 50 per triangle
stl_size=$(stat -c %s "$out/surface.stl")
(( stl_size > 84 && (stl_size - 84) % 50 == 0 )) || fail "surface.stl is not a binary STL ($stl_size bytes)"
grep -q 'Name="depth"' "$out/depth.vti" || fail "depth.vti holds no depth field"
[[ ! -e "$out/depth.vox" ]] || fail "the skin depth was written as .vox, which holds voxels only"
echo "ok - section, X-ray, view, surface and volume (model, thickness, depth, X-ray) exports written"

# Settings: a session without a script reads the window size it had last time, remembers the file it opened,
# and keeps ImGui's ini beside its own.
mkdir -p "$XDG_CONFIG_HOME/voxmod"
printf 'window_width = 1000\nwindow_height = 700\nlit = 0\n' >"$XDG_CONFIG_HOME/voxmod/voxmod.ini"
status=0
xvfb-run -a -s "-screen 0 1280x800x24" "$voxmod" "$out/part.vxm" --screenshot "$out/03_session.png" \
  >"$out/session.log" 2>&1 || status=$?
((status == 0)) || fail "the plain session exited with status $status: $(cat "$out/session.log")"
size=$(identify -format "%wx%h" "$out/03_session.png")
[[ "$size" == 1000x700 ]] || fail "the window did not open at the remembered 1000x700 (screenshot is $size)"
ini="$XDG_CONFIG_HOME/voxmod/voxmod.ini"
grep -q "^recent = .*part.vxm$" "$ini" || fail "part.vxm is not in the recent files: $(cat "$ini")"
grep -q "^lit = 0$" "$ini" || fail "the shading choice was not kept: $(cat "$ini")"
grep -q "^window_width = 1000$" "$ini" || fail "the window size was not kept: $(cat "$ini")"
[[ -f "$XDG_CONFIG_HOME/voxmod/imgui.ini" ]] || fail "no imgui.ini beside voxmod.ini"
echo "ok - settings: window size, recent files and choices remembered in $ini"
echo "files test passed; output in $out"
