#include "vox/render/point_cloud.h"

#include <algorithm>
#include <cstddef>
#include <map>
#include <tuple>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "test_grids.h"
#include "vox/core/surface.h"

namespace vox::render {
namespace {

using testing::ball;
using testing::box;
using testing::fillBox;
using testing::noise;

TEST(PackedPoint, isEightBytesInTheShaderLayout) {
  EXPECT_EQ(sizeof(PackedPoint), 8u);
  EXPECT_EQ(offsetof(PackedPoint, x), 0u);
  EXPECT_EQ(offsetof(PackedPoint, y), 2u);
  EXPECT_EQ(offsetof(PackedPoint, z), 4u);
  EXPECT_EQ(offsetof(PackedPoint, code), 6u);
  EXPECT_EQ(offsetof(PackedPoint, flags), 7u);
}

TEST(PointCloud, holdsExactlyTheSurfaceVoxelsWithTheirCodes) {
  const VoxelGrid g = noise(Dims{70, 13, 11}, 0.6, 1);  // 70 + 2 padding bits: rows span two words
  const PointCloud cloud(g);
  EXPECT_EQ(cloud.size(), countSurfaceVoxels(g));
  int64_t seen = 0;
  for (int32_t z = 0; z < cloud.layerCount(); ++z) {
    for (const PackedPoint& p : cloud.layer(z).points) {
      EXPECT_EQ(p.z, z);
      EXPECT_TRUE(g.get(p.x, p.y, p.z));
      EXPECT_EQ(p.code, g.neighbourCode(p.x, p.y, p.z));
      EXPECT_LT(p.code, 63);
      EXPECT_EQ(p.flags, 0);
      ++seen;
    }
  }
  EXPECT_EQ(seen, cloud.size());
}

TEST(PointCloud, layersAreGroupedByCodeInScanOrder) {
  const VoxelGrid g = noise(Dims{40, 30, 6}, 0.5, 2);
  PointCloud cloud;
  cloud.build(g, 1);
  std::array<int64_t, 64> totals{};
  for (int32_t z = 0; z < cloud.layerCount(); ++z) {
    const LayerSlice& s = cloud.layer(z);
    EXPECT_EQ(s.group_first[0], 0u);
    EXPECT_EQ(s.group_first[64], s.points.size());
    for (int c = 0; c < 64; ++c) {
      ASSERT_LE(s.group_first[size_t(c)], s.group_first[size_t(c) + 1]);
      for (uint32_t i = s.group_first[size_t(c)]; i < s.group_first[size_t(c) + 1]; ++i) {
        EXPECT_EQ(s.points[i].code, c);
        if (i > s.group_first[size_t(c)]) {  // y, then x ascending inside a group
          const PackedPoint& a = s.points[i - 1];
          EXPECT_LT(std::tie(a.y, a.x), std::tie(s.points[i].y, s.points[i].x));
        }
      }
      totals[size_t(c)] += s.groupSize(c);
    }
  }
  for (int c = 0; c < 64; ++c) EXPECT_EQ(cloud.groupSize(c), totals[size_t(c)]);
  EXPECT_EQ(cloud.groupSize(63), 0);
}

TEST(PointCloud, assembleIsCodeMajorAndHoldsEveryPoint) {
  const VoxelGrid g = noise(Dims{33, 20, 9}, 0.55, 3);
  const PointCloud cloud(g);
  PointBuffer buf;
  cloud.assemble(buf);
  ASSERT_EQ(int64_t(buf.points.size()), cloud.size());
  EXPECT_EQ(buf.group_first[64], cloud.size());
  for (int c = 0; c < 64; ++c) {
    EXPECT_EQ(buf.groupSize(c), cloud.groupSize(c));
    for (int64_t i = buf.group_first[size_t(c)]; i < buf.group_first[size_t(c) + 1]; ++i) {
      EXPECT_EQ(buf.points[size_t(i)].code, c);
    }
  }
  std::vector<PackedPoint> from_layers;
  for (int32_t z = 0; z < cloud.layerCount(); ++z) {
    from_layers.insert(from_layers.end(), cloud.layer(z).points.begin(), cloud.layer(z).points.end());
  }
  auto key = [](const PackedPoint& p) { return std::tie(p.z, p.y, p.x); };
  auto less = [&](const PackedPoint& a, const PackedPoint& b) { return key(a) < key(b); };
  std::vector<PackedPoint> assembled = buf.points;
  std::sort(assembled.begin(), assembled.end(), less);
  std::sort(from_layers.begin(), from_layers.end(), less);
  EXPECT_EQ(assembled, from_layers);
}

TEST(PointCloud, threadCountDoesNotChangeTheResult) {
  const VoxelGrid g = ball(48, 20.3);
  PointCloud one, many;
  one.build(g, 1);
  many.build(g, 4);
  PointBuffer a, b;
  one.assemble(a);
  many.assemble(b);
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.group_first, b.group_first);
}

// Incremental updates must give exactly the cloud a full build gives, including the layers next to the edit whose
// codes changed (an edit at z changes the z-1 / z+1 bits of its neighbours above and below).
TEST(PointCloud, incrementalLayerRebuildEqualsFullRebuild) {
  VoxelGrid g = ball(40, 17.5);
  PointCloud cloud(g);
  std::mt19937 rng(7);
  for (int step = 0; step < 25; ++step) {
    const int32_t z0 = int32_t(rng() % 40), z1 = std::min(40, z0 + 1 + int32_t(rng() % 4));
    for (int32_t z = z0; z < z1; ++z) {
      for (int k = 0; k < 30; ++k) g.set(rng() % 40, rng() % 40, z, rng() % 2 == 0);
    }
    const uint64_t version = cloud.version();
    cloud.rebuildLayers(g, z0, z1);
    EXPECT_GT(cloud.version(), version);
    const PointCloud full(g);
    ASSERT_EQ(cloud.size(), full.size()) << "step " << step;
    for (int32_t z = 0; z < 40; ++z) {
      EXPECT_EQ(cloud.layer(z).points, full.layer(z).points) << "step " << step << " layer " << z;
      EXPECT_EQ(cloud.layer(z).group_first, full.layer(z).group_first);
    }
    for (int c = 0; c < 64; ++c) EXPECT_EQ(cloud.groupSize(c), full.groupSize(c));
  }
}

TEST(PointCloud, rebuildWithOtherDimsIsAFullBuild) {
  PointCloud cloud(ball(20, 8));
  const VoxelGrid other = ball(26, 11);
  cloud.rebuildLayers(other, 3, 4);
  EXPECT_EQ(cloud.dims(), other.dims());
  EXPECT_EQ(cloud.size(), countSurfaceVoxels(other));
}

TEST(PointCloud, boundsAreTheTightBoxOfTheSolid) {
  const VoxelGrid g = box(Dims{50, 40, 30}, {5, 7, 9}, {20, 33, 11});
  const Box3 b = PointCloud(g).bounds();
  EXPECT_EQ(b.min, glm::dvec3(5, 7, 9));
  EXPECT_EQ(b.max, glm::dvec3(20, 33, 11));
  const Box3 empty = PointCloud(VoxelGrid(Dims{4, 5, 6})).bounds();
  EXPECT_EQ(empty.max, glm::dvec3(4, 5, 6));
}

TEST(PointCloud, sectionBoundsHoldTheKeptHalfAndTheCutLayer) {
  VoxelGrid g = box(Dims{50, 40, 30}, {5, 7, 9}, {20, 33, 25});
  fillBox(g, {30, 2, 20}, {45, 4, 30});  // a second block, only at z >= 20
  const PointCloud cloud(g);
  EXPECT_EQ(cloud.bounds().min, glm::dvec3(5, 2, 9));
  const Box3 below = cloud.bounds(CutAway{SectionAxis::kZ, 15, SectionSide::kBelow});
  EXPECT_EQ(below.min, glm::dvec3(5, 7, 9));  // the second block is cut away entirely
  EXPECT_EQ(below.max, glm::dvec3(20, 33, 16));
  const Box3 above = cloud.bounds(CutAway{SectionAxis::kZ, 15, SectionSide::kAbove});
  EXPECT_EQ(above.min, glm::dvec3(5, 2, 15));
  EXPECT_EQ(above.max, glm::dvec3(45, 33, 30));
  const Box3 none = cloud.bounds(CutAway{SectionAxis::kX, 2, SectionSide::kBelow});  // nothing kept
  EXPECT_EQ(none.min, cloud.bounds().min);
}

// ---- Group culling ----

TEST(GroupCulling, orthographicAxisViewsSeeOnlyTheFacingDirection) {
  const Box3 b{{0, 0, 0}, {10, 10, 10}};
  struct Case {
    StandardView view;
    size_t face;  // index into kFaceNormals
  };
  for (const Case& c : {Case{StandardView::kNegY, 0}, Case{StandardView::kNegX, 1}, Case{StandardView::kPosX, 2},
                        Case{StandardView::kPosY, 3}, Case{StandardView::kNegZ, 4}, Case{StandardView::kPosZ, 5}}) {
    Camera cam;
    cam.projection = Projection::kOrthographic;
    cam.setStandardView(c.view);
    const auto v = visibleFaceDirections(cam, b);
    for (size_t f = 0; f < 6; ++f) EXPECT_EQ(v[f], f == c.face) << "view " << int(c.view) << " face " << f;
  }
  Camera iso;
  iso.projection = Projection::kOrthographic;
  iso.setStandardView(StandardView::kIso);
  EXPECT_EQ(visibleFaceDirections(iso, b), (std::array<bool, 6>{false, false, true, true, false, true}));
}

TEST(GroupCulling, codesAreVisibleWhenAnyFreeFaceIs) {
  std::array<bool, 6> dirs{};
  dirs[5] = true;  // only +Z faces face the camera
  const auto v = visibleCodes(dirs);
  EXPECT_TRUE(v[0]);    // isolated voxel: all faces free
  EXPECT_TRUE(v[62]);   // only z+1 free
  EXPECT_FALSE(v[61]);  // only z-1 free
  EXPECT_FALSE(v[31]);  // only y-1 free
  EXPECT_TRUE(v[63 & ~1 & ~32]);
  EXPECT_FALSE(v[63]);
  int n = 0;
  for (bool b : v) n += b;
  EXPECT_EQ(n, 32);  // codes with bit 1 clear
}

TEST(GroupCulling, perspectiveEyeInsideTheBoxSeesEverything) {
  Camera cam;
  cam.target = {5, 5, 5};
  cam.distance = 1;
  const auto v = visibleFaceDirections(cam, Box3{{0, 0, 0}, {10, 10, 10}});
  for (bool b : v) EXPECT_TRUE(b);
}

// Against the exact per-voxel test: from the eye, a free face of a voxel is front-facing when the eye lies strictly
// on its outer side. Every voxel with such a face must be in a drawn group.
TEST(GroupCulling, perspectiveTestNeverDropsAFrontFacingVoxel) {
  const VoxelGrid g = ball(30, 12.2);
  const PointCloud cloud(g);
  const Box3 b = cloud.bounds();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> angle(-180, 180);
  int64_t culled_total = 0;
  for (int trial = 0; trial < 40; ++trial) {
    Camera cam;
    cam.target = {15, 15, 15};
    cam.yaw_deg = angle(rng);
    cam.pitch_deg = angle(rng) / 2;
    cam.distance = 14 + trial * 3;  // from just outside the ball to far away
    const auto drawn = visibleCodes(visibleFaceDirections(cam, b));
    const glm::dvec3 eye = cam.eyePosition();
    for (int32_t z = 0; z < cloud.layerCount(); ++z) {
      for (const PackedPoint& p : cloud.layer(z).points) {
        bool front = false;
        for (size_t f = 0; f < 6; ++f) {
          if (p.code & kFaceBits[f]) continue;
          const glm::dvec3 n(kFaceNormals[f][0], kFaceNormals[f][1], kFaceNormals[f][2]);
          const glm::dvec3 face_centre = glm::dvec3(p.x, p.y, p.z) + 0.5 + n * 0.5;
          if (glm::dot(eye - face_centre, n) > 0) front = true;
        }
        if (front) {
          EXPECT_TRUE(drawn[p.code]) << "trial " << trial << " code " << int(p.code);
        }
        if (!drawn[p.code]) ++culled_total;
      }
    }
  }
  EXPECT_GT(culled_total, 0);  // and it does cull something from outside
}

// ---- Section ----

TEST(CutAway, keepsStrictlyOneSide) {
  const CutAway none;
  EXPECT_TRUE(keepsPoint(none, {5, 5, 5}));
  const CutAway below{SectionAxis::kY, 10, SectionSide::kBelow};
  EXPECT_TRUE(keepsPoint(below, {99, 9, 99}));
  EXPECT_FALSE(keepsPoint(below, {0, 10, 0}));  // the plane itself is drawn as the cut face
  EXPECT_FALSE(keepsPoint(below, {0, 11, 0}));
  const CutAway above{SectionAxis::kZ, 3, SectionSide::kAbove};
  EXPECT_TRUE(keepsPoint(above, {0, 0, 4}));
  EXPECT_FALSE(keepsPoint(above, {0, 0, 3}));
  EXPECT_FALSE(keepsPoint(above, {0, 0, 2}));
}

TEST(CutAway, cutFaceIsEveryFilledVoxelOfThePlane) {
  const VoxelGrid g = ball(40, 15.7);
  for (SectionAxis axis : {SectionAxis::kX, SectionAxis::kY, SectionAxis::kZ}) {
    for (int32_t index : {3, 20, 27}) {
      const CutAway s{axis, index, SectionSide::kBelow};
      const auto pts = sectionPoints(g, s);
      int64_t expected = 0;
      for (int32_t a = 0; a < 40; ++a)
        for (int32_t b = 0; b < 40; ++b) {
          const glm::ivec3 v = axis == SectionAxis::kX   ? glm::ivec3(index, a, b)
                               : axis == SectionAxis::kY ? glm::ivec3(a, index, b)
                                                         : glm::ivec3(a, b, index);
          expected += g.get(v.x, v.y, v.z);
        }
      EXPECT_EQ(int64_t(pts.size()), expected) << "axis " << int(axis) << " index " << index;
      for (const PackedPoint& p : pts) {
        EXPECT_EQ(p.flags, kPointFlagCut);
        EXPECT_TRUE(g.get(p.x, p.y, p.z));
        EXPECT_EQ(p.code, g.neighbourCode(p.x, p.y, p.z));
        EXPECT_EQ(glm::ivec3(p.x, p.y, p.z)[int(axis) - 1], index);
      }
    }
  }
  // Interior voxels of the plane are included (they are what makes the cut face closed).
  const auto mid = sectionPoints(g, CutAway{SectionAxis::kZ, 20, SectionSide::kAbove});
  EXPECT_TRUE(std::any_of(mid.begin(), mid.end(), [](const PackedPoint& p) { return p.code == 63; }));
  EXPECT_TRUE(sectionPoints(g, CutAway{SectionAxis::kX, 40, SectionSide::kBelow}).empty());
  EXPECT_TRUE(sectionPoints(g, CutAway{SectionAxis::kZ, -1, SectionSide::kBelow}).empty());
  EXPECT_TRUE(sectionPoints(g, CutAway{}).empty());
}

// A plane at any angle: the cut face is the standard digital plane's filled voxels, one voxel thick and without
// gaps, so the kept half and the removed half never touch across a face.
TEST(CutAway, aPlaneAtAnAngleSeparatesTheHalvesByAGaplessSlab) {
  for (const glm::vec3 n : {glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f)), glm::normalize(glm::vec3(1.0f, 2.0f, 3.0f)),
                            glm::normalize(glm::vec3(-0.3f, 0.1f, 1.0f))}) {
    const SectionPlane plane = sectionPlane(CutAway{SectionAxis::kPlane, 0, SectionSide::kBelow, n, 31.37f});
    for (int32_t z = 0; z < 30; ++z)
      for (int32_t y = 0; y < 30; ++y)
        for (int32_t x = 0; x < 30; ++x) {
          const int here = sectionSlab(plane, {x, y, z});
          for (const glm::ivec3 step : {glm::ivec3(1, 0, 0), glm::ivec3(0, 1, 0), glm::ivec3(0, 0, 1)}) {
            ASSERT_NE(here * sectionSlab(plane, glm::ivec3(x, y, z) + step), -1) << x << " " << y << " " << z;
          }
        }
  }
}

