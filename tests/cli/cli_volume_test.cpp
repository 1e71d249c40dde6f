// Volume export from the command line (docs/conventions.md, "Command line"): `convert IN OUT` by OUT's extension,
// thickness and distance fields in the volume formats that hold fields; refusals before any work, failures that
// leave nothing behind. What the files hold is checked by the io tests and the judges (VTK, OpenVDB).
#include <filesystem>

#include <nlohmann/json.hpp>

#include "support/test_support.h"
#include "vox/io/nrrd.h"
#include "vox/io/stl.h"

namespace vox {
namespace {

using test::runVoxmod;
using json = nlohmann::json;

class CliVolume : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(io::saveStlBinary(test::unitCubeMesh(), box_stl()).ok()); }
  std::string box_stl() const { return (tmp_ / "box.stl").string(); }
  std::string path(const std::string& name) const { return (tmp_ / name).string(); }
  int files() const {
    int n = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(tmp_.path())) ++n;
    return n;
  }
  test::TempDir tmp_;
};

TEST_F(CliVolume, convertWritesEveryVolumeFormatByExtension) {
  for (const char* name : {"box.nrrd", "box.vti", "box.vdb", "box.vox", "BOX.VTI"}) {
    SCOPED_TRACE(name);
    auto r = runVoxmod({"convert", box_stl(), path(name), "--res", "12", "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json j = json::parse(r.out);
    EXPECT_EQ(j["dims"], json::array({12, 12, 12}));
    EXPECT_EQ(j["filled"], 12 * 12 * 12);
    EXPECT_EQ(j["output"], path(name));
    EXPECT_GT(std::filesystem::file_size(path(name)), 0u);
  }
  auto vox = runVoxmod({"convert", box_stl(), path("big.vox"), "--res", "300", "--json"});
  ASSERT_EQ(vox.exit_code, 0) << vox.err;
  EXPECT_EQ(json::parse(vox.out)["models"], 8);  // 300^3 in 256^3 models
}

TEST_F(CliVolume, thicknessWritesItsFieldsAsVolumesAndRefusesVoxOnlyFormats) {
  auto r = runVoxmod({"thickness", box_stl(), "--res", "10", "-o", path("t.vti"), "--distance", path("d.vdb")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(path("t.vti")));
  EXPECT_TRUE(std::filesystem::exists(path("d.vdb")));
  for (const char* bad : {"t.vox", "t.raw"}) {
    SCOPED_TRACE(bad);
    auto refused = runVoxmod({"thickness", box_stl(), "--res", "10", "-o", path(bad)});
    EXPECT_EQ(refused.exit_code, 1);
    EXPECT_NE(refused.err.find(".nrrd, .vti or .vdb"), std::string::npos) << refused.err;
    EXPECT_FALSE(std::filesystem::exists(path(bad)));
  }
}

// The 10^3 block of the unit cube at R = 10: 5 skin layers; every ray along an axis crosses 10 voxels of 0.1.
TEST_F(CliVolume, peelWritesTheDepthAndXrayTheRaysAsVolumes) {
  auto peel = runVoxmod(
      {"peel", box_stl(), "--res", "10", "--all", "--depth", path("depth.nrrd"), "-o", path("core.vxm"), "--json"});
  ASSERT_EQ(peel.exit_code, 0) << peel.err;
  EXPECT_EQ(json::parse(peel.out)["depth"], path("depth.nrrd"));
  EXPECT_TRUE(std::filesystem::exists(path("core.vxm")));
  auto depth = io::loadNrrdField(path("depth.nrrd"));
  ASSERT_TRUE(depth.ok()) << depth.error().message;
  EXPECT_EQ(depth->at(0, 0, 0), 1.0f);  // the outer skin
  EXPECT_EQ(depth->at(4, 5, 5), 5.0f);  // the core
  EXPECT_EQ(depth->at(2, 5, 5), 3.0f);

  auto xray = runVoxmod({"xray", box_stl(), "--res", "10", "--axis", "y", "--mode", "total", "-o", path("x.png"),
                         "--volume", path("x.nrrd")});
  ASSERT_EQ(xray.exit_code, 0) << xray.err;
  auto slab = io::loadNrrdField(path("x.nrrd"));
  ASSERT_TRUE(slab.ok()) << slab.error().message;
  EXPECT_EQ(slab->dims, (Dims{10, 1, 10}));
  for (float v : slab->values) EXPECT_NEAR(v, 1.0f, 1e-6f);

  EXPECT_EQ(runVoxmod({"peel", box_stl(), "--res", "10", "--all", "--depth", path("d.vox")}).exit_code, 1);
  EXPECT_EQ(runVoxmod({"peel", box_stl(), "--res", "10", "--distance", "0.1", "--depth", path("d.vti")}).exit_code, 1);
  EXPECT_EQ(runVoxmod({"xray", box_stl(), "--res", "10", "--axis", "y", "--mode", "total", "-o", path("y.png"),
                       "--volume", path("y.vox")})
                .exit_code,
            1);
  EXPECT_FALSE(std::filesystem::exists(path("y.png")));
}

TEST_F(CliVolume, anUnwritableOutputIsExitTwoNamingTheFileAndLeavesNothing) {
  const int before = files();
  for (const char* name : {"missing/box.vti", "missing/box.vdb", "missing/box.vox", "missing/box.nrrd"}) {
    auto r = runVoxmod({"convert", box_stl(), path(name), "--res", "8"});
    EXPECT_EQ(r.exit_code, 2) << name;
    EXPECT_NE(r.err.find(path(name)), std::string::npos) << r.err;
  }
  EXPECT_EQ(files(), before);
  auto unknown = runVoxmod({"convert", box_stl(), path("box.xyz"), "--res", "8"});
  EXPECT_EQ(unknown.exit_code, 1);
  EXPECT_NE(unknown.err.find(".nrrd, .vti, .vdb or .vox"), std::string::npos) << unknown.err;
}

}  // namespace
}  // namespace vox
