// The Thickness panel's lists (thickness_panel.cpp): thin-wall regions, largest first, and hot spots, thickest
// first. Clicking a row selects it (the thin-region and hot-spot actions): the section through it, the 3D view turned
// about it, both marking it (thickness_view.cpp, thickness_image.cpp).
#include <algorithm>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "app/actions.h"
#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/ui.h"
#include "vox/core/units.h"

namespace vox::app {
namespace {

constexpr int kMostRows = 200;  // more would not be read; the count above the list says how many there are

}  // namespace

// A scrolling table showing at most `shown` rows at once.
bool beginScrollList(const char* id, int columns, int rows, int shown) {
  const float row_h = ImGui::GetTextLineHeightWithSpacing() + 2.0f;
  const float height = float(std::min(rows, shown) + 1) * row_h + 6.0f;
  if (!ImGui::BeginTable(id, columns, ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_BordersOuter,
                         ImVec2(0.0f, height)))
    return false;
  ImGui::TableSetupScrollFreeze(0, 1);
  return true;
}

void drawThinWallList(AppState& state, const Walls& thin, const std::string& units) {
  const std::string specks = thin.specks > 0 ? " (and " + countOf(thin.specks, "speck") + " under " +
                                                   formatArea(thin.min_area, units) + ", not listed)"
                                             : std::string();
  if (thin.regions.empty()) {
    ImGui::TextWrapped("No wall is thinner than %s%s. Convex edges and corners are not walls.",
                       formatLength(thin.min_wall, units).c_str(), specks.c_str());
    return;
  }
  ImGui::TextWrapped(
      "%s thinner than %s%s, red (edges are not walls: grey in the section). Lengths in %s; click one to see it.",
      countOf(int64_t(thin.regions.size()), "wall").c_str(), formatLength(thin.min_wall, units).c_str(), specks.c_str(),
      unitsLabel(units).c_str());
  const int rows = std::min(int(thin.regions.size()), kMostRows);
  if (!beginScrollList("thin_walls", 3, rows, 5)) return;
  ImGui::TableSetupColumn("Voxels", ImGuiTableColumnFlags_WidthFixed, 70.0f);
  ImGui::TableSetupColumn("Wall");
  ImGui::TableSetupColumn("Box, voxels");
  ImGui::TableHeadersRow();
  for (int i = 0; i < rows; ++i) {
    const ThinWallRegion& g = thin.regions[size_t(i)];
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::PushID(i);
    const bool selected = selectedRegion(state) == &g;
    if (widget::Selectable(groupDigits(g.voxels).c_str(), selected, ImGuiSelectableFlags_SpanAllColumns)) {
      dispatchValues(state, ActionId::kThinRegion, {std::to_string(i + 1)});
    }
    ImGui::PopID();
    ImGui::TableSetColumnIndex(1);
    ImGui::Text("%.4g", g.min);
    ImGui::TableSetColumnIndex(2);
    const glm::ivec3 e = g.bbox_max_ijk - g.bbox_min_ijk + 1;
    ImGui::Text("%d x %d x %d", e.x, e.y, e.z);
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("voxels (%d, %d, %d) to (%d, %d, %d)", g.bbox_min_ijk.x, g.bbox_min_ijk.y, g.bbox_min_ijk.z,
                        g.bbox_max_ijk.x, g.bbox_max_ijk.y, g.bbox_max_ijk.z);
    }
  }
  ImGui::EndTable();
  markWidget("thin_wall_list");
}

void drawHotSpotList(AppState& state, const ThicknessResult& r, const std::string& units) {
  ImGui::TextWrapped(
      "Centres of the thickest regions (magenta rings): where a casting freezes last. Isolated: behind a thinner "
      "neck, so it needs its own feeder. Lengths in %s.",
      unitsLabel(units).c_str());
  ImGui::TextDisabled("Modulus");
  termMarker(state, "modulus");
  ImGui::SameLine();
  ImGui::TextDisabled("Isolated");
  termMarker(state, "isolated");
  if (r.hot_spots.empty()) return;
  const int rows = std::min(int(r.hot_spots.size()), kMostRows);
  if (!beginScrollList("hot_spots", 4, rows, 8)) return;
  ImGui::TableSetupColumn("#", ImGuiTableColumnFlags_WidthFixed, 24.0f);
  ImGui::TableSetupColumn("Radius");
  ImGui::TableSetupColumn("Modulus");
  ImGui::TableSetupColumn("Isolated", ImGuiTableColumnFlags_WidthFixed, 60.0f);
  ImGui::TableHeadersRow();
  for (int i = 0; i < rows; ++i) {
    const HotSpot& s = r.hot_spots[size_t(i)];
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::PushID(i);
    const bool selected = selectedHotSpot(state) == &s;
    if (widget::Selectable(std::to_string(i + 1).c_str(), selected, ImGuiSelectableFlags_SpanAllColumns)) {
      dispatchValues(state, ActionId::kHotSpot, {std::to_string(i + 1)});
    }
    ImGui::PopID();
    ImGui::TableSetColumnIndex(1);
    ImGui::Text("%.4g", s.radius);
    ImGui::TableSetColumnIndex(2);
    ImGui::Text("%.4g", s.modulus);
    ImGui::TableSetColumnIndex(3);
    ImGui::TextUnformatted(s.isolated ? "yes" : "no");
  }
  ImGui::EndTable();
  markWidget("hot_spot_list");
}

}  // namespace vox::app
