#pragma once
// Surface meshes out, by extension (docs/file-format.md, "Mesh exports"): .stl binary (voxmod's own writer, the
// soup STL stores), .ply (binary little-endian) and .obj (no material file) through assimp, .3mf (voxmod's own
// writer, every coordinate as the shortest text that reads back as the same double, the model's unit), which keep
// the shared vertices. Coordinates in model units. Written atomically: a failure leaves the previous file as it was
// and names the path.
#include <filesystem>
#include <string>

#include "vox/core/indexed_mesh.h"
#include "vox/core/result.h"

namespace vox::io {

// True for the extensions saveMesh writes (.stl, .ply, .obj, .3mf, any case).
bool isMeshExportFile(const std::filesystem::path& path);
// "stl, ply, obj, 3mf" for messages.
std::string meshExportExtensions();

// `units`: the model's ("mm", "cm", "m", "in"; "model" or empty for none), written as the 3MF model's unit
// (millimeter, 3MF's default, for none); the other formats carry no unit.
Status saveMesh(const IndexedMesh& mesh, const std::filesystem::path& path, const std::string& units = "model");

}  // namespace vox::io
