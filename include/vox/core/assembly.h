#pragma once
// An assembly: parts on one lattice (vox/core/lattice.h; docs/conventions.md, "Assemblies"). Each part
// has a name, a colour, a visibility, its voxels as added (a grid over a box of the lattice) and a placement: a
// translation in whole voxels and quarter turns about X, Y and Z, both of which keep every voxel on the lattice.
// Adding a part never touches the others: the assembly's extent is just the union of the parts' placed boxes.
// What the window's Parts panel edits; operations between parts are in vox/analysis/assembly.h.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "vox/core/feeder.h"
#include "vox/core/lattice.h"
#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"

namespace vox {

struct PartPlacement {
  glm::ivec3 translation{0};    // lattice voxels
  glm::ivec3 quarter_turns{0};  // turns of +90 degrees (right-handed) about X, then Y, then Z; taken modulo 4
  bool operator==(const PartPlacement&) const = default;
  bool identity() const;
};

struct Part {
  std::string name;
  glm::vec3 colour{0.8f, 0.8f, 0.8f};  // RGB in [0, 1]
  bool visible = true;
  LatticeGrid voxels;  // as added, before the placement
  PartPlacement placement;
  // A casting's feeder (the Casting panel places them as parts): the cylinder its voxels were made from, in model
  // units before the placement. A feeder is moved, never turned (it stands along +Z).
  std::optional<Feeder> feeder;
};

// A distinct colour for part `i` (a fixed palette, repeating with a small change of brightness after 12 parts).
glm::vec3 partColour(size_t i);

// The voxels of `g` turned by quarter turns about X, then Y, then Z, about the centre of its box (the turned box keeps
// its centre, rounded down to whole voxels where the sizes' parity differs). O(filled voxels).
LatticeGrid turnQuarter(const LatticeGrid& g, const glm::ivec3& quarter_turns, const Lattice& lattice);

class Assembly {
 public:
  Assembly() = default;
  explicit Assembly(Lattice lattice) : lattice_(std::move(lattice)), has_lattice_(true) {}

  bool hasLattice() const { return has_lattice_; }
  const Lattice& lattice() const { return lattice_; }

  // Adds a grid as a part. The first grid of an assembly without a lattice sets it (latticeOf(grid.frame())); a later
  // grid must share the lattice (checkSharedLattice: same voxel size and units, origin a whole number of voxels
  // away), else an error names the part and says how they differ. Returns the new part's index.
  Result<size_t> addGrid(VoxelGrid grid, const std::string& name);
  // Adds voxels already placed on this assembly's lattice (e.g. the bodies of one mesh, voxelizeBodies).
  size_t addPart(LatticeGrid voxels, const std::string& name);
  void removePart(size_t i);

  size_t size() const { return parts_.size(); }
  // Part i; an index out of range throws std::out_of_range (never reads past the parts).
  const Part& part(size_t i) const { return parts_.at(i); }
  Part& part(size_t i) { return parts_.at(i); }  // to edit name, colour, visibility, placement
  const std::vector<Part>& parts() const { return parts_; }

  void setPlacement(size_t i, const PartPlacement& placement) { parts_.at(i).placement = placement; }
  // A translation in model units snapped to whole voxels (rounded to the nearest).
  glm::ivec3 snapTranslation(const glm::dvec3& model_units) const;
  // The part's voxels with its placement applied (no copy of the voxels when it has no quarter turns).
  LatticeGrid placedVoxels(size_t i) const;
  // Part i's feeder moved by its placement's translation (model units), or none when the part is not a feeder.
  std::optional<Feeder> placedFeeder(size_t i) const;
  // Every part placed (the order of parts()).
  std::vector<LatticeGrid> placedParts() const;
  // The union of the parts' placed boxes (empty for no parts).
  Box3i extent() const;

 private:
  Lattice lattice_;
  bool has_lattice_ = false;
  std::vector<Part> parts_;
};

}  // namespace vox
