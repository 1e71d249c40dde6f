// Saving a scene part by part: every part, placed on the scene's lattice, as a .vxm file in one folder, all the files
// written or none (io::saveVoxelFiles, the same writer as `voxmod bodies -o DIR`). Save and Save As write the union
// (or the selected part, as the Parts panel's scope says) as one file; this is the other choice the user has.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "app/parts.h"
#include "vox/core/text.h"
#include "vox/io/file_util.h"
#include "vox/io/mesh_file.h"
#include "vox/io/voxel_file.h"

namespace vox::app {

std::string partFileName(const Assembly& parts, size_t i) {
  const int width = int(std::to_string(parts.size()).size());
  char number[24];
  std::snprintf(number, sizeof number, "%0*zu", std::max(width, 2), i + 1);
  std::string name = parts.part(i).name;
  // A part added from a file is named after it: "a.stl" is saved as "02_a.vxm".
  const std::string ext = io::lowerExtension(name);
  const std::vector<std::string>& meshes = io::meshFileExtensions();
  if (io::isVoxelFile(name) || std::find(meshes.begin(), meshes.end(), ext) != meshes.end()) {
    name.resize(name.size() - ext.size());
  }
  for (char& c : name) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == ' ' ||
                      c == '-' || c == '_' || c == '.';
    if (!keep) c = '_';
  }
  return std::string(number) + "_" + name + ".vxm";
}

Status saveParts(AppState& state, const std::filesystem::path& dir) {
  const Assembly* parts = currentParts(state);
  if (!parts) {
    return makeError(ErrorCode::kInvalidArgument,
                     "there are no parts to save: Save writes the model; split it into bodies or add a part first");
  }
  if (dir.filename().empty()) return makeError(ErrorCode::kInvalidArgument, "no folder name given");
  std::vector<io::VoxelFileToWrite> files;
  files.reserve(parts->size());
  for (size_t i = 0; i < parts->size(); ++i) {
    LatticeGrid placed = parts->placedVoxels(i);
    placed.grid.frame() = parts->lattice().frameAt(placed.first, parts->part(i).name);
    files.push_back(io::VoxelFileToWrite{dir / partFileName(*parts, i), std::move(placed.grid)});
  }
  if (Status s = io::saveVoxelFiles(files); !s) return s;
  state.status_message = "Wrote " + countOf(int64_t(files.size()), "part") + " as .vxm files to " +
                         std::filesystem::absolute(dir).lexically_normal().string();
  state.status_since = nowSeconds();
  return Ok{};
}

}  // namespace vox::app
