#include "app/thickness.h"

#include <algorithm>
#include <memory>
#include <utility>

#include "app/document.h"
#include "app/ui.h"  // formatLength
#include "vox/analysis/distance.h"
#include "vox/workflow/thickness_run.h"
#include "vox/core/text.h"

namespace vox::app {

namespace {

// The same voxels in the same place and size (the units' name may differ: a result's lengths do not depend on it).
bool sameSolid(const VoxelGrid& a, const VoxelGrid& b) {
  return a.frame().origin == b.frame().origin && a.frame().voxel_size == b.frame().voxel_size && a.sameVoxels(b);
}

}  // namespace

void adoptThickness(AppState& state) {
  const uint64_t key = state.model_version;
  if (state.model.empty() || state.thickness.get(key)) return;
  if (const auto* held = state.thickness.held(); held && *held && sameSolid((*held)->grid, state.model)) {
    state.thickness.rekey(key);
  }
}

std::shared_ptr<const MeshSource> rayMesh(const AppState& state) {
  const auto& m = state.doc.model;
  if (!state.doc.mesh || !m || m->peeled > 0 || !m->round_peels.empty() || m->parts) return nullptr;
  return state.doc.mesh;
}

void requestThickness(AppState& state) {
  state.thickness.poll();
  const uint64_t key = state.model_version;
  if (state.thickness.get(key)) {
    // Back to a model whose result is here (undo): a computation still under way for the one left is not wanted,
    // and its end would replace this result.
    if (state.thickness.busy()) state.thickness.rekey(key);
    return;
  }
  if (state.panel != Panel::kThickness || state.model.empty()) return;
  if (state.thickness_ui.cancelled_version == key || !state.thickness.wants(key)) return;
  adoptThickness(state);  // a result that landed after the version changed (on another panel) may be this one's
  if (state.thickness.get(key)) return;
  VoxelGrid grid = state.model;
  const uint64_t id = takeId(state);
  state.thickness.request(key, "Computing thickness", [grid, id](const ProgressFn& progress) {
    using R = Result<std::shared_ptr<const ThicknessResult>>;
    // The bar's share of each stage, as their times go on real parts: distance 0..10%, hot spots 10..30%, wall
    // ridge 30..40%, thickness 40..100% (in the order of ThicknessStage; the rays are a job of their own).
    const workflow::StageProgress bar = [&progress](workflow::ThicknessStage stage, double f) {
      const double from[] = {0.0, 0.1, 0.4, 0.3, 1.0}, to[] = {0.1, 0.3, 1.0, 0.4, 1.0};
      const int i = int(stage);
      return !progress || progress(from[i] + (to[i] - from[i]) * f);
    };
    workflow::ThicknessRunOptions options;
    options.walls = WallRidgeParams{};
    auto run = workflow::runThickness(grid, options, bar);
    if (!run) return R(run.error());
    auto out = std::make_shared<ThicknessResult>();
    out->id = id;
    out->grid = grid;
    out->thickness = std::move(run->thickness);
    out->hot_spots = std::move(run->hot_spots);
    out->ridge = std::move(run->ridge).value();
    out->distance_max = run->distance_max;
    out->seconds = run->distance_s + run->hot_spots_s + run->walls_s + run->thickness_s;
    return R(std::shared_ptr<const ThicknessResult>(std::move(out)));
  });
}

const RayThicknessResult* shownRay(const AppState& state, const ThicknessResult& r) {
  if (!state.thickness_ui.ray) return nullptr;
  const auto* rays = state.rays.get(r.id);
  return rays && *rays ? rays->get() : nullptr;
}

double shownThickness(const AppState& state, const ThicknessResult& r, const glm::ivec3& v) {
  const RayThicknessResult* ray = shownRay(state, r);
  return ray ? double(ray->field.at(v.x, v.y, v.z)) : r.thickness.model(v.x, v.y, v.z);
}

void requestRays(AppState& state) {
  state.rays.poll();
  const ThicknessResult* r = currentThickness(state);
  if (!state.thickness_ui.ray || !r || state.panel != Panel::kThickness) return;
  if (state.thickness_ui.rays_cancelled == r->id || !state.rays.wants(r->id)) return;
  const std::shared_ptr<const MeshSource> mesh = rayMesh(state);
  if (!mesh) return;
  const VoxelGrid grid = r->grid;
  const double distance_max = r->distance_max;
  state.rays.request(r->id, "Casting rays", [mesh, grid, distance_max](const ProgressFn& progress) {
    using R = Result<std::shared_ptr<const RayThicknessResult>>;
    auto rays = workflow::runRayThickness(mesh->mesh, grid, distance_max, RayThicknessParams{}, progress);
    if (!rays) return R(rays.error());
    return R(std::shared_ptr<const RayThicknessResult>(std::make_shared<RayThicknessResult>(std::move(rays).value())));
  });
}

bool raysComputing(const AppState& state) { return state.rays.busy(); }

const Error* raysError(const AppState& state) {
  const ThicknessResult* r = currentThickness(state);
  return r ? state.rays.error(r->id) : nullptr;
}

void cancelRays(AppState& state) {
  if (!state.rays.busy()) return;
  const ThicknessResult* r = currentThickness(state);
  state.rays.clear();
  state.thickness_ui.rays_cancelled = r ? r->id : 0;
}

const ThicknessResult* currentThickness(const AppState& state) {
  const auto* r = state.thickness.get(state.model_version);
  return r ? r->get() : nullptr;
}

void cancelThickness(AppState& state) {
  if (!state.thickness.computing(state.model_version)) return;
  state.thickness.clear();
  state.thickness_ui.cancelled_version = state.model_version;
}

void retryThickness(AppState& state) { state.thickness_ui.cancelled_version = 0; }

double minWall(const AppState& state) {
  if (state.thickness_ui.min_wall >= 0.0) return state.thickness_ui.min_wall;
  const ThicknessResult* r = currentThickness(state);
  return r ? 0.25 * r->thickness.stats.max : 0.0;
}

const Walls* currentThinWalls(AppState& state) {
  state.thin_walls.poll();
  const auto* held = state.thickness.get(state.model_version);
  if (!held || !*held) return nullptr;
  const std::shared_ptr<const ThicknessResult> r = *held;
  ThicknessUi& ui = state.thickness_ui;
  const WallsKey key{r->id, minWall(state), ui.min_area};
  if (const auto* walls = state.thin_walls.get(key); walls && *walls) {
    if (!(ui.walls_shown == key)) {
      ui.selected_region = -1;  // its index was into the regions found before
      ui.walls_shown = key;
    }
    return walls->get();
  }
  // found in the background: at R = 1000 a large minimum wall paints for many seconds
  state.thin_walls.request(key, "Finding walls", [r, key](const ProgressFn& progress) {
    using R = Result<std::shared_ptr<const Walls>>;
    auto walls = findWalls(r->ridge, r->thickness.radius, WallParams{key.min_wall, key.min_area}, progress);
    if (!walls) return R(walls.error());
    return R(std::shared_ptr<const Walls>(std::make_shared<Walls>(std::move(walls).value())));
  });
  return nullptr;
}

const ThinWallRegion* selectedRegion(AppState& state) {
  const Walls* thin = currentThinWalls(state);
  const ThicknessResult* r = currentThickness(state);
  const ThicknessUi& ui = state.thickness_ui;
  if (!thin || !r || ui.selected_result != r->id || ui.selected_region < 0 ||
      size_t(ui.selected_region) >= thin->regions.size())
    return nullptr;
  return &thin->regions[size_t(ui.selected_region)];
}

const HotSpot* selectedHotSpot(const AppState& state) {
  const ThicknessResult* r = currentThickness(state);
  const ThicknessUi& ui = state.thickness_ui;
  if (!r || ui.selected_result != r->id || ui.selected_spot < 0 || size_t(ui.selected_spot) >= r->hot_spots.size())
    return nullptr;
  return &r->hot_spots[size_t(ui.selected_spot)];
}

Status peelDistance(AppState& state, double distance) {
  if (!state.doc.model) return makeError(ErrorCode::kInvalidArgument, "peel-distance: there is no model to peel");
  if (!(distance >= 0.0)) return makeError(ErrorCode::kInvalidArgument, "peel-distance takes a distance >= 0");
  const ModelSnapshot& cur = *state.doc.model;
  auto peeled = peelByDistance(cur.grid, distance);
  if (!peeled) return peeled.error();
  if (peeled->filledCount() == 0 && cur.grid.filledCount() > 0) {
    // Nothing would be left to look at: say how deep the part goes instead of emptying it.
    auto depth = computeDistance(cur.grid);
    const std::string deepest = depth ? formatLength(depth->maxModel(), cur.grid.frame().units) : std::string("?");
    return makeError(ErrorCode::kInvalidArgument, "peeling " + formatLength(distance, cur.grid.frame().units) +
                                                      " round would remove the whole model: its deepest voxel is " +
                                                      deepest + " from the outside");
  }
  // A new base: the layer peel (the depth map) then works on what the round peel left.
  const std::string d = formatLength(distance, cur.grid.frame().units);
  const std::string before = cur.peeled > 0 ? std::to_string(cur.peeled) + " layers + " : std::string();
  const std::string round_peels = cur.round_peels.empty() ? before + d : cur.round_peels + " + " + before + d;
  ModelSnapshot next = newBase(state, std::move(peeled).value(), cur.origin, "peel " + d + " round");
  next.round_peels = round_peels;
  setModel(state, std::move(next), true);
  return Ok{};
}

}  // namespace vox::app
