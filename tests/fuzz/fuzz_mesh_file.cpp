// libFuzzer target: loadMeshFile's readers from memory (parseMeshFile), every format. The first byte picks the name
// the rest is read under, so one corpus reaches every reader, the content checks (a PLY named .step) and the
// sniffing of unknown extensions. Bounded: a small grid for CAD tessellations and a memory limit for 3MF packages.
// Accepted meshes must be usable: at least one triangle, finite coordinates, bodies covering the triangles.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>

#include "vox/io/mesh_file.h"

namespace {

constexpr const char* kNames[] = {"fuzz.obj", "fuzz.ply", "fuzz.3mf",  "fuzz.gltf", "fuzz.glb",
                                  "fuzz.off", "fuzz.stl", "fuzz.step", "fuzz.iges", "fuzz"};

void check(const vox::io::MeshFileLoad& m) {
  if (m.mesh.triangles.empty() || m.bodies.empty()) __builtin_trap();
  uint64_t covered = 0;
  for (const vox::io::MeshBody& b : m.bodies) {
    if (b.first_triangle != covered) __builtin_trap();
    covered += b.triangle_count;
  }
  if (covered != m.mesh.triangles.size()) __builtin_trap();
  for (const vox::Triangle& t : m.mesh.triangles) {
    for (const glm::vec3& v : t.v) {
      if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) __builtin_trap();
    }
  }
}

// Open CASCADE registers its STEP and IGES controllers on first use and keeps them to the end: read one of each
// before fuzzing, so that those one-time allocations are not taken for a leak of the first input that reaches them.
const char* const kWarmUpStep =
    "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\nFILE_NAME('','',(''),(''),'','','');\n"
    "FILE_SCHEMA(('AUTOMOTIVE_DESIGN'));\nENDSEC;\nDATA;\nENDSEC;\nEND-ISO-10303-21;\n";

std::string igesRecord(const std::string& text, char section) {
  std::string line = text;
  line.resize(72, ' ');
  return line + section + "      1\n";
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const std::string iges =
      igesRecord("warm-up", 'S') + igesRecord("1H,,1H;;", 'G') + igesRecord("S      1G      1D      0P      0", 'T');
  for (const auto& [name, text] :
       {std::pair<const char*, std::string>{"warm.step", kWarmUpStep}, {"warm.iges", iges}}) {
    (void)vox::io::parseMeshFile({reinterpret_cast<const uint8_t*>(text.data()), text.size()}, name);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  vox::io::MeshFileOptions options;
  options.resolution = 16;
  options.memory_limit_bytes = uint64_t(256) << 20;
  const char* name = kNames[data[0] % (sizeof kNames / sizeof kNames[0])];
  auto result = vox::io::parseMeshFile({data + 1, size - 1}, name, options);
  if (result.ok()) check(*result);
  return 0;
}
