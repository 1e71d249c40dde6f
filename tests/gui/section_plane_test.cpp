// The section's plane through picked voxels, checked against the plane's equation worked out by hand, and the 3D
// view's cut along it: the picked voxels lie in the cut's slab.
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "app/section_plane.h"

namespace vox::app {
namespace {

GridFrame frame() {
  GridFrame f;
  f.origin = glm::dvec3(-5.0, 2.0, 10.0);
  f.voxel_size = 0.5;
  return f;
}

TEST(SectionPlane, threePointsGiveTheirPlanesUnitNormalWithItsLargestComponentPositive) {
  const auto n = planeNormal({0, 0, 0}, {0, 2, 0}, {1, 0, 0});  // the plane z = 0; (0,2,0) x (1,0,0) = (0,0,-2)
  ASSERT_TRUE(n.ok());
  EXPECT_DOUBLE_EQ(n->z, 1.0);
  const auto tilted = planeNormal({1, 0, 0}, {0, 1, 0}, {0, 0, 1});  // x + y + z = 1
  ASSERT_TRUE(tilted.ok());
  for (int k = 0; k < 3; ++k) EXPECT_NEAR((*tilted)[k], 1.0 / std::sqrt(3.0), 1e-12);
  EXPECT_FALSE(planeNormal({0, 0, 0}, {1, 1, 1}, {3, 3, 3}).ok());  // on one line
  EXPECT_FALSE(planeNormal({0, 0, 0}, {0, 0, 0}, {3, 0, 1}).ok());  // two the same
}

TEST(SectionPlane, throughThreeVoxelsTheSectionAndTheCutAwayPassThroughTheirCentres) {
  const Dims dims{40, 30, 20};
  const GridFrame f = frame();
  SectionUi s;
  const std::vector<glm::ivec3> picks{{3, 4, 5}, {30, 6, 2}, {10, 25, 15}};
  ASSERT_TRUE(placeSectionPlane(s, f, dims, picks));
  EXPECT_TRUE(s.oblique);
  // The plane: through the box's centre moved `offset` along the unit normal, so n.p = n.centre + offset.
  const glm::dvec3 n = glm::normalize(s.normal);
  const glm::dvec3 centre = f.origin + 0.5 * f.voxel_size * glm::dvec3(40, 30, 20);
  for (const glm::ivec3& v : picks) {
    EXPECT_NEAR(glm::dot(n, f.voxelCentre(v.x, v.y, v.z)), glm::dot(n, centre) + s.offset, 1e-9);
  }
  const glm::dvec3 a = f.voxelCentre(3, 4, 5), b = f.voxelCentre(30, 6, 2), c = f.voxelCentre(10, 25, 15);
  EXPECT_NEAR(std::abs(glm::dot(n, glm::normalize(glm::cross(b - a, c - a)))), 1.0, 1e-12);
  const render::CutAway cut = obliqueCutAway(f, dims, s);
  for (const glm::ivec3& v : picks) EXPECT_EQ(sectionSlab(render::sectionPlane(cut), v), 0);
}

TEST(SectionPlane, throughOneVoxelTheNormalIsKeptAndBadPicksLeaveTheSectionAsItWas) {
  const Dims dims{40, 30, 20};
  SectionUi s;
  s.normal = {0.0, 3.0, 4.0};
  ASSERT_TRUE(placeSectionPlane(s, frame(), dims, {{7, 8, 9}}));
  EXPECT_EQ(s.normal, glm::dvec3(0.0, 3.0, 4.0));
  // y and z of voxel (7, 8, 9): 2 + 8.5 * 0.5 and 10 + 9.5 * 0.5; of the centre: 2 + 7.5 and 10 + 5.
  EXPECT_NEAR(s.offset, 0.6 * (6.25 - 9.5) + 0.8 * (14.75 - 15.0), 1e-12);
  const SectionUi before = s;
  EXPECT_FALSE(placeSectionPlane(s, frame(), dims, {{40, 0, 0}}));                       // outside the grid
  EXPECT_FALSE(placeSectionPlane(s, frame(), dims, {{0, 0, 0}, {1, 1, 1}}));             // two
  EXPECT_FALSE(placeSectionPlane(s, frame(), dims, {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}));  // on one line
  EXPECT_EQ(s.normal, before.normal);
  EXPECT_EQ(s.offset, before.offset);
}

// A normal of any size gives a direction (its largest component scaled to 1 first), so a tiny or huge one cuts as its
// unit vector does; one that gives no direction cuts nothing. The cut is moved kPlaneNudge voxels off the plane.
TEST(SectionPlane, theCutAwayTakesANormalOfAnySizeAndMovesOffTheVoxelCentres) {
  const Dims dims{40, 30, 20};
  SectionUi s;
  s.offset = 0.0;
  for (const glm::dvec3 n : {glm::dvec3(1e-200, 0.0, 0.0), glm::dvec3(1e200, 0.0, 1e-300), glm::dvec3(3.0, 0.0, 0.0)}) {
    s.normal = n;
    const render::CutAway cut = obliqueCutAway(frame(), dims, s);
    ASSERT_EQ(cut.axis, render::SectionAxis::kPlane);
    EXPECT_FLOAT_EQ(cut.normal.x, 1.0f);
    EXPECT_FLOAT_EQ(cut.normal.z, 0.0f);
    EXPECT_FLOAT_EQ(cut.offset, float(20.0 + kPlaneNudge));  // the box's centre, x = 20 voxels
  }
  s.normal = glm::dvec3(0.0);
  EXPECT_EQ(obliqueCutAway(frame(), dims, s).axis, render::SectionAxis::kNone);
}

}  // namespace
}  // namespace vox::app
