// Parts on one lattice: adding, placing, quarter turns.
#include "vox/core/assembly.h"

#include <array>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

namespace vox {

bool PartPlacement::identity() const {
  return translation == glm::ivec3(0) && (quarter_turns.x & 3) == 0 && (quarter_turns.y & 3) == 0 &&
         (quarter_turns.z & 3) == 0;
}

glm::vec3 partColour(size_t i) {
  static constexpr std::array<glm::vec3, 12> kPalette = {
      glm::vec3(0.90f, 0.40f, 0.30f), glm::vec3(0.30f, 0.60f, 0.90f), glm::vec3(0.40f, 0.80f, 0.40f),
      glm::vec3(0.95f, 0.75f, 0.25f), glm::vec3(0.70f, 0.45f, 0.85f), glm::vec3(0.30f, 0.80f, 0.80f),
      glm::vec3(0.90f, 0.50f, 0.70f), glm::vec3(0.60f, 0.60f, 0.30f), glm::vec3(0.50f, 0.70f, 0.95f),
      glm::vec3(0.85f, 0.60f, 0.40f), glm::vec3(0.55f, 0.85f, 0.60f), glm::vec3(0.75f, 0.75f, 0.75f)};
  const float shade = 1.0f - 0.15f * float((i / kPalette.size()) % 3);
  return kPalette[i % kPalette.size()] * shade;
}

namespace {

// One +90 degree turn about `axis` (0 = X, 1 = Y, 2 = Z) of voxel p in a box of size n: about Z (x, y) -> (-y, x),
// about X (y, z) -> (-z, y), about Y (z, x) -> (-x, z), shifted back into [0, n').
glm::ivec3 turnVoxel(const glm::ivec3& p, const glm::ivec3& n, int axis) {
  switch (axis) {
    case 0:
      return {p.x, n.z - 1 - p.z, p.y};
    case 1:
      return {p.z, p.y, n.x - 1 - p.x};
    default:
      return {n.y - 1 - p.y, p.x, p.z};
  }
}

glm::ivec3 turnSize(const glm::ivec3& n, int axis) {
  switch (axis) {
    case 0:
      return {n.x, n.z, n.y};
    case 1:
      return {n.z, n.y, n.x};
    default:
      return {n.y, n.x, n.z};
  }
}

LatticeGrid turnOnce(const LatticeGrid& g, int axis, const Lattice& lattice) {
  const glm::ivec3 n(g.grid.nx(), g.grid.ny(), g.grid.nz());
  const glm::ivec3 m = turnSize(n, axis);
  LatticeGrid out;
  out.first = g.first + (n - m) / 2;  // keeps the box's centre (to half a voxel)
  out.grid = VoxelGrid(Dims{m.x, m.y, m.z}, lattice.frameAt(out.first, g.grid.frame().source));
  const int64_t wpr = g.grid.wordsPerRow();
  for (int32_t z = 0; z < n.z; ++z) {
    if (!g.grid.layerAllocated(z)) continue;
    for (int32_t y = 0; y < n.y; ++y) {
      const uint64_t* row = g.grid.rowWords(y, z);
      for (int64_t w = 0; w < wpr; ++w) {
        for (uint64_t v = row[w]; v != 0; v &= v - 1) {
          const int32_t x = int32_t(w * 64 + std::countr_zero(v) - 1);
          const glm::ivec3 q = turnVoxel(glm::ivec3(x, y, z), n, axis);
          out.grid.set(q.x, q.y, q.z);
        }
      }
    }
  }
  return out;
}

}  // namespace

LatticeGrid turnQuarter(const LatticeGrid& g, const glm::ivec3& quarter_turns, const Lattice& lattice) {
  LatticeGrid out = g;
  for (int axis = 0; axis < 3; ++axis) {
    for (int k = 0; k < (quarter_turns[axis] & 3); ++k) out = turnOnce(out, axis, lattice);
  }
  return out;
}

Result<size_t> Assembly::addGrid(VoxelGrid grid, const std::string& name) {
  glm::ivec3 first(0);
  if (!has_lattice_) {
    lattice_ = latticeOf(grid.frame());
    has_lattice_ = true;
  } else {
    GridFrame lattice_frame = lattice_.frameAt(glm::ivec3(0));
    if (Status s = checkSharedLattice(lattice_frame, grid.frame(), &first); !s) {
      return makeError(ErrorCode::kInvalidArgument, name + " is not on the assembly's lattice: " + s.error().message);
    }
  }
  grid.frame() = lattice_.frameAt(first, grid.frame().source);
  return addPart(LatticeGrid{std::move(grid), first}, name);
}

size_t Assembly::addPart(LatticeGrid voxels, const std::string& name) {
  Part p;
  p.name = name;
  p.colour = partColour(parts_.size());
  p.voxels = std::move(voxels);
  parts_.push_back(std::move(p));
  return parts_.size() - 1;
}

void Assembly::removePart(size_t i) {
  if (i >= parts_.size()) throw std::out_of_range("Assembly::removePart: no part " + std::to_string(i));
  parts_.erase(parts_.begin() + std::ptrdiff_t(i));
}

glm::ivec3 Assembly::snapTranslation(const glm::dvec3& d) const {
  const glm::dvec3 v = d / lattice_.voxel_size;
  return glm::ivec3(int32_t(std::lround(v.x)), int32_t(std::lround(v.y)), int32_t(std::lround(v.z)));
}

std::optional<Feeder> Assembly::placedFeeder(size_t i) const {
  const Part& p = parts_.at(i);
  if (!p.feeder) return std::nullopt;
  Feeder f = *p.feeder;
  f.base += glm::dvec3(p.placement.translation) * lattice_.voxel_size;
  return f;
}

LatticeGrid Assembly::placedVoxels(size_t i) const {
  const Part& p = parts_.at(i);
  LatticeGrid g = turnQuarter(p.voxels, p.placement.quarter_turns, lattice_);
  g.first += p.placement.translation;
  g.grid.frame() = lattice_.frameAt(g.first, g.grid.frame().source);
  return g;
}

std::vector<LatticeGrid> Assembly::placedParts() const {
  std::vector<LatticeGrid> out;
  out.reserve(parts_.size());
  for (size_t i = 0; i < parts_.size(); ++i) out.push_back(placedVoxels(i));
  return out;
}

Box3i Assembly::extent() const {
  Box3i box;
  for (size_t i = 0; i < parts_.size(); ++i) {
    const Part& p = parts_[i];
    glm::ivec3 first = p.voxels.first, n = p.voxels.box().size();
    for (int axis = 0; axis < 3; ++axis) {
      for (int k = 0; k < (p.placement.quarter_turns[axis] & 3); ++k) {
        const glm::ivec3 m = turnSize(n, axis);
        first += (n - m) / 2;  // as turnOnce places it
        n = m;
      }
    }
    first += p.placement.translation;
    box = unite(box, Box3i{first, first + n});
  }
  return box;
}

}  // namespace vox
