#pragma once
// The thickness section as a figure (the map, its colour bar and legend), as `voxmod thickness --png` writes it and
// the window exports it from the Thickness panel: local thickness, or the ray thickness when given, whose colours
// stop at the thickest inscribed ball's diameter (a longer ray runs along the part, from an end face down a bar).
#include <string>

#include "vox/analysis/analysis.h"
#include "vox/analysis/ray_thickness.h"
#include "vox/analysis/thickness.h"
#include "vox/core/image.h"
#include "vox/core/result.h"

namespace vox::workflow {

Result<ImageRgb> thicknessSectionFigure(const Thickness& thickness, const RayThicknessResult* ray,
                                        const SectionParams& params, const std::string& units, int32_t scale);

}  // namespace vox::workflow
