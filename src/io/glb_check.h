#pragma once
// A binary glTF (GLB) container checked before assimp reads it. assimp 5.2 allocates what the header's chunk lengths
// say before it compares them with the file: a 700-byte file whose JSON chunk claims 4 GB makes it allocate 4 GB
// (found by tests/fuzz/fuzz_mesh_file.cpp). This checks the container only (glTF 2.0, "GLB File Format
// Specification": a 12-byte header "glTF", version 2, total length; then chunks of length, type and data, the first
// one JSON) against the bytes there are; the JSON and the binary data are left to assimp.
#include <cstdint>
#include <span>
#include <string>

#include "vox/core/result.h"

namespace vox::io {

// Errors (kParse) name the file and the field, e.g. "part.glb: GLB chunk 1 says 4294509077 bytes where 701 remain".
Status checkGlb(std::span<const uint8_t> bytes, const std::string& name);

}  // namespace vox::io
