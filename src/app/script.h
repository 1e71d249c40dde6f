#pragma once
// `voxmod --script FILE`: line commands that drive the window deterministically, for tests and for the screenshots
// in docs/. One command per line, '#' starts a comment. Each command does what the matching widget or menu item
// does (it calls the same operations), and the next command runs only when the previous one has finished: a
// voxelization, a load or a peel waits for its worker; `screenshot` waits for the frame to be drawn.
//
// clang-format off
//   open PATH                        open a mesh (.stl) or voxel file (.vxm, .binvox)
//   voxelize R [MODE]                voxelize the open mesh, R voxels on the longest axis, MODE
//                                    auto|parity|nonzero|vote
//   section AXIS INDEX | section off show the section at voxel INDEX along x|y|z (and the Section panel)
//   sweep AXIS [STEP]                move the section through every STEP-th index along AXIS, one per frame, and
//                                    print the frame rate (the section-slider benchmark)
//   peel N | peel core | peel back | peel reset
//   xray AXIS MODE                   X-ray along x|y|z, MODE min|max|total (and the X-ray panel)
//   panel NAME                       show a panel: model|section|skin|xray|mass
//   view YAW PITCH | view NAME       camera angles in degrees, or iso|+x|-x|+y|-y|+z|-z; refits the model
//   zoom FACTOR                      > 1 zooms in
//   measure I J K | measure clear    pick voxel (I, J, K) for measuring, as a click does (two: their distance)
//   lit on|off, round on|off, disputed on|off, cut on|off, lod on|off
//   undo | redo
//   save PATH                        save the model (.vxm or .binvox)
//   export-view PATH | export-section PATH | export-xray PATH | export-csv PATH   as File > Export does
//   export-size W H                  size of an exported 3D view in pixels (0 0: as the view is shown)
//   screenshot PATH                  the whole window as PNG, after the next frame is drawn
//   state PATH                       once background work has finished, write the window's state as "key = value"
//                                    lines (widget rectangles in window pixels, section index, peel level, ...)
//   wait N | wait frames N           draw N frames
//   hover WIDGET [FX FY]             move the pointer to a widget recorded by `state` (e.g. xray_image), at
//                                    fractions FX, FY of its width and height (default the centre)
//   dialog voxelize|open|save|about|controls|close   open one of the dialogs, or close whichever is open
//   wait-file PATH [SECONDS]         keep drawing until PATH exists (a test driver's signal), default 60 s
//   expect-error TEXT                the next command must fail with an error containing TEXT (its error dialog
//                                    stays up); any other outcome fails the script
//   echo TEXT                        print TEXT to stdout
//   quit                             close the window, discarding unsaved changes
// clang-format on
#include <filesystem>
#include <string>
#include <vector>

#include "vox/core/result.h"

namespace vox::app {

struct ScriptCommand {
  int line = 0;
  std::string name;               // first word
  std::vector<std::string> args;  // the remaining words
  std::string rest;               // everything after the first word (for paths with spaces and echo)
};

// Splits a script into commands and checks each command's name and argument count, so a typo fails before the
// window opens. Errors read "FILE:LINE: message".
Result<std::vector<ScriptCommand>> parseScript(const std::string& text, const std::string& name);
Result<std::vector<ScriptCommand>> loadScript(const std::filesystem::path& path);

}  // namespace vox::app
