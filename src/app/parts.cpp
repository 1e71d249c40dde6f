#include "app/parts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>

#include <glm/common.hpp>

#include "app/document.h"
#include "app/parts_detail.h"
#include "app/messages.h"
#include "app/model_jobs.h"
#include "app/thickness.h"
#include "app/update.h"
#include "vox/core/grid_placement.h"
#include "vox/core/text.h"
#include "vox/core/units.h"
#include "vox/workflow/parts_input.h"

namespace vox::app {
namespace {

using PartsResult = Result<std::shared_ptr<const Assembly>>;

Error partsError(std::string message) { return makeError(ErrorCode::kInvalidArgument, std::move(message)); }

// The union of `after`'s parts, where only part i was placed differently from `before`, whose union is `before_union`
// (the model's base): made again only over part i's old and new boxes (redoUnionIn), the rest of the union kept.
// The whole union when `before_union` is not on `before`'s extent.
VoxelGrid unionAfterPlacing(const Assembly& before, const Assembly& after, size_t i, const VoxelGrid& before_union) {
  const Box3i old_extent = before.extent(), extent = after.extent();
  if (Dims{old_extent.size().x, old_extent.size().y, old_extent.size().z} != before_union.dims()) {
    return partsUnion(after);
  }
  const Lattice& lattice = after.lattice();
  const std::vector<LatticeGrid> placed = after.placedParts();
  LatticeGrid u{before_union, old_extent.min};
  if (extent != old_extent) u = reframe(u, extent, lattice);
  redoUnionIn(u, placed, before.placedVoxels(i).box());
  redoUnionIn(u, placed, placed[i].box());
  u.grid.frame() = lattice.frameAt(extent.min);
  return std::move(u.grid);
}

// A change of how the parts are shown (colour, visibility) as an undo step of its own: the state before it goes on the
// undo stack (a cheap copy: the grids share their layers) and the current state takes the new parts. The model version
// stays: the voxels are the same, so nothing derived from them (the renderers' points, the interference, the mass) is
// found again, and the document is not unsaved by it (a .vxm file holds voxels only). `merge`: the change is part of
// the current step (a colour drag), so nothing is pushed.
void commitLook(AppState& state, std::shared_ptr<const Assembly> parts, std::string label, bool merge) {
  Document& doc = state.doc;
  if (!merge) {
    doc.undo_stack.push_back(*doc.model);
    doc.redo_stack.clear();
  }
  doc.model->parts = std::move(parts);
  doc.model->label = std::move(label);
  state.viewport.dirty = true;
}

PartsResult shared(Result<Assembly> scene) {
  if (!scene) return scene.error();
  return std::shared_ptr<const Assembly>(std::make_shared<Assembly>(std::move(scene).value()));
}

void startPartsJob(AppState& state, const std::string& label, std::string undo_label,
                   Job<std::shared_ptr<const Assembly>>::Work work) {
  state.parts_job_label = std::move(undo_label);
  state.job_started = nowSeconds();
  state.parts_job.start(label, std::move(work));
}

}  // namespace

// A new model state holding `parts`: the union as the model (found here when not given), a new base (the skin layers
// of the union).
void commitParts(AppState& state, std::shared_ptr<const Assembly> parts, const std::string& label,
                 std::optional<VoxelGrid> union_of_parts) {
  auto origin = std::make_shared<ModelOrigin>();
  const ModelOrigin* prev = state.doc.model ? state.doc.model->origin.get() : nullptr;
  origin->what = std::to_string(parts->size()) + (parts->size() == 1 ? " part" : " parts") + " on one lattice";
  origin->resolution = prev ? prev->resolution : 0;
  VoxelGrid grid = union_of_parts ? std::move(*union_of_parts) : partsUnion(*parts);
  ModelSnapshot snap = newBase(state, std::move(grid), std::move(origin), label);
  snap.parts = std::move(parts);
  state.parts_ui.selected.clear();
  setModel(state, std::move(snap), true);
}

// Refuses, before anything is allocated, a scene whose box would not fit a grid or whose union would take more than
// half the memory a large piece of work may plan for (the union is made next to the one before it).
Status checkSceneSize(const Assembly& scene, const std::string& what) {
  const glm::ivec3 n = scene.extent().size();
  const std::string box = std::to_string(n.x) + " x " + std::to_string(n.y) + " x " + std::to_string(n.z);
  if (n.x > VoxelGrid::kMaxDim || n.y > VoxelGrid::kMaxDim || n.z > VoxelGrid::kMaxDim) {
    return makeError(ErrorCode::kLimit, what + " would make the parts' box " + box + " voxels; a grid holds at most " +
                                            std::to_string(VoxelGrid::kMaxDim) +
                                            " along each axis. Nothing was changed");
  }
  const uint64_t row_bytes = (uint64_t(n.x) + 2 + 63) / 64 * 8;
  const uint64_t bytes = row_bytes * (uint64_t(n.y) + 2) * (uint64_t(n.z) + 2);
  const uint64_t limit = defaultMemoryLimitBytes() / 2;
  if (bytes > limit) {
    return makeError(ErrorCode::kLimit, what + " would make the parts' box " + box +
                                            " voxels, whose grid needs up to " + formatBytes(bytes) +
                                            ", more than the " + formatBytes(limit) +
                                            " this machine can give it. Nothing was changed");
  }
  return Ok{};
}

// The current model as an assembly of one part (a document that is not a scene yet), or the current parts.
Assembly sceneOfModel(const AppState& state) {
  if (const Assembly* a = currentParts(state)) return *a;
  Assembly scene;
  if (!state.doc.model) return scene;
  const VoxelGrid& g = state.doc.model->grid;
  std::string name = state.doc.path.empty() ? "model" : state.doc.path.filename().string();
  (void)scene.addGrid(g, name);  // the first grid sets the lattice: cannot fail
  return scene;
}

const Assembly* currentParts(const AppState& state) {
  return state.doc.model && state.doc.model->parts ? state.doc.model->parts.get() : nullptr;
}

bool partsBusy(const AppState& state) { return state.parts_job.active(); }

void startSplitBodies(AppState& state) {
  if (!state.doc.model || currentParts(state)) return;
  const VoxelGrid model = state.doc.model->base;
  if (state.doc.mesh) {
    auto mesh = state.doc.mesh;
    VoxelizeParams params = state.voxelize_job_params;
    startPartsJob(
        state, "Splitting into bodies", "split into bodies", [mesh, params, model](const ProgressFn& progress) {
          return shared(
              workflow::splitMeshIntoBodies(mesh->mesh, mesh->bodies, mesh->cad != nullptr, params, model, progress));
        });
  } else {
    const Connectivity c = state.parts_ui.connectivity;
    startPartsJob(state, "Finding connected components", "split into components",
                  [model, c](const ProgressFn&) { return shared(workflow::splitIntoComponents(model, c)); });
  }
}

void startAddPart(AppState& state, const std::filesystem::path& path) {
  Assembly scene = sceneOfModel(state);
  VoxelizeParams params = state.voxelize_job_params;
  startPartsJob(state, "Adding " + path.filename().string(), "add part " + path.filename().string(),
                [scene = std::move(scene), path, params](const ProgressFn& progress) {
                  return shared(workflow::addFileAsPart(scene, path, params, progress));
                });
}

Status partBoolean(AppState& state, PartOp op, size_t a, size_t b) {
  const Assembly* parts = currentParts(state);
  if (!parts) return partsError("there are no parts: split the model into bodies or add a part first");
  if (a >= parts->size() || b >= parts->size()) {
    return partsError("part numbers go from 1 to " + std::to_string(parts->size()));
  }
  if (a == b) return partsError("a Boolean needs two different parts");
  auto scene = std::make_shared<Assembly>(*parts);
  LatticeGrid r = booleanParts(scene->placedVoxels(a), scene->placedVoxels(b), op, scene->lattice());
  const Box3i box = filledBox(r);
  if (!box.empty()) r = reframe(r, box, scene->lattice());
  const std::string name = scene->part(a).name + " " + partOpName(op) + " " + scene->part(b).name;
  const size_t k = scene->addPart(std::move(r), name);
  scene->part(k).colour = partColour(k);
  commitParts(state, std::move(scene), partOpName(op) + std::string(" of two parts"));
  state.parts_ui.selected = {k};
  return Ok{};
}

Status removePart(AppState& state, size_t i) {
  const Assembly* parts = currentParts(state);
  if (!parts) return partsError("there are no parts to remove");
  if (i >= parts->size()) return partsError("part numbers go from 1 to " + std::to_string(parts->size()));
  if (parts->size() == 1) return partsError("the last part stays (close the document instead)");
  auto scene = std::make_shared<Assembly>(*parts);
  const std::string name = scene->part(i).name;
  scene->removePart(i);
  commitParts(state, std::move(scene), "remove " + name);
  return Ok{};
}

Status placePart(AppState& state, size_t i, const PartPlacement& placement) {
  const Assembly* parts = currentParts(state);
  if (!parts) return partsError("there are no parts to move: split the model into bodies or add a part first");
  if (i >= parts->size()) return partsError("part numbers go from 1 to " + std::to_string(parts->size()));
  PartPlacement p = placement;
  p.quarter_turns &= 3;  // turns are taken modulo 4: the same placement, one way of writing it
  if (parts->part(i).placement == p) return Ok{};
  const bool turned = p.quarter_turns != parts->part(i).placement.quarter_turns;
  if (turned && parts->part(i).feeder) {
    return partsError(parts->part(i).name +
                      " is a feeder: it stands upright on the part, so it is moved, never turned");
  }
  auto scene = std::make_shared<Assembly>(*parts);
  scene->setPlacement(i, p);
  const std::string label = (turned ? "turn " : "move ") + scene->part(i).name;
  if (Status s = checkSceneSize(*scene, (turned ? "Turning " : "Moving ") + scene->part(i).name); !s) return s;
  const std::vector<size_t> selected = state.parts_ui.selected;
  VoxelGrid union_of_parts = unionAfterPlacing(*parts, *scene, i, state.doc.model->base);
  commitParts(state, std::move(scene), label, std::move(union_of_parts));
  state.parts_ui.selected = selected;
  applyPartsScope(state);
  return Ok{};
}

Status checkTranslation(const AppState& state, double model_units) {
  const Assembly* parts = currentParts(state);
  if (!parts) return Ok{};
  const double voxels = model_units / parts->lattice().voxel_size;
  if (!std::isfinite(voxels) || std::abs(voxels) > double(VoxelGrid::kMaxDim)) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", model_units);
    return makeError(ErrorCode::kLimit, std::string("A move of ") + buf + " " + unitsLabel(parts->lattice().units) +
                                            " is more than the " + std::to_string(VoxelGrid::kMaxDim) +
                                            " voxels a grid holds along an axis. Nothing was moved");
  }
  return Ok{};
}

