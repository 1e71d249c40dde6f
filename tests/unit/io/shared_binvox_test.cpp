// The reference voxelizations in ../shared/reference/ (written by an independent tool) read with the filled counts
// and headers that ../shared/reference/manifest.json records, and survive a write/read round trip through our
// own binvox writer.
#include <gtest/gtest.h>

#include "support/test_support.h"
#include "vox/io/voxel_file.h"

namespace vox::io {
namespace {

struct ReferenceCase {
  const char* file;
  int64_t filled;
};

// `filled` of every R = 64 entry of ../shared/reference/manifest.json.
const ReferenceCase kReferences[] = {
    {"featuretype_r64.binvox", 24722},       {"plate_holes_r64.binvox", 8069},
    {"rocker_arm_r64.binvox", 11141},        {"fandisk_r64.binvox", 37656},
    {"tray_bottom_ascii_r64.binvox", 3543},  {"orion_capsule_ascii_r64.binvox", 17378},
    {"armadillo_r64.binvox", 18020},         {"femur_right_r64.binvox", 1668},
    {"igea_refined_508k_r64.binvox", 74493}, {"cube_axis_aligned_r64.binvox", 262144},
    {"cube_rotated_45z_r64.binvox", 91305},  {"two_disjoint_cubes_r64.binvox", 32600},
};

class ReferenceBinvox : public ::testing::TestWithParam<ReferenceCase> {};

TEST_P(ReferenceBinvox, readsWithManifestFilledCountAndRoundTripsThroughOurWriter) {
  VOX_REQUIRE_SHARED(shared);
  const ReferenceCase& c = GetParam();
  const auto r = loadBinvox(shared / "reference" / c.file);
  ASSERT_TRUE(r.ok()) << r.error().message;
  const VoxelGrid& g = r.value();
  EXPECT_EQ(g.dims(), (Dims{64, 64, 64}));
  EXPECT_EQ(g.filledCount(), c.filled);
  EXPECT_EQ(g.frame().source, c.file);

  const auto again = decodeBinvox(encodeBinvox(g), "again.binvox");
  ASSERT_TRUE(again.ok()) << again.error().message;
  ASSERT_EQ(again->dims(), g.dims());
  EXPECT_EQ(again->frame().origin, g.frame().origin);
  EXPECT_EQ(again->frame().voxel_size, g.frame().voxel_size);  // exact: D = 64 is a power of two
  int64_t mismatches = 0;
  for (int z = 0; z < 64; ++z)
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) mismatches += g.get(x, y, z) != again->get(x, y, z);
  EXPECT_EQ(mismatches, 0);
}

INSTANTIATE_TEST_SUITE_P(Corpus, ReferenceBinvox, ::testing::ValuesIn(kReferences),
                         [](const ::testing::TestParamInfo<ReferenceCase>& p) {
                           std::string n = p.param.file;
                           n = n.substr(0, n.find('.'));
                           for (char& ch : n) {
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           }
                           return n;
                         });

TEST(ReferenceBinvoxDetails, headerGivesOriginAndVoxelSizeAndAxisOrder) {
  VOX_REQUIRE_SHARED(shared);
  // fandisk R = 64 (manifest): translate (0, 12.605500221252441, -2.680259943008423), scale 5.244500160217285.
  const auto r = loadBinvox(shared / "reference" / "fandisk_r64.binvox");
  ASSERT_TRUE(r.ok()) << r.error().message;
  const GridFrame& f = r->frame();
  EXPECT_DOUBLE_EQ(f.origin.x, 0.0);
  EXPECT_DOUBLE_EQ(f.origin.y, 12.605500221252441);
  EXPECT_DOUBLE_EQ(f.origin.z, -2.680259943008423);
  EXPECT_DOUBLE_EQ(f.voxel_size, 5.244500160217285 / 64);
  // fandisk's extents are 4.83 x 5.24 x 2.68: y is the long axis, so the filled voxels reach y = 63 but stay
  // below x = 59 and z = 33. A reader that swapped the axes would put them elsewhere.
  int max_ijk[3] = {-1, -1, -1};
  for (int z = 0; z < 64; ++z)
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) {
        if (!r->get(x, y, z)) continue;
        max_ijk[0] = std::max(max_ijk[0], x);
        max_ijk[1] = std::max(max_ijk[1], y);
        max_ijk[2] = std::max(max_ijk[2], z);
      }
  EXPECT_EQ(max_ijk[1], 63);
  EXPECT_LE(max_ijk[0], 58);
  EXPECT_LE(max_ijk[2], 32);
}

}  // namespace
}  // namespace vox::io
