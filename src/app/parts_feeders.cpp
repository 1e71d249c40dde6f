// The Casting panel's feeders as parts of the scene (parts.h, "Feeders"): placing one adds its cylinder's voxels as a
// part, so the Parts panel moves and removes it and Undo takes it back; the casting's run takes the parts that are
// not feeders as the metal to cast and the feeder parts, placed, as its feeders.
#include <algorithm>
#include <cstdlib>
#include <memory>
#include <string>
#include <utility>

#include "app/parts.h"
#include "app/parts_detail.h"
#include "vox/analysis/assembly.h"

namespace vox::app {
namespace {

const glm::vec3 kFeederPartColour{1.0f, 0.72f, 0.25f};

}  // namespace

Status addFeederPart(AppState& state, const Feeder& feeder) {
  if (!state.doc.model) return makeError(ErrorCode::kInvalidArgument, "there is no part to stand a feeder on");
  auto scene = std::make_shared<Assembly>(sceneOfModel(state));
  auto voxels = feederVoxels(feeder, scene->lattice());
  if (!voxels) return makeError(voxels.error().code, voxels.error().message + ". Nothing was placed");
  int next = 1;  // one past the highest number a feeder has (a feeder deleted leaves its number unused)
  for (const Part& p : scene->parts())
    if (p.feeder && p.name.rfind("feeder ", 0) == 0) next = std::max(next, std::atoi(p.name.c_str() + 7) + 1);
  const std::string name = "feeder " + std::to_string(next);
  const size_t k = scene->addPart(std::move(voxels).value(), name);
  scene->part(k).colour = kFeederPartColour;
  scene->part(k).feeder = feeder;
  if (Status s = checkSceneSize(*scene, "Placing " + name); !s) return s;
  commitParts(state, std::move(scene), "place " + name);
  return Ok{};
}

std::vector<size_t> feederParts(const AppState& state) {
  std::vector<size_t> out;
  if (const Assembly* parts = currentParts(state)) {
    for (size_t i = 0; i < parts->size(); ++i)
      if (parts->part(i).feeder) out.push_back(i);
  }
  return out;
}

std::vector<Feeder> placedFeeders(const AppState& state) {
  std::vector<Feeder> out;
  if (const Assembly* parts = currentParts(state)) {
    for (size_t i = 0; i < parts->size(); ++i)
      if (auto f = parts->placedFeeder(i)) out.push_back(*f);
  }
  return out;
}

VoxelGrid castPart(const Assembly& parts, size_t only) {
  std::vector<LatticeGrid> metal;
  for (size_t i = 0; i < parts.size(); ++i) {
    if (!parts.part(i).feeder && (only == SIZE_MAX || i == only)) metal.push_back(parts.placedVoxels(i));
  }
  LatticeGrid u = unionOfParts(metal, parts.extent(), parts.lattice());
  u.grid.frame() = parts.lattice().frameAt(parts.extent().min);
  return std::move(u.grid);
}

}  // namespace vox::app