// Checks a plane with this normal (any signs, any largest component) through about the ball's centre.
void checkSlabOfBall(const VoxelGrid& g, const glm::dvec3& normal) {
  const glm::vec3 n = glm::vec3(glm::normalize(normal));
  const glm::dvec3 nd = glm::dvec3(n);
  const float offset = float(glm::dot(nd, glm::dvec3(20.0))) + 0.123f;  // near the ball's centre
  const CutAway cut{SectionAxis::kPlane, 0, SectionSide::kBelow, n, offset};
  const auto pts = sectionPoints(g, cut);
  // Independently: the filled voxels whose centre lies within half the normal's L1 norm of the plane (double).
  const double l1 = std::abs(nd.x) + std::abs(nd.y) + std::abs(nd.z);
  const double half = 0.5 * l1;
  int64_t expected = 0;
  for (int32_t z = 0; z < 40; ++z)
    for (int32_t y = 0; y < 40; ++y)
      for (int32_t x = 0; x < 40; ++x) {
        const double s = glm::dot(nd, glm::dvec3(x, y, z) + 0.5) - double(offset);
        const bool in = s >= -half && s < half;
        expected += in && g.get(x, y, z);
        if (g.get(x, y, z) && !in) {
          EXPECT_EQ(keepsPoint(cut, {x, y, z}), s < -half);
        }
      }
  EXPECT_EQ(int64_t(pts.size()), expected);
  for (const PackedPoint& p : pts) {
    EXPECT_EQ(p.flags, kPointFlagCut);
    EXPECT_TRUE(g.get(p.x, p.y, p.z));
    EXPECT_EQ(sectionSlab(sectionPlane(cut), {p.x, p.y, p.z}), 0);
  }
  // A standard plane holds |n|_1 voxels per unit of its area: the disc of radius 15.7 through (about) the centre.
  const double disc = 3.14159265358979 * 15.7 * 15.7 * l1;
  EXPECT_NEAR(double(pts.size()), disc, 0.05 * disc);
}

