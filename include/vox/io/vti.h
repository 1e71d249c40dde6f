#pragma once
// VTK image data (.vti: ParaView, VTK), written through VTK's own vtkXMLImageDataWriter (docs/file-format.md,
// "Volume files").
//
// One vtkImageData with dimensions nx ny nz (point data, one point per voxel centre), origin = the centre of voxel
// (0, 0, 0), spacing = the voxel size on every axis; point-data arrays "voxels" (unsigned char 0/1, the active
// scalars when present) and one float array per field under its name; field data "units" (a string: "mm", ...,
// "model" when unknown). Appended raw binary, zlib-compressed, 64-bit block headers (so volumes over 4 GiB fit).
#include <cstdint>
#include <vector>

#include "vox/io/volume_export.h"

namespace vox::io {

// The file in memory. Errors: content that does not fit (volumeContentProblem), VTK's own, cancellation.
Result<std::vector<uint8_t>> encodeVti(const VolumeContent& content, const ProgressFn& progress = {});

}  // namespace vox::io
