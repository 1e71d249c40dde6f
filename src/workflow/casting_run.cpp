#include "vox/workflow/casting_run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "vox/analysis/distance.h"
#include "vox/analysis/thickness.h"
#include "vox/analysis/thickness_map.h"
#include "vox/io/figure.h"
#include "vox/core/text.h"
#include "vox/core/units.h"

namespace vox::workflow {

Result<CastingRun> runCasting(const VoxelGrid& part, CastingParams params, const CastingProgress& progress,
                              uint64_t memory_limit_bytes) {
  const std::string& name = part.frame().source.empty() ? std::string("the part") : part.frame().source;
  params.metres_per_unit = metresPerUnit(part.frame().units);
  if (params.metres_per_unit <= 0.0) {
    return makeError(ErrorCode::kInvalidArgument,
                     name +
                         " has no length units, and a casting's times depend on its size: say what its numbers "
                         "are in (--units mm|cm|m|in)");
  }
  params.modulus = nullptr;
  if (Status s = checkCasting(part, params); !s) return s.error();
  const uint64_t limit = memory_limit_bytes ? memory_limit_bytes : defaultMemoryLimitBytes();
  // The simulation's arrays, and the modulus's distance, thickness and labels (about 16 bytes a voxel of the part):
  // estimated from the part's V/A first, and again from its real modulus before the simulation starts.
  const auto fits = [&](const CastingParams& p) -> Status {
    const uint64_t need = uint64_t(estimateCastingBytes(part, p)) + uint64_t(part.dims().count()) * 16;
    if (limit && need > limit) {
      return makeError(ErrorCode::kLimit, name + ": the casting simulation needs about " + formatBytes(need) +
                                              ", more than the " + formatBytes(limit) +
                                              " this machine allows; use fewer voxels (--res)");
    }
    return Ok{};
  };
  if (Status s = fits(params); !s) return s.error();
  const auto stage = [&progress](CastingStage s) {
    if (!progress) return ProgressFn();
    return ProgressFn([&progress, s](double f) { return progress(s, f); });
  };
  CastingRun run;
  const double t0 = nowSeconds();
  {
    const ProgressFn modulus_progress = stage(CastingStage::kModulus);
    const auto part_of = [&](double from, double to) {
      if (!modulus_progress) return ProgressFn();
      return ProgressFn([&, from, to](double f) { return modulus_progress(from + (to - from) * f); });
    };
    auto distance = computeDistance(part, part_of(0.0, 0.3), DistanceLayout::kDense);
    if (!distance) return distance.error();
    auto thickness = computeThickness(*distance, {}, part_of(0.3, 0.7));
    if (!thickness) return thickness.error();
    auto modulus = computeModulusField(*distance, &thickness->radius, {}, part_of(0.7, 1.0));
    if (!modulus) return modulus.error();
    run.modulus = std::move(modulus).value();
  }
  for (const float v : run.modulus.values) run.modulus_max = std::max(run.modulus_max, double(v));
  run.modulus_s = nowSeconds() - t0;
  params.modulus = &run.modulus;
  if (Status s = fits(params); !s) return s.error();
  auto result = simulateCasting(part, params, stage(CastingStage::kSimulate));
  if (!result) return result.error();
  run.result = std::move(result).value();
  return run;
}

SectionParams latestHotSpotSection(const CastingResult& result) {
  SectionParams params;
  params.axis = Axis::kZ;
  const CastingHotSpot* spot = nullptr;
  for (const CastingHotSpot& s : result.hot_spots) {
    if (!spot || (spot->in_feeder && !s.in_feeder)) spot = &s;
    if (!spot->in_feeder) break;
  }
  if (spot) {
    const double z = (spot->centre.z - result.frame.origin.z) / result.frame.voxel_size - 0.5;
    params.index = std::clamp(int32_t(std::lround(z)), 0, std::max(result.dims.nz - 1, 0));
  }
  return params;
}

Result<ImageRgb> castingSectionFigure(const CastingResult& result, const SectionParams& params, int32_t scale) {
  auto map = scaledSection(result.time, params, 10.0);  // tenths of a second
  if (!map) return map.error();
  ScalarMapLegend legend;
  legend.title =
      std::string("Solidification time, section ") + axisName(params.axis) + " = " + std::to_string(params.index);
  legend.value_name = "s";
  legend.units_per_value = 1.0 / 60.0;
  legend.value_divisor = 10;
  legend.units = "min";
  legend.right_axis = axisName(imageRightAxis(params.axis));
  legend.up_axis = axisName(imageUpAxis(params.axis));
  char buf[200];
  std::snprintf(buf, sizeof buf, "the casting is solid after %.4g s (%.3g min); feeders too after %.4g s",
                result.solidification_s, result.solidification_s / 60.0, result.last_metal_s);
  legend.notes.push_back(buf);
  legend.notes.push_back(result.verdict);
  const int64_t top = std::max<int64_t>(1, std::lround(result.last_metal_s * 10.0));
  return io::drawScalarMapFigure(*map, top, legend, scale).image;
}

}  // namespace vox::workflow
