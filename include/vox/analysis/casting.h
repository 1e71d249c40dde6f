#pragma once
// Casting solidification (`voxmod casting`, the window's Casting panel; docs/conventions.md, "Casting"):
//  - materials: alloys and moulds with cited properties (casting_materials.cpp);
//  - feeders: cylinders standing on the part along +Z, voxelized on the part's lattice;
//  - the simulation: transient conduction with latent heat (an enthalpy formulation) over the metal and an envelope
//    of mould about it, on the voxel lattice, implicit in time (split by direction, a tridiagonal solve per line) so
//    that metal and sand together are stable at any time step;
//  - its results: each metal voxel's solidification time, Niyama's criterion where it freezes, the hot spots (the
//    regions freezing last, each isolated or fed) and the verdict.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vector_relational.hpp>

#include "vox/core/feeder.h"
#include "vox/core/progress.h"
#include "vox/core/result.h"
#include "vox/core/scalar_field.h"
#include "vox/core/voxel_grid.h"

namespace vox {

// ---- Materials (SI units; sources in docs/conventions.md, "Casting") ----
struct Alloy {
  std::string name;
  double liquidus_c = 0.0, solidus_c = 0.0;  // equal for a pure metal
  double density_kg_m3 = 0.0;
  double latent_heat_j_kg = 0.0;
  double conductivity_w_mk = 0.0;
  double specific_heat_j_kgk = 0.0;
};
struct MouldMaterial {
  std::string name;
  double conductivity_w_mk = 0.0;
  double density_kg_m3 = 0.0;
  double specific_heat_j_kgk = 0.0;
  double temperature_c = 20.0;  // the mould's usual starting temperature (a die is preheated)
};
const std::vector<Alloy>& castingAlloys();          // aluminium, a356, grey-iron, carbon-steel
const std::vector<MouldMaterial>& castingMoulds();  // silica-sand, steel
const Alloy* findAlloy(std::string_view name);      // null when unknown
const MouldMaterial* findMould(std::string_view name);
std::string alloyNames();  // "aluminium, a356, ..." for messages
std::string mouldNames();

// ---- Feeders: vox/core/feeder.h ----

// ---- The simulation ----
struct CastingParams {
  Alloy alloy;
  MouldMaterial mould;  // mould.temperature_c is the temperature it starts at
  double superheat_k = 50.0;
  double metres_per_unit = 0.001;  // the model's units in metres (a part without units is refused before this)
  std::vector<Feeder> feeders;
  // Time steps over the estimated solidification time (Chvorinov's rule for the largest modulus): the step is that
  // time over this many, the same at every resolution.
  int steps_per_estimate = 160;
  // The mould about the metal, model units; <= 0: 3.5 times the distance heat diffuses in the mould over 1.5 times
  // the estimated time (at least two voxels).
  double envelope = 0.0;
  // The geometric modulus of the part (computeModulusField), over the part's grid, or null: then the hot spots'
  // moduli are 0 and the time estimate uses the feeders and the part's V/A from its voxels' faces.
  const ScalarField* modulus = nullptr;
  // Planes of symmetry: on these axes the box ends at the metal's own extent, with no mould beyond, its faces
  // insulated: a part cut along a plane of symmetry simulates as the whole (and a slab with x and y set is a plate
  // of infinite width).
  glm::bvec3 symmetry{false};
  int64_t max_cells = int64_t(1) << 31;  // refused (kLimit) before any work when the box with its mould is larger
};

struct CastingHotSpot {
  glm::dvec3 centre{0.0};  // model units: the voxel freezing last in the region
  double solidification_s = 0.0;
  double modulus = 0.0;   // the geometric modulus there (a feeder's: the feeder's), model units
  int64_t voxels = 0;     // the region: its metal voxels that feed toward this spot
  bool isolated = false;  // no path to later-freezing metal without crossing metal freezing earlier
  bool in_feeder = false;
  // A fed spot: where its path to later metal dips lowest (model units) and the spot it feeds from (index in the
  // list); -1 for an isolated spot.
  glm::dvec3 saddle{0.0};
  int32_t fed_by = -1;
};

struct FeederResult {
  Feeder feeder;
  double modulus = 0.0;  // feederModulus, model units
  double volume = 0.0;   // its voxels outside the part, model units^3
};

struct CastingResult {
  // Over the part's grid grown to hold the feeders (same lattice; `frame` its placement): each metal voxel's
  // solidification time (s; 0 elsewhere), Niyama's criterion where it crossed the solidus ((K s)^0.5 / mm; 0 elsewhere)
  // and the metal (part and feeders) and feeders' voxels.
  Dims dims;
  GridFrame frame;
  glm::ivec3 part_offset{0};  // the part's voxel (0, 0, 0) in these dims
  ScalarField time, niyama;
  VoxelGrid metal, feeder_voxels;
  double solidification_s = 0.0;          // until the last casting voxel is below the solidus
  double last_metal_s = 0.0;              // ... the last voxel of metal, feeders too
  std::vector<CastingHotSpot> hot_spots;  // latest first
  bool sound = false;
  std::string verdict;  // one sentence: why sound or not
  std::vector<FeederResult> feeders;
  double casting_volume = 0.0, feeder_volume = 0.0, yield = 1.0;  // model units^3; casting / (casting + feeders)
  double estimate_s = 0.0;                                        // Chvorinov's estimate the step was taken from
  double time_step_s = 0.0;
  int64_t steps = 0;
  Dims box;  // the simulated box (metal and mould)
  int32_t envelope_voxels = 0;
  double simulate_s = 0.0;  // wall-clock seconds
};

// Bytes the simulation of `part` with `params` would hold at its peak (checked against available memory by callers).
int64_t estimateCastingBytes(const VoxelGrid& part, const CastingParams& params);

// The checks simulateCasting makes before any work (materials, temperatures, units, feeders, the box's size).
Status checkCasting(const VoxelGrid& part, const CastingParams& params);

// Fails with kInvalidArgument for an empty part, bad materials or feeders (one that touches no voxel of the part
// included), kLimit for a box over max_cells, and kCancelled when progress returns false (nothing is kept).
Result<CastingResult> simulateCasting(const VoxelGrid& part, const CastingParams& params,
                                      const ProgressFn& progress = {});

}  // namespace vox
