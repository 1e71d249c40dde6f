#pragma once
// An OFF file checked before assimp reads it. assimp 5.2's OFF reader trusts the file: counts larger than the data,
// faces with indices past the vertices or lines that are not numbers crash it (found by
// tests/fuzz/fuzz_mesh_file.cpp). This walks the file as the format describes it (Geomview / Princeton OFF: a header
// keyword [ST][C][N][4][n]OFF, then "vertices faces [edges]", one vertex per line with at least x y z, one face per
// line "n i1 ... in" with optional colour values after; '#' starts a comment) without keeping the values, and refuses
// what does not fit: the error names the file and the line. Lines are taken as assimp takes them: a comment or
// spaces alone on a line among the vertices and faces is refused (assimp reads it as a face without corners and
// takes one off its face count, which wraps around when such lines outnumber the faces: a crash, found by the
// fuzzer), as are faces of more than 9 corners (assimp drops them the same way) and NUL bytes (its end of file).
#include <cstdint>
#include <span>
#include <string>

#include "vox/core/result.h"

namespace vox::io {

Status checkOff(std::span<const uint8_t> bytes, const std::string& name);

}  // namespace vox::io
