#!/usr/bin/env bash
# GUI test: the real modeler window (GLFW + ImGui, Mesa llvmpipe) under Xvfb, driven by real X input events.
#
#   gui_test.sh VOXMOD SOURCE_DIR OUT_DIR
#
# voxmod runs tests/gui/drive.script (a --script, see src/app/script.h) that voxelizes models/featuretype.stl and
# then waits at marked points for this driver. The driver reads the window's `state` files (widget rectangles in
# window pixels), moves the mouse with xdotool (XTEST: the same events a person's mouse makes), and signals voxmod
# to continue by creating a file. It checks that:
#   - dragging the section slider with the mouse moves the section to the index under the mouse, and the section
#     image and the 3D cut-away change while the side panel's static parts do not;
#   - clicking "Peel one" twice peels two skin layers, and the 3D view changes;
#   - clicking the X-ray Minimum / Maximum / Total buttons changes the X-ray image each time, while the 3D view
#     stays identical (the model did not change);
#   - dragging in the 3D view orbits the camera.
# Screenshots and state files are kept in OUT_DIR for inspection.
#
# Exit codes: 0 pass, 1 fail, 77 skipped (CTest SKIP_RETURN_CODE) when xvfb-run, xdotool or ImageMagick is missing
# outside CI. In CI (CI=true) a missing tool is a failure: scripts/setup.sh installs them.
set -euo pipefail

voxmod=$1
src=$2
out=$3
here="$src/tests/gui"

missing=()
for tool in xvfb-run xauth xdotool compare convert; do
  command -v "$tool" >/dev/null 2>&1 || missing+=("$tool")
done
if ((${#missing[@]} > 0)); then
  msg="gui test needs ${missing[*]} (apt-get install xvfb xauth xdotool imagemagick; scripts/setup.sh does this)"
  if [[ "${CI:-}" == "true" ]]; then
    echo "FAIL: $msg" >&2
    exit 1
  fi
  echo "SKIP: $msg" >&2
  exit 77
fi

rm -rf "$out"
mkdir -p "$out"
export XDG_CONFIG_HOME="$out/config"  # settings of this run, not the user's
export VOXMOD_GUI_OUT="$out" VOXMOD_EXE="$voxmod" VOXMOD_SRC="$src"
# -a: pick a free display (other jobs may hold :99); 24-bit screen so the PNGs carry the window's colours.
exec xvfb-run -a -s "-screen 0 1280x800x24" bash "$here/drive.sh"
