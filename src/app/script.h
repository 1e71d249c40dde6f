#pragma once
// `voxmod --script FILE`: line commands that drive the window deterministically, for tests and for the screenshots
// in docs/. One command per line, '#' starts a comment; the next command runs only when the previous one has
// finished (its background work done, or its frames drawn).
//
// A command is the name of an action (actions.h: the table behind the menus, shortcuts and buttons), with the values
// it takes, dispatched exactly as a menu item is. For example:
// clang-format off
//   open PATH | save PATH | save-as PATH | export-view PATH | export-section PATH | export-xray PATH | export-csv PATH
//   export-volume PATH (.vti .vdb .nrrd .vox) | export-thickness PATH (.vti .vdb .nrrd)
//   export-depth PATH | export-xray-volume PATH (.vti .vdb .nrrd)
//   voxelize R [MODE]                voxelize the open mesh (MODE auto|parity|nonzero|vote); no values: the dialog
//   section AXIS INDEX               the section at voxel INDEX along x|y|z (and the Section panel)
//   section-plane NX NY NZ [OFFSET]  the section at any angle: normal (NX, NY, NZ), OFFSET model units along it from
//                                    the centre of the model's box
//   peel N | peel-one | peel-back | peel-core | peel-reset
//   skin-layers | cancel-skin-layers | compute-thickness | cancel-thickness   compute again after a cancel; cancel
//   xray AXIS MODE                   X-ray along x|y|z, MODE min|max|total (and the X-ray panel)
//   panel-model | panel-section | panel-skin | panel-xray | panel-mass | panel-thickness | panel-parts
//   thickness-method sphere|ray      what the Thickness panel's views show (ray: the model's mesh only)
//   min-wall W | thin-region N | hot-spot N   the Thickness panel's minimum wall (model units); row N of its lists of
//                                    thin-wall regions and hot spots, selected and shown (section and 3D view there)
//   view YAW PITCH | view-iso | view-pos-x | view-neg-x | ... | zoom FACTOR | zoom-in | zoom-out | fit
//   measure I J K | measure-clear    pick voxel (I, J, K) for measuring, as a click does (two: their distance)
//   lit on|off, round on|off, disputed on|off, cut on|off, lod on|off   (no value: toggle)
//   undo | redo | quit | cancel | export-size W H | about | controls | terms [TERM] | close-dialogs
//   ortho [on|off] | section-zoom [Z [U V]]
// The harness's own commands look, wait and write what the window shows; they change nothing a user edits:
//   sweep AXIS [STEP]                the section action once per frame through every STEP-th index along AXIS, then
//                                    print the frame rate (the section-slider benchmark)
//   screenshot PATH                  the whole window as PNG, after the next frame is drawn
//   state PATH                       once background work has finished, write the window's state as "key = value"
//                                    lines (widget rectangles in window pixels, section index, peel level, ...)
//   wait N | wait frames N           draw N frames
//   wait-file PATH [SECONDS]         keep drawing until PATH exists (a test driver's signal), default 60 s
//   hover WIDGET [FX FY]             move the pointer to a widget recorded by `state` (e.g. xray_image), at
//                                    fractions FX, FY of its width and height (default the centre)
//   press WIDGET                     press a widget drawn last frame (a button, checkbox, list row, combo, ...) with
//                                    the mouse as ImGui sees it: over it, down, up; then wait for the work it started.
//                                    WIDGET is its label, with ImGui's hidden "##id" written "@id" ("Cancel@parts")
//   click WIDGET FX FY               press at fractions FX, FY of a widget's width and height (a picture's point)
//   type TEXT WIDGET                 click the field WIDGET, select all, type TEXT (one word) and press Enter
//   press-all                        press every widget on screen, one after another (fields are given "2"), each
//                                    found again before it is pressed; dialogs and error messages it raises are
//                                    closed on the way, and the count of presses and errors is printed
//   expect-error TEXT                the next command must fail with an error containing TEXT (its error dialog
//                                    stays up); any other outcome fails the script
//   echo TEXT                        print TEXT to stdout
//   exit                             close the window without asking (unsaved changes are dropped)
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
// True for the harness's own commands (echo, sweep, screenshot, state, wait, wait-file, hover, press, type,
// press-all, expect-error, exit).
bool isHarnessCommand(const std::string& name);

}  // namespace vox::app
