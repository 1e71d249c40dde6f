// voxmod printcheck (SPEC 11) as a user runs it: a cantilever's overhang and support, a sealed void, the ranked build
// directions, the fields written all or none, and bad input refused.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "support/test_meshes.h"
#include "support/test_support.h"
#include "vox/io/stl.h"

namespace vox {
namespace {

using test::runVoxmod;

// The cantilever of tests/unit/analysis/printability_test.cpp: 300 mm^2 hanging 15 mm over the plate.
std::string cantileverStl(const test::TempDir& dir) {
  const TriangleMesh m = test::cantileverMesh();
  const std::string stl = (dir / "cantilever.stl").string();
  EXPECT_TRUE(io::saveStlBinary(m, stl).ok());
  return stl;
}

TEST(CliPrintCheck, aCantileverNeedsItsHandComputedSupportAndLiesBestOnItsSide) {
  test::TempDir dir;
  const std::string stl = cantileverStl(dir);
  auto r = runVoxmod({"printcheck", stl, "--res", "80", "--units", "mm", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["overhang_area"].get<double>(), 300.0, 3.0);
  EXPECT_NEAR(j["support_volume"].get<double>(), 4500.0, 45.0);
  EXPECT_NEAR(j["height"].get<double>(), 20.0, 1e-6);
  EXPECT_EQ(j["trapped_cavities"].size(), 0u);
  EXPECT_EQ(j["trapped_volume"].get<double>(), 0.0);
  EXPECT_EQ(j["normals"], "mesh");

  r = runVoxmod({"printcheck", stl, "--res", "80", "--units", "mm", "--build-direction", "-z", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NEAR(nlohmann::json::parse(r.out)["support_volume"].get<double>(), 0.0, 1e-9);

  r = runVoxmod({"printcheck", stl, "--res", "80", "--units", "mm", "--orient", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["orientations"].size(), 106u);
  double last = -1.0;
  for (const auto& o : j["orientations"]) {
    EXPECT_GE(o["support_volume"].get<double>(), last);
    last = o["support_volume"].get<double>();
    EXPECT_TRUE(o.contains("direction") && o.contains("overhang_area") && o.contains("height"));
  }
  EXPECT_NEAR(j["orientations"][0]["support_volume"].get<double>(), 0.0, 1e-9);
  EXPECT_EQ(j["best_direction"], j["orientations"][0]["direction"]);
}

TEST(CliPrintCheck, aSealedVoidIsOneTrappedCavityAndTheFieldsAreWrittenTogether) {
  test::TempDir dir;
  // a 20 mm box with a sealed 6 mm cubic void (the inner box turned inside out)
  TriangleMesh m = test::boxMesh({0, 0, 0}, {20, 20, 20});
  TriangleMesh inner = test::boxMesh({7, 7, 7}, {13, 13, 13});
  for (Triangle& t : inner.triangles) std::swap(t.v[1], t.v[2]);
  m = test::combined(m, inner);
  const std::string stl = (dir / "void.stl").string();
  ASSERT_TRUE(io::saveStlBinary(m, stl).ok());
  const std::string overhang = (dir / "overhang.nrrd").string(), support = (dir / "support.vti").string();
  auto r = runVoxmod(
      {"printcheck", stl, "--res", "40", "--units", "mm", "--json", "--overhang", overhang, "--support", support});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["trapped_cavities"].size(), 1u);
  const auto& c = j["trapped_cavities"][0];
  EXPECT_NEAR(c["volume"].get<double>(), 216.0, 1e-6);  // 6 mm on a 0.5 mm lattice: exactly 12^3 voxels
  EXPECT_NEAR(c["centre"][0].get<double>(), 10.0, 1e-9);
  EXPECT_NEAR(c["bbox"]["min"][2].get<double>(), 7.0, 1e-9);
  EXPECT_NEAR(c["bbox"]["max"][2].get<double>(), 13.0, 1e-9);
  EXPECT_NEAR(j["trapped_volume"].get<double>(), 216.0, 1e-6);
  // the void's ceiling needs support inside it: 36 mm^2 over 6 mm
  EXPECT_NEAR(j["support_volume"].get<double>(), 216.0, 3.0);
  EXPECT_TRUE(std::filesystem::exists(overhang));
  EXPECT_TRUE(std::filesystem::exists(support));

  // a second file that cannot be written: neither is
  std::filesystem::remove(overhang);
  r = runVoxmod({"printcheck", stl, "--res", "40", "--units", "mm", "--overhang", overhang, "--support",
                 (dir / "missing" / "support.nrrd").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_FALSE(std::filesystem::exists(overhang));
}

TEST(CliPrintCheck, aVoxelFileUsesItsOwnSurfaceAndBadInputIsRefused) {
  test::TempDir dir;
  const std::string stl = cantileverStl(dir), vxm = (dir / "c.vxm").string();
  ASSERT_EQ(runVoxmod({"voxelize", stl, "--res", "80", "--units", "mm", "-o", vxm}).exit_code, 0);
  auto r = runVoxmod({"printcheck", vxm, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["normals"], "voxel surface");
  EXPECT_NEAR(j["support_volume"].get<double>(), 4500.0, 0.03 * 4500.0);

  r = runVoxmod({"printcheck", stl, "--build-direction", "up"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("build direction 'up'"), std::string::npos) << r.err;
  EXPECT_EQ(runVoxmod({"printcheck", stl, "--build-direction", "0,0,0"}).exit_code, 1);
  EXPECT_EQ(runVoxmod({"printcheck", stl, "--overhang-angle", "95"}).exit_code, 1);
  r = runVoxmod({"printcheck", stl, "--support", (dir / "s.png").string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_FALSE(std::filesystem::exists(dir / "s.png"));
  r = runVoxmod({"printcheck", (dir / "nothing.stl").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("nothing.stl"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace vox
