// The Print entries of the action table (actions.cpp): the panel, the build direction (a list, a vector or a face
// laid on the plate), the overhang angle, the search over build directions and its list, the trapped cavities' list.
// Row numbers in scripts count from 1, as the panel shows them.
#include <algorithm>
#include <cmath>
#include <string>

#include "app/action_functions.h"
#include "app/print.h"
#include "app/update.h"  // centreView, axisLength
#include "vox/core/text.h"

namespace vox::app::actions {
void panelPrint(AppState& s) { showPanel(s, Panel::kPrint); }
bool onPrint(const AppState& s) { return s.panel == Panel::kPrint; }
bool printComputingNow(const AppState& s) { return printComputing(s); }
bool printCancelledNow(const AppState& s) { return printCancelled(s); }
bool hasPrint(const AppState& s) { return currentPrint(s) != nullptr; }

Status printDirectionAt(AppState& s, const ActionArgs& a) {
  std::string text;
  for (const std::string& w : a.words) text += (text.empty() ? "" : ",") + w;
  if (Status st = setPrintDirection(s, text); !st) return st;
  showPanel(s, Panel::kPrint);
  return Ok{};
}

Status overhangAngleAt(AppState& s, const ActionArgs& a) {
  double v = 0.0;
  if (!parseNumber(a.words[0], v) || !(v >= 0.0 && v < 90.0)) {
    return badValues("overhang-angle takes degrees from the vertical, 0 to under 90");
  }
  s.print_ui.overhang_angle = v;
  showPanel(s, Panel::kPrint);
  return Ok{};
}

void printOrient(AppState& s) {
  s.print_ui.orient = true;
  showPanel(s, Panel::kPrint);
}

Status printOrientationAt(AppState& s, const ActionArgs& a) {
  const PrintResult* r = currentPrint(s);
  const auto i = listRow(a, r ? r->check.orientations.size() : 0, "print-orientation", "Print",
                         "no build directions were searched (Find the best way up)");
  if (!i) return i.error();
  // the list found stays for the direction applied (print.cpp, knownOrientations): it is not searched again
  s.print_ui.up = r->check.orientations[*i].direction;
  showPanel(s, Panel::kPrint);
  return Ok{};
}

Status printCavityAt(AppState& s, const ActionArgs& a) {
  const PrintResult* r = currentPrint(s);
  const auto i =
      listRow(a, r ? r->check.cavities.size() : 0, "print-cavity", "Print", "the part has no trapped cavity");
  if (!i) return i.error();
  const TrappedCavity& c = r->check.cavities[*i];
  // the section through the cavity's middle along the section's axis, the 3D view about it
  const int axis = int(s.section.axis);
  s.section.index =
      std::clamp((c.box_min[axis] + c.box_max[axis]) / 2, 0, std::max(axisLength(s, s.section.axis) - 1, 0));
  s.section.oblique = false;
  s.section.playing = false;
  const glm::ivec3 size = c.box_max - c.box_min + 1;
  centreView(s, glm::dvec3(c.box_min + c.box_max + 1) * 0.5, 3.0 * double(std::max({size.x, size.y, size.z})));
  s.print_ui.selected_cavity = int32_t(*i);
  s.print_ui.selected_result = r->id;
  showPanel(s, Panel::kPrint);
  return Ok{};
}

void printLayFaceMode(AppState& s) {
  s.print_ui.lay_face = !s.print_ui.lay_face;
  showPanel(s, Panel::kPrint);
}

Status printLayFaceAt(AppState& s, const ActionArgs& a) {
  glm::ivec3 v(0);
  for (int k = 0; k < 3; ++k) {
    if (!parseNumber(a.words[size_t(k)], v[k])) return badValues("print-lay-face takes I J K, a voxel index");
  }
  if (Status st = layFaceOnPlate(s, v); !st) return st;
  showPanel(s, Panel::kPrint);
  return Ok{};
}

void computePrint(AppState& s) { retryPrint(s); }
void cancelPrintNow(AppState& s) { cancelPrint(s); }

}  // namespace vox::app::actions
