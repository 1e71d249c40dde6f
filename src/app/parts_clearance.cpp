// The clearance between two parts (vox/analysis/assembly.h, findClearance) for the Parts panel: found on a worker for
// the two selected parts of one model version; the panel shows the gap and the 3D view marks the two voxels that
// realise it (view_overlays.cpp).
#include <algorithm>
#include <cstdio>
#include <utility>
#include <vector>

#include <glm/common.hpp>

#include "app/parts.h"
#include "app/update.h"
#include "vox/core/text.h"

namespace vox::app {
namespace {

std::string lengthText(double value, const std::string& units) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g %s", value, units == "model" ? "model units" : units.c_str());
  return buf;
}

// The clearance is shown while its two parts are the selection (in either order).
bool forSelection(const AppState& state) {
  const PartsUi& ui = state.parts_ui;
  const std::vector<size_t>& sel = ui.selected;
  return sel.size() == 2 && ((sel[0] == ui.clearance_a && sel[1] == ui.clearance_b) ||
                             (sel[0] == ui.clearance_b && sel[1] == ui.clearance_a));
}

}  // namespace

void startClearance(AppState& state, size_t a, size_t b) {
  const Assembly* parts = currentParts(state);
  if (!parts || a >= parts->size() || b >= parts->size() || a == b) return;
  const uint64_t version = state.doc.model->version;
  PartsUi& ui = state.parts_ui;
  if (ui.clearance_version == version && ui.clearance_a == a && ui.clearance_b == b) return;  // known
  if (state.clearance_job.active() && state.clearance_job_version == version && state.clearance_job_a == a &&
      state.clearance_job_b == b) {
    return;  // under way
  }
  LatticeGrid pa = parts->placedVoxels(a), pb = parts->placedVoxels(b);
  const Lattice lattice = parts->lattice();
  state.clearance_job_a = a;
  state.clearance_job_b = b;
  state.clearance_job_version = version;
  state.job_started = nowSeconds();
  state.clearance_job.start("Finding the clearance",
                            [pa = std::move(pa), pb = std::move(pb), lattice](const ProgressFn& progress) {
                              return findClearance(pa, pb, lattice, {}, progress);
                            });
}

void updateClearance(AppState& state) {
  auto r = state.clearance_job.take();
  if (!r || !state.doc.model || state.clearance_job_version != state.doc.model->version) return;
  PartsUi& ui = state.parts_ui;
  ui.clearance_a = state.clearance_job_a;
  ui.clearance_b = state.clearance_job_b;
  ui.clearance_version = state.clearance_job_version;
  if (r->ok()) {
    ui.clearance = std::move(*r).value();
    ui.clearance_error.clear();
    // The view turns to the gap, as to a clicked interference pair: its marker was off screen until a Fit.
    glm::ivec3 a, b;
    if (clearanceVoxels(state, a, b)) {
      const glm::dvec3 mid = (glm::dvec3(a) + glm::dvec3(b)) * 0.5 + 0.5;
      const glm::ivec3 span = glm::abs(a - b);
      centreView(state, mid, 1.2 * double(std::max({span.x, span.y, span.z})) + 8.0);
    }
  } else {
    ui.clearance.reset();
    ui.clearance_error = r->error().message;
  }
  state.viewport.dirty = true;
}

const Clearance* currentClearance(const AppState& state) {
  const PartsUi& ui = state.parts_ui;
  if (!state.doc.model || !ui.clearance || ui.clearance_version != state.doc.model->version) return nullptr;
  return &*ui.clearance;
}

std::string clearanceText(const AppState& state) {
  const Assembly* parts = currentParts(state);
  const PartsUi& ui = state.parts_ui;
  if (!parts || !state.doc.model || ui.clearance_version != state.doc.model->version || !forSelection(state)) return {};
  if (ui.clearance_a >= parts->size() || ui.clearance_b >= parts->size()) return {};
  const std::string pair = parts->part(ui.clearance_a).name + " and " + parts->part(ui.clearance_b).name;
  if (!ui.clearance) return "No clearance between " + pair + ": " + ui.clearance_error;
  const Clearance& c = *ui.clearance;
  if (!c.found) return "No clearance between " + pair + ": a part has no voxels";
  if (c.touching) return pair + " touch (they share a voxel or a face): no gap";
  char voxels[48];
  std::snprintf(voxels, sizeof voxels, "%.3g", c.centre_distance_voxels);
  return "Gap between " + pair + ": " + lengthText(c.gap, parts->lattice().units) + " (the closest voxels' centres " +
         voxels + " voxels apart, marked in the view)";
}

bool clearanceVoxels(const AppState& state, glm::ivec3& a, glm::ivec3& b) {
  const Assembly* parts = currentParts(state);
  const Clearance* c = currentClearance(state);
  if (!parts || !c || !c->found || c->touching || !forSelection(state)) return false;
  const glm::ivec3 origin = parts->extent().min;
  a = c->voxel_a - origin;
  b = c->voxel_b - origin;
  return true;
}

}  // namespace vox::app