TEST(CutAway, aPlaneAtAnAngleCutsTheFilledVoxelsOfItsSlab) {
  const VoxelGrid g = ball(40, 15.7);
  for (const glm::dvec3 n : {glm::dvec3(1, 2, 3), glm::dvec3(-3, 1, 0.5), glm::dvec3(0.2, -2, 0.7)}) {
    SCOPED_TRACE(::testing::Message() << "normal " << n.x << " " << n.y << " " << n.z);
    checkSlabOfBall(g, n);
  }
  const glm::vec3 n = glm::normalize(glm::vec3(1.0f, 2.0f, 3.0f));
  const float offset = float(glm::dot(glm::dvec3(n), glm::dvec3(20.0))) + 0.123f;
  const CutAway cut{SectionAxis::kPlane, 0, SectionSide::kBelow, n, offset};
  // Normal to an axis, the plane through the voxel centres of an index is that axis section.
  const CutAway z20{SectionAxis::kPlane, 0, SectionSide::kBelow, glm::vec3(0.0f, 0.0f, 1.0f), 20.5f};
  EXPECT_EQ(sectionPoints(g, z20).size(), sectionPoints(g, CutAway{SectionAxis::kZ, 20, SectionSide::kBelow}).size());
  // A plane far outside the grid cuts nothing.
  for (const float far : {1e12f, -1e12f}) {
    EXPECT_TRUE(sectionPoints(g, CutAway{SectionAxis::kPlane, 0, SectionSide::kBelow, n, far}).empty());
  }
  // At a level of detail with 2^k fine voxels per point the offset is in that level's units.
  EXPECT_FLOAT_EQ(sectionPlane(cut, 2).offset, offset / 4.0f);
  EXPECT_FLOAT_EQ(sectionPlane(CutAway{SectionAxis::kX, 21}, 1).offset, 10.5f);
}

