// The analyses of the reference voxelizations against ../shared/reference/<mesh>_r128.analysis.json (README
// section 6): counts exactly, floating-point values to a relative 1e-9.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "support/test_support.h"
#include "peel_layers.h"
#include "vox/analysis/analysis.h"
#include "vox/io/voxel_file.h"

namespace vox {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct Case {
  std::string name;
  json ref;
  VoxelGrid grid;
};

// Every <mesh>_r128.analysis.json with its grid, loaded once for all tests.
const std::vector<Case>& referenceCases(const fs::path& shared) {
  static std::vector<Case> cases;
  static bool loaded = false;
  if (loaded) return cases;
  loaded = true;
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(shared / "reference")) {
    const std::string n = e.path().filename().string();
    if (n.size() > 19 && n.ends_with("_r128.analysis.json")) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& f : files) {
    Case c;
    c.name = f.filename().string();
    std::ifstream in(f);
    c.ref = json::parse(in);
    const fs::path binvox = f.parent_path() / c.ref.at("file").get<std::string>();
    auto g = io::loadBinvox(binvox);
    if (!g.ok()) {
      ADD_FAILURE() << binvox << ": " << g.error().message;
      continue;
    }
    c.grid = std::move(g).value();
    cases.push_back(std::move(c));
  }
  return cases;
}

void expectRel(double got, double want, double scale, const std::string& what) {
  EXPECT_NEAR(got, want, 1e-9 * std::max(std::abs(want), scale)) << what;
}

TEST(ReferenceAnalysis, allTwelveFilesArePresent) {
  VOX_REQUIRE_SHARED(shared);
  EXPECT_EQ(referenceCases(shared).size(), 12u);
}

TEST(ReferenceAnalysis, gridMatchesTheHeader) {
  VOX_REQUIRE_SHARED(shared);
  for (const Case& c : referenceCases(shared)) {
    const std::vector<int> dims = c.ref.at("dims");
    EXPECT_EQ(c.grid.dims(), (Dims{dims[0], dims[1], dims[2]})) << c.name;
    expectRel(c.grid.voxelSize(), c.ref.at("h"), 0, c.name + " h");
  }
}

TEST(ReferenceAnalysis, surfaceAndCodeHistogram) {
  VOX_REQUIRE_SHARED(shared);
  for (const Case& c : referenceCases(shared)) {
    const SurfaceStats s = computeSurfaceStats(c.grid);
    EXPECT_EQ(s.filled, c.ref.at("filled").get<int64_t>()) << c.name;
    EXPECT_EQ(s.surface_voxels, c.ref.at("surface_voxels").get<int64_t>()) << c.name;
    const std::vector<int64_t> hist = c.ref.at("code_histogram");
    ASSERT_EQ(hist.size(), 64u);
    for (size_t code = 0; code < 64; ++code)
      EXPECT_EQ(s.code_histogram[code], hist[code]) << c.name << " code " << code;
  }
}

TEST(ReferenceAnalysis, sectionCounts) {
  VOX_REQUIRE_SHARED(shared);
  for (const Case& c : referenceCases(shared)) {
    for (Axis axis : {Axis::kX, Axis::kY, Axis::kZ}) {
      const std::vector<int64_t> want = c.ref.at("section_counts").at(axisName(axis));
      for (size_t i = 0; i < want.size(); ++i) {
        ASSERT_EQ(sectionCount(c.grid, axis, int32_t(i)), want[i]) << c.name << " " << axisName(axis) << " " << i;
      }
      // The images agree with the counts; spot-check a few indices.
      for (size_t i = 0; i < want.size(); i += 37) {
        auto s = computeSection(c.grid, SectionParams{axis, int32_t(i)});
        ASSERT_TRUE(s.ok());
        EXPECT_EQ(s->filled, want[i]) << c.name << " " << axisName(axis) << " " << i;
      }
    }
  }
}

