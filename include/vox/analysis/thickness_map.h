#pragma once
// Maps of the distance and thickness fields (vox/analysis/thickness.h) for showing and exporting: a section through
// the local thickness in the image axes of computeSection, the words of its legend, and whole-grid scalar fields in
// model units (what NRRD export writes).
#include <string>

#include "vox/analysis/analysis.h"
#include "vox/analysis/distance.h"
#include "vox/analysis/thickness.h"
#include "vox/core/image.h"
#include "vox/core/scalar_field.h"

namespace vox {

// Tenths of a voxel in a thickness section: the map holds round(10 x thickness in voxels), 0 where empty.
inline constexpr int32_t kThicknessTenths = 10;

// The local thickness in the section `params` names, in the axes of computeSection's mask (X -> (y right, z up),
// Y -> (x right, z up), Z -> (x right, y up); row 0 holds the largest index), in tenths of a voxel.
Result<Image2D<int32_t>> thicknessSection(const Thickness& thickness, const SectionParams& params);
// Its legend: the title names the section, values in voxels and model units, statistics as notes.
ScalarMapLegend thicknessLegend(const Thickness& thickness, const SectionParams& params, const std::string& units);

// A section through a field of lengths (model units, 0: no value; the ray thickness) in the same axes and tenths of
// a voxel, and its legend.
Result<Image2D<int32_t>> fieldSection(const ScalarField& field, const SectionParams& params);
ScalarMapLegend rayThicknessLegend(const ScalarField& field, const SectionParams& params, const std::string& units,
                                   double min, double max, double mean);

// A section through any scalar field (0: no value) in the same axes, each value times `scale`, rounded (at least 1
// where the value is positive): the casting's times in tenths of a second with scale 10.
Result<Image2D<int32_t>> scaledSection(const ScalarField& field, const SectionParams& params, double scale);

// The whole grid's local thickness in model units (0 in empty voxels).
ScalarField thicknessField(const Thickness& thickness);
// The whole grid's distance in model units (0 in empty voxels). With `clearance` (computeClearance of the same
// grid), empty voxels hold minus their distance to the material: a signed distance, negative outside.
ScalarField distanceField(const DistanceField& distance, const DistanceField* clearance = nullptr);

}  // namespace vox
