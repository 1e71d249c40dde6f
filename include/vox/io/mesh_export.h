#pragma once
// Surface meshes out, by extension (docs/file-format.md, "Mesh exports"): .stl binary (voxmod's own writer, the
// soup STL stores), .ply (binary little-endian), .obj (no material file) and .3mf through assimp, which keep the
// shared vertices. Coordinates in model units (3MF: millimetres). Written atomically: a failure leaves the
// previous file as it was and names the path.
#include <filesystem>
#include <string>

#include "vox/core/indexed_mesh.h"
#include "vox/core/result.h"

namespace vox::io {

// True for the extensions saveMesh writes (.stl, .ply, .obj, .3mf, any case).
bool isMeshExportFile(const std::filesystem::path& path);
// "stl, ply, obj, 3mf" for messages.
std::string meshExportExtensions();

Status saveMesh(const IndexedMesh& mesh, const std::filesystem::path& path);

}  // namespace vox::io