PartPlacement placementWithTranslation(const AppState& state, size_t i, const glm::dvec3& model_units) {
  const Assembly& parts = *currentParts(state);
  PartPlacement p = parts.part(i).placement;
  p.translation = parts.snapTranslation(model_units);
  return p;
}

PartPlacement placementTurned(const AppState& state, size_t i, int axis) {
  PartPlacement p = currentParts(state)->part(i).placement;
  p.quarter_turns[axis] = (p.quarter_turns[axis] + 1) & 3;
  return p;
}

void setPartColour(AppState& state, size_t i, const glm::vec3& colour, bool drag) {
  const Assembly* parts = currentParts(state);
  const glm::vec3 c = glm::clamp(colour, glm::vec3(0.0f), glm::vec3(1.0f));
  if (!parts || i >= parts->size() || parts->part(i).colour == c) return;
  PartsUi& ui = state.parts_ui;
  // A drag goes on in the step its first change made, as long as that step is still the current state.
  const bool merge = drag && ui.colour_step_part == i && ui.colour_step == state.doc.model->parts;
  auto scene = std::make_shared<Assembly>(*parts);
  scene->part(i).colour = c;
  commitLook(state, std::move(scene), "colour of " + parts->part(i).name, merge);
  ui.colour_step = state.doc.model->parts;
  ui.colour_step_part = i;
}

