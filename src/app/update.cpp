#include "app/parts.h"
#include "app/update.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <tuple>
#include <utility>

#include <glm/common.hpp>

#include "app/document.h"
#include "app/export_volume.h"
#include "app/full_section.h"
#include "app/messages.h"
#include "app/model_jobs.h"
#include "app/skin.h"
#include "app/casting.h"
#include "app/print.h"
#include "app/thickness.h"

namespace vox::app {

namespace {

// A section just computed: kept with no error, or none with the error's words; its texture is re-uploaded by the
// panel when shown.
template <class T>
void keepResult(Result<T> r, std::optional<T>& result, std::string& error, Texture& texture) {
  if (r) {
    result = std::move(r).value();
    error.clear();
  } else {
    result.reset();
    error = r.error().message;
  }
  texture.reset();
}

}  // namespace

const Section* currentSection(AppState& state) {
  if (state.model.empty()) return nullptr;
  const int32_t n = axisLength(state, state.section.axis);
  state.section.index = std::clamp(state.section.index, 0, std::max(n - 1, 0));
  const SectionKey key{state.model_version, state.section.axis, state.section.index};
  if (!(key == state.section_key)) {
    state.section_key = key;
    keepResult(computeSection(state.model, SectionParams{state.section.axis, state.section.index}),
               state.section_result, state.section_error, state.section_texture);
  }
  return state.section_result ? &*state.section_result : nullptr;
}

const ObliqueSection* currentObliqueSection(AppState& state) {
  if (state.model.empty() || !state.section.oblique) return nullptr;
  const auto key = std::make_tuple(state.model_version, state.section.normal, state.section.offset);
  if (key != state.oblique_key) {
    state.oblique_key = key;
    ObliqueSectionParams p;  // through the centre of the model's box, moved along the normal
    p.normal = state.section.normal;
    p.offset = state.section.offset;
    keepResult(computeObliqueSection(state.model, p), state.oblique_result, state.oblique_error, state.oblique_texture);
  }
  return state.oblique_result ? &*state.oblique_result : nullptr;
}

void updateDocument(AppState& state) {
  if (auto loaded = state.load_job.take()) {
    if (loaded->ok()) {
      applyLoaded(state, std::move(*loaded).value());
    } else if (loaded->error().code != ErrorCode::kCancelled) {
      reportError(state, loaded->error().message);
    }
  }
  if (auto result = state.voxelize_job.take()) {
    if (result->ok()) {
      applyVoxelized(state, std::move(*result).value(), state.voxelize_job_params, nowSeconds() - state.job_started);
    } else if (result->error().code != ErrorCode::kCancelled) {
      reportError(state, result->error().message, state.doc.path);
    }
  }
  updateParts(state);
  state.depth.poll();
  state.surface_stats.poll();
  state.mass.poll();
  state.xray_result.poll();
  requestThickness(state);
  requestRays(state);  // once the thickness is known, while the panel shows rays
  if (state.panel == Panel::kThickness) currentThinWalls(state);  // the walls under the minimum wall, asked for
  requestPrint(state);
  requestCasting(state);
  advanceCastingPlay(state, state.frame_time_s);
  pollVolumeExport(state);
  pollFullSection(state);
  if (!state.doc.model) return;

  const ModelSnapshot& m = *state.doc.model;
  // The depth map of the base: needed by the Skin panel and by queued peels.
  // (Each request runs only when its key has nothing yet: the grid copies for the workers are made only then.)
  if ((state.panel == Panel::kSkin || state.skin.pending_peel) && state.depth.wants(m.base_id) &&
      state.skin.cancelled_base != m.base_id) {
    VoxelGrid base = m.base;
    state.depth.request(m.base_id, "Computing skin layers", [base](const ProgressFn& progress) {
      // Refused before anything is allocated when it could run the machine out of memory (it would take the
      // window, and the user's work, with it).
      if (const std::string why = skinLayersMemoryProblem(base); !why.empty()) {
        return Result<std::shared_ptr<const DepthMap>>(makeError(ErrorCode::kLimit, why));
      }
      auto d = computeDepthMap(base, kPeelAll, progress);
      if (!d) return Result<std::shared_ptr<const DepthMap>>(d.error());
      return Result<std::shared_ptr<const DepthMap>>(std::make_shared<const DepthMap>(std::move(d).value()));
    });
  }
  if (const Error* e = state.depth.error(m.base_id); e && state.skin.pending_peel) {
    state.skin.pending_peel.reset();
    reportError(state, "skin removal failed: " + e->message, state.doc.path);
  }
  if (state.skin.pending_peel && currentDepthMap(state)) peelTo(state, *state.skin.pending_peel);

  const VoxelGrid& grid = state.model;
  if (state.surface_stats.wants(state.model_version)) {
    state.surface_stats.request(state.model_version, "Counting surface voxels",
                                [grid](const ProgressFn&) { return Result<SurfaceStats>(computeSurfaceStats(grid)); });
  }
  if (state.panel == Panel::kMass && state.mass.wants(state.model_version)) {
    state.mass.request(state.model_version, "Mass properties",
                       [grid](const ProgressFn&) { return Result<MassProperties>(computeMassProperties(grid)); });
  }
  const XrayKey xray_key{state.model_version, state.xray.params.axis, state.xray.params.mode};
  if (state.panel == Panel::kXray && state.xray_result.wants(xray_key)) {
    const XrayKey& key = xray_key;
    const XrayParams params = state.xray.params;
    state.xray_result.request(key, "X-ray", [grid, params](const ProgressFn&) {
      auto x = computeXray(grid, params);
      if (!x) return Result<std::shared_ptr<const XrayResult>>(x.error());
      return Result<std::shared_ptr<const XrayResult>>(std::make_shared<const XrayResult>(std::move(x).value()));
    });
  }
}

const XrayResult* currentXray(const AppState& state) {
  const XrayKey key{state.model_version, state.xray.params.axis, state.xray.params.mode};
  const auto* x = state.xray_result.get(key);
  return x ? x->get() : nullptr;
}

void zoomSection(AppState& state, double zoom, glm::dvec2 uv) {
  const int32_t w = std::max(axisLength(state, imageRightAxis(state.section.axis)), 1);
  const int32_t h = std::max(axisLength(state, imageUpAxis(state.section.axis)), 1);
  const double half = 0.5 / zoom;  // the picture shown: [centre - half, centre + half] on each axis, within [0, 1]
  state.section.zoom = zoom;
  state.section.centre =
      glm::clamp(glm::dvec2((uv.x + 0.5) / w, (uv.y + 0.5) / h), glm::dvec2(half), glm::dvec2(1.0 - half));
}

int32_t axisLength(const AppState& state, Axis axis) {
  if (state.model.empty()) return 0;
  switch (axis) {
    case Axis::kX:
      return state.model.nx();
    case Axis::kY:
      return state.model.ny();
    case Axis::kZ:
      return state.model.nz();
  }
  return 0;
}

void centreView(AppState& state, glm::dvec3 centre, double extent) {
  render::Camera& c = state.view.camera;
  c.target = centre;
  double d = std::min(c.distance, std::max(40.0, 6.0 * extent));
  // A target inside the material (the middle of a thin wall deep in the part) would put the eye inside the surface,
  // close up: the eye stays outside the model's box, looking at the target from where it looked before.
  const render::Box3 box =
      state.model_bounds
          ? *state.model_bounds
          : render::Box3{glm::dvec3(0.0), glm::dvec3(state.model.nx(), state.model.ny(), state.model.nz())};
  const glm::dvec3 dir = c.eyeDirection();
  double exit = 0.0;  // how far from the target along dir the box ends
  bool bounded = false;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(dir[a]) < 1e-12) continue;
    const double t = ((dir[a] > 0.0 ? box.max[a] : box.min[a]) - centre[a]) / dir[a];
    exit = bounded ? std::min(exit, t) : t;
    bounded = true;
  }
  if (bounded) d = std::max(d, exit + 2.0);
  c.distance = d;
  state.view.fit_pending = false;
}

}  // namespace vox::app
