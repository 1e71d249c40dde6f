#include "app/view_overlays.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "app/measure.h"
#include "app/parts.h"

namespace vox::app {

void shadowText(ImDrawList* dl, ImVec2 p, ImU32 colour, const char* text) {
  dl->AddText(ImVec2(p.x + 1.0f, p.y + 1.0f), IM_COL32(0, 0, 0, 255), text);
  dl->AddText(p, colour, text);
}

bool projectToView(const glm::dmat4& vp, glm::dvec3 p, ImVec2 pos, int w, int h, ImVec2& out) {
  const glm::dvec4 c = vp * glm::dvec4(p, 1.0);
  if (c.w <= 0.0) return false;
  out = ImVec2(pos.x + float((c.x / c.w + 1.0) * 0.5 * w), pos.y + float((1.0 - c.y / c.w) * 0.5 * h));
  return true;
}

void drawMeasureOverlay(const AppState& state, ImDrawList* dl, ImVec2 pos, int w, int h, double aspect, float top) {
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
  float y = std::max(top, pos.y + 30.0f);
  const float wrap = std::max(float(w) - 16.0f, 80.0f);
  ImFont* font = ImGui::GetFont();
  const float size = ImGui::GetFontSize();
  for (const std::string& line : measureLines(state)) {
    dl->AddText(font, size, ImVec2(pos.x + 9.0f, y + 1.0f), IM_COL32(0, 0, 0, 255), line.c_str(), nullptr, wrap);
    dl->AddText(font, size, ImVec2(pos.x + 8.0f, y), IM_COL32(255, 220, 60, 255), line.c_str(), nullptr, wrap);
    y += ImGui::CalcTextSize(line.c_str(), nullptr, false, wrap).y + ImGui::GetStyle().ItemSpacing.y;
  }
}

void drawClearanceOverlay(const AppState& state, ImDrawList* dl, ImVec2 pos, int w, int h, double aspect) {
  glm::ivec3 voxels[2];
  if (!state.model_bounds || !clearanceVoxels(state, voxels[0], voxels[1])) return;
  const Clearance& c = *currentClearance(state);
  const glm::dmat4 vp = state.view.camera.viewProjection(aspect, *state.model_bounds);
  ImVec2 screen[2];
  for (int i = 0; i < 2; ++i) {
    const glm::dvec4 p = vp * glm::dvec4(glm::dvec3(voxels[i]) + 0.5, 1.0);
    if (p.w <= 0.0) return;
    screen[i] = ImVec2(pos.x + float((p.x / p.w + 1.0) * 0.5 * w), pos.y + float((1.0 - p.y / p.w) * 0.5 * h));
  }
  const ImU32 cyan = IM_COL32(60, 230, 255, 255), black = IM_COL32(0, 0, 0, 255);
  dl->AddLine(screen[0], screen[1], black, 4.0f);
  dl->AddLine(screen[0], screen[1], cyan, 2.0f);
  for (const ImVec2& p : screen) {
    dl->AddCircle(p, 8.0f, black, 0, 4.0f);
    dl->AddCircle(p, 8.0f, cyan, 0, 2.0f);
  }
  char text[64];
  const std::string& units = currentParts(state)->lattice().units;
  std::snprintf(text, sizeof text, "gap %.4g %s", c.gap, units == "model" ? "" : units.c_str());
  const ImVec2 mid((screen[0].x + screen[1].x) * 0.5f + 10.0f, (screen[0].y + screen[1].y) * 0.5f - 8.0f);
  dl->AddText(ImVec2(mid.x + 1.0f, mid.y + 1.0f), black, text);
  dl->AddText(mid, cyan, text);
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
