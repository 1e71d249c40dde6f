#pragma once
// STL reader (binary and ASCII, chosen by content, docs/file-format.md): binary when the size is exactly
// 84 + 50 * count (even if the header starts with "solid"); else ASCII when the file starts with "solid" and holds
// no NUL byte; else not an STL when its first bytes name another format; else a binary file of the wrong size
// (truncated is an error; extra bytes after the declared triangles are ignored with a warning). Errors name the
// file, and the line for ASCII, e.g. "part.stl:88: expected 'vertex', found 'endloop'".
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "vox/core/indexed_mesh.h"
#include "vox/core/mesh.h"
#include "vox/core/result.h"

namespace vox::io {

struct StlLoad {
  TriangleMesh mesh;  // degenerate triangles are kept (they cross no ray); see warnings
  bool ascii = false;
  std::string header;                 // binary: the 80-byte header (trimmed); ASCII: the first solid's name
  MeshTopology topology;              // watertightness: boundary and non-manifold edge counts
  std::vector<std::string> warnings;  // e.g. "part.stl: 3 degenerate triangles", "part.stl: not watertight: ..."
  std::vector<std::string> notes;     // information, e.g. "part.stl: treated as closed: ... (exporter noise)"
};

// Reads an STL file. Fails on: missing/unreadable file, empty mesh, truncated binary data, another format,
// NaN/Inf coordinates, bad ASCII tokens.
Result<StlLoad> loadStl(const std::filesystem::path& path);
// The same from bytes in memory; `name` is used in messages (for tests and fuzzing).
Result<StlLoad> parseStl(std::span<const uint8_t> bytes, const std::string& name);

// Writes a binary STL atomically (used by tests and tools to generate meshes).
Status saveStlBinary(const TriangleMesh& mesh, const std::filesystem::path& path);
// The same from shared vertices (doubles, written as float), without a TriangleMesh copy.
Status saveStlBinary(const IndexedMesh& mesh, const std::filesystem::path& path);

}  // namespace vox::io
