// The voxelizer against ../shared/reference: exact voxelizations of every watertight shared mesh at R = 64, 128 and
// 256 (docs/conventions.md, "Grid placement"). Every mode that applies must reproduce them voxel for voxel.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/test_support.h"
#include "support/test_meshes.h"
#include "vox/io/stl.h"
#include "vox/io/voxel_file.h"
#include "vox/voxelize/voxelize.h"

namespace vox {
namespace {

const std::vector<std::string> kReferenceMeshes = {
    "featuretype", "plate_holes", "rocker_arm",        "fandisk",           "tray_bottom_ascii", "orion_capsule_ascii",
    "armadillo",   "femur_right", "igea_refined_508k", "cube_axis_aligned", "cube_rotated_45z",  "two_disjoint_cubes"};

class ReferenceVoxelization : public ::testing::TestWithParam<std::string> {};

TEST_P(ReferenceVoxelization, everyModeMatchesTheReferenceVoxelForVoxel) {
  VOX_REQUIRE_SHARED(shared);
  const std::string mesh_name = GetParam();
  auto stl = io::loadStl(shared / "meshes" / (mesh_name + ".stl"));
  ASSERT_TRUE(stl.ok()) << stl.error().message;
  for (int r : {64, 128, 256}) {
    auto ref = io::loadBinvox(shared / "reference" / (mesh_name + "_r" + std::to_string(r) + ".binvox"));
    ASSERT_TRUE(ref.ok()) << ref.error().message;
    for (FillMode mode : {FillMode::kParity, FillMode::kNonzero, FillMode::kAuto}) {
      VoxelizeParams params;
      params.resolution = r;
      params.mode = mode;
      auto got = voxelizeSolid(stl->mesh, params, {}, &stl->topology);
      ASSERT_TRUE(got.ok()) << got.error().message;
      EXPECT_EQ(test::mismatches(got->grid, *ref), 0) << mesh_name << " R=" << r << " mode " << fillModeName(mode)
                                                      << " (used " << fillModeName(got->mode_used) << ")";
      EXPECT_EQ(got->grid.filledCount(), ref->filledCount());
      for (const std::string& w : got->warnings) {
        EXPECT_EQ(w.find("odd number"), std::string::npos) << w;
        EXPECT_EQ(w.find("winding"), std::string::npos) << w;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Shared, ReferenceVoxelization, ::testing::ValuesIn(kReferenceMeshes),
                         [](const auto& p) { return p.param; });

}  // namespace
}  // namespace vox
