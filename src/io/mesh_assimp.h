#pragma once
// OBJ, PLY, 3MF, glTF / GLB and OFF through assimp (Open Asset Import Library 5.2), into a MeshFileLoad's mesh and
// bodies. The caller (mesh_file.cpp) has already checked the content against the format and adds units, topology
// and findings.
#include <filesystem>
#include <span>
#include <string>

#include "vox/core/result.h"
#include "vox/io/mesh_file.h"

namespace vox::io {

// `bytes` hold the file (for 3MF, the repacked package); `directory`, when given, is where files the main file refers
// to (a .gltf's buffers) are looked up, by relative names that do not leave it.
Result<MeshFileLoad> importWithAssimp(std::span<const uint8_t> bytes, const std::string& name, MeshFormat format,
                                      const std::filesystem::path* directory);

}  // namespace vox::io
