#include "render_fixture.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>

#include "support/test_support.h"
#include "unit/render/test_grids.h"
#include "vox/io/image_io.h"

namespace vox::render::testing {
namespace {

struct ContextHolder {
  std::unique_ptr<HeadlessContext> context;
  std::string error;
  ContextHolder() {
    // Pin the software rasteriser before EGL is first touched: the baselines are llvmpipe images.
    setenv("GALLIUM_DRIVER", "llvmpipe", 1);
    setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1);
    auto c = HeadlessContext::create();
    if (c) {
      context = std::move(c).value();
    } else {
      error = c.error().message;
    }
  }
};

ContextHolder& holder() {
  static ContextHolder h;
  return h;
}

}  // namespace

HeadlessContext* sharedContext() { return holder().context.get(); }
const std::string& contextError() { return holder().error; }

Comparison compareImages(const ImageRgba& actual, const ImageRgba& expected) {
  Comparison c;
  c.same_size = actual.width == expected.width && actual.height == expected.height;
  if (!c.same_size) return c;
  for (size_t i = 0; i < actual.pixels.size(); ++i) {
    const Rgba8 a = actual.pixels[i], e = expected.pixels[i];
    const int d = std::max({std::abs(a.r - e.r), std::abs(a.g - e.g), std::abs(a.b - e.b)});
    c.max_difference = std::max(c.max_difference, d);
    if (d > kPixelTolerance) ++c.different;
  }
  return c;
}

std::filesystem::path outputDir() {
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  const auto dir = (ec ? std::filesystem::current_path() : exe.parent_path()) / "render_output";
  std::filesystem::create_directories(dir, ec);
  return dir;
}

void expectMatchesBaseline(const ImageRgba& actual, const std::string& name) {
  const auto baseline_path = ::vox::test::sourceDir() / "tests" / "baselines" / (name + ".png");
  const auto actual_path = outputDir() / (name + ".png");
  const auto diff_path = outputDir() / (name + ".diff.png");
  auto expected = io::loadPng(baseline_path);
  std::string problem;
  Comparison c;
  if (!expected) {
    problem = "no baseline (" + expected.error().message + ")";
  } else {
    c = compareImages(actual, *expected);
    const double pixels = double(actual.width) * double(actual.height);
    if (!c.same_size) {
      problem = "size " + std::to_string(actual.width) + "x" + std::to_string(actual.height) +
                " differs from the baseline's " + std::to_string(expected->width) + "x" +
                std::to_string(expected->height);
    } else if (double(c.different) > kMaxDifferentFraction * pixels) {
      problem = std::to_string(c.different) + " pixels (" + std::to_string(100.0 * double(c.different) / pixels) +
                "%) differ by more than " + std::to_string(kPixelTolerance) +
                "/255 (allowed: " + std::to_string(100.0 * kMaxDifferentFraction) + "%); largest difference " +
                std::to_string(c.max_difference);
    }
  }
  if (problem.empty()) {
    ::testing::Test::RecordProperty("different_pixels", std::to_string(c.different));
    return;
  }
  EXPECT_TRUE(io::savePng(actual, actual_path).ok());
  if (expected && c.same_size) {
    ImageRgba diff(actual.width, actual.height);
    for (size_t i = 0; i < diff.pixels.size(); ++i) {
      const Rgba8 a = actual.pixels[i], e = expected->pixels[i];
      const int d = std::max({std::abs(a.r - e.r), std::abs(a.g - e.g), std::abs(a.b - e.b)});
      diff.pixels[i] = d > kPixelTolerance ? Rgba8{255, 0, 0, 255}
                                           : Rgba8{uint8_t(a.r / 4), uint8_t(a.g / 4), uint8_t(a.b / 4), 255};
    }
    EXPECT_TRUE(io::savePng(diff, diff_path).ok());
    ADD_FAILURE() << name << ": " << problem << "\n  baseline: " << baseline_path.string()
                  << "\n  actual:   " << actual_path.string() << "\n  diff:     " << diff_path.string();
  } else {
    ADD_FAILURE() << name << ": " << problem << "\n  actual: " << actual_path.string()
                  << "\n  (look at it; if it is right, copy it to " << baseline_path.string() << ")";
  }
}

VoxelGrid ball(double r) { return ball(int32_t(std::ceil(2 * r)) + 4, r); }

void fillBox(VoxelGrid& g, glm::ivec3 lo, glm::ivec3 hi, bool filled) {
  for (int32_t z = lo.z; z < hi.z; ++z)
    for (int32_t y = lo.y; y < hi.y; ++y)
      for (int32_t x = lo.x; x < hi.x; ++x) g.set(x, y, z, filled);
}

int64_t holesInsideBall(const ImageRgba& image, Rgba8 background) {
  int32_t x0 = image.width, x1 = -1, y0 = image.height, y1 = -1;
  for (int32_t y = 0; y < image.height; ++y)
    for (int32_t x = 0; x < image.width; ++x)
      if (!(image.at(x, y) == background)) {
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        y0 = std::min(y0, y);
        y1 = std::max(y1, y);
      }
  if (x1 < 0) return -1;
  const double cx = (x0 + x1) * 0.5, cy = (y0 + y1) * 0.5, r = 0.9 * 0.5 * std::min(x1 - x0, y1 - y0);
  int64_t holes = 0;
  for (int32_t y = 0; y < image.height; ++y)
    for (int32_t x = 0; x < image.width; ++x)
      if ((x - cx) * (x - cx) + (y - cy) * (y - cy) < r * r && image.at(x, y) == background) ++holes;
  return holes;
}

}  // namespace vox::render::testing
