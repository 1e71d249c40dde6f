#include "io/glb_check.h"

#include <cstring>

namespace vox::io {
namespace {

uint32_t readU32(const uint8_t* p) {
  return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

}  // namespace

Status checkGlb(std::span<const uint8_t> bytes, const std::string& name) {
  auto refuse = [&](const std::string& what) { return makeError(ErrorCode::kParse, name + ": " + what); };
  if (bytes.size() < 12 || std::memcmp(bytes.data(), "glTF", 4) != 0) {
    return refuse("not a GLB file: it does not start with the 12-byte header 'glTF'");
  }
  const uint32_t version = readU32(bytes.data() + 4), length = readU32(bytes.data() + 8);
  if (version != 2) return refuse("GLB version " + std::to_string(version) + " (voxmod reads glTF 2.0)");
  if (length > bytes.size() || length < 12) {
    return refuse("GLB header says " + std::to_string(length) + " bytes where the file holds " +
                  std::to_string(bytes.size()));
  }
  uint64_t at = 12;
  int chunk = 0;
  while (at < length) {
    ++chunk;
    if (length - at < 8) return refuse("GLB chunk " + std::to_string(chunk) + " is cut short in its header");
    const uint32_t chunk_length = readU32(bytes.data() + at), type = readU32(bytes.data() + at + 4);
    at += 8;
    if (chunk_length > length - at) {
      return refuse("GLB chunk " + std::to_string(chunk) + " says " + std::to_string(chunk_length) + " bytes where " +
                    std::to_string(length - at) + " remain");
    }
    if (chunk == 1 && type != 0x4E4F534Au) return refuse("GLB's first chunk is not its JSON");
    at += chunk_length;
  }
  if (chunk == 0) return refuse("GLB file holds no JSON chunk");
  return Ok{};
}

}  // namespace vox::io
