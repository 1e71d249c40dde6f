#pragma once
// Helpers shared by the test executables: where the shared meshes are, temporary directories, running voxmod.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "vox/core/mesh.h"

namespace vox::test {

// ../shared beside the checkout (or $VOXMOD_SHARED_DIR); empty path when it does not exist.
std::filesystem::path sharedDir();
// True when running in CI (CI=true): tests that need shared data fail there instead of skipping.
bool inCI();
// The source tree (for tests/data, models/).
std::filesystem::path sourceDir();

// The unit cube [0, 1]^3 as 12 outward-facing triangles (a closed, consistently oriented mesh).
TriangleMesh unitCubeMesh();

// A fresh directory under the system temp dir, removed when the object goes out of scope.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

std::string readFile(const std::filesystem::path& p);
void writeFile(const std::filesystem::path& p, const std::string& bytes);

struct RunResult {
  int exit_code = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};
// The voxmod executable under test (for tests that start it themselves: under mpirun, killed midway).
std::string voxmodExecutable();
// Runs the voxmod executable with these arguments (no shell quoting needed), capturing stdout and stderr.
RunResult runVoxmod(const std::vector<std::string>& args);

}  // namespace vox::test

// Skips (outside CI) or fails (in CI) the current test when ../shared is missing; otherwise binds `var` to it.
#define VOX_REQUIRE_SHARED(var)                                                             \
  const std::filesystem::path var = ::vox::test::sharedDir();                               \
  if (var.empty()) {                                                                        \
    if (::vox::test::inCI()) FAIL() << "shared test data (../shared) is missing in CI";     \
    GTEST_SKIP() << "shared test data (../shared beside the checkout) not found; skipping"; \
  }
