#include "app/view_overlays.h"

#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "app/measure.h"

namespace vox::app {

void drawMeasureOverlay(const AppState& state, ImDrawList* dl, ImVec2 pos, int w, int h, double aspect) {
  const std::vector<glm::ivec3>& picks = measurePicks(state);
  if (picks.empty() || !state.model_bounds) return;
  const glm::dmat4 vp = state.view.camera.viewProjection(aspect, *state.model_bounds);
  std::vector<ImVec2> screen;
  for (size_t i = 0; i < picks.size(); ++i) {
    const glm::dvec4 c = vp * glm::dvec4(glm::dvec3(picks[i]) + 0.5, 1.0);
    if (c.w <= 0.0) continue;
    const ImVec2 p(pos.x + float((c.x / c.w + 1.0) * 0.5 * w), pos.y + float((1.0 - c.y / c.w) * 0.5 * h));
    screen.push_back(p);
    dl->AddCircle(p, 7.0f, IM_COL32(0, 0, 0, 255), 0, 4.0f);
    dl->AddCircle(p, 7.0f, IM_COL32(255, 220, 60, 255), 0, 2.0f);
    const char label[2] = {char('A' + i), 0};
    dl->AddText(ImVec2(p.x + 9.0f, p.y - 18.0f), IM_COL32(255, 220, 60, 255), label);
  }
  if (screen.size() == 2) dl->AddLine(screen[0], screen[1], IM_COL32(255, 220, 60, 200), 1.5f);
  float y = pos.y + 30.0f;
  for (const std::string& line : measureLines(state)) {
    dl->AddText(ImVec2(pos.x + 9.0f, y + 1.0f), IM_COL32(0, 0, 0, 255), line.c_str());
    dl->AddText(ImVec2(pos.x + 8.0f, y), IM_COL32(255, 220, 60, 255), line.c_str());
    y += ImGui::GetTextLineHeightWithSpacing();
  }
}

void drawAxisTriad(const render::Camera& camera, ImVec2 origin, float length) {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const glm::dvec3 right = camera.rightAxis();
  const glm::dvec3 up = camera.upAxis();
  const struct {
    glm::dvec3 axis;
    ImU32 colour;
    const char* name;
  } axes[3] = {{{1, 0, 0}, IM_COL32(235, 80, 80, 255), "X"},
               {{0, 1, 0}, IM_COL32(90, 210, 90, 255), "Y"},
               {{0, 0, 1}, IM_COL32(90, 140, 255, 255), "Z"}};
  for (const auto& a : axes) {
    const ImVec2 tip(origin.x + float(glm::dot(a.axis, right)) * length,
                     origin.y - float(glm::dot(a.axis, up)) * length);
    dl->AddLine(origin, tip, a.colour, 2.0f);
    dl->AddText(ImVec2(tip.x + 2.0f, tip.y - 7.0f), a.colour, a.name);
  }
}

}  // namespace vox::app
