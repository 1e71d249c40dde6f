// libFuzzer target: loadMeshFile's readers from memory (parseMeshFile), every format. The first byte picks the name
// the rest is read under, so one corpus reaches every reader, the content checks (a PLY named .step) and the
// sniffing of unknown extensions. Bounded: a small grid for CAD tessellations and a memory limit for 3MF packages.
// Accepted meshes must be usable: at least one triangle, finite coordinates, bodies covering the triangles.
#include <cmath>
#include <cstddef>
#include <cstdint>

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

}  // namespace

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
