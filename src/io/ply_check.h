#pragma once
// A PLY file's body checked against its header before assimp reads it. assimp 5.2 trusts the header's element
// counts: an ASCII file that declares more vertices than it holds reads the missing ones as zeros, and one that
// declares fewer faces than it holds drops the rest, silently. This walks the body as the header describes it
// (Greg Turk, "The PLY Polygon File Format", 1994: ascii with one element per line, binary_little_endian,
// binary_big_endian; scalar and list properties) without interpreting the values, and refuses a body that ends early,
// an ASCII line with more or fewer values than its element declares, data after the declared elements, and a header
// without a vertex element with x, y and z.
#include <cstdint>
#include <span>
#include <string>

#include "vox/core/result.h"

namespace vox::io {

struct PlyFacts {
  bool ascii = false;
  bool big_endian = false;
  uint64_t vertices = 0;
  uint64_t faces = 0;
};

// Errors (kParse) name the file, the element and the line or byte offset, e.g. "part.ply: PLY data ends in vertex
// 5 of 1000 (byte 48 of the body): the header declares more elements than the file holds", "part.ply:20: PLY vertex
// 9 of 9 has 5 values where the header declares 3: its counts do not match the data".
Result<PlyFacts> checkPly(std::span<const uint8_t> bytes, const std::string& name);

}  // namespace vox::io
