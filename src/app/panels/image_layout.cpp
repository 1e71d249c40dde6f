// How the main area is shared between the 3D view and the 2D image of the Section and X-ray panels (ImageLayout,
// panels.h).
#include <algorithm>
#include <cmath>

#include <imgui.h>

#include "app/casting.h"
#include "app/print.h"
#include "app/operations.h"
#include "app/panels/panels.h"

namespace vox::app {
namespace {

// Magnification of an image made of a fixed part (legend, labels) and a part that scales (the voxels), in an area.
// Whole numbers above 1, so every voxel covers the same number of pixels.
float fitScale(ImVec2 fixed, ImVec2 scalable, ImVec2 area) {
  const float s = std::min((area.x - fixed.x) / scalable.x, (area.y - fixed.y) / scalable.y);
  return s >= 1.0f ? std::floor(s) : std::max(s, 0.05f);
}

}  // namespace

ImageLayout layoutImage(AppState& state, float w, float h) {
  ImageLayout l;
  l.view = ImVec2(w, h);
  const bool thickness = state.panel == Panel::kThickness;
  // The Parts panel shows the section through the interference pair it shows.
  const bool parts = state.panel == Panel::kParts && state.parts_ui.pair >= 0;
  // The Print panel shows the section through the trapped cavity clicked in its list.
  const bool print = state.panel == Panel::kPrint && selectedCavity(state) != nullptr;
  // The Casting panel shows the section coloured by the field it shows, once it has a run.
  const bool casting = state.panel == Panel::kCasting && currentCasting(state) != nullptr;
  if (state.model.empty() ||
      (state.panel != Panel::kSection && state.panel != Panel::kXray && !thickness && !parts && !print && !casting)) {
    return l;
  }
  const float text = 3.0f * ImGui::GetTextLineHeightWithSpacing();  // title and read-out lines around the image
  constexpr float kMost = 0.6f, kLeast = 0.35f;
  ImVec2 fixed(40.0f, text + 16.0f), scalable(1.0f, 1.0f);
  if (state.panel == Panel::kXray) {
    const XrayResult* x = currentXray(state);
    if (!x) return l;  // not computed yet: the whole area for the 3D view
    fixed = ImVec2(xrayLegendSize().x + 40.0f, text + 16.0f);
    scalable = ImVec2(float(x->thickness.width), float(x->thickness.height));
  } else if (thickness && !currentThickness(state)) {
    return l;  // not computed yet: the whole area for the 3D view
  } else if (const Section* s = currentSection(state)) {
    scalable = ImVec2(float(s->mask.width), float(s->mask.height));
    if (thickness) fixed.x += 230.0f;  // the colour bar and its labels
  }
  const float side = fitScale(fixed, scalable, ImVec2(kMost * w, h));
  const float stacked = fitScale(fixed, scalable, ImVec2(w, kMost * h));
  if (stacked >= side) {
    const float ih = std::clamp(fixed.y + scalable.y * stacked, kLeast * h, kMost * h);
    l.image = ImVec2(w, std::floor(ih));
    l.view = ImVec2(w, h - l.image.y);
    l.image_offset = ImVec2(0.0f, l.view.y);
  } else {
    const float iw = std::clamp(fixed.x + scalable.x * side, kLeast * w, kMost * w);
    l.image = ImVec2(std::floor(iw), h);
    l.view = ImVec2(w - l.image.x, h);
    l.image_offset = ImVec2(l.view.x, 0.0f);
  }
  return l;
}

}  // namespace vox::app
