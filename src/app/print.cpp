#include "app/print.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include <glm/geometric.hpp>

#include "app/document.h"
#include "app/thickness.h"  // rayMesh

namespace vox::app {

PrintKey wantedPrintKey(const AppState& state) {
  return PrintKey{state.model_version, state.print_ui.up, state.print_ui.overhang_angle, state.print_ui.orient};
}

void requestPrint(AppState& state) {
  state.print.poll();
  const PrintKey key = wantedPrintKey(state);
  if (state.panel != Panel::kPrint || state.model.empty() || state.print.get(key)) return;
  if (state.print_ui.was_cancelled && state.print_ui.cancelled == key) return;
  if (!state.print.wants(key)) return;
  VoxelGrid grid = state.model;
  const uint64_t id = takeId(state);
  const std::shared_ptr<const MeshSource> mesh = rayMesh(state);
  state.print.request(key, "Checking printability", [grid, id, mesh, key](const ProgressFn& progress) {
    using R = Result<std::shared_ptr<const PrintResult>>;
    // The bar's share of each stage: the surface 0..10%, support 10..50%, cavities 50..60% and directions 60..100%
    // when searched (else support 10..80%, cavities 80..100%).
    const workflow::PrintProgress bar = [&progress, &key](workflow::PrintStage stage, double f) {
      const double from[] = {0.0, 0.1, key.orient ? 0.5 : 0.8, 0.6},
                   to[] = {0.1, key.orient ? 0.5 : 0.8, key.orient ? 0.6 : 1.0, 1.0};
      const int i = int(stage);
      return !progress || progress(from[i] + (to[i] - from[i]) * f);
    };
    workflow::PrintCheckOptions options;
    options.params.up = key.up;
    options.params.overhang_angle_deg = key.overhang_angle;
    options.params.fields = true;
    options.orient_directions = key.orient ? 100 : 0;
    if (mesh) options.mesh = &mesh->mesh;
    auto check = workflow::runPrintCheck(grid, options, bar);
    if (!check) return R(check.error());
    auto out = std::make_shared<PrintResult>();
    out->id = id;
    out->key = key;
    out->check = std::move(check).value();
    out->seconds = out->check.surface_s + out->check.support_s + out->check.cavities_s + out->check.orient_s;
    return R(std::shared_ptr<const PrintResult>(std::move(out)));
  });
}

const PrintResult* currentPrint(const AppState& state) {
  const auto* r = state.print.get(wantedPrintKey(state));
  return r ? r->get() : nullptr;
}

bool printComputing(const AppState& state) { return state.print.computing(wantedPrintKey(state)); }

bool printCancelled(const AppState& state) {
  return state.print_ui.was_cancelled && state.print_ui.cancelled == wantedPrintKey(state);
}

void cancelPrint(AppState& state) {
  if (!printComputing(state)) return;
  state.print.clear();
  state.print_ui.cancelled = wantedPrintKey(state);
  state.print_ui.was_cancelled = true;
}

void retryPrint(AppState& state) { state.print_ui.was_cancelled = false; }

Status setPrintDirection(AppState& state, const std::string& text) {
  auto up = parsePrintDirection(text);
  if (!up) return up.error();
  state.print_ui.up = *up;
  return Ok{};
}

Status layFaceOnPlate(AppState& state, glm::ivec3 voxel) {
  const VoxelGrid& g = state.model;
  if (!g.inBounds(voxel.x, voxel.y, voxel.z) || !g.get(voxel.x, voxel.y, voxel.z)) {
    return makeError(ErrorCode::kInvalidArgument, "lay-face: no part at that voxel");
  }
  // the outward normal: away from the filled voxels about it
  glm::dvec3 inward(0.0);
  for (int z = -2; z <= 2; ++z)
    for (int y = -2; y <= 2; ++y)
      for (int x = -2; x <= 2; ++x) {
        const glm::ivec3 q = voxel + glm::ivec3(x, y, z);
        if (g.inBounds(q.x, q.y, q.z) && g.get(q.x, q.y, q.z)) inward += glm::dvec3(x, y, z);
      }
  if (glm::length(inward) < 1e-9) {
    return makeError(ErrorCode::kInvalidArgument, "lay-face: that voxel has no face to lay on the plate");
  }
  glm::dvec3 down_face =
      glm::normalize(inward);  // the face's outward normal is -inward; laid on the plate, up = inward
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(down_face[axis]) > std::cos(10.0 * 3.14159265358979 / 180.0)) {
      down_face = glm::dvec3(0.0);
      down_face[axis] = inward[axis] > 0 ? 1.0 : -1.0;
    }
  }
  state.print_ui.up = down_face;
  state.print_ui.lay_face = false;
  return Ok{};
}

const TrappedCavity* selectedCavity(const AppState& state) {
  const PrintResult* r = currentPrint(state);
  const PrintUi& ui = state.print_ui;
  if (!r || ui.selected_result != r->id || ui.selected_cavity < 0 ||
      size_t(ui.selected_cavity) >= r->check.cavities.size())
    return nullptr;
  return &r->check.cavities[size_t(ui.selected_cavity)];
}

}  // namespace vox::app
