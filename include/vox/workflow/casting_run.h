#pragma once
// The casting pipeline both front ends run (vox/analysis/casting.h): the part's geometric modulus (the
// distance field, local thickness, the hot spots' regions), then the solidification of the part with its feeders in
// its mould. `voxmod casting` and the window's Casting panel call this one function.
#include <functional>

#include "vox/analysis/casting.h"
#include "vox/analysis/analysis.h"
#include "vox/core/image.h"
#include "vox/core/result.h"
#include "vox/core/scalar_field.h"
#include "vox/core/voxel_grid.h"

namespace vox::workflow {

enum class CastingStage { kModulus, kSimulate };

// Progress within one stage (fraction in [0, 1]); returning false stops the run, which then fails with kCancelled.
using CastingProgress = std::function<bool(CastingStage stage, double fraction)>;

struct CastingRun {
  ScalarField modulus;       // over the part's grid, model units (computeModulusField)
  double modulus_max = 0.0;  // model units
  CastingResult result;
  double modulus_s = 0.0;
};

// params.modulus is ignored (this computes it) and params.metres_per_unit is taken from the grid's units: a grid
// without length units is refused (kInvalidArgument, saying so), as is one whose simulation needs more memory than
// `memory_limit_bytes` (kLimit, before any work; 0: the default limit, 80% of physical memory).
Result<CastingRun> runCasting(const VoxelGrid& part, CastingParams params, const CastingProgress& progress = {},
                              uint64_t memory_limit_bytes = 0);

// The section of the solidification times (result.time's grid) as a figure: each metal voxel coloured by when it
// froze, a colour bar in seconds and minutes, the title naming the section. kInvalidArgument for an index outside it.
Result<ImageRgb> castingSectionFigure(const CastingResult& result, const SectionParams& params, int32_t scale);
// The Z section through the latest hot spot outside the feeders (else the latest), on result.time's grid.
SectionParams latestHotSpotSection(const CastingResult& result);

}  // namespace vox::workflow
