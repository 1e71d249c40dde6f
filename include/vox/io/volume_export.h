#pragma once
// Volume export, by the output file's extension (docs/file-format.md, "Volume files"): NRRD for 3D Slicer (nrrd.h,
// through Teem), VTK image data .vti for ParaView (vti.h, through VTK), OpenVDB .vdb for Blender and Houdini (vdb.h,
// through libopenvdb) and MagicaVoxel .vox (magicavoxel.h). Every format but .vox carries the placement: the origin
// is the centre of voxel (0, 0, 0), the spacing the voxel size, in the grid's units; .vox has unit voxels only.
//
// A volume holds the model's voxels, scalar fields on the same lattice (thickness, distance), or both. What each
// format holds: NRRD one volume per file (the voxels or one field); .vti and .vdb the voxels and any number of
// fields, each under its name; .vox the voxels only. Files are written atomically (a temporary file beside the
// target, renamed when complete): a failure leaves no file behind, and its message names the file.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "vox/core/progress.h"
#include "vox/core/result.h"
#include "vox/core/scalar_field.h"
#include "vox/core/voxel_grid.h"

namespace vox::io {

enum class VolumeFormat { kNrrd, kVti, kVdb, kVox };

// By extension, case-insensitive: .nrrd, .vti, .vdb, .vox; nullopt for anything else.
std::optional<VolumeFormat> volumeFormatOf(const std::filesystem::path& path);
bool isVolumeFile(const std::filesystem::path& path);
// ".nrrd", ".vti", ".vdb", ".vox".
const char* volumeExtension(VolumeFormat format);
// All four, or (fields_only) those that hold scalar fields: for menus and messages ("use .nrrd, .vti, .vdb or .vox").
std::vector<std::string> volumeExtensions(bool fields_only = false);
std::string volumeExtensionList(bool fields_only = false);
bool holdsFields(VolumeFormat format);          // all but .vox
bool holdsSeveralVolumes(VolumeFormat format);  // .vti and .vdb

// A scalar field and the name it is written under ("thickness", "distance"). Not owned.
struct NamedField {
  std::string name;
  const ScalarField* field = nullptr;
};

// What a volume file holds. `voxels` (not owned) is written under the name "voxels" (0/1); every field must lie on
// the same lattice (dims, origin, voxel size) as the voxels and as each other.
struct VolumeContent {
  const VoxelGrid* voxels = nullptr;
  std::vector<NamedField> fields;

  Dims dims() const;
  const GridFrame& frame() const;
};
inline VolumeContent voxelsOnly(const VoxelGrid& grid) { return VolumeContent{&grid, {}}; }
inline VolumeContent oneField(const std::string& name, const ScalarField& field) {
  return VolumeContent{nullptr, {NamedField{name, &field}}};
}

// Why `content` cannot be written as `format` (empty when it can): nothing to write, a format that does not hold
// fields or several volumes, fields off the voxels' lattice, empty or duplicate names.
std::string volumeContentProblem(const VolumeContent& content, VolumeFormat format);

// The whole file in memory (for writing several files as one with writeFilesAtomic). `name` prefixes errors.
// `progress` reports the fraction done and may cancel (ErrorCode::kCancelled).
Result<std::vector<uint8_t>> encodeVolume(const VolumeContent& content, VolumeFormat format, const std::string& name,
                                          const ProgressFn& progress = {});
// Written atomically by the path's extension; an unknown extension is an error naming the supported ones.
Status saveVolume(const VolumeContent& content, const std::filesystem::path& path, const ProgressFn& progress = {});

}  // namespace vox::io
