#include "app/skin.h"

#include <algorithm>
#include <utility>

#include "app/document.h"
#include "vox/core/text.h"

namespace vox::app {

uint64_t skinLayersMemoryLimit() { return defaultMemoryLimitBytes(); }

std::string skinLayersMemoryProblem(const VoxelGrid& grid) {
  const uint64_t need = estimateDepthMapBytes(grid) + grid.memoryBytes();
  const uint64_t limit = skinLayersMemoryLimit();
  if (need <= limit) return {};
  return "the skin layers of this " + dimsText(grid.dims()) + " model need up to " + formatBytes(need) +
         " with the model, more than " + formatBytes(limit) +
         " (80% of this machine's memory): voxelize at a lower resolution to peel in the window, "
         "or peel with 'voxmod peel FILE --layers N' (three copies of the grid and one per binary digit of N)";
}

const DepthMap* currentDepthMap(const AppState& state) {
  if (!state.doc.model) return nullptr;
  const auto* d = state.depth.get(state.doc.model->base_id);
  return d ? d->get() : nullptr;
}

int32_t peelLayersAvailable(const AppState& state) {
  const DepthMap* d = currentDepthMap(state);
  return d ? d->layers() : -1;
}

void cancelSkinLayers(AppState& state) {
  if (!state.doc.model || !state.depth.computing(state.doc.model->base_id)) return;
  state.depth.clear();
  state.skin.cancelled_base = state.doc.model->base_id;
  state.skin.pending_peel.reset();
}

void computeSkinLayers(AppState& state) { state.skin.cancelled_base = 0; }

void peelTo(AppState& state, int32_t layers) {
  if (!state.doc.model) return;
  const DepthMap* depth = currentDepthMap(state);
  if (!depth) {
    state.skin.cancelled_base = 0;     // a peel asks for the layers again
    state.skin.pending_peel = layers;  // applied by updateDocument when the depth map arrives
    return;
  }
  state.skin.pending_peel.reset();
  // The core (the last layer) stays: peeling it too would leave nothing to look at.
  const int32_t k = std::clamp(layers, 0, std::max(depth->layers() - 1, 0));
  const ModelSnapshot& cur = *state.doc.model;
  if (k == cur.peeled) return;
  ModelSnapshot next;
  next.base_id = cur.base_id;
  next.base = cur.base;
  next.peeled = k;
  next.origin = cur.origin;
  next.round_peels = cur.round_peels;
  next.label = k == 0 ? "reset skin" : "peel to layer " + std::to_string(k);
  // A state the document was in before (the same base and round peels, the same layers peeled) holds the same voxels:
  // it comes back as it was, with its version (what was derived from it is found again and, when it is what the file
  // holds, the document is not unsaved: a peel and then Reset skin) and its parts (Reset skin on a peeled scene).
  const ModelSnapshot* same = nullptr;
  for (const auto* stack : {&state.doc.undo_stack, &state.doc.redo_stack}) {
    for (const ModelSnapshot& s : *stack) {
      if (s.base_id == cur.base_id && s.peeled == k && s.round_peels == cur.round_peels) same = &s;
    }
  }
  if (same) {
    next.version = same->version;
    next.grid = same->grid;
    next.parts = same->parts;
  } else {
    next.version = takeId(state);
    next.grid = depth->peeled(k).remaining;
    next.grid.frame() = cur.base.frame();  // the depth map keeps the frame it was computed with; units may differ now
  }
  setModel(state, std::move(next), true);
}

}  // namespace vox::app
