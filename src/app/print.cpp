#include "app/print.h"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <memory>
#include <utility>

#include <glm/geometric.hpp>

#include "app/document.h"
#include "app/thickness.h"  // rayMesh

namespace vox::app {
namespace {

// The box of a grid's filled voxels, or false when it has none.
bool filledBox(const VoxelGrid& g, glm::ivec3& lo, glm::ivec3& hi) {
  lo = glm::ivec3(INT32_MAX);
  hi = glm::ivec3(-1);
  for (int32_t z = 0; z < g.nz(); ++z) {
    if (!g.layerAllocated(z)) continue;
    for (int32_t y = 0; y < g.ny(); ++y) {
      const uint64_t* row = g.rowWords(y, z);
      for (int64_t w = 0; w < g.wordsPerRow(); ++w) {
        if (!row[w]) continue;
        const auto x0 = int32_t(w * 64 + std::countr_zero(row[w])) - 1;
        const auto x1 = int32_t(w * 64 + 63 - std::countl_zero(row[w])) - 1;
        lo = glm::min(lo, glm::ivec3(x0, y, z));
        hi = glm::max(hi, glm::ivec3(x1, y, z));
      }
    }
  }
  return hi.x >= 0;
}

// The overhangs as bytes over their box, for the 3D view's red (at most 512 M voxels of box: a byte each).
void overhangVolume(PrintResult& r) {
  if (!r.check.support.overhang) return;
  const VoxelGrid& overhang = *r.check.support.overhang;
  glm::ivec3 lo, hi;
  if (!filledBox(overhang, lo, hi)) return;
  const glm::ivec3 size = hi - lo + 1;
  const Dims dims{size.x, size.y, size.z};
  if (dims.count() > (int64_t(1) << 29)) {
    r.overhang_problem = "The overhangs are not shown in red: their box is too large to colour.";
    return;
  }
  r.overhang_min = lo;
  r.overhang_dims = dims;
  r.overhang_values.assign(size_t(dims.count()), 0);
  size_t i = 0;
  for (int32_t z = lo.z; z <= hi.z; ++z)
    for (int32_t y = lo.y; y <= hi.y; ++y)
      for (int32_t x = lo.x; x <= hi.x; ++x, ++i)
        if (overhang.get(x, y, z)) r.overhang_values[i] = 1;
}

// The build directions searched for this model and angle before, whatever the direction then: applying one of them
// does not search again.
std::vector<PrintSupport> knownOrientations(const AppState& state, const PrintKey& key) {
  const auto* held = state.print.held();
  if (!key.orient || !held || !*held) return {};
  const PrintKey& k = (*held)->key;
  if (k.model_version != key.model_version || k.overhang_angle != key.overhang_angle) return {};
  return (*held)->check.orientations;
}

}  // namespace

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
  std::vector<PrintSupport> known = knownOrientations(state, key);
  state.print.request(key, "Checking printability", [grid, id, mesh, key, known](const ProgressFn& progress) {
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
    options.orient_directions = key.orient && known.empty() ? 100 : 0;
    if (mesh) options.mesh = &mesh->mesh;
    auto check = workflow::runPrintCheck(grid, options, bar);
    if (!check) return R(check.error());
    auto out = std::make_shared<PrintResult>();
    out->id = id;
    out->key = key;
    out->check = std::move(check).value();
    if (key.orient && !known.empty()) out->check.orientations = known;
    overhangVolume(*out);
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
