// .vdb export read back by OpenVDB itself: the grid "voxels" (a float fog volume), its transform (index (0, 0, 0) at
// the centre of voxel (0, 0, 0), the voxel size as scale), the filled voxels as the active ones, full 8^3 blocks as
// tiles, the units as metadata, and fields as grids of their own.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>

#include "support/grids.h"
#include "vox/io/vdb.h"

namespace vox::io {
namespace {

GridFrame frame() {
  return GridFrame{.origin = glm::dvec3(-1.0, 2.0, 0.5), .voxel_size = 0.25, .units = "mm", .source = ""};
}

openvdb::GridPtrVecPtr readBack(const std::vector<uint8_t>& bytes) {
  openvdb::initialize();
  std::istringstream in(std::string(bytes.begin(), bytes.end()), std::ios_base::binary);
  return openvdb::io::Stream(in).getGrids();
}

openvdb::FloatGrid::Ptr gridNamed(const openvdb::GridPtrVec& grids, const std::string& name) {
  for (const auto& g : grids) {
    if (g->getName() == name) return openvdb::gridPtrCast<openvdb::FloatGrid>(g);
  }
  return nullptr;
}

TEST(Vdb, openVdbReadsTheVoxelsWithTheirTransformAndUnits) {
  VoxelGrid g = test::randomGrid(Dims{70, 19, 11}, 0.3, 11);  // leaves cut by the grid's far faces
  g.frame() = frame();
  auto bytes = encodeVdb(voxelsOnly(g));
  ASSERT_TRUE(bytes.ok()) << bytes.error().message;
  auto grids = readBack(*bytes);
  ASSERT_EQ(grids->size(), 1u);
  auto v = gridNamed(*grids, "voxels");
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(v->getGridClass(), openvdb::GRID_FOG_VOLUME);
  EXPECT_EQ(v->background(), 0.0f);
  EXPECT_EQ(int64_t(v->activeVoxelCount()), g.filledCount());
  const openvdb::Vec3d c0 = v->indexToWorld(openvdb::Coord(0, 0, 0));
  EXPECT_NEAR(c0.x(), -0.875, 1e-12);
  EXPECT_NEAR(c0.y(), 2.125, 1e-12);
  EXPECT_NEAR(c0.z(), 0.625, 1e-12);
  EXPECT_NEAR(v->voxelSize().x(), 0.25, 1e-12);
  const openvdb::Vec3d c = v->indexToWorld(openvdb::Coord(5, 3, 2));
  EXPECT_NEAR(c.x(), g.frame().voxelCentre(5, 3, 2).x, 1e-12);
  EXPECT_EQ(v->metaValue<std::string>("units"), "mm");
  EXPECT_EQ(v->metaValue<openvdb::Vec3i>("dims"), openvdb::Vec3i(70, 19, 11));
  auto acc = v->getConstAccessor();
  for (int32_t z = 0; z < g.nz(); ++z)
    for (int32_t y = 0; y < g.ny(); ++y)
      for (int32_t x = 0; x < g.nx(); ++x) {
        const openvdb::Coord ijk(x, y, z);
        ASSERT_EQ(acc.isValueOn(ijk), g.get(x, y, z)) << x << " " << y << " " << z;
        ASSERT_EQ(acc.getValue(ijk), g.get(x, y, z) ? 1.0f : 0.0f);
      }
}

TEST(Vdb, fullBlocksAreStoredAsTiles) {
  VoxelGrid g(Dims{40, 40, 40}, frame());
  for (int32_t z = 0; z < 32; ++z)
    for (int32_t y = 0; y < 32; ++y) g.fillRun(y, z, 0, 32);  // 4^3 whole leaves
  g.set(35, 35, 35);                                          // and one partial leaf
  auto bytes = encodeVdb(voxelsOnly(g));
  ASSERT_TRUE(bytes.ok()) << bytes.error().message;
  auto v = gridNamed(*readBack(*bytes), "voxels");
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(int64_t(v->activeVoxelCount()), 32 * 32 * 32 + 1);
  EXPECT_EQ(v->tree().leafCount(), 1u);
  EXPECT_EQ(v->tree().activeTileCount(), 64u);
}

TEST(Vdb, fieldsAreGridsUnderTheirNamesWithTheSameTransform) {
  VoxelGrid g = test::randomGrid(Dims{12, 9, 10}, 0.5, 5);
  g.frame() = frame();
  ScalarField thickness(g.dims(), g.frame());
  for (int32_t z = 0; z < g.nz(); ++z)
    for (int32_t y = 0; y < g.ny(); ++y)
      for (int32_t x = 0; x < g.nx(); ++x) thickness.at(x, y, z) = g.get(x, y, z) ? float(1 + x + 10 * y) * 0.5f : 0.0f;
  auto bytes = encodeVdb(VolumeContent{&g, {{"thickness", &thickness}}});
  ASSERT_TRUE(bytes.ok()) << bytes.error().message;
  auto grids = readBack(*bytes);
  ASSERT_EQ(grids->size(), 2u);
  auto t = gridNamed(*grids, "thickness");
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(int64_t(t->activeVoxelCount()), g.filledCount());  // active where the value is not 0
  EXPECT_NEAR(t->indexToWorld(openvdb::Coord(0, 0, 0)).x(), -0.875, 1e-12);
  auto acc = t->getConstAccessor();
  for (int32_t z = 0; z < g.nz(); ++z)
    for (int32_t y = 0; y < g.ny(); ++y)
      for (int32_t x = 0; x < g.nx(); ++x) ASSERT_EQ(acc.getValue(openvdb::Coord(x, y, z)), thickness.at(x, y, z));
}

TEST(Vdb, aFieldAloneIsWrittenAndNothingIsRefused) {
  ScalarField f(Dims{2, 2, 2}, frame());
  EXPECT_TRUE(encodeVdb(oneField("distance", f)).ok());
  EXPECT_FALSE(encodeVdb(VolumeContent{}).ok());
}

}  // namespace
}  // namespace vox::io
