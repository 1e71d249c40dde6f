#include <gtest/gtest.h>

#include "grids.h"
#include "vox/analysis/analysis.h"

namespace vox {
namespace {

TEST(Boolean, wordOperationsMatchVoxelLogic) {
  const VoxelGrid a = test::randomBoxes(Dims{70, 20, 30}, 5, 1);
  VoxelGrid b = test::randomBoxes(Dims{70, 20, 30}, 5, 2);
  for (BoolOp op : {BoolOp::kUnion, BoolOp::kIntersection, BoolOp::kDifference}) {
    auto r = booleanOp(a, b, op);
    ASSERT_TRUE(r.ok());
    for (int z = 0; z < 30; ++z)
      for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 70; ++x) {
          const bool va = a.get(x, y, z), vb = b.get(x, y, z);
          const bool want =
              op == BoolOp::kUnion ? (va || vb) : (op == BoolOp::kIntersection ? (va && vb) : (va && !vb));
          ASSERT_EQ(r->get(x, y, z), want);
        }
  }
}

TEST(Boolean, layersOnlyOneOperandHasAreHandled) {
  VoxelGrid a(Dims{10, 10, 10}), b(Dims{10, 10, 10});
  test::fillBox(a, {0, 0, 0}, {10, 10, 3});
  test::fillBox(b, {0, 0, 7}, {10, 10, 10});
  EXPECT_EQ(booleanOp(a, b, BoolOp::kUnion)->filledCount(), 600);
  const VoxelGrid inter = *booleanOp(a, b, BoolOp::kIntersection);
  EXPECT_EQ(inter.filledCount(), 0);
  EXPECT_EQ(inter.allocatedLayers(), 0);
  const VoxelGrid diff = *booleanOp(a, b, BoolOp::kDifference);
  EXPECT_EQ(diff.filledCount(), 300);
  EXPECT_TRUE(diff.sharesLayerWith(a, 0));  // untouched layers are shared, not copied
  EXPECT_EQ(a.filledCount(), 300);          // operands unchanged
  EXPECT_EQ(b.filledCount(), 300);
}

TEST(Boolean, differentLatticesAreRefusedWithTheReason) {
  const VoxelGrid a(Dims{10, 10, 10}, GridFrame{glm::dvec3(0), 1.0, "mm", "a.stl"});
  auto msg = [&](const VoxelGrid& b) {
    auto r = booleanOp(a, b, BoolOp::kUnion);
    EXPECT_FALSE(r.ok());
    return r.ok() ? std::string() : r.error().message;
  };
  EXPECT_NE(msg(VoxelGrid(Dims{10, 10, 11}, a.frame())).find("dimensions: 10 x 10 x 10 vs 10 x 10 x 11"),
            std::string::npos);
  EXPECT_NE(msg(VoxelGrid(Dims{10, 10, 10}, GridFrame{glm::dvec3(0), 0.5, "mm", ""})).find("voxel size"),
            std::string::npos);
  EXPECT_NE(msg(VoxelGrid(Dims{10, 10, 10}, GridFrame{glm::dvec3(0, 1, 0), 1.0, "mm", ""})).find("origin"),
            std::string::npos);
  EXPECT_NE(msg(VoxelGrid(Dims{10, 10, 10}, GridFrame{glm::dvec3(0), 1.0, "in", ""})).find("units"), std::string::npos);
  // Another source name is the same lattice.
  EXPECT_TRUE(
      booleanOp(a, VoxelGrid(Dims{10, 10, 10}, GridFrame{glm::dvec3(0), 1.0, "mm", "b.stl"}), BoolOp::kIntersection)
          .ok());
}

TEST(Names, axesAndModesRoundTrip) {
  for (Axis a : {Axis::kX, Axis::kY, Axis::kZ}) EXPECT_EQ(parseAxis(axisName(a)), a);
  for (XrayMode m : {XrayMode::kMin, XrayMode::kMax, XrayMode::kTotal}) EXPECT_EQ(parseXrayMode(xrayModeName(m)), m);
  EXPECT_EQ(parseAxis("Z"), Axis::kZ);
  EXPECT_FALSE(parseAxis("w").has_value());
  EXPECT_FALSE(parseAxis("").has_value());
  EXPECT_FALSE(parseXrayMode("mean").has_value());
  EXPECT_STREQ(axisName(Axis::kY), "y");
  EXPECT_STREQ(xrayModeName(XrayMode::kTotal), "total");
}

}  // namespace
}  // namespace vox
