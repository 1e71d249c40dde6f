// Casting solidification checked against physics (vox/analysis/casting.h): the classic sand-mould solution for a
// plate (Flemings), a sphere of the same modulus freezing sooner, convergence as the voxels shrink, the geometric
// modulus of plates, bars, cubes and spheres, and a cube with a large and a small feeder.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "analysis/casting_detail.h"
#include "grids.h"
#include "vox/analysis/casting.h"
#include "vox/analysis/distance.h"
#include "vox/analysis/thickness.h"

namespace vox {
namespace {

CastingParams aluminiumInSand() {
  CastingParams p;
  p.alloy = *findAlloy("aluminium");
  p.mould = *findMould("silica-sand");
  p.superheat_k = 0.0;
  p.metres_per_unit = 0.001;  // mm
  return p;
}

// Flemings' freezing time of a plate of modulus m (metres) in a semi-infinite sand mould, the metal at its melting
// point throughout: t = pi / 4 (rho L / (Tm - T0))^2 m^2 / (k rho c)_mould.
double flemingsSeconds(const CastingParams& p, double m) {
  const double q = p.alloy.density_kg_m3 * p.alloy.latent_heat_j_kg / (p.alloy.solidus_c - p.mould.temperature_c);
  const double kpc = p.mould.conductivity_w_mk * p.mould.density_kg_m3 * p.mould.specific_heat_j_kgk;
  return std::numbers::pi / 4.0 * q * q * m * m / kpc;
}

ScalarField modulusOf(const VoxelGrid& grid) {
  auto distance = computeDistance(grid, {}, DistanceLayout::kDense);
  EXPECT_TRUE(distance.ok());
  auto thickness = computeThickness(*distance);
  EXPECT_TRUE(thickness.ok());
  auto field = computeModulusField(*distance, &thickness->radius);
  EXPECT_TRUE(field.ok());
  return std::move(field).value();
}

// A plate `thickness` mm thick and infinitely wide (one column of voxels between planes of symmetry) of voxel h mm.
Result<CastingResult> plate(double thickness, double h) {
  GridFrame frame;
  frame.voxel_size = h;
  frame.units = "mm";
  const auto n = int32_t(std::lround(thickness / h));
  const VoxelGrid slab = test::boxGrid(Dims{1, 1, n}, {0, 0, 0}, {1, 1, n}, frame);
  CastingParams p = aluminiumInSand();
  p.symmetry = glm::bvec3(true, true, false);
  ScalarField m(slab.dims(), frame, float(thickness / 2));
  p.modulus = &m;
  return simulateCasting(slab, p);
}

TEST(Casting, wideAluminiumPlateInSandFreezesInFlemingsTime) {
  const auto r = plate(20.0, 1.0);
  ASSERT_TRUE(r.ok()) << r.error().message;
  const double expected = flemingsSeconds(aluminiumInSand(), 0.010);  // modulus 10 mm: about 226 s
  EXPECT_NEAR(r->solidification_s, expected, 0.10 * expected);
  EXPECT_GT(r->steps, 100);
  // The plate freezes from both faces: the last voxels are the middle ones.
  ASSERT_FALSE(r->hot_spots.empty());
  EXPECT_NEAR(r->hot_spots.front().centre.z, 10.0, 1.01);
}

TEST(Casting, halvingTheVoxelsChangesThePlatesTimeByLittle) {
  const auto coarse = plate(20.0, 1.0), fine = plate(20.0, 0.5);
  ASSERT_TRUE(coarse.ok() && fine.ok());
  EXPECT_NEAR(fine->solidification_s, coarse->solidification_s, 0.03 * fine->solidification_s);
}

// An independent reference for a ball of pure aluminium in sand: the same physics in spherical coordinates (one
// radius, finite volumes: `metal_cells` shells in the metal, 0.2 mm shells in the sand out to three radii),
// explicit in time at 0.3 of its stability limit. Seconds until the centre freezes.
double radialBallSeconds(const CastingParams& p, double radius, int metal_cells) {
  std::vector<double> face{0.0};
  for (int i = 1; i <= metal_cells; ++i) face.push_back(radius * i / metal_cells);
  const int sand_cells = int(std::lround(2.0 * radius / 2e-4));
  for (int i = 1; i <= sand_cells; ++i) face.push_back(radius + 2.0 * radius * i / sand_cells);
  const size_t n = face.size() - 1;
  const Alloy& a = p.alloy;
  const MouldMaterial& m = p.mould;
  const double rc_metal = a.density_kg_m3 * a.specific_heat_j_kgk, latent = a.density_kg_m3 * a.latent_heat_j_kg;
  const double rc_sand = m.density_kg_m3 * m.specific_heat_j_kgk;
  std::vector<double> h(n), volume(n), centre(n), conductance(n, 0.0);  // conductance[i]: between i - 1 and i
  for (size_t i = 0; i < n; ++i) {
    volume[i] = 4.0 / 3.0 * std::numbers::pi * (std::pow(face[i + 1], 3) - std::pow(face[i], 3));
    centre[i] = 0.5 * (face[i] + face[i + 1]);
    h[i] = int(i) < metal_cells ? latent : rc_sand * m.temperature_c;  // metal: about its solidus, just liquid
  }
  const auto k = [&](size_t i) { return int(i) < metal_cells ? a.conductivity_w_mk : m.conductivity_w_mk; };
  double step = 1e30;
  for (size_t i = 1; i < n; ++i) {
    const double kf = 2.0 * k(i - 1) * k(i) / (k(i - 1) + k(i));
    conductance[i] = kf * 4.0 * std::numbers::pi * face[i] * face[i] / (centre[i] - centre[i - 1]);
  }
  for (size_t i = 0; i < n; ++i) {
    const double rc = int(i) < metal_cells ? rc_metal : rc_sand;
    step = std::min(step, rc * volume[i] / (conductance[i] + (i + 1 < n ? conductance[i + 1] : 0.0)));
  }
  step *= 0.3;
  std::vector<double> t(n), flow(n);
  for (double time = step;; time += step) {
    bool liquid = false;
    for (size_t i = 0; i < n; ++i) {
      if (int(i) >= metal_cells) {
        t[i] = h[i] / rc_sand;
      } else {
        t[i] = a.solidus_c + (h[i] < 0.0 ? h[i] / rc_metal : (h[i] > latent ? (h[i] - latent) / rc_metal : 0.0));
        liquid = liquid || h[i] >= 0.0;
      }
    }
    if (!liquid) return time - step;
    std::fill(flow.begin(), flow.end(), 0.0);
    for (size_t i = 1; i < n; ++i) {
      const double q = conductance[i] * (t[i - 1] - t[i]);
      flow[i - 1] -= q;
      flow[i] += q;
    }
    for (size_t i = 0; i < n; ++i) h[i] += step * flow[i] / volume[i];
  }
}

// A ball of the plate's modulus (radius 30 mm) freezes sooner, as the curved mould about it takes the heat faster
// than a flat one (q = k dT (1 / sqrt(pi a t) + 1 / r)), and in the time of the radial reference.
TEST(Casting, aSphereOfEqualModulusFreezesSoonerInTheRadialReferenceTime) {
  GridFrame frame;
  frame.voxel_size = 2.0;
  frame.units = "mm";
  const VoxelGrid ball = test::ballGrid(Dims{32, 32, 32}, glm::dvec3(16.0), 15.0, frame);  // radius 30 mm
  const ScalarField m = modulusOf(ball);
  CastingParams p = aluminiumInSand();
  p.modulus = &m;
  const auto r = simulateCasting(ball, p);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_LT(r->solidification_s, 0.85 * flemingsSeconds(p, 0.010));
  const double reference = radialBallSeconds(p, 0.030, 60);
  EXPECT_NEAR(r->solidification_s, reference, 0.05 * reference) << "radial reference " << reference << " s";
  ASSERT_FALSE(r->hot_spots.empty());
  EXPECT_LT(glm::distance(r->hot_spots.front().centre, glm::dvec3(32.0)), 4.0);  // the centre, within 2 voxels
  EXPECT_FALSE(r->sound);                                                        // nothing feeds it
}

TEST(Casting, plateBarCubeAndSphereOfOneModulusReadIt) {
  GridFrame frame;
  frame.voxel_size = 0.1;
  const double modulus = 1.0;  // 10 voxels
  const VoxelGrid shapes[] = {
      test::boxGrid(Dims{404, 404, 24}, {2, 2, 2}, {402, 402, 22}, frame),  // plate 2 thick
      test::boxGrid(Dims{44, 44, 404}, {2, 2, 2}, {42, 42, 402}, frame),    // bar 4 x 4
      test::boxGrid(Dims{64, 64, 64}, {2, 2, 2}, {62, 62, 62}, frame),      // cube 6
      test::ballGrid(Dims{64, 64, 64}, glm::dvec3(32.0), 30.0, frame),      // ball 6 across
  };
  for (const VoxelGrid& g : shapes) {
    const ScalarField m = modulusOf(g);
    float most = 0.0f;
    for (const float v : m.values) most = std::max(most, v);
    EXPECT_NEAR(most, modulus, 0.1 * modulus) << "dims " << g.nx() << " x " << g.ny() << " x " << g.nz();
  }
}

// A fin on a block reads as the fin: at most half its thickness, not the block's modulus.
TEST(Casting, aThinFinReadsItsOwnModulus) {
  GridFrame frame;
  VoxelGrid g = test::boxGrid(Dims{80, 40, 40}, {0, 0, 0}, {40, 40, 40}, frame);
  test::fillBox(g, {40, 0, 18}, {80, 40, 22});  // 4 thick
  const ScalarField m = modulusOf(g);
  EXPECT_LE(m.at(70, 20, 20), 2.0f + 1e-4f);
  EXPECT_GT(m.at(20, 20, 20), 4.0f);
}

// A 40 mm cube of aluminium (modulus 6.7 mm) in sand, with a feeder on top.
Result<CastingResult> cubeWithFeeder(double diameter, double height) {
  GridFrame frame;
  frame.voxel_size = 2.0;
  frame.units = "mm";
  const VoxelGrid cube = test::boxGrid(Dims{20, 20, 20}, {0, 0, 0}, {20, 20, 20}, frame);
  const ScalarField m = modulusOf(cube);
  CastingParams p = aluminiumInSand();
  p.modulus = &m;
  p.feeders.push_back(Feeder{glm::dvec3(20.0, 20.0, 40.0), diameter, height});
  return simulateCasting(cube, p);
}

TEST(Casting, aCubeWithALargeFeederIsSoundAndFreezesLastInIt) {
  const auto r = cubeWithFeeder(40.0, 80.0);  // modulus 8.9 mm, 1.33 times the cube's
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_TRUE(r->sound) << r->verdict;
  ASSERT_FALSE(r->hot_spots.empty());
  EXPECT_TRUE(r->hot_spots.front().in_feeder);
  EXPECT_GT(r->hot_spots.front().centre.z, 40.0);
  EXPECT_GT(r->last_metal_s, r->solidification_s);
  ASSERT_EQ(r->feeders.size(), 1u);
  EXPECT_NEAR(r->feeders[0].modulus, 40.0 * 80.0 / (4 * 80.0 + 40.0), 1e-9);
  EXPECT_NEAR(r->feeders[0].volume, std::numbers::pi * 400.0 * 80.0, 0.08 * std::numbers::pi * 400.0 * 80.0);
  EXPECT_NEAR(r->yield, 64000.0 / (64000.0 + r->feeders[0].volume), 1e-9);
}

TEST(Casting, aCubeWithASmallFeederIsNotSound) {
  const auto r = cubeWithFeeder(12.0, 18.0);  // modulus 2.6 mm
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_FALSE(r->sound);
  ASSERT_FALSE(r->hot_spots.empty());
  const CastingHotSpot& last = r->hot_spots.front();
  EXPECT_FALSE(last.in_feeder);
  EXPECT_TRUE(last.isolated);
  EXPECT_LT(glm::distance(last.centre, glm::dvec3(20.0, 20.0, 20.0)), 8.0);
  EXPECT_NE(r->verdict.find("Not sound"), std::string::npos);
}

TEST(Casting, refusesWhatItCannotSimulate) {
  GridFrame frame;
  const VoxelGrid cube = test::boxGrid(Dims{4, 4, 4}, {0, 0, 0}, {4, 4, 4}, frame);
  CastingParams p = aluminiumInSand();
  p.metres_per_unit = 0.0;
  EXPECT_EQ(simulateCasting(cube, p).error().code, ErrorCode::kInvalidArgument);
  p = aluminiumInSand();
  p.max_cells = 10;
  EXPECT_EQ(simulateCasting(cube, p).error().code, ErrorCode::kLimit);
  p = aluminiumInSand();
  EXPECT_EQ(simulateCasting(cube, p, [](double) { return false; }).error().code, ErrorCode::kCancelled);
  p.mould.temperature_c = 700.0;  // above the solidus
  EXPECT_EQ(simulateCasting(cube, p).error().code, ErrorCode::kInvalidArgument);
}

// The freezing order's regions on a bar of metal (a row of cells) whose times are given: two peaks parted by a deep
// dip are both isolated; a peak whose dip is shallow is fed by the later one, through its saddle.
TEST(Casting, hotSpotsByFreezingOrderAreIsolatedOrFed) {
  const Dims d{40, 1, 1};
  std::vector<uint8_t> kind(40, casting_detail::kMetal);
  kind[39] = casting_detail::kMould;
  std::vector<float> time(40, 0.0f);
  for (int x = 0; x < 39; ++x) {
    // peaks at x = 5 (100 s) and x = 20 (80 s) parted by a dip to about 61 s near x = 10.5; a bump at x = 32
    // (78 s) parted from the x = 20 peak by a dip to 77 s at x = 22
    const double a = 100.0 - 7.0 * std::abs(x - 5), b = 80.0 - 2.0 * std::abs(x - 20);
    const double c = 78.0 - 0.1 * std::abs(x - 32);
    time[size_t(x)] = float(std::max({a, b, x >= 21 ? c : 0.0, 50.0}));
  }
  GridFrame frame;
  const auto spots = casting_detail::findTimeSpots(d, kind, time, frame, 0.5, 0.02, 3);
  ASSERT_EQ(spots.size(), 3u);
  EXPECT_EQ(spots[0].cell, 5);
  EXPECT_TRUE(spots[0].spot.isolated);  // the last of the bar
  EXPECT_EQ(spots[1].cell, 20);
  EXPECT_TRUE(spots[1].spot.isolated);  // 30 s above the dip at x = 12
  EXPECT_EQ(spots[2].cell, 32);
  EXPECT_FALSE(spots[2].spot.isolated);  // 1 s above its dip: fed
  EXPECT_EQ(spots[2].spot.fed_by, 1);
  EXPECT_NEAR(spots[2].spot.saddle.x, 22.5, 1e-9);
  EXPECT_FALSE(spots[0].spot.in_feeder);
}

TEST(Casting, feedersParseAndMaterialsAreKnown) {
  auto f = parseFeeder("cylinder:1,2.5,-3,10,20");
  ASSERT_TRUE(f.ok());
  EXPECT_EQ(f->base, glm::dvec3(1.0, 2.5, -3.0));
  EXPECT_EQ(f->diameter, 10.0);
  EXPECT_EQ(f->height, 20.0);
  for (const char* bad :
       {"cylinder:1,2,3,4", "sphere:1,2,3,4,5", "cylinder:1,2,3,0,5", "cylinder:1,2,3,4,x", "cylinder:1,2,3,4,5,6"}) {
    EXPECT_FALSE(parseFeeder(bad).ok()) << bad;
  }
  for (const char* name : {"aluminium", "a356", "grey-iron", "carbon-steel"}) EXPECT_NE(findAlloy(name), nullptr);
  for (const char* name : {"silica-sand", "steel"}) EXPECT_NE(findMould(name), nullptr);
  EXPECT_EQ(findAlloy("unobtainium"), nullptr);
}

}  // namespace
}  // namespace vox
