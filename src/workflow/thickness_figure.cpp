#include "vox/workflow/thickness_figure.h"

#include <algorithm>
#include <cmath>

#include "vox/analysis/thickness_map.h"
#include "vox/io/figure.h"

namespace vox::workflow {

Result<ImageRgb> thicknessSectionFigure(const Thickness& thickness, const RayThicknessResult* ray,
                                        const SectionParams& params, const std::string& units, int32_t scale) {
  if (!ray) {
    auto map = thicknessSection(thickness, params);
    if (!map) return map.error();
    const int64_t top = std::max<int64_t>(1, std::lround(2.0 * thickness.radius.maxVoxels() * kThicknessTenths));
    return io::drawScalarMapFigure(*map, top, thicknessLegend(thickness, params, units), scale).image;
  }
  auto map = fieldSection(ray->field, params);
  if (!map) return map.error();
  const double h = ray->field.frame.voxel_size, ball = thickness.stats.max;
  const int64_t top = std::max<int64_t>(1, std::lround(std::min(ray->max, ball) / h * kThicknessTenths));
  ScalarMapLegend legend = rayThicknessLegend(ray->field, params, units, ray->min, ray->max, ray->mean);
  if (ray->max > ball) {
    legend.notes.push_back("longer rays (along the part) in the top colour: it is the thickest inscribed ball's");
  }
  return io::drawScalarMapFigure(*map, top, legend, scale).image;
}

}  // namespace vox::workflow
