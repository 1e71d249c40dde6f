// Hot spots against a brute force written from their definition (docs/accuracy.md), on random fields: the basins'
// bookkeeping (the greatest neighbours by separable maxima, the paths to the summits across layers and threads, the
// joins of basins, the merge and its plateaus) must give every regional maximum with its plateau, saddle and
// dynamic. (Their moduli, from the regions they feed, are checked against plates, bars, cubes and balls in
// thickness_test.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <queue>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "grids.h"
#include "vox/analysis/analysis.h"
#include "vox/analysis/distance.h"
#include "vox/analysis/thickness.h"
#include "vox/io/stl.h"
#include "vox/voxelize/voxelize.h"
#include "support/test_support.h"

namespace vox {
namespace {

// Every 26-connected plateau of equal nonzero value without a higher neighbour is a regional maximum. It dies at the
// highest level L from which a path over voxels at L or above reaches a higher maximum (a larger value, or the same
// value with a plateau whose first voxel in x, y, z order comes earlier): a best-first search that always extends
// the path whose lowest value is highest. A maximum that reaches none never dies.
std::vector<HotSpot> bruteHotSpots(const DistanceField& f, const HotSpotParams& params) {
  const Dims d = f.boxDims();
  const int64_t n = d.count();
  std::vector<uint32_t> values(static_cast<size_t>(n));  // read voxel by voxel: either layout (dense or packed rows)
  for (int64_t i = 0; i < n; ++i) {
    values[size_t(i)] =
        f.squared(f.boxMin().x + i % d.nx, f.boxMin().y + (i / d.nx) % d.ny, f.boxMin().z + i / (int64_t(d.nx) * d.ny));
  }
  const uint32_t* s = values.data();
  auto neighbours = [&](int64_t i, auto&& visit) {
    const int64_t x = i % d.nx, y = (i / d.nx) % d.ny, z = i / (int64_t(d.nx) * d.ny);
    for (int64_t dz = -1; dz <= 1; ++dz)
      for (int64_t dy = -1; dy <= 1; ++dy)
        for (int64_t dx = -1; dx <= 1; ++dx) {
          const int64_t qx = x + dx, qy = y + dy, qz = z + dz;
          if ((dx || dy || dz) && qx >= 0 && qy >= 0 && qz >= 0 && qx < d.nx && qy < d.ny && qz < d.nz) {
            visit(qx + d.nx * (qy + int64_t(d.ny) * qz));
          }
        }
  };
  std::vector<int64_t> plateau_of(size_t(n), -1);
  std::vector<std::vector<int64_t>> plateaus;
  std::vector<bool> is_max;
  for (int64_t i = 0; i < n; ++i) {
    if (!s[i] || plateau_of[size_t(i)] >= 0) continue;
    const auto id = int64_t(plateaus.size());
    std::vector<int64_t> voxels{i};
    plateau_of[size_t(i)] = id;
    bool top = true;
    for (size_t k = 0; k < voxels.size(); ++k) {
      neighbours(voxels[k], [&](int64_t q) {
        if (s[q] > s[i]) top = false;
        if (s[q] == s[i] && plateau_of[size_t(q)] < 0) {
          plateau_of[size_t(q)] = id;
          voxels.push_back(q);
        }
      });
    }
    std::sort(voxels.begin(), voxels.end());  // voxels[0]: the plateau's first voxel
    plateaus.push_back(std::move(voxels));
    is_max.push_back(top);
  }
  std::vector<HotSpot> out;
  const double h = f.voxelSize();
  const glm::ivec3 lo = f.boxMin();
  for (size_t p = 0; p < plateaus.size(); ++p) {
    if (!is_max[p]) continue;
    const std::vector<int64_t>& own = plateaus[p];
    const uint32_t v = s[own[0]];
    auto higher = [&](int64_t q) {
      return s[q] > v ||
             (s[q] == v && plateau_of[size_t(q)] != int64_t(p) && plateaus[size_t(plateau_of[size_t(q)])][0] < own[0]);
    };
    std::vector<int64_t> best(size_t(n), -1);
    std::priority_queue<std::pair<uint32_t, int64_t>> open;
    for (int64_t i : own) {
      best[size_t(i)] = v;
      open.emplace(v, i);
    }
    bool dead = false;
    uint32_t saddle = 0;
    while (!open.empty()) {
      const auto [low, i] = open.top();
      open.pop();
      if (int64_t(low) < best[size_t(i)]) continue;
      if (higher(i)) {
        dead = true;
        saddle = low;
        break;
      }
      neighbours(i, [&](int64_t q) {
        const uint32_t l = std::min(low, s[q]);
        if (s[q] && int64_t(l) > best[size_t(q)]) {
          best[size_t(q)] = l;
          open.emplace(l, q);
        }
      });
    }
    const double r = std::sqrt(double(v));
    const double dyn = dead ? r - std::sqrt(double(saddle)) : r;
    if (dead && dyn < std::max(params.min_dynamic_voxels, params.min_dynamic_fraction * r)) continue;
    int64_t sx = 0, sy = 0, sz = 0;
    for (int64_t i : own) {
      sx += i % d.nx;
      sy += (i / d.nx) % d.ny;
      sz += i / (int64_t(d.nx) * d.ny);
    }
    HotSpot hs;
    const auto count = double(own.size());
    hs.centre = f.frame().origin + (glm::dvec3(lo) + glm::dvec3(double(sx), double(sy), double(sz)) / count + 0.5) * h;
    hs.plateau_voxels = int64_t(own.size());
    hs.radius = r * h;
    hs.dynamic = dyn * h;
    hs.saddle = dead ? std::sqrt(double(saddle)) * h : 0.0;
    hs.isolated = !dead || dyn >= std::max(params.isolation_voxels, params.isolation_fraction * r);
    double nearest = INFINITY;
    for (int64_t i : own) {
      const glm::ivec3 g =
          lo + glm::ivec3(int32_t(i % d.nx), int32_t((i / d.nx) % d.ny), int32_t(i / (int64_t(d.nx) * d.ny)));
      const glm::dvec3 e = f.frame().voxelCentre(g.x, g.y, g.z) - hs.centre;
      const double dd = e.x * e.x + e.y * e.y + e.z * e.z;
      if (dd < nearest) {
        nearest = dd;
        hs.voxel = g;
      }
    }
    out.push_back(hs);
  }
  return out;
}

auto key(const HotSpot& h) { return std::make_tuple(-h.radius, h.centre.x, h.centre.y, h.centre.z, h.plateau_voxels); }

std::string describe(const HotSpot& h) {
  return "r " + std::to_string(h.radius) + " at " + std::to_string(h.centre.x) + "," + std::to_string(h.centre.y) +
         "," + std::to_string(h.centre.z) + " plateau " + std::to_string(h.plateau_voxels) + " saddle " +
         std::to_string(h.saddle) + " dynamic " + std::to_string(h.dynamic) + (h.isolated ? " isolated" : "");
}

void expectMatchesBruteForce(const DistanceField& f, const std::string& what) {
  int spots = 0;
  for (const HotSpotParams params : {HotSpotParams{0.0, 2.0}, HotSpotParams{}, HotSpotParams{1.5, 3.0}}) {
    auto got = findHotSpots(f, params);
    ASSERT_TRUE(got.ok()) << what << ": " << got.error().message;
    std::vector<HotSpot> expect = bruteHotSpots(f, params);
    for (size_t i = 1; i < got->size(); ++i) {
      EXPECT_GE((*got)[i - 1].radius, (*got)[i].radius) << what << ": not largest first";
    }
    std::vector<HotSpot> sorted = *got;
    auto order = [](const HotSpot& a, const HotSpot& b) { return key(a) < key(b); };
    std::sort(sorted.begin(), sorted.end(), order);
    std::sort(expect.begin(), expect.end(), order);
    ASSERT_EQ(sorted.size(), expect.size()) << what << " (min dynamic " << params.min_dynamic_voxels << ")";
    for (size_t i = 0; i < expect.size(); ++i) {
      const HotSpot &a = sorted[i], &e = expect[i];
      const bool same = a.centre == e.centre && a.voxel == e.voxel && a.plateau_voxels == e.plateau_voxels &&
                        a.radius == e.radius && a.dynamic == e.dynamic && a.saddle == e.saddle &&
                        a.isolated == e.isolated;
      EXPECT_TRUE(same) << what << ": " << describe(a) << " expected " << describe(e);
    }
    spots += int(expect.size());
  }
  EXPECT_GT(spots, 0) << what;
}

// A field of random values with plateaus and saddles: noise, smoothed by a running maximum over a few voxels and
// quantised to `levels` values spaced `step` apart (zeros, the empty voxels, where the noise is lowest).
DistanceField randomField(Dims d, int levels, uint32_t step, uint32_t seed) {
  GridFrame frame;
  frame.voxel_size = 0.25;
  frame.origin = glm::dvec3(1.0, -2.0, 0.5);
  DistanceField f(Dims{d.nx + 5, d.ny + 3, d.nz + 2}, frame, glm::ivec3(2, 1, 1), d, 0);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> value(0, levels * 4);
  std::vector<int> noise(size_t(d.count()));
  for (int& v : noise) v = value(rng);
  uint32_t mx = 0;
  for (int64_t z = 0; z < d.nz; ++z)
    for (int64_t y = 0; y < d.ny; ++y)
      for (int64_t x = 0; x < d.nx; ++x) {
        int m = 0;
        for (int64_t k = std::max<int64_t>(x - 1, 0); k <= std::min<int64_t>(x + 1, d.nx - 1); ++k) {
          m = std::max(m, noise[size_t(k + d.nx * (y + int64_t(d.ny) * z))]);
        }
        const int q = m * levels / (levels * 4 + 1) - 1;  // -1: empty
        const uint32_t s = q < 0 ? 0 : uint32_t(q + 1) * step;
        f.data()[x + d.nx * (y + int64_t(d.ny) * z)] = s;
        mx = std::max(mx, s);
      }
  f.setMaxSquared(mx);
  return f;
}

TEST(HotSpots, matchBruteForceOnRandomFields) {
  // axes shorter and longer than the 16 rows of a band, none a whole number of bands
  const Dims dims[] = {Dims{21, 17, 13}, Dims{9, 33, 18}, Dims{19, 5, 22}, Dims{1, 1, 7}};
  uint32_t seed = 1;
  for (const Dims& d : dims) {
    for (const auto& [levels, step] : {std::pair{4, 1u}, std::pair{9, 3u}, std::pair{25, 1u}, std::pair{6, 40000u}}) {
      const DistanceField f = randomField(d, levels, step, seed++);
      expectMatchesBruteForce(f, "field " + std::to_string(d.nx) + "x" + std::to_string(d.ny) + "x" +
                                     std::to_string(d.nz) + " levels " + std::to_string(levels) + " step " +
                                     std::to_string(step));
    }
  }
}

// A lattice of single-voxel peaks of distance 2 to 4 at every other voxel along x and y and every fifth along z,
// the voxels between them at distance 1, in a box of dims (over 2^19 voxels: swept on every thread). Every peak is
// a maximum that dies at 1, but the first of the highest, which never does. The voxels between the peaks' layers
// climb along the plateau of 1s to the earlier voxels, through the layers below, to a layer of peaks.
void expectLatticeOfPeaks(const Dims& dims, int64_t summits) {
  DistanceField f(dims, GridFrame{}, glm::ivec3(0), dims, 0);
  auto peak = [](int x, int y, int z) { return uint32_t(2 + (x / 2 + y / 2 + z / 5) % 3); };
  int64_t peaks = 0, highest = 0;
  for (int z = 0; z < dims.nz; ++z)
    for (int y = 0; y < dims.ny; ++y)
      for (int x = 0; x < dims.nx; ++x) {
        const bool top = x % 2 == 0 && y % 2 == 0 && z % 5 == 0;
        f.data()[f.boxIndex(x, y, z)] = top ? peak(x, y, z) : 1;
        peaks += top;
        highest += top && peak(x, y, z) == 4;
      }
  f.setMaxSquared(4);
  ASSERT_EQ(peaks, summits);
  ASSERT_GT(dims.count(), int64_t(1) << 19);
  auto all = findHotSpots(f, HotSpotParams{0.0, 2.0});
  ASSERT_TRUE(all.ok());
  ASSERT_EQ(int64_t(all->size()), peaks);
  const HotSpot& first = all->front();
  EXPECT_EQ(first.voxel, glm::ivec3(4, 0, 0));  // the first voxel of distance 4
  EXPECT_EQ(first.saddle, 0.0);
  EXPECT_EQ(first.radius, 2.0);
  int64_t wrong = 0;
  for (size_t k = 1; k < all->size(); ++k) {
    const HotSpot& h = (*all)[k];
    const glm::ivec3 v = h.voxel;
    wrong += h.saddle != 1.0 || h.plateau_voxels != 1 || v.x % 2 != 0 || v.y % 2 != 0 || v.z % 5 != 0 ||
             h.radius != std::sqrt(double(peak(v.x, v.y, v.z))) || h.isolated;
  }
  EXPECT_EQ(wrong, 0);
  // by default only the peaks that stand out by a voxel: those of distance 4 (radius 2, saddle 1)
  auto standing = findHotSpots(f);
  ASSERT_TRUE(standing.ok());
  EXPECT_EQ(int64_t(standing->size()), highest);
}

// Summits numbered 16384 and up: 16-bit labels whose number has the bit that marks a waiting path.
TEST(HotSpots, summitNumbersUsingEvery16Bits) { expectLatticeOfPeaks(Dims{60, 60, 150}, 30 * 30 * 30); }

// More summits than 16-bit labels number: the labels widen to 32 bits.
TEST(HotSpots, moreMaximaThan16BitLabelsNumber) { expectLatticeOfPeaks(Dims{82, 82, 100}, 41 * 41 * 20); }

// g with the voxels of `other` (same dims) added.
void add(VoxelGrid& g, const VoxelGrid& other) {
  auto both = booleanOp(g, other, BoolOp::kUnion);
  ASSERT_TRUE(both.ok());
  g = std::move(both.value());
}

TEST(HotSpots, matchBruteForceOnDistanceFields) {
  std::mt19937 rng(7);
  for (int shape = 0; shape < 6; ++shape) {
    // a few overlapping balls of assorted radii, and some noise: maxima with plateaus, necks and ties
    VoxelGrid g(Dims{26, 19, 23});
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int b = 0; b < 2 + shape; ++b) {
      const glm::dvec3 c(3 + 20 * u(rng), 3 + 13 * u(rng), 3 + 17 * u(rng));
      const double r = 1.5 + 5.5 * u(rng);
      add(g, test::ballGrid(g.dims(), c, r));
    }
    if (shape % 2) add(g, test::randomGrid(g.dims(), 0.05, uint32_t(shape)));
    auto f = computeDistance(g);
    ASSERT_TRUE(f.ok());
    expectMatchesBruteForce(*f, "balls " + std::to_string(shape));
  }
}

// A box large enough that the sweeps run on every thread (threadsFor: 2^19 voxels in the filled box), with basins
// meeting across the threads' slabs and bands of rows.
TEST(HotSpots, matchBruteForceOnAFieldSweptByAllThreads) {
  const Dims dims{96, 84, 116};
  VoxelGrid g(dims);
  const glm::dvec4 balls[] = {{15, 20, 15, 14}, {75, 55, 40, 19}, {45, 40, 85, 20}, {30, 25, 55, 9}, {80, 64, 100, 14}};
  for (const glm::dvec4& b : balls) add(g, test::ballGrid(dims, glm::dvec3(b), b.w));
  auto f = computeDistance(g);
  ASSERT_TRUE(f.ok());
  ASSERT_GT(f->boxDims().count(), int64_t(1) << 19);
  expectMatchesBruteForce(*f, "five balls");
}

// Basins meeting at equal levels (a real part's many small maxima, swept by every thread): which set a dying one
// joins decides the regions. It is the same however the threads met the edges, so the modulus painted over the
// regions is the same each time.
TEST(HotSpots, regionsAndTheModulusFieldDoNotDependOnTheThreads) {
  VOX_REQUIRE_SHARED(shared);
  auto mesh = io::loadStl(shared / "meshes" / "rocker_arm.stl");
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  auto g =
      voxelizeSolid(mesh->mesh, VoxelizeParams{.resolution = 150});  // its ties at R = 150 showed the threads' order
  ASSERT_TRUE(g.ok()) << g.error().message;
  auto f = computeDistance(g->grid, {}, DistanceLayout::kDense);
  ASSERT_TRUE(f.ok());
  ASSERT_GT(f->boxDims().count(), int64_t(1) << 19);
  auto thickness = computeThickness(*f);
  ASSERT_TRUE(thickness.ok());
  auto first = computeModulusField(*f, &thickness->radius);
  ASSERT_TRUE(first.ok()) << first.error().message;
  for (int run = 0; run < 8; ++run) {
    auto again = computeModulusField(*f, &thickness->radius);
    ASSERT_TRUE(again.ok());
    ASSERT_TRUE(again->values == first->values) << "run " << run;
  }
}

// Progress rises to 1 through every step, and a stop asked for at any report ends the search as cancelled.
TEST(HotSpots, reportProgressAndCancel) {
  auto f = computeDistance(test::ballGrid(Dims{92, 92, 92}, {46, 46, 46}, 45.5));
  ASSERT_TRUE(f.ok());
  int reports = 0;
  double last = -1;
  bool monotone = true;
  ASSERT_TRUE(findHotSpots(*f, {}, [&](double p) {
                monotone = monotone && p >= last;
                last = p;
                ++reports;
                return true;
              }).ok());
  EXPECT_TRUE(monotone);
  EXPECT_DOUBLE_EQ(last, 1.0);
  ASSERT_GT(reports, 20);
  for (const int stop : {1, 2, 5, reports / 2, reports - 2}) {
    int calls = 0;
    auto r = findHotSpots(*f, {}, [&](double) { return ++calls < stop; });
    ASSERT_FALSE(r.ok()) << stop;
    EXPECT_EQ(r.error().code, ErrorCode::kCancelled) << stop;
    EXPECT_EQ(calls, stop) << "reports after the stop";
  }
}

}  // namespace
}  // namespace vox
