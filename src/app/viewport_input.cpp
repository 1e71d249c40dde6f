// The 3D view's input (viewport_input.h): the mouse's drags, wheel and clicks, and the view buttons.
#include "app/viewport_input.h"

#include <cmath>
#include <iterator>
#include <optional>
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <imgui.h>
#include <imgui_internal.h>  // ImGuiButtonFlags_AllowItemOverlap

#include "app/actions.h"
#include "app/measure.h"
#include "app/ui.h"
#include "vox/analysis/analysis.h"

namespace vox::app {
namespace {

constexpr double kOrbitDegreesPerPixel = 0.4;
constexpr double kZoomPerWheelStep = 1.15;

// The surface voxel under the mouse in the view at `pos` (w x h pixels), or none.
std::optional<glm::ivec3> voxelUnderMouse(const AppState& state, ImVec2 pos, int w, int h, double aspect) {
  if (!state.model_bounds) return std::nullopt;
  const ImGuiIO& io = ImGui::GetIO();
  const glm::dmat4 inv = glm::inverse(state.view.camera.viewProjection(aspect, *state.model_bounds));
  const double nx = 2.0 * double(io.MousePos.x - pos.x) / double(w) - 1.0;
  const double ny = 1.0 - 2.0 * double(io.MousePos.y - pos.y) / double(h);
  const auto unproject = [&](double z) {
    const glm::dvec4 p = inv * glm::dvec4(nx, ny, z, 1.0);
    return glm::dvec3(p) / p.w;
  };
  return pickVoxel(state.model, unproject(-1.0), unproject(1.0));
}

}  // namespace

void drawViewToolbar(AppState& state, ImVec2 pos) {
  ImGui::SetCursorScreenPos(pos);
  const ActionId views[] = {ActionId::kViewFit,  ActionId::kViewIso,  ActionId::kViewPosX, ActionId::kViewNegX,
                            ActionId::kViewPosY, ActionId::kViewNegY, ActionId::kViewPosZ, ActionId::kViewNegZ};
  const char* short_labels[] = {"Fit", "Iso", "+X", "-X", "+Y", "-Y", "+Z", "-Z"};
  for (size_t i = 0; i < std::size(views); ++i) {
    if (i > 0) ImGui::SameLine(0.0f, 2.0f);
    if (widget::SmallButton(short_labels[i])) dispatch(state, views[i]);
    if (ImGui::IsItemHovered()) {
      const Action& a = action(views[i]);
      const std::string sc = shortcutText(a.shortcut);
      ImGui::SetTooltip("%s%s%s%s", a.label, sc.empty() ? "" : " (", sc.c_str(), sc.empty() ? "" : ")");
    }
  }
  // the projection: lit while orthographic
  ImGui::SameLine(0.0f, 8.0f);
  const Action& projection = action(ActionId::kViewOrtho);
  const bool ortho = projection.checked(state);
  if (ortho) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
  if (widget::SmallButton("Ortho")) dispatch(state, projection.id);
  if (ortho) ImGui::PopStyleColor();
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("%s (%s): %s", projection.label, shortcutText(projection.shortcut).c_str(),
                      ortho ? "on, parallel lines stay parallel" : "off, the view is in perspective");
  }
}

bool handleViewMouse(AppState& state, ImVec2 pos, int w, int h, double aspect) {
  ImGui::InvisibleButton("##view", ImVec2(float(w), float(h)),
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle | ImGuiButtonFlags_AllowItemOverlap);
  // the view buttons and the view cube are drawn over it afterwards: without this the first item drawn, the view,
  // would keep the mouse and their clicks would orbit it
  ImGui::SetItemAllowOverlap();
  const ImGuiIO& io = ImGui::GetIO();
  bool dragging = false;
  if (ImGui::IsItemActive()) {
    const ImVec2 d = io.MouseDelta;
    const bool pan = ImGui::IsMouseDown(ImGuiMouseButton_Right) || ImGui::IsMouseDown(ImGuiMouseButton_Middle) ||
                     (ImGui::IsMouseDown(ImGuiMouseButton_Left) && io.KeyShift);
    if (d.x != 0.0f || d.y != 0.0f) {
      if (pan) {
        state.view.camera.pan(d.x, d.y, double(h));
      } else {
        state.view.camera.orbit(-d.x * kOrbitDegreesPerPixel, d.y * kOrbitDegreesPerPixel);
      }
    }
    dragging = true;
  }
  if (ImGui::IsItemHovered()) {
    if (io.MouseWheel != 0.0f) state.view.camera.zoom(std::pow(kZoomPerWheelStep, double(io.MouseWheel)));
    if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) state.view.fit_pending = true;
    // Ctrl+click (a click, not a drag) picks the voxel under the cursor for measuring.
    const bool click = ImGui::IsMouseReleased(ImGuiMouseButton_Left) && io.MouseDragMaxDistanceSqr[0] < 9.0f;
    if (click && io.KeyCtrl) {
      if (const auto v = voxelUnderMouse(state, pos, w, h, aspect)) addMeasurePick(state, *v);
    } else if (click && state.panel == Panel::kCasting && state.casting_ui.placing_feeder) {
      // the Casting panel's "Place a feeder": on the part's top above the voxel clicked
      if (const auto v = voxelUnderMouse(state, pos, w, h, aspect)) {
        dispatchValues(state, ActionId::kCastingPlaceFeeder,
                       {std::to_string(v->x), std::to_string(v->y), std::to_string(v->z)});
      }
    } else if (click && state.panel == Panel::kPrint && state.print_ui.lay_face) {
      // the Print panel's "Lay a face on the plate": the face clicked goes down
      if (const auto v = voxelUnderMouse(state, pos, w, h, aspect)) {
        dispatchValues(state, ActionId::kPrintLayFace,
                       {std::to_string(v->x), std::to_string(v->y), std::to_string(v->z)});
      }
    }
  }
  return dragging;
}

}  // namespace vox::app
