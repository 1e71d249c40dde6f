#pragma once
// Shared set-up for the render regression tests: one headless EGL context per test program on Mesa's llvmpipe
// (pinned through GALLIUM_DRIVER / LIBGL_ALWAYS_SOFTWARE before the first EGL call, so the images do not depend
// on the machine's GPU), image comparison against tests/baselines/*.png, and grids built in code.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "vox/core/image.h"
#include "vox/core/voxel_grid.h"
#include "vox/render/context.h"

#include "support/test_support.h"

namespace vox::render::testing {

// The context shared by all render tests; null when EGL is unavailable (the tests then skip).
HeadlessContext* sharedContext();
// Why sharedContext() is null.
const std::string& contextError();

// Skips the test when there is no headless OpenGL (fails instead in CI, where Mesa's EGL is installed by
// scripts/setup.sh); otherwise makes the shared context current.
#define VOX_REQUIRE_GL()                                                                                         \
  do {                                                                                                           \
    if (!::vox::render::testing::sharedContext()) {                                                              \
      if (::vox::test::inCI()) FAIL() << "no headless OpenGL in CI: " << ::vox::render::testing::contextError(); \
      GTEST_SKIP() << "no headless OpenGL: " << ::vox::render::testing::contextError();                          \
    }                                                                                                            \
    ASSERT_TRUE(::vox::render::testing::sharedContext()->makeCurrent().ok());                                    \
  } while (0)

// ---- Image comparison (f3d style: a missing or failing baseline writes the actual image and a diff) ----
//
// Metric: for each pixel, d = the largest absolute difference over its R, G and B channels, on the 0..255 scale.
// A pixel counts as different when d > kPixelTolerance (24, about 10% of full scale: it absorbs rounding changes
// in a later Mesa while any change of shading, point size or position shows up at full strength). The image
// passes when the fraction of different pixels is at most kMaxDifferentFraction (0.005 = 0.5% of the pixels, 327
// of a 256 x 256 image). llvmpipe itself is deterministic (identical bytes for any LP_NUM_THREADS), so on the
// Mesa the baselines were made with (22.3.6) the measured difference is 0.
inline constexpr int kPixelTolerance = 24;
inline constexpr double kMaxDifferentFraction = 0.005;

struct Comparison {
  bool same_size = false;
  int64_t different = 0;   // pixels with d > kPixelTolerance
  int max_difference = 0;  // largest d
};
Comparison compareImages(const ImageRgba& actual, const ImageRgba& expected);

// Compares `actual` with tests/baselines/<name>.png. On a missing baseline or a failed comparison, writes
// <test binary dir>/render_output/<name>.png (the actual image) and <name>.diff.png (different pixels in red over a
// dimmed copy of the actual image), prints both paths and fails the test. A human looks at the actual image and
// copies it into tests/baselines/ when it is right.
void expectMatchesBaseline(const ImageRgba& actual, const std::string& name);

// Where failed comparisons write their images.
std::filesystem::path outputDir();

// ---- Scenes ----

// A ball of radius r voxels centred in a cube grid with a 2-voxel margin.
VoxelGrid ball(double r);
// Filled box [lo, hi) in a grid of dims d.
void fillBox(VoxelGrid& g, glm::ivec3 lo, glm::ivec3 hi, bool filled = true);

// Background pixels of a ball's image inside 90% of its silhouette's radius (the silhouette found as the bounding
// square of the non-background pixels): 0 when the point surface is closed.
int64_t holesInsideBall(const ImageRgba& image, Rgba8 background);

}  // namespace vox::render::testing
