#include "app/view_cube.h"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <imgui.h>
#include <imgui_internal.h>  // GetActiveID

#include "app/actions.h"
#include "app/ui.h"

namespace vox::app {
namespace {

struct Face {
  glm::dvec3 normal;
  glm::dvec3 u, v;  // the face's own axes (with the normal: its four corners at normal +- u +- v)
  const char* name;
  ActionId view;
};

constexpr double kSeen = 0.02;  // a face seen this edge-on or less is not drawn (nor clicked)

const std::array<Face, 6>& faces() {
  static const std::array<Face, 6> f = {{
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, "+X", ActionId::kViewPosX},
      {{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}, "-X", ActionId::kViewNegX},
      {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}, "+Y", ActionId::kViewPosY},
      {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}, "-Y", ActionId::kViewNegY},
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, "+Z", ActionId::kViewPosZ},
      {{0, 0, -1}, {1, 0, 0}, {0, 1, 0}, "-Z", ActionId::kViewNegZ},
  }};
  return f;
}

// Whether p lies inside the convex quad q (corners in order round it).
bool insideQuad(const std::array<ImVec2, 4>& q, ImVec2 p) {
  int sign = 0;
  for (size_t i = 0; i < 4; ++i) {
    const ImVec2 a = q[i], b = q[(i + 1) % 4];
    const float cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    const int s = cross > 0.0f ? 1 : (cross < 0.0f ? -1 : 0);
    if (s != 0 && sign != 0 && s != sign) return false;
    if (s != 0) sign = s;
  }
  return true;
}

}  // namespace

void drawViewCube(AppState& state, ImVec2 centre, float half) {
  const render::Camera& camera = state.view.camera;
  const glm::dvec3 right = camera.rightAxis(), up = camera.upAxis(), eye = camera.eyeDirection();
  const auto screen = [&](glm::dvec3 p) {
    return ImVec2(centre.x + float(glm::dot(p, right)) * half, centre.y - float(glm::dot(p, up)) * half);
  };
  // the faces seen, farthest first (a convex cube's seen faces never overlap; the order only matters at edges)
  std::vector<const Face*> seen;
  for (const Face& f : faces())
    if (glm::dot(f.normal, eye) > kSeen) seen.push_back(&f);
  std::sort(seen.begin(), seen.end(),
            [&](const Face* a, const Face* b) { return glm::dot(a->normal, eye) < glm::dot(b->normal, eye); });
  std::vector<std::array<ImVec2, 4>> quads;
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const Face* under = nullptr;
  for (const Face* f : seen) {
    quads.push_back({screen(f->normal - f->u - f->v), screen(f->normal + f->u - f->v), screen(f->normal + f->u + f->v),
                     screen(f->normal - f->u + f->v)});
    if (insideQuad(quads.back(), mouse)) under = f;
  }
  // A button takes the click before the view's orbit does, only over a face (or while it is held): a click beside
  // the cube orbits the view.
  const float reach = half * 1.75f;
  const ImGuiID id = ImGui::GetID("##view_cube");
  bool clicked = false, hovered = false;
  if (under || ImGui::GetActiveID() == id) {
    ImGui::SetCursorScreenPos(ImVec2(centre.x - reach, centre.y - reach));
    clicked = ImGui::InvisibleButton("##view_cube", ImVec2(2.0f * reach, 2.0f * reach));
    hovered = ImGui::IsItemHovered();
  }
  if (!hovered) under = nullptr;
  ImDrawList* dl = ImGui::GetWindowDrawList();
  for (size_t i = 0; i < seen.size(); ++i) {
    const Face* f = seen[i];
    const std::array<ImVec2, 4>& q = quads[i];
    const bool over = f == under;
    const int shade = 70 + int(110.0 * glm::dot(f->normal, eye));
    dl->AddQuadFilled(q[0], q[1], q[2], q[3],
                      over ? IM_COL32(90, 140, 220, 230) : IM_COL32(shade, shade, shade + 25, 210));
    dl->AddQuad(q[0], q[1], q[2], q[3], IM_COL32(20, 20, 30, 255), 1.0f);
    const ImVec2 mid = screen(f->normal);
    if (glm::dot(f->normal, eye) > 0.3) {  // named where it faces the eye enough to read
      const ImVec2 size = ImGui::CalcTextSize(f->name);
      dl->AddText(ImVec2(mid.x - size.x * 0.5f, mid.y - size.y * 0.5f), IM_COL32(255, 255, 255, 255), f->name);
    }
    ImVec2 lo = q[0], hi = q[0];
    for (const ImVec2& c : q) {
      lo = ImVec2(std::min(lo.x, c.x), std::min(lo.y, c.y));
      hi = ImVec2(std::max(hi.x, c.x), std::max(hi.y, c.y));
    }
    recordAt(std::string("view cube ") + f->name, "button", lo, hi);  // its box's centre is the face's centre
  }
  if (under && hovered) ImGui::SetTooltip("Look from %s (%s)", under->name, action(under->view).label);
  if (clicked && under) dispatch(state, under->view);
}

}  // namespace vox::app