TEST(ReferenceAnalysis, peelLayers) {
  VOX_REQUIRE_SHARED(shared);
  for (const Case& c : referenceCases(shared)) {
    const json& p = c.ref.at("peel");
    const std::vector<int64_t> want = p.at("removed_per_layer");
    auto r = test::peelLayers(c.grid, PeelParams{0, true});
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->removed_per_layer, want) << c.name;
    EXPECT_EQ(int64_t(r->removed_per_layer.size()), p.at("layers").get<int64_t>()) << c.name;
    EXPECT_EQ(r->core_voxels, p.at("core_voxels").get<int64_t>()) << c.name;
    auto d = computeDepthMap(c.grid);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(d->removedPerLayer(), want) << c.name;
    EXPECT_EQ(d->coreVoxels(), p.at("core_voxels").get<int64_t>()) << c.name;
  }
}

TEST(ReferenceAnalysis, xrayPerAxisAndMode) {
  VOX_REQUIRE_SHARED(shared);
  for (const Case& c : referenceCases(shared)) {
    for (Axis axis : {Axis::kX, Axis::kY, Axis::kZ}) {
      const json& ax = c.ref.at("xray").at(axisName(axis));
      for (XrayMode mode : {XrayMode::kMin, XrayMode::kMax, XrayMode::kTotal}) {
        const std::string what = c.name + " " + axisName(axis) + " " + xrayModeName(mode);
        const json& m = ax.at(xrayModeName(mode));
        auto r = computeXray(c.grid, XrayParams{axis, mode});
        ASSERT_TRUE(r.ok());
        EXPECT_EQ(r->rays_hit, ax.at("rays_hit").get<int64_t>()) << what;
        EXPECT_EQ(r->min, m.at("min").get<int64_t>()) << what;
        EXPECT_EQ(r->max, m.at("max").get<int64_t>()) << what;
        expectRel(r->mean, m.at("mean"), 0, what + " mean");
        int64_t sum = 0;
        for (int32_t v : r->thickness.pixels) sum += v;
        EXPECT_EQ(sum, m.at("sum").get<int64_t>()) << what;
        const double h = r->voxel_size;
        expectRel(double(r->min) * h, m.at("min_mm"), 0, what + " min_mm");
        expectRel(double(r->max) * h, m.at("max_mm"), 0, what + " max_mm");
        expectRel(r->mean * h, m.at("mean_mm"), 0, what + " mean_mm");
      }
    }
  }
}

TEST(ReferenceAnalysis, massProperties) {
  VOX_REQUIRE_SHARED(shared);
  for (const Case& c : referenceCases(shared)) {
    const json& m = c.ref.at("mass");
    const MassProperties mp = computeMassProperties(c.grid);
    const double scale = c.ref.at("scale");  // model-unit size of the grid, for values near zero
    expectRel(mp.volume, m.at("volume"), 0, c.name + " volume");
    const std::vector<double> centroid = m.at("centroid");
    const std::vector<double> bmin = m.at("bbox_min"), bmax = m.at("bbox_max");
    const std::vector<int> imin = m.at("bbox_min_ijk"), imax = m.at("bbox_max_ijk");
    const std::vector<std::vector<double>> inertia = m.at("inertia");
    double inertia_scale = 0;
    for (int a = 0; a < 3; ++a) inertia_scale = std::max(inertia_scale, std::abs(inertia[size_t(a)][size_t(a)]));
    for (int a = 0; a < 3; ++a) {
      const std::string ax = axisName(Axis(a));
      expectRel(mp.centroid[a], centroid[size_t(a)], scale, c.name + " centroid " + ax);
      expectRel(mp.bbox.min[a], bmin[size_t(a)], scale, c.name + " bbox_min " + ax);
      expectRel(mp.bbox.max[a], bmax[size_t(a)], scale, c.name + " bbox_max " + ax);
      EXPECT_EQ(mp.bbox_min_ijk[a], imin[size_t(a)]) << c.name;
      EXPECT_EQ(mp.bbox_max_ijk[a], imax[size_t(a)]) << c.name;
      for (int b = 0; b < 3; ++b) {
        // The tensor is symmetric, so glm's column-major [col][row] reads the same as the JSON's [row][col].
        expectRel(mp.inertia[a][b], inertia[size_t(a)][size_t(b)], inertia_scale,
                  c.name + " inertia " + std::to_string(a) + std::to_string(b));
      }
    }
    EXPECT_EQ(mp.filled, c.ref.at("filled").get<int64_t>()) << c.name;
  }
}

}  // namespace
}  // namespace vox
