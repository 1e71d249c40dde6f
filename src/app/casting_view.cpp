#include "app/casting_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "app/casting.h"
#include "app/print_view.h"      // shownPrint
#include "app/thickness_view.h"  // shownThickness
#include "app/ui.h"
#include "app/view_overlays.h"

namespace vox::app {
namespace {

constexpr ImU32 kIsolatedColour = IM_COL32(255, 80, 70, 255);
constexpr ImU32 kFedColour = IM_COL32(240, 240, 240, 255);
constexpr ImU32 kInFeederColour = IM_COL32(110, 170, 255, 255);
constexpr ImU32 kFeederColour = IM_COL32(255, 200, 80, 255);
constexpr ImU32 kLegendColour = IM_COL32(230, 230, 230, 255);

void uploadColours(AppState& state, const CastingOutcome& r) {
  const VoxelGrid& g = state.model;
  const Dims d = g.dims();
  const double front = castingTimeShown(state, r);
  std::vector<uint8_t> values(size_t(d.count()), 0);
  if (state.casting_ui.field == CastingField::kTime && r.time_bytes.size() == values.size()) {
    // from the worker's bytes: what freezes after the front is not yet solid (1, red)
    const uint8_t at = castingFrontByte(r, front);
    const bool before_end = front < r.run.result.last_metal_s;
    for (size_t i = 0; i < values.size(); ++i) {
      const uint8_t b = r.time_bytes[i];
      values[i] = before_end && b > at ? 1 : b;
    }
  } else {
    size_t i = 0;
    for (int32_t z = 0; z < d.nz; ++z)
      for (int32_t y = 0; y < d.ny; ++y)
        for (int32_t x = 0; x < d.nx; ++x, ++i)
          values[i] = castingColourValue(r, state.casting_ui.field, front, {x, y, z});
  }
  if (Status s = state.viewport.renderer->setScalarVolume(glm::ivec3(0), d, values); !s) {
    state.casting_ui.volume_problem = "The 3D view is not coloured: " + s.error().message + ".";
  }
}

std::string seconds(double s) {
  char text[48];
  if (s >= 120.0) {
    std::snprintf(text, sizeof text, "%.3g s (%.3g min)", s, s / 60.0);
  } else {
    std::snprintf(text, sizeof text, "%.3g s", s);
  }
  return text;
}

}  // namespace

const CastingOutcome* shownCasting(const AppState& state) {
  return state.panel == Panel::kCasting && !state.model.empty() ? currentCasting(state) : nullptr;
}

void syncCastingView(AppState& state) {
  if (!state.viewport.renderer) return;
  CastingUi& ui = state.casting_ui;
  const CastingOutcome* r = shownCasting(state);
  const uint64_t key = r ? r->id : 0;
  const bool front = r && ui.field == CastingField::kTime;  // only the time's colours move with the front
  const std::vector<double> sig = {double(int(ui.field)), front ? castingTimeShown(state, *r) : 0.0};
  if (key == ui.volume_key && (!r || sig == ui.volume_sig)) return;
  ui.volume_key = key;
  ui.volume_sig = sig;
  ui.volume_problem.clear();
  state.viewport.dirty = true;
  if (r) {
    uploadColours(state, *r);
  } else if (!shownThickness(state) && !shownPrint(state)) {
    state.viewport.renderer->clearScalarVolume();  // the other panels' colours are theirs to clear
  }
}

void castingDrawParams(const AppState& state, render::DrawParams& p) {
  if (!shownCasting(state) || !state.viewport.renderer || !state.viewport.renderer->hasScalarVolume()) return;
  p.scalar_colour = true;
  p.scalar_threshold = 0.5f / 254.0f;  // the value 1, metal still liquid at the front: red
}

float drawCastingOverlay(AppState& state, ImDrawList* dl, ImVec2 pos, int w, int h, double aspect) {
  if (state.panel != Panel::kCasting || state.model.empty() || !state.model_bounds) return pos.y;
  const float lh = ImGui::GetTextLineHeightWithSpacing();
  float y = pos.y + 30.0f;
  const auto line = [&](ImU32 colour, const std::string& text) {
    shadowText(dl, ImVec2(pos.x + 12.0f, y), colour, text.c_str());
    y += lh;
  };
  if (state.casting_ui.placing_feeder) line(kFeederColour, "Click the part where a feeder should stand");
  const glm::dmat4 vp = state.view.camera.viewProjection(aspect, *state.model_bounds);
  const GridFrame& frame = state.model.frame();
  const CastingOutcome* r = shownCasting(state);
  if (!r) {
    line(kLegendColour, castingComputing(state) ? "Simulating the casting..." : "Casting: Simulate in the panel");
    return y;
  }
  const CastingResult& c = r->run.result;
  const CastingField field = state.casting_ui.field;
  const std::string units = state.model.frame().units;
  if (field == CastingField::kTime) {
    line(kLegendColour,
         "Solidification time: dark " + seconds(r->first_solid_s) + ", yellow " + seconds(c.last_metal_s) + " (last)");
    const double front = castingTimeShown(state, *r);
    if (front < c.last_metal_s) line(kIsolatedColour, "red: not yet solid at " + seconds(front));
  } else {
    char text[160];
    std::snprintf(text, sizeof text, "%s: dark 0, yellow %.3g %s", castingFieldName(field), castingFieldMax(*r, field),
                  castingFieldUnit(field, units).c_str());
    line(kLegendColour, text);
  }
  line(c.sound ? IM_COL32(120, 230, 120, 255) : kIsolatedColour, c.sound ? "Sound" : "Not sound");
  if (!state.casting_ui.volume_problem.empty()) line(IM_COL32(255, 200, 80, 255), state.casting_ui.volume_problem);
  const CastingHotSpot* chosen = selectedCastingSpot(state);
  // feeding paths: from each fed spot through its saddle to the spot it feeds from
  for (const CastingHotSpot& s : c.hot_spots) {
    if (s.fed_by < 0 || size_t(s.fed_by) >= c.hot_spots.size()) continue;
    ImVec2 a, b, e;
    if (projectToView(vp, (s.centre - frame.origin) / frame.voxel_size, pos, w, h, a) &&
        projectToView(vp, (s.saddle - frame.origin) / frame.voxel_size, pos, w, h, b) &&
        projectToView(vp, (c.hot_spots[size_t(s.fed_by)].centre - frame.origin) / frame.voxel_size, pos, w, h, e)) {
      for (const auto& [p, q] : {std::pair(a, b), std::pair(b, e)}) {
        dl->AddLine(p, q, IM_COL32(0, 0, 0, 255), 4.0f);
        dl->AddLine(p, q, kFedColour, 2.0f);
      }
    }
  }
  for (size_t i = 0; i < c.hot_spots.size() && i < 20; ++i) {
    const CastingHotSpot& s = c.hot_spots[i];
    ImVec2 p;
    if (!projectToView(vp, (s.centre - frame.origin) / frame.voxel_size, pos, w, h, p)) continue;
    const ImU32 colour = s.in_feeder ? kInFeederColour : (s.isolated ? kIsolatedColour : kFedColour);
    const float radius = &s == chosen ? 14.0f : 9.0f;
    dl->AddCircle(p, radius, IM_COL32(0, 0, 0, 255), 0, 4.0f);
    dl->AddCircle(p, radius, colour, 0, 2.0f);
    shadowText(dl, ImVec2(p.x + radius + 2.0f, p.y - 18.0f), colour, ("hot spot " + std::to_string(i + 1)).c_str());
  }
  return y;
}

}  // namespace vox::app
