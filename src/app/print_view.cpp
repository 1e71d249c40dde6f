#include "app/print_view.h"

#include <algorithm>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "app/casting_view.h"  // shownCasting
#include "app/print.h"
#include "app/thickness_view.h"  // shownThickness
#include "app/ui.h"
#include "app/view_overlays.h"

namespace vox::app {
namespace {

constexpr glm::vec3 kSupportColour{0.35f, 0.65f, 1.0f};
constexpr float kSupportOpacity = 0.35f;
constexpr ImU32 kOverhangText = IM_COL32(255, 110, 100, 255);
constexpr ImU32 kSupportText = IM_COL32(120, 180, 255, 255);
constexpr ImU32 kCavityColour = IM_COL32(255, 220, 60, 255);

// The overhangs (made on the worker, print.cpp) as the renderer's scalar volume: under the threshold, red.
void uploadOverhangs(AppState& state, const PrintResult& r) {
  if (!r.overhang_problem.empty()) {
    state.print_ui.volume_problem = r.overhang_problem;
    state.viewport.renderer->clearScalarVolume();
    return;
  }
  if (r.overhang_values.empty()) {
    state.viewport.renderer->clearScalarVolume();
    return;
  }
  if (Status s = state.viewport.renderer->setScalarVolume(r.overhang_min, r.overhang_dims, r.overhang_values); !s) {
    state.print_ui.volume_problem = "The overhangs are not shown in red: " + s.error().message + ".";
  }
}

}  // namespace

const PrintResult* shownPrint(const AppState& state) {
  return state.panel == Panel::kPrint && !state.model.empty() ? currentPrint(state) : nullptr;
}

void syncPrintView(AppState& state) {
  Viewport& vp = state.viewport;
  if (!vp.renderer || !vp.support) return;
  PrintUi& ui = state.print_ui;
  const PrintResult* r = shownPrint(state);
  const uint64_t key = r ? r->id : 0;
  if (key != ui.volume_key) {
    ui.volume_key = key;
    ui.volume_problem.clear();
    vp.dirty = true;
    if (r) {
      uploadOverhangs(state, *r);
    } else if (!shownThickness(state) && !shownCasting(state)) {
      vp.renderer->clearScalarVolume();  // the other panels' colours are not this panel's to clear
    }
  }
  if (key != ui.support_key) {
    ui.support_key = key;
    vp.dirty = true;
    if (r && r->check.support.support) vp.support->setGrid(*r->check.support.support);
  }
}

void printDrawParams(const AppState& state, render::DrawParams& p) {
  if (!shownPrint(state) || !state.viewport.renderer || !state.viewport.renderer->hasScalarVolume()) return;
  p.scalar_colour = true;
  p.scalar_threshold = 0.5f;  // every value of the overhangs' volume is under it: red
}

void drawPrintSupport(AppState& state, int w, int h, const render::DrawParams& params) {
  const PrintResult* r = shownPrint(state);
  if (!r || !r->check.support.support || state.print_ui.support_key != r->id || !state.viewport.support) return;
  render::DrawParams p = params;
  p.scalar_colour = false;
  p.lut = render::Lut::kLit;
  p.colour = kSupportColour;
  p.opacity = kSupportOpacity;
  state.viewport.support->draw(state.view.camera, w, h, p);
}

float drawPrintOverlay(AppState& state, ImDrawList* dl, ImVec2 pos, int w, int h, double aspect) {
  if (state.panel != Panel::kPrint || state.model.empty() || !state.model_bounds) return pos.y;
  const float lh = ImGui::GetTextLineHeightWithSpacing();
  float y = pos.y + 30.0f;
  const PrintResult* r = shownPrint(state);
  if (!r) {
    shadowText(dl, ImVec2(pos.x + 12.0f, y), IM_COL32(230, 230, 230, 255),
               printCancelled(state) ? "Printability cancelled (Compute in the panel)" : "Checking printability...");
    return y + lh;
  }
  const std::string units = state.model.frame().units;
  const PrintSupport& s = r->check.support;
  char angle[32];
  std::snprintf(angle, sizeof angle, "%.3g", r->key.overhang_angle);
  const std::string build = "Build direction " + printDirectionName(s.direction) + " (arrow)";
  shadowText(dl, ImVec2(pos.x + 12.0f, y), IM_COL32(230, 230, 230, 255), build.c_str());
  y += lh;
  const std::string over = "red: overhang past " + std::string(angle) + " deg, " + formatArea(s.overhang_area, units);
  shadowText(dl, ImVec2(pos.x + 12.0f, y), kOverhangText, over.c_str());
  y += lh;
  const std::string sup = "blue: support, " + formatVolume(s.support_volume, units);
  shadowText(dl, ImVec2(pos.x + 12.0f, y), kSupportText, sup.c_str());
  y += lh;
  if (!state.print_ui.volume_problem.empty()) {
    shadowText(dl, ImVec2(pos.x + 12.0f, y), IM_COL32(255, 200, 80, 255), state.print_ui.volume_problem.c_str());
    y += lh;
  }
  const glm::dmat4 vp = state.view.camera.viewProjection(aspect, *state.model_bounds);
  // the build direction: an arrow up from the part's centre, a third of its size long
  const glm::dvec3 lo = state.model_bounds->min, hi = state.model_bounds->max;
  const glm::dvec3 centre = 0.5 * (lo + hi);
  const double reach = 0.6 * glm::length(hi - lo);
  ImVec2 a, b;
  if (projectToView(vp, centre, pos, w, h, a) && projectToView(vp, centre + s.direction * reach, pos, w, h, b)) {
    dl->AddLine(a, b, IM_COL32(0, 0, 0, 255), 5.0f);
    dl->AddLine(a, b, IM_COL32(255, 255, 255, 255), 2.5f);
    dl->AddCircleFilled(b, 5.0f, IM_COL32(255, 255, 255, 255));
    shadowText(dl, ImVec2(b.x + 8.0f, b.y - 8.0f), IM_COL32(255, 255, 255, 255), "up");
  }
  // the trapped cavities: numbered rings as in the panel's list, the one clicked larger
  const TrappedCavity* chosen = selectedCavity(state);
  const double h_vox = state.model.voxelSize();
  for (size_t i = 0; i < r->check.cavities.size() && i < 20; ++i) {
    const TrappedCavity& c = r->check.cavities[i];
    ImVec2 p;
    if (!projectToView(vp, (c.centre - state.model.frame().origin) / h_vox, pos, w, h, p)) continue;
    const float radius = &c == chosen ? 14.0f : 8.0f;
    dl->AddCircle(p, radius, IM_COL32(0, 0, 0, 255), 0, 4.0f);
    dl->AddCircle(p, radius, kCavityColour, 0, 2.0f);
    shadowText(dl, ImVec2(p.x + radius + 2.0f, p.y - 18.0f), kCavityColour,
               ("cavity " + std::to_string(i + 1)).c_str());
  }
  return y;
}

}  // namespace vox::app