void setPartVisible(AppState& state, size_t i, bool visible) {
  const Assembly* parts = currentParts(state);
  if (!parts || i >= parts->size() || parts->part(i).visible == visible) return;
  auto scene = std::make_shared<Assembly>(*parts);
  scene->part(i).visible = visible;
  commitLook(state, std::move(scene), (visible ? "show " : "hide ") + parts->part(i).name, false);
}

void selectPart(AppState& state, size_t i, bool additive) {
  std::vector<size_t>& sel = state.parts_ui.selected;
  if (!additive) {
    sel = {i};
  } else if (auto it = std::find(sel.begin(), sel.end(), i); it != sel.end()) {
    sel.erase(it);
  } else {
    sel.push_back(i);
  }
  state.viewport.dirty = true;
  if (state.parts_ui.scope_selected) applyPartsScope(state);
  // An interference pair stays shown only while its two parts are the selection.
  if (const Interference* inter = currentInterference(state); inter && state.parts_ui.pair >= 0) {
    const InterferencePair& p = inter->pairs.at(size_t(state.parts_ui.pair));
    const std::vector<size_t> pair{size_t(p.a), size_t(p.b)}, swapped{size_t(p.b), size_t(p.a)};
    if (sel != pair && sel != swapped) showInterferencePair(state, -1);
  }
}

