#pragma once
// NRRD volumes (docs/conventions.md, "NRRD"), written and read through Teem's nrrd library: 3D Slicer, ParaView and
// Teem's own tools open them. A voxel grid is written as uint8 0/1, a scalar field as float; sizes nx ny nz (x
// fastest), space directions with the voxel size on the diagonal, space origin at the centre of voxel (0, 0, 0),
// space units the grid's units ("mm", ..., "model" when unknown), little-endian, raw or gzip. volume_export.h writes
// NRRD among the other volume formats, by extension.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "vox/core/result.h"
#include "vox/core/scalar_field.h"
#include "vox/core/voxel_grid.h"

namespace vox::io {

enum class NrrdEncoding { kRaw, kGzip };

// The whole file in memory (for writing several files as one with writeFilesAtomic).
Result<std::vector<uint8_t>> encodeNrrd(const VoxelGrid& grid, NrrdEncoding encoding = NrrdEncoding::kGzip);
Result<std::vector<uint8_t>> encodeNrrd(const ScalarField& field, NrrdEncoding encoding = NrrdEncoding::kGzip);
// Written atomically: the previous file stays when anything fails.
Status saveNrrd(const VoxelGrid& grid, const std::filesystem::path& path, NrrdEncoding encoding = NrrdEncoding::kGzip);
Status saveNrrd(const ScalarField& field, const std::filesystem::path& path,
                NrrdEncoding encoding = NrrdEncoding::kGzip);
// A 3D NRRD of any scalar type as floats, with its placement (voxel size from the space directions, which must be
// an equal-spaced diagonal; origin from the space origin; units from the space units when given). Errors name the
// file and the problem.
Result<ScalarField> loadNrrdField(const std::filesystem::path& path);

}  // namespace vox::io
