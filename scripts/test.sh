#!/usr/bin/env bash
# One command for a new user and for CI: install what is missing, build, and run the whole test suite.
# Tests that need ../shared skip outside CI and fail inside CI (CI=true).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh ${VOXMOD_CMAKE_ARGS:-}
cd "${VOXMOD_BUILD_DIR:-build}"
ctest --output-on-failure -j "${VOXMOD_JOBS:-$(nproc)}" ${VOXMOD_CTEST_ARGS:-}
