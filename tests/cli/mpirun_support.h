#pragma once
// Running voxmod under mpirun in the CLI tests (the MPI batch and the MPI voxelization).
#include <map>
#include <string>
#include <vector>

#include "support/test_support.h"

namespace vox::test {

// Runs a program (not through a shell) with stdout and stderr captured; `env` adds variables.
RunResult runProgram(const std::vector<std::string>& args, const std::map<std::string, std::string>& env = {});
// `mpirun --oversubscribe -np RANKS [--allow-run-as-root] VOXMOD`: add voxmod's arguments.
std::vector<std::string> mpirunArgs(int ranks);
// Why voxmod cannot be tested under MPI here (no mpirun, or a voxmod built without MPI), or empty.
std::string mpiMissing();

}  // namespace vox::test

// Skips (outside CI) or fails (in CI, CI=true) the current test when mpiMissing() says why.
#define VOX_REQUIRE_MPI()                                                \
  if (const std::string why = ::vox::test::mpiMissing(); !why.empty()) { \
    if (::vox::test::inCI()) FAIL() << why << " in CI";                  \
    GTEST_SKIP() << why << "; skipping";                                 \
  }