void setPartsScope(AppState& state, bool selected) {
  state.parts_ui.scope_selected = selected;
  applyPartsScope(state);
}

void applyPartsScope(AppState& state) {
  if (!state.doc.model) return;
  const Assembly* parts = currentParts(state);
  PartsUi& ui = state.parts_ui;
  if (parts) std::erase_if(ui.selected, [&](size_t i) { return i >= parts->size(); });
  if (ui.interference_version != state.doc.model->version) {
    ui.pair = -1;
    ui.pair_key = 0;
    ui.pair_overlap = VoxelGrid{};
  }
  if (parts && ui.scope_selected && !ui.selected.empty()) {
    state.model = partOnExtent(*parts, ui.selected.front());
    state.model_version = takeId(state);
  } else {
    state.model = state.doc.model->grid;
    state.model_version = state.doc.model->version;
  }
  adoptThickness(state);  // the same voxels under another version keep their thickness
  state.viewport.dirty = true;
}

void updateParts(AppState& state) {
  if (auto r = state.parts_job.take()) {
    if (r->ok()) {
      commitParts(state, std::move(*r).value(), state.parts_job_label);
      state.panel = Panel::kParts;
      state.panel_change_requested = true;
    } else if (r->error().code != ErrorCode::kCancelled) {
      reportError(state, r->error().message, state.doc.path);
    }
  }
  if (auto r = state.interference_job.take()) {
    if (!r->ok()) {
      if (r->error().code != ErrorCode::kCancelled) reportError(state, r->error().message);
    } else if (state.doc.model && state.interference_job_version == state.doc.model->version) {
      state.parts_ui.interference = std::move(*r).value();
      state.parts_ui.interference_version = state.interference_job_version;
      state.parts_ui.interference_s = nowSeconds() - state.job_started;
      state.parts_ui.pair = -1;
    }
  }
  updateClearance(state);
}

const std::vector<int64_t>& partVoxelCounts(AppState& state) {
  PartsUi& ui = state.parts_ui;
  const Assembly* parts = currentParts(state);
  const uint64_t version = parts ? state.doc.model->version : 0;
  if (ui.counts_version != version) {
    ui.voxel_counts.clear();
    if (parts) {
      for (const Part& p : parts->parts()) ui.voxel_counts.push_back(p.voxels.grid.filledCount());
    }
    ui.counts_version = version;
  }
  return ui.voxel_counts;
}

VoxelGrid partsUnion(const Assembly& parts) {
  return unionOfParts(parts.placedParts(), parts.extent(), parts.lattice()).grid;
}

VoxelGrid partOnExtent(const Assembly& parts, size_t i) {
  LatticeGrid g = reframe(parts.placedVoxels(i), parts.extent(), parts.lattice());
  g.grid.frame() = parts.lattice().frameAt(parts.extent().min);
  return std::move(g.grid);
}

}  // namespace vox::app
