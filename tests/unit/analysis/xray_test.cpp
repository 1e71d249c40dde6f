#include <gtest/gtest.h>

#include <numeric>
#include <sstream>

#include "grids.h"
#include "vox/analysis/analysis.h"

namespace vox {
namespace {

using test::fillBox;

// A hollow box whose walls across `axis` are t1 (low side) and t2 (high side) thick, with a cavity between them;
// the other walls are 2 thick. Rays along `axis` through the cavity meet t1, then empty space, then t2.
VoxelGrid hollowBox(int axis, int t1, int t2, int cavity, glm::ivec3* cavity_lo, glm::ivec3* cavity_hi) {
  const int side = 20;  // across the other two axes
  glm::ivec3 size(side);
  size[axis] = t1 + cavity + t2;
  VoxelGrid g(Dims{size.x + 4, size.y + 4, size.z + 4});
  const glm::ivec3 lo(2);
  fillBox(g, lo, lo + size);
  glm::ivec3 clo = lo + glm::ivec3(2), chi = lo + size - glm::ivec3(2);
  clo[axis] = lo[axis] + t1;
  chi[axis] = lo[axis] + t1 + cavity;
  for (int z = clo.z; z < chi.z; ++z)
    for (int y = clo.y; y < chi.y; ++y)
      for (int x = clo.x; x < chi.x; ++x) g.reset(x, y, z);
  *cavity_lo = clo;
  *cavity_hi = chi;
  return g;
}

TEST(Xray, hollowBoxGivesTheWallThicknesses) {
  for (int axis = 0; axis < 3; ++axis) {
    const int t1 = 3, t2 = 7, cavity = 10;
    glm::ivec3 clo, chi;
    const VoxelGrid g = hollowBox(axis, t1, t2, cavity, &clo, &chi);
    const int full = t1 + cavity + t2;
    const int64_t rays = 20 * 20, cavity_rays = 16 * 16;
    for (XrayMode mode : {XrayMode::kMin, XrayMode::kMax, XrayMode::kTotal}) {
      auto r = computeXray(g, XrayParams{Axis(axis), mode});
      ASSERT_TRUE(r.ok());
      EXPECT_EQ(r->rays_hit, rays);
      // The ray through the middle of the cavity.
      const glm::ivec3 mid = (clo + chi) / 2;
      const int u = axis == 0 ? mid.y : mid.x;
      const int v = axis == 2 ? mid.y : mid.z;
      const int32_t value = r->thickness.at(u, r->thickness.height - 1 - v);
      const int expect = mode == XrayMode::kMin ? t1 : (mode == XrayMode::kMax ? t2 : t1 + t2);
      EXPECT_EQ(value, expect) << "axis " << axis << " mode " << xrayModeName(mode);
      // Over all rays: cavity rays give `expect`, the others pass the full solid length.
      EXPECT_EQ(r->min, mode == XrayMode::kMax ? t2 : expect);
      EXPECT_EQ(r->max, mode == XrayMode::kTotal ? full : full);
      EXPECT_DOUBLE_EQ(r->mean, double(cavity_rays * expect + (rays - cavity_rays) * full) / double(rays));
    }
  }
}

TEST(Xray, matchesBruteForceRunsOnRandomGrids) {
  for (int nx : {1, 62, 63, 64, 65, 126, 130}) {
    const VoxelGrid g = test::randomGrid(Dims{nx, 13, 11}, 0.55, uint32_t(nx * 3));
    for (int axis = 0; axis < 3; ++axis) {
      for (XrayMode mode : {XrayMode::kMin, XrayMode::kMax, XrayMode::kTotal}) {
        auto r = computeXray(g, XrayParams{Axis(axis), mode});
        ASSERT_TRUE(r.ok());
        const Image2D<int32_t>& t = r->thickness;
        const int nu = axis == 0 ? g.ny() : g.nx();
        const int nv = axis == 2 ? g.ny() : g.nz();
        ASSERT_EQ(t.width, nu);
        ASSERT_EQ(t.height, nv);
        int64_t hit = 0, sum = 0;
        for (int v = 0; v < nv; ++v) {
          for (int u = 0; u < nu; ++u) {
            glm::ivec3 s(0);
            if (axis == 0) s = {0, u, v};
            if (axis == 1) s = {u, 0, v};
            if (axis == 2) s = {u, v, 0};
            const std::vector<int> runs = test::bruteRuns(g, s, axis);
            int expect = 0;
            if (!runs.empty()) {
              if (mode == XrayMode::kMin) expect = *std::min_element(runs.begin(), runs.end());
              if (mode == XrayMode::kMax) expect = *std::max_element(runs.begin(), runs.end());
              if (mode == XrayMode::kTotal) expect = std::accumulate(runs.begin(), runs.end(), 0);
              ++hit;
              sum += expect;
            }
            ASSERT_EQ(t.at(u, nv - 1 - v), expect) << "nx " << nx << " axis " << axis << " u " << u << " v " << v;
          }
        }
        EXPECT_EQ(r->rays_hit, hit);
        if (hit) {
          EXPECT_DOUBLE_EQ(r->mean, double(sum) / double(hit));
        }
      }
    }
  }
}

TEST(Xray, csvListsRaysThatHitMaterial) {
  VoxelGrid g(Dims{4, 3, 5}, GridFrame{glm::dvec3(0), 0.25, "mm", ""});
  fillBox(g, {1, 2, 0}, {2, 3, 3});  // one column along z at (1, 2), 3 long
  g.set(3, 0, 4);
  auto r = computeXray(g, XrayParams{Axis::kZ, XrayMode::kTotal});
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->rays_hit, 2);
  EXPECT_EQ(r->min, 1);
  EXPECT_EQ(r->max, 3);
  EXPECT_DOUBLE_EQ(r->mean, 2.0);
  EXPECT_EQ(xrayCsv(*r), "u,v,thickness_voxels,thickness_mm\n3,0,1,0.25\n1,2,3,0.75\n");
}

TEST(Xray, emptyGridHasNoHits) {
  auto r = computeXray(VoxelGrid(Dims{5, 6, 7}), XrayParams{Axis::kY, XrayMode::kMax});
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->rays_hit, 0);
  EXPECT_EQ(r->min, 0);
  EXPECT_EQ(r->max, 0);
  EXPECT_EQ(r->thickness.width, 5);
  EXPECT_EQ(r->thickness.height, 7);
  EXPECT_FALSE(computeXray(VoxelGrid(), XrayParams{}).ok());
}

TEST(Xray, legendSaysWhatTheMapShows) {
  const VoxelGrid g = test::ballGrid(Dims{40, 30, 20}, glm::dvec3(20, 15, 10), 9.5);
  auto r = computeXray(g, XrayParams{Axis::kY, XrayMode::kMax});
  ASSERT_TRUE(r.ok());
  const ScalarMapLegend l = xrayLegend(*r);
  EXPECT_EQ(l.title, "X-ray along y: max thickness per ray");
  EXPECT_EQ(l.right_axis, "x");  // rays along Y: the image shows x across and z up
  EXPECT_EQ(l.up_axis, "z");
  EXPECT_EQ(l.value_name, "voxels");
  EXPECT_EQ(l.units_per_value, g.voxelSize());
  ASSERT_EQ(l.notes.size(), 2u);
  EXPECT_NE(l.notes[0].find("max " + std::to_string(r->max)), std::string::npos) << l.notes[0];
}

}  // namespace
}  // namespace vox
