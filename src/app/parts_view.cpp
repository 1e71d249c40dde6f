#include "app/parts_view.h"

#include <algorithm>
#include <optional>

#include <glm/common.hpp>

#include "app/messages.h"
#include "app/parts.h"
#include "app/casting_view.h"
#include "app/print_view.h"
#include "app/thickness_view.h"

namespace vox::app {
namespace {

constexpr float kFaintOpacity = 0.12f;  // parts around the pair or part in focus: there, never in the way
constexpr float kDimmed = 0.4f;         // colour factor of the parts not selected while some are

bool isSelected(const PartsUi& ui, size_t i) {
  return std::find(ui.selected.begin(), ui.selected.end(), i) != ui.selected.end();
}

// A pair or the selected part alone is in focus: the other parts are drawn faint.
bool inFocus(const PartsUi& ui) { return ui.pair >= 0 || (ui.scope_selected && !ui.selected.empty()); }

// The same voxels: the same box, and every layer shared (a part's grid is never edited in place, so a copy that shares
// all its layers holds what it holds). O(layers).
bool sameVoxels(const LatticeGrid& a, const LatticeGrid& b) {
  if (a.first != b.first || a.grid.dims() != b.grid.dims()) return false;
  for (int32_t z = 0; z < a.grid.nz(); ++z) {
    if (!a.grid.sharesLayerWith(b.grid, z)) return false;
  }
  return true;
}

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
  // A renderer that holds a part as it is now (same voxels, same placement) is kept as it is, wherever the part now
  // lies in the list (a part removed before it); only the others are filled again, reusing the renderers left over.
  std::vector<Viewport::PartView> before = std::move(vp.parts);
  vp.parts = std::vector<Viewport::PartView>(parts->size());
  std::vector<bool> matched(parts->size(), false);
  const auto holds = [](const Viewport::PartView& v, const Part& p) {
    return v.renderer && v.placement == p.placement && sameVoxels(v.voxels, p.voxels);
  };
  for (size_t i = 0; i < parts->size(); ++i) {
    const Part& p = parts->part(i);
    auto it = i < before.size() && holds(before[i], p)
                  ? before.begin() + ptrdiff_t(i)
                  : std::find_if(before.begin(), before.end(), [&](const auto& v) { return holds(v, p); });
    if (it != before.end()) {
      vp.parts[i] = std::move(*it);
      matched[i] = true;
    }
  }
  std::erase_if(before, [](const Viewport::PartView& v) { return !v.renderer; });
  for (size_t i = 0; i < parts->size(); ++i) {
    if (matched[i]) continue;
    Viewport::PartView& v = vp.parts[i];
    if (!before.empty()) {
      v.renderer = std::move(before.back().renderer);
      before.pop_back();
    } else {
      auto r = render::PointRenderer::create();
      if (!r) {
        reportError(state, "the parts cannot be drawn: " + r.error().message);
        vp.parts.clear();
        return;
      }
      v.renderer = std::move(r).value();
    }
    const Part& p = parts->part(i);
    const LatticeGrid placed = parts->placedVoxels(i);
    v.renderer->setGrid(placed.grid);
    v.voxels = p.voxels;
    v.placement = p.placement;
    v.box = placed.box();
    ++vp.part_fills;
  }
}

bool drawsParts(const AppState& state) {
  const Assembly* parts = currentParts(state);
  return parts && state.viewport.parts.size() == parts->size() && state.viewport.parts_version != 0 &&
         // the thickness, printability and casting colour the model's points
         !shownThickness(state) && !shownPrint(state) && !shownCasting(state);
}

std::optional<render::Box3> partsBounds(const AppState& state) {
  if (!drawsParts(state)) return std::nullopt;
  const glm::ivec3 first = currentParts(state)->extent().min;
  const PartsUi& ui = state.parts_ui;
  std::optional<render::Box3> bounds;
  for (size_t i = 0; i < state.viewport.parts.size(); ++i) {
    // The model is the selected part alone when the scope says so: its box, as its own renderer would give.
    if (ui.scope_selected && !ui.selected.empty() && i != ui.selected.front()) continue;
    const Viewport::PartView& v = state.viewport.parts[i];
    const glm::dvec3 offset(v.box.min - first);
    const render::Box3 b = v.renderer->bounds();
    if (!bounds) {
      bounds = render::Box3{b.min + offset, b.max + offset};
    } else {
      bounds->min = glm::min(bounds->min, b.min + offset);
      bounds->max = glm::max(bounds->max, b.max + offset);
    }
  }
  return bounds;
}

render::DrawStats drawParts(AppState& state, int w, int h, const render::DrawParams& params) {
  const Assembly& parts = *currentParts(state);
  const PartsUi& ui = state.parts_ui;
  const bool focus = inFocus(ui);
  const glm::ivec3 first = parts.extent().min;
  render::DrawStats total;
  // Opaque parts first, then the faint ones (blended over what is drawn, depth-tested but not written).
  for (int pass = 0; pass < 2; ++pass) {
    for (size_t i = 0; i < parts.size(); ++i) {
      const Part& part = parts.part(i);
      const bool selected = isSelected(ui, i);
      const bool faint = focus && !selected;
      if (!part.visible || faint != (pass == 1)) continue;
      const Viewport::PartView& v = state.viewport.parts[i];
      render::DrawParams p = params;
      p.colour = part.colour * (!focus && !ui.selected.empty() && !selected ? kDimmed : 1.0f);
      if (faint) p.opacity = kFaintOpacity;
      // The renderer holds the part on its own box, which starts `offset` voxels into the model's frame: the camera
      // (in the model's voxel-index space) and the section plane are moved the other way.
      const glm::ivec3 offset = v.box.min - first;
      render::Camera camera = state.view.camera;
      camera.target -= glm::dvec3(offset);
      if (p.section.axis == render::SectionAxis::kPlane) {
        p.section.offset -= glm::dot(p.section.normal, glm::vec3(offset));
      } else if (p.section.active()) {
        const int a = int(p.section.axis) - 1;
        p.section.index = std::clamp(p.section.index - offset[a], -1, v.box.size()[a]);
      }
      const render::DrawStats s = v.renderer->draw(camera, w, h, p);
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
