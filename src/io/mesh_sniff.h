#pragma once
// What a file's first bytes say it is (magic numbers and leading keywords), for choosing a reader and for messages
// that name the format a misnamed file really holds.
#include <cstdint>
#include <span>
#include <string>

#include "vox/io/mesh_file.h"

namespace vox::io {

struct ContentKind {
  MeshFormat format = MeshFormat::kUnknown;  // a mesh or CAD format voxmod reads, or kUnknown
  // For messages: "a PLY file", "a zip archive (3MF)", "a .binvox file"; nullptr when nothing is recognised (binary
  // STL and OBJ carry no signature).
  const char* what = nullptr;
  // How to have voxmod read it: "name it .ply", "use the .binvox extension"; empty when nothing is recognised.
  const char* hint = "";
};

ContentKind sniffContent(std::span<const uint8_t> bytes);

// "a PLY", "an STL": for "not a PLY file".
std::string withArticle(MeshFormat format);

// "part.ply: not a PLY file: it looks like a STEP file (voxmod reads it as one when its name ends in .step)".
std::string notWhatItSays(const std::string& name, MeshFormat expected, const ContentKind& found);

}  // namespace vox::io