// ---- Level of detail ----

TEST(Downsample, coarseVoxelIsTheOrOfItsEightFineVoxels) {
  for (Dims d : {Dims{7, 5, 3}, Dims{130, 9, 8}, Dims{64, 64, 5}, Dims{191, 3, 4}}) {
    const VoxelGrid fine = noise(d, 0.04, 5);
    const VoxelGrid coarse = downsample2(fine);
    ASSERT_EQ(coarse.dims(), (Dims{(d.nx + 1) / 2, (d.ny + 1) / 2, (d.nz + 1) / 2}));
    EXPECT_DOUBLE_EQ(coarse.voxelSize(), 2 * fine.voxelSize());
    for (int32_t z = 0; z < coarse.nz(); ++z)
      for (int32_t y = 0; y < coarse.ny(); ++y)
        for (int32_t x = 0; x < coarse.nx(); ++x) {
          bool any = false;
          for (int k = 0; k < 8; ++k) any |= fine.get(2 * x + (k & 1), 2 * y + ((k >> 1) & 1), 2 * z + (k >> 2));
          ASSERT_EQ(coarse.get(x, y, z), any)
              << d.nx << "x" << d.ny << "x" << d.nz << " at " << x << "," << y << "," << z;
        }
    // Padding bits stay clear (the extractor relies on them).
    for (int32_t z = 0; z < coarse.nz(); ++z)
      for (int32_t y = 0; y < coarse.ny(); ++y) {
        EXPECT_FALSE(coarse.get(-1, y, z));
        EXPECT_FALSE(coarse.get(coarse.nx(), y, z));
      }
  }
}

TEST(Downsample, layerRangeUpdateMatchesFullDownsample) {
  VoxelGrid fine = ball(50, 21);
  VoxelGrid coarse = downsample2(fine);
  for (int32_t z = 10; z < 14; ++z)
    for (int32_t y = 0; y < 50; ++y) fine.mutableRowWords(y, z)[0] = 0;  // carve x < 63 of four layers
  fine.set(49, 49, 13);
  downsample2Layers(fine, coarse, 5, 7);
  const VoxelGrid expected = downsample2(fine);
  for (int32_t z = 0; z < coarse.nz(); ++z)
    for (int32_t y = 0; y < coarse.ny(); ++y)
      for (int32_t x = 0; x < coarse.nx(); ++x) ASSERT_EQ(coarse.get(x, y, z), expected.get(x, y, z));
}

TEST(Downsample, quartersTheSurfacePointsOfABall) {
  const VoxelGrid g = ball(96, 40);
  const double ratio = double(PointCloud(downsample2(g)).size()) / double(PointCloud(g).size());
  EXPECT_GT(ratio, 0.2);
  EXPECT_LT(ratio, 0.3);
}

}  // namespace
}  // namespace vox::render
