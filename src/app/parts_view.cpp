#include "app/parts_view.h"

#include <algorithm>

#include "app/messages.h"
#include "app/parts.h"

namespace vox::app {
namespace {

constexpr float kFaintOpacity = 0.12f;  // parts around the pair or part in focus: there, never in the way
constexpr float kDimmed = 0.4f;         // colour factor of the parts not selected while some are

bool isSelected(const PartsUi& ui, size_t i) {
  return std::find(ui.selected.begin(), ui.selected.end(), i) != ui.selected.end();
}

// A pair or the selected part alone is in focus: the other parts are drawn faint.
bool inFocus(const PartsUi& ui) { return ui.pair >= 0 || (ui.scope_selected && !ui.selected.empty()); }

}  // namespace

void syncPartRenderers(AppState& state) {
  Viewport& vp = state.viewport;
  const Assembly* parts = currentParts(state);
  const uint64_t version = parts ? state.doc.model->version : 0;
  if (version == vp.parts_version) return;
  vp.parts_version = version;
  vp.dirty = true;
  if (!parts) {
    vp.parts.clear();
    return;
  }
  vp.parts.resize(parts->size());
  for (size_t i = 0; i < parts->size(); ++i) {
    if (!vp.parts[i]) {
      auto r = render::PointRenderer::create();
      if (!r) {
        reportError(state, "the parts cannot be drawn: " + r.error().message);
        vp.parts.clear();
        return;
      }
      vp.parts[i] = std::move(r).value();
    }
    vp.parts[i]->setGrid(partOnExtent(*parts, i));
  }
}

bool drawsParts(const AppState& state) {
  const Assembly* parts = currentParts(state);
  return parts && state.viewport.parts.size() == parts->size() && state.viewport.parts_version != 0;
}

render::DrawStats drawParts(AppState& state, int w, int h, const render::DrawParams& params) {
  const Assembly& parts = *currentParts(state);
  const PartsUi& ui = state.parts_ui;
  const bool focus = inFocus(ui);
  render::DrawStats total;
  // Opaque parts first, then the faint ones (blended over what is drawn, depth-tested but not written).
  for (int pass = 0; pass < 2; ++pass) {
    for (size_t i = 0; i < parts.size(); ++i) {
      const Part& part = parts.part(i);
      const bool selected = isSelected(ui, i);
      const bool faint = focus && !selected;
      if (!part.visible || faint != (pass == 1)) continue;
      render::DrawParams p = params;
      p.colour = part.colour * (!focus && !ui.selected.empty() && !selected ? kDimmed : 1.0f);
      if (faint) p.opacity = kFaintOpacity;
      const render::DrawStats s = state.viewport.parts[i]->draw(state.view.camera, w, h, p);
      total.points_drawn += s.points_drawn;
      total.points_available += s.points_available;
      total.cut_points += s.cut_points;
      total.lod_level = std::max(total.lod_level, s.lod_level);
      total.point_size_px = s.point_size_px;
    }
  }
  return total;
}

void appendPartsSignature(const AppState& state, std::vector<double>& signature) {
  const Assembly* parts = currentParts(state);
  if (!parts) return;
  const PartsUi& ui = state.parts_ui;
  signature.push_back(double(ui.pair_key));
  signature.push_back(double(ui.scope_selected));
  signature.push_back(double(ui.selected.size()));
  for (size_t i : ui.selected) signature.push_back(double(i));
  for (const Part& p : parts->parts()) {
    signature.push_back(p.visible ? 1.0 : 0.0);
    signature.insert(signature.end(), {double(p.colour.x), double(p.colour.y), double(p.colour.z)});
  }
  // The clearance's marks are drawn over the image; a new clearance redraws it.
  signature.push_back(double(ui.clearance_version));
  signature.push_back(double(ui.clearance_a));
  signature.push_back(double(ui.clearance_b));
}

}  // namespace vox::app
