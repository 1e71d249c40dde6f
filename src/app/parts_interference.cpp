// The interference of the parts (vox/analysis/assembly.h, findInterference) for the Parts panel: found on a worker,
// one pair shown at a time: its shared voxels become a grid on the model's frame (drawn in red over the parts and
// in the section), the section moves through the overlap's centre and the camera turns to it.
#include <algorithm>
#include <cmath>
#include <utility>

#include "app/actions.h"  // kMaxSectionZoom
#include "app/document.h"
#include "app/parts.h"
#include "app/update.h"
#include "vox/io/figure.h"

namespace vox::app {

void startInterference(AppState& state) {
  const Assembly* parts = currentParts(state);
  if (!parts) return;
  const uint64_t version = state.doc.model->version;
  if (state.parts_ui.interference_version == version && state.parts_ui.interference) return;
  if (state.interference_job.active() && state.interference_job_version == version) return;
  std::vector<LatticeGrid> placed = parts->placedParts();
  const Lattice lattice = parts->lattice();
  state.interference_job_version = version;
  state.parts_ui.interference_cancelled_version = 0;
  state.interference_job.start("Finding interference",
                               [placed = std::move(placed), lattice](const ProgressFn& progress) {
                                 return findInterference(placed, lattice, progress);
                               });
  state.job_started = nowSeconds();
}

void cancelInterference(AppState& state) {
  if (!state.interference_job.active()) return;
  state.interference_job.cancel();
  state.parts_ui.interference_cancelled_version = state.interference_job_version;
}

const Interference* currentInterference(const AppState& state) {
  const PartsUi& ui = state.parts_ui;
  if (!state.doc.model || !ui.interference || ui.interference_version != state.doc.model->version) return nullptr;
  return &*ui.interference;
}

void showInterferencePair(AppState& state, int32_t i) {
  PartsUi& ui = state.parts_ui;
  const Assembly* parts = currentParts(state);
  const Interference* inter = currentInterference(state);
  state.section_texture.reset();  // the section picture shows the overlap in red: drawn again
  state.viewport.dirty = true;
  if (!parts || !inter || i < 0 || i >= int32_t(inter->pairs.size())) {
    ui.pair = -1;
    ui.pair_key = 0;
    ui.pair_overlap = VoxelGrid{};
    return;
  }
  const InterferencePair& p = inter->pairs[size_t(i)];
  const Lattice& lattice = parts->lattice();
  const Box3i ext = parts->extent();
  LatticeGrid shared = sharedVoxels(parts->placedVoxels(size_t(p.a)), parts->placedVoxels(size_t(p.b)), lattice);
  LatticeGrid on_model = reframe(shared, ext, lattice);
  on_model.grid.frame() = lattice.frameAt(ext.min);
  ui.pair = i;
  ui.pair_overlap = std::move(on_model.grid);
  ui.pair_key = takeId(state);
  ui.selected = {size_t(p.a), size_t(p.b)};
  if (ui.scope_selected) applyPartsScope(state);
  // The section through the overlap's middle voxel along the section's axis, and the camera centred on the
  // overlap's box (voxel coordinates of the model, whose voxel 0 is the extent's first).
  const glm::dvec3 centre = glm::dvec3(p.box.min + p.box.max) * 0.5 - glm::dvec3(ext.min);
  const int a = int(state.section.axis);
  state.section.index =
      std::clamp(int(std::floor(centre[a])), 0, std::max(axisLength(state, state.section.axis) - 1, 0));
  const glm::ivec3 size = p.box.size();
  centreView(state, centre, double(std::max({size.x, size.y, size.z})));
  // ... and the section's picture zoomed onto the overlap, its box a third of the picture at most: a small overlap
  // is more than a red pixel
  const int r = int(imageRightAxis(state.section.axis)), u = int(imageUpAxis(state.section.axis));
  const double fit = std::min(double(axisLength(state, Axis(r))) / std::max(size[r], 1),
                              double(axisLength(state, Axis(u))) / std::max(size[u], 1)) /
                     3.0;
  zoomSection(state, std::clamp(fit, 1.0, kMaxSectionZoom), glm::dvec2(centre[r] - 0.5, centre[u] - 0.5));
}

std::string interferencePairText(const AppState& state) {
  const Assembly* parts = currentParts(state);
  const Interference* inter = currentInterference(state);
  const int32_t i = state.parts_ui.pair;
  if (!parts || !inter || i < 0 || i >= int32_t(inter->pairs.size())) return {};
  const InterferencePair& p = inter->pairs[size_t(i)];
  return "Overlap of " + parts->part(size_t(p.a)).name + " and " + parts->part(size_t(p.b)).name + ": " +
         std::to_string(p.voxels) + " voxels, in red through the parts";
}

ImageRgb partsSectionPicture(const AppState& state, const Section& section) {
  ImageRgb picture = io::sectionPicture(section.mask, 1);
  const PartsUi& ui = state.parts_ui;
  if (ui.pair < 0 || ui.pair_overlap.empty() || ui.pair_overlap.dims() != state.model.dims()) return picture;
  auto overlap = computeSection(ui.pair_overlap, SectionParams{section.axis, section.index});
  if (!overlap) return picture;
  const Image2D<uint8_t>& m = overlap->mask;
  for (int32_t y = 0; y < m.height; ++y) {
    for (int32_t x = 0; x < m.width; ++x) {
      if (m.at(x, y)) picture.at(x, y) = Rgb8{235, 40, 40};
    }
  }
  return picture;
}

}  // namespace vox::app
