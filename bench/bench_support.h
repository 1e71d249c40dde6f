#pragma once
// Shared helpers for the benchmarks: where the shared meshes are.
#include <cstdlib>
#include <filesystem>
#include <string>

namespace vox::bench {

inline std::filesystem::path sharedDir() {
  const char* env = std::getenv("VOXMOD_SHARED_DIR");
  return env && *env ? std::filesystem::path(env) : std::filesystem::path(VOXMOD_SHARED_DIR);
}
inline std::filesystem::path sharedMesh(const std::string& name) { return sharedDir() / "meshes" / name; }

}  // namespace vox::bench
