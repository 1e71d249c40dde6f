// The voxelizer on meshes built in code, against analytic or independent answers (docs/conventions.md,
// "Grid placement").
#include "vox/core/text.h"
#include "vox/voxelize/voxelize.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "support/test_support.h"
#include "support/test_meshes.h"
#include "vox/core/bits.h"

namespace vox {
namespace {

using test::boxMesh;
using test::combined;
using test::mismatches;
using test::tetrahedron;

VoxelizeResult voxelize(const TriangleMesh& mesh, int64_t resolution, FillMode mode, int threads = 0) {
  VoxelizeParams p;
  p.resolution = resolution;
  p.mode = mode;
  p.threads = threads;
  auto r = voxelizeSolid(mesh, p);
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message);
  return r.ok() ? std::move(r).value() : VoxelizeResult{};
}

bool hasWarning(const VoxelizeResult& r, const std::string& text) {
  return std::any_of(r.warnings.begin(), r.warnings.end(),
                     [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

// Markers at the corners of [0, 16]^3: with R = 16 the voxel size is 1 and the centres are k + 0.5, exactly.
TriangleMesh unitGridFrame() {
  return combined(tetrahedron({0, 0, 0}, 0.25), tetrahedron({15.75, 15.75, 15.75}, 0.25));
}

// ---- Ties: centres exactly on faces, rays exactly through edges and vertices ----

// A box whose faces pass exactly through rows of centres: SoS makes it the half-open box [min, max) on every axis
// (a centre on a face whose normal points to -x, -y or -z is inside, +x, +y, +z outside), in every mode.
TEST(VoxelizeTies, axisAlignedBoxOnCentresIsHalfOpen) {
  const TriangleMesh mesh = combined(unitGridFrame(), boxMesh({1.5, 2.5, 0.5}, {4.5, 5.5, 3.5}));
  for (FillMode mode : {FillMode::kParity, FillMode::kNonzero, FillMode::kVote}) {
    const VoxelizeResult r = voxelize(mesh, 16, mode);
    ASSERT_EQ(r.grid.dims(), (Dims{16, 16, 16}));
    ASSERT_EQ(r.grid.voxelSize(), 1.0);
    const VoxelGrid expected = test::gridFromPredicate(r.grid, [](const glm::dvec3& c) {
      return c.x >= 1.5 && c.x < 4.5 && c.y >= 2.5 && c.y < 5.5 && c.z >= 0.5 && c.z < 3.5;
    });
    EXPECT_EQ(mismatches(r.grid, expected), 0) << fillModeName(mode);
    EXPECT_EQ(r.grid.filledCount(), 27) << fillModeName(mode);
    EXPECT_EQ(r.disputed_count, 0) << fillModeName(mode);
    EXPECT_FALSE(hasWarning(r, "odd number")) << fillModeName(mode);
  }
}

// An octahedron |p - c|_1 <= 4 centred on a voxel centre: its six vertices lie exactly on rays, its edges run along
// rays or through ray points, and 66 centres (4 r^2 + 2 lattice points) lie exactly on its surface. With the centre
// displaced by (eps, eps^3, eps^2), a centre on the surface is inside iff its x is below c.x (the x displacement
// decides; a zero offset counts as positive). Rays along Y and Z (vote) displace along their own axis first, so there
// the tie goes by y resp. z, and vote takes the majority of the three.
TEST(VoxelizeTies, octahedronWithVerticesOnRaysFollowsTheSosRuleExactly) {
  const glm::dvec3 c(8.5, 8.5, 8.5);
  const TriangleMesh mesh = combined(unitGridFrame(), test::octahedron(c, 4.0));
  auto l1 = [&](const glm::dvec3& p) { return std::abs(p.x - c.x) + std::abs(p.y - c.y) + std::abs(p.z - c.z); };
  int64_t ties = 0;
  for (FillMode mode : {FillMode::kParity, FillMode::kNonzero, FillMode::kAuto}) {
    const VoxelizeResult r = voxelize(mesh, 16, mode);
    ties = 0;
    const VoxelGrid expected = test::gridFromPredicate(r.grid, [&](const glm::dvec3& p) {
      if (l1(p) != 4.0) return l1(p) < 4.0;
      ++ties;
      return p.x < c.x;
    });
    EXPECT_EQ(mismatches(r.grid, expected), 0) << fillModeName(mode);
    EXPECT_FALSE(hasWarning(r, "odd number")) << fillModeName(mode);
    EXPECT_FALSE(hasWarning(r, "winding")) << fillModeName(mode);
  }
  EXPECT_EQ(ties, 66);
  const VoxelizeResult vote = voxelize(mesh, 16, FillMode::kVote);
  int64_t disputed = 0;
  const VoxelGrid expected = test::gridFromPredicate(vote.grid, [&](const glm::dvec3& p) {
    if (l1(p) != 4.0) return l1(p) < 4.0;
    const int votes = (p.x < c.x) + (p.y < c.y) + (p.z < c.z);
    disputed += votes == 1 || votes == 2;
    return votes >= 2;
  });
  const VoxelGrid expected_disputed = test::gridFromPredicate(vote.grid, [&](const glm::dvec3& p) {
    const int votes = (p.x < c.x) + (p.y < c.y) + (p.z < c.z);
    return l1(p) == 4.0 && (votes == 1 || votes == 2);
  });
  EXPECT_EQ(mismatches(vote.grid, expected), 0);
  EXPECT_EQ(vote.disputed_count, disputed);
  ASSERT_TRUE(vote.disputed.has_value());
  EXPECT_EQ(vote.disputed->count(), disputed);
  EXPECT_EQ(mismatches(vote.disputed->toGrid(), expected_disputed), 0);
}

// A prism along X over a diamond |y - 8.5| + |z - 8.5| <= 4: its slanted faces have normals with x = 0, and 16 rows
// of centres lie exactly on them (so the rays run inside those faces and exactly through the diamond's edges in
// projection). docs/conventions.md, "Grid placement": with x out of the question, -z decides, then -y: a centre on a
// slanted face is inside iff its z is below the axis. The caps at x = 2.5 and 12.5 are half-open. Rays along Y (vote)
// displace y first, so they decide by y; rays along Z decide by z like X, so the vote follows X and disputes the ties
// where y and z differ.
TEST(VoxelizeTies, diamondPrismWithFacesParallelToXFollowsZThenY) {
  const TriangleMesh mesh =
      combined(unitGridFrame(), test::prismAlongX({{12.5, 8.5}, {8.5, 12.5}, {4.5, 8.5}, {8.5, 4.5}}, 2.5, 12.5));
  auto in_x = [](const glm::dvec3& p) { return p.x >= 2.5 && p.x < 12.5; };
  auto l1 = [](const glm::dvec3& p) { return std::abs(p.y - 8.5) + std::abs(p.z - 8.5); };
  auto in_yz = [&](const glm::dvec3& p, bool y_first) {
    if (l1(p) != 4.0) return l1(p) < 4.0;
    return y_first ? p.y < 8.5 : p.z < 8.5;
  };
  for (FillMode mode : {FillMode::kParity, FillMode::kNonzero, FillMode::kAuto}) {
    const VoxelizeResult r = voxelize(mesh, 16, mode);
    const VoxelGrid expected =
        test::gridFromPredicate(r.grid, [&](const glm::dvec3& p) { return in_x(p) && in_yz(p, false); });
    EXPECT_EQ(mismatches(r.grid, expected), 0) << fillModeName(mode);
  }
  const VoxelizeResult vote = voxelize(mesh, 16, FillMode::kVote);
  int64_t disputed = 0;
  const VoxelGrid expected = test::gridFromPredicate(vote.grid, [&](const glm::dvec3& p) {
    disputed += in_x(p) && in_yz(p, false) != in_yz(p, true);
    return in_x(p) && in_yz(p, false);
  });
  EXPECT_EQ(mismatches(vote.grid, expected), 0);
  EXPECT_EQ(vote.disputed_count, disputed);
  EXPECT_GT(disputed, 0);
}

// Two cubes sharing a face (a closed mesh of two shells that touch): the shared face's triangles are crossed by
// the rays through it exactly as often as their orientation says; the union is one half-open box.
TEST(VoxelizeTies, cubesTouchingFaceToFaceGiveTheirHalfOpenUnion) {
  const TriangleMesh mesh = combined(
      unitGridFrame(), combined(boxMesh({2.5, 2.5, 2.5}, {6.5, 7.5, 8.5}), boxMesh({6.5, 2.5, 2.5}, {9.5, 7.5, 8.5})));
  const VoxelGrid expected =
      test::gridFromPredicate(voxelize(mesh, 16, FillMode::kParity).grid, [](const glm::dvec3& p) {
        return p.x >= 2.5 && p.x < 9.5 && p.y >= 2.5 && p.y < 7.5 && p.z >= 2.5 && p.z < 8.5;
      });
  for (FillMode mode : {FillMode::kParity, FillMode::kNonzero}) {
    EXPECT_EQ(mismatches(voxelize(mesh, 16, mode).grid, expected), 0) << fillModeName(mode);
  }
}

// ---- Generic meshes against an independent inside test (the generalized winding number) ----

void expectMatchesWindingNumber(const TriangleMesh& mesh, int64_t resolution, const char* what) {
  std::optional<VoxelGrid> expected;
  for (FillMode mode : {FillMode::kParity, FillMode::kNonzero, FillMode::kVote}) {
    const VoxelizeResult r = voxelize(mesh, resolution, mode);
    if (!expected) {
      expected =
          test::gridFromPredicate(r.grid, [&](const glm::dvec3& p) { return test::windingNumber(mesh, p) > 0.5; });
    }
    EXPECT_EQ(mismatches(r.grid, *expected), 0) << what << " " << fillModeName(mode);
    EXPECT_GT(r.grid.filledCount(), 0) << what;
    EXPECT_EQ(r.disputed_count, 0) << what << " " << fillModeName(mode);
  }
}

TEST(VoxelizeGeneric, icosphereMatchesWindingNumber) {
  expectMatchesWindingNumber(test::icosphere({0.1, -0.2, 0.3}, 1.0, 2), 23, "icosphere");
}

TEST(VoxelizeGeneric, rotatedCubesMatchWindingNumber) {
  const TriangleMesh cube = boxMesh({-1, -1, -1}, {1, 1, 1});
  int i = 0;
  for (auto [axis, degrees] : std::vector<std::pair<glm::dvec3, double>>{
           {{0, 0, 1}, 45.0}, {{1, 1, 0}, 30.0}, {{1, 2, 3}, 73.0}, {{-2, 1, 0.5}, 11.0}}) {
    const TriangleMesh rotated = test::transformed(cube, test::rotation(axis, degrees), {0.01, 0.02, 0.03});
    expectMatchesWindingNumber(rotated, 21 + i++, "rotated cube");
  }
}

TEST(VoxelizeGeneric, torusMatchesWindingNumberAndHasAHole) {
  const TriangleMesh t =
      test::transformed(test::torus({0, 0, 0}, 1.0, 0.35, 32, 16), test::rotation({1, 0.3, 0}, 20.0), {0, 0, 0});
  expectMatchesWindingNumber(t, 25, "torus");
  const VoxelizeResult r = voxelize(test::torus({0, 0, 0}, 1.0, 0.35, 48, 24), 24, FillMode::kNonzero);
  EXPECT_FALSE(r.grid.get(12, 12, r.grid.nz() / 2)) << "the torus's hole must stay empty";
}

// ---- Modes ----

// Two overlapping closed cubes: along a ray through the overlap the crossings are +1 +1 -1 -1, so parity leaves the
// overlap empty while nonzero fills the union.
TEST(VoxelizeModes, overlappingCubesParityLeavesOverlapEmptyNonzeroFillsUnion) {
  const glm::dvec3 a0(0.013, 0.021, 0.017), a1(1.311, 1.107, 1.203), b0(0.611, 0.413, 0.309), b1(1.913, 1.617, 1.509);
  const TriangleMesh mesh = combined(boxMesh(a0, a1), boxMesh(b0, b1));
  auto in = [](const glm::dvec3& p, glm::dvec3 lo, glm::dvec3 hi) {
    return p.x >= lo.x && p.x < hi.x && p.y >= lo.y && p.y < hi.y && p.z >= lo.z && p.z < hi.z;
  };
  // The float32 corners, as the voxelizer sees them.
  auto f = [](glm::dvec3 v) { return glm::dvec3(glm::vec3(v)); };
  const VoxelizeResult parity = voxelize(mesh, 40, FillMode::kParity);
  const VoxelizeResult nonzero = voxelize(mesh, 40, FillMode::kNonzero);
  const VoxelGrid xor_grid = test::gridFromPredicate(
      parity.grid, [&](const glm::dvec3& p) { return in(p, f(a0), f(a1)) != in(p, f(b0), f(b1)); });
  const VoxelGrid union_grid = test::gridFromPredicate(
      parity.grid, [&](const glm::dvec3& p) { return in(p, f(a0), f(a1)) || in(p, f(b0), f(b1)); });
  EXPECT_EQ(mismatches(parity.grid, xor_grid), 0);
  EXPECT_EQ(mismatches(nonzero.grid, union_grid), 0);
  EXPECT_LT(parity.grid.filledCount(), nonzero.grid.filledCount());
  // Auto sees a closed mesh (two closed shells) and uses nonzero.
  const VoxelizeResult automatic = voxelize(mesh, 40, FillMode::kAuto);
  EXPECT_EQ(automatic.mode_used, FillMode::kNonzero);
  EXPECT_NE(automatic.mode_reason.find("closed"), std::string::npos) << automatic.mode_reason;
  EXPECT_EQ(mismatches(automatic.grid, union_grid), 0);
}

// An inside-out shell inside a solid cancels in nonzero mode (winding 1 - 1 = 0) and in parity (two crossings).
TEST(VoxelizeModes, insideOutShellCarvesACavity) {
  TriangleMesh inner = boxMesh({0.4, 0.4, 0.4}, {0.6, 0.6, 0.6});
  for (auto& t : inner.triangles) std::swap(t.v[1], t.v[2]);
  const TriangleMesh mesh = combined(boxMesh({0.013, 0.011, 0.017}, {0.987, 0.989, 0.991}), inner);
  for (FillMode mode : {FillMode::kParity, FillMode::kNonzero}) {
    const VoxelizeResult r = voxelize(mesh, 20, mode);
    EXPECT_FALSE(r.grid.get(9, 9, 9)) << fillModeName(mode);
    EXPECT_TRUE(r.grid.get(3, 3, 3)) << fillModeName(mode);
  }
}

// A sphere with a hole: auto detects the open mesh and votes; parity along X alone leaves streaks (odd rays) that
// the Y and Z votes outvote, and the voxels where the axes disagree are reported.
TEST(VoxelizeModes, meshWithHoleVotesAndReportsDisputedVoxels) {
  TriangleMesh sphere = test::icosphere({0, 0, 0}, 1.0, 3);
  const VoxelizeResult closed = voxelize(sphere, 40, FillMode::kNonzero);
  // Remove the triangles whose centroid lies near -x: rays along X then enter without a crossing and fill the
  // outside behind the sphere instead of its inside.
  std::erase_if(sphere.triangles,
                [](const Triangle& t) { return (double(t.v[0].x) + t.v[1].x + t.v[2].x) / 3.0 < -0.97; });
  const MeshTopology topo = analyzeTopology(sphere);
  ASSERT_GT(topo.boundary_edges, 0);
  const VoxelizeResult vote = voxelize(sphere, 40, FillMode::kAuto);
  EXPECT_EQ(vote.mode_used, FillMode::kVote);
  EXPECT_NE(vote.mode_reason.find("not watertight"), std::string::npos) << vote.mode_reason;
  EXPECT_NE(vote.mode_reason.find(std::to_string(topo.boundary_edges) + " boundary edges"), std::string::npos)
      << vote.mode_reason;
  EXPECT_GT(vote.disputed_count, 0);
  ASSERT_TRUE(vote.disputed.has_value());
  EXPECT_EQ(vote.disputed->count(), vote.disputed_count);
  EXPECT_EQ(vote.disputed->toGrid().filledCount(), vote.disputed_count);
  EXPECT_TRUE(hasWarning(vote, "odd number of crossings"));
  const VoxelizeResult parity = voxelize(sphere, 40, FillMode::kParity);
  EXPECT_TRUE(hasWarning(parity, "odd number of crossings"));
  // The vote repairs most of the damage: it differs from the closed sphere far less than parity along X does. (Where
  // the rays of all three axes pass through the hole, all three are wrong: a small cap behind the hole.)
  const int64_t vote_errors = mismatches(vote.grid, closed.grid);
  const int64_t parity_errors = mismatches(parity.grid, closed.grid);
  EXPECT_LT(vote_errors * 3, parity_errors) << vote_errors << " vs " << parity_errors;
  // Explicit parity on an open mesh warns when the topology is known.
  VoxelizeParams p;
  p.resolution = 20;
  p.mode = FillMode::kParity;
  auto warned = voxelizeSolid(sphere, p, {}, &topo);
  ASSERT_TRUE(warned.ok());
  EXPECT_TRUE(hasWarning(*warned, "not watertight"));
}

TEST(VoxelizeModes, namesParseAndRoundTrip) {
  for (FillMode m : {FillMode::kAuto, FillMode::kParity, FillMode::kNonzero, FillMode::kVote}) {
    EXPECT_EQ(parseFillMode(fillModeName(m)), m);
  }
  EXPECT_FALSE(parseFillMode("even-odd").has_value());
}

// ---- Accuracy ----

// The voxel volume of a sphere converges to the mesh volume; the error is bounded by the surface's voxel layer.
TEST(VoxelizeAccuracy, sphereVolumeErrorShrinksWithResolution) {
  const TriangleMesh sphere = test::icosphere({0.05, 0.1, -0.05}, 1.0, 4);
  const double exact = signedVolume(sphere);
  double previous = 1e300;
  for (int64_t r : {16, 32, 64, 128}) {
    const VoxelizeResult v = voxelize(sphere, r, FillMode::kAuto);
    const double h = v.grid.voxelSize();
    const double error = std::abs(double(v.grid.filledCount()) * h * h * h - exact) / exact;
    EXPECT_LT(error, previous * 0.75) << "R=" << r;
    EXPECT_LT(error, 3.0 / double(r)) << "R=" << r;
    previous = error;
  }
  EXPECT_LT(previous, 0.003);
}

// ---- Thin structures, strays, degenerate input ----

TEST(VoxelizeStrays, removeStraysDeletesVoxelLinesButKeepsSolidsAndSheets) {
  // A solid box, a rod thinner than a voxel through one row of centres (a voxel line) and a one-voxel sheet.
  TriangleMesh mesh = combined(unitGridFrame(), boxMesh({2.1, 2.1, 2.1}, {6.9, 6.9, 6.9}));
  mesh = combined(mesh, boxMesh({8.1, 10.4, 10.4}, {14.9, 10.6, 10.6}));  // centres y = z = 10.5: x = 8.5 .. 14.5
  mesh = combined(mesh, boxMesh({1.1, 12.4, 1.1}, {5.9, 12.6, 5.9}));     // sheet y = 12.5, 5 x 5 voxels
  VoxelizeParams p;
  p.resolution = 16;
  p.mode = FillMode::kParity;
  auto plain = voxelizeSolid(mesh, p);
  ASSERT_TRUE(plain.ok());
  EXPECT_EQ(plain->strays_removed, 0);
  EXPECT_EQ(plain->grid.filledCount(), 125 + 7 + 25);
  p.remove_strays = true;
  auto cleaned = voxelizeSolid(mesh, p);
  ASSERT_TRUE(cleaned.ok());
  // The rod's 7 voxels (4 or 5 free faces) and the sheet's 4 corners (4 free faces) go; the sheet's edges (3 free
  // faces) and inside (2), and the box's corners (3), stay.
  EXPECT_EQ(cleaned->strays_removed, 7 + 4);
  EXPECT_EQ(cleaned->grid.filledCount(), 125 + 25 - 4);
  EXPECT_FALSE(cleaned->grid.get(10, 10, 10));
  EXPECT_FALSE(cleaned->grid.get(1, 12, 1));
  EXPECT_TRUE(cleaned->grid.get(2, 12, 1));
  EXPECT_TRUE(cleaned->grid.get(3, 12, 3));
  EXPECT_TRUE(cleaned->grid.get(2, 2, 2));
}

TEST(VoxelizeInput, degenerateTrianglesAreIgnoredWithAWarning) {
  TriangleMesh mesh = boxMesh({0.013, 0.011, 0.017}, {0.987, 0.989, 0.991});
  const VoxelizeResult clean = voxelize(mesh, 16, FillMode::kParity);
  mesh.triangles.push_back({{{0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}, {0.7f, 0.2f, 0.4f}}});  // repeated vertex
  mesh.triangles.push_back({{{0.1f, 0.1f, 0.1f}, {0.2f, 0.2f, 0.2f}, {0.4f, 0.4f, 0.4f}}});  // collinear
  const VoxelizeResult r = voxelize(mesh, 16, FillMode::kParity);
  EXPECT_TRUE(hasWarning(r, "2 degenerate triangles"));
  EXPECT_EQ(mismatches(r.grid, clean.grid), 0);
}

// A plate thinner than a voxel, between two planes of centres, crosses rays without holding a centre: the layers it
// alone spans get toggles but no voxel, and must not stay allocated (a layer without voxels is the shared zero
// layer, which analyses, renderer and writers skip). The plate is in the upper half, the cube in the lower.
TEST(VoxelizeInput, layersWithCrossingsButNoVoxelsAreNotAllocated) {
  // A cube below, a one-voxel box in the top corner (so the grid spans z up to 3 at R = 30: h = 0.1), and between
  // them a plate across x between the centres of columns 4 and 5.
  const TriangleMesh solids = combined(test::boxMesh({0, 0, 0}, {1, 1, 1}), test::boxMesh({0.9, 0.9, 2.9}, {1, 1, 3}));
  VoxelizeParams p;
  p.resolution = 30;
  const auto placement = planVoxelization(solids.bounds(), p);
  ASSERT_TRUE(placement.ok());
  const GridFrame& f = placement->placement.frame;
  const double x4 = f.voxelCentre(4, 0, 0).x, x5 = f.voxelCentre(5, 0, 0).x;
  const TriangleMesh scene =
      combined(solids, test::boxMesh({x4 + 0.25 * (x5 - x4), 0.2, 2.2}, {x4 + 0.75 * (x5 - x4), 0.8, 2.8}));
  ASSERT_EQ(scene.bounds().min, solids.bounds().min);  // the same grid
  ASSERT_EQ(scene.bounds().max, solids.bounds().max);
  for (FillMode mode : {FillMode::kParity, FillMode::kNonzero}) {
    const VoxelizeResult r = voxelize(scene, 30, mode);
    int64_t empty_but_crossed = 0;
    for (int32_t z = 0; z < r.grid.nz(); ++z) {
      int64_t filled = 0;
      for (int32_t y = 0; y < r.grid.ny(); ++y) filled += popcountWords(r.grid.rowWords(y, z), r.grid.wordsPerRow());
      EXPECT_EQ(r.grid.layerAllocated(z), filled > 0) << fillModeName(mode) << " layer " << z;
      const double zc = f.voxelCentre(0, 0, z).z;
      empty_but_crossed += filled == 0 && zc > 2.2 && zc < 2.8;
    }
    EXPECT_GT(empty_but_crossed, 0) << fillModeName(mode);  // the plate's layers hold no voxel
  }
}

TEST(VoxelizeInput, resultIsIdenticalForAnyNumberOfThreads) {
  const TriangleMesh mesh =
      combined(test::icosphere({0, 0, 0}, 1.0, 3), test::torus({0.5, 0.2, 0.1}, 0.8, 0.3, 32, 16));
  for (FillMode mode : {FillMode::kParity, FillMode::kNonzero, FillMode::kVote}) {
    const VoxelizeResult one = voxelize(mesh, 57, mode, 1);
    for (int threads : {2, 3, 8}) {
      const VoxelizeResult many = voxelize(mesh, 57, mode, threads);
      EXPECT_EQ(mismatches(one.grid, many.grid), 0) << fillModeName(mode) << " threads " << threads;
      EXPECT_EQ(one.disputed_count, many.disputed_count);
      if (mode == FillMode::kVote) {
        ASSERT_TRUE(one.disputed && many.disputed);
        EXPECT_EQ(mismatches(one.disputed->toGrid(), many.disputed->toGrid()), 0) << "threads " << threads;
      }
      EXPECT_EQ(one.warnings, many.warnings);
    }
  }
}

TEST(VoxelizeInput, gridFollowsSpecPlacementAndCarriesUnitsAndSource) {
  TriangleMesh mesh = boxMesh({-1.0, 2.0, 3.0}, {3.0, 4.0, 3.5});
  mesh.name = "slab.stl";
  VoxelizeParams p;
  p.resolution = 32;
  p.units = "mm";
  auto r = voxelizeSolid(mesh, p);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->grid.dims(), (Dims{32, 16, 4}));
  EXPECT_EQ(r->grid.voxelSize(), 4.0 / 32.0);
  EXPECT_EQ(r->grid.frame().origin, glm::dvec3(-1.0, 2.0, 3.0));
  EXPECT_EQ(r->grid.frame().units, "mm");
  EXPECT_EQ(r->grid.frame().source, "slab.stl");
  EXPECT_EQ(r->grid.filledCount(), 32 * 16 * 4);  // the box is its own bounding box: every centre inside
  p.voxel_size = 0.5;
  auto by_size = voxelizeSolid(mesh, p);
  ASSERT_TRUE(by_size.ok());
  EXPECT_EQ(by_size->grid.dims(), (Dims{8, 4, 1}));
}

// ---- Progress, cancellation, limits, bad parameters ----

TEST(VoxelizeControl, progressIsMonotoneBoundedAndEndsAtOne) {
  const TriangleMesh mesh = test::icosphere({0, 0, 0}, 1.0, 3);
  for (FillMode mode : {FillMode::kNonzero, FillMode::kVote}) {
    std::vector<double> seen;
    VoxelizeParams p;
    p.resolution = 300;
    p.mode = mode;
    auto r = voxelizeSolid(mesh, p, [&](double f) {
      seen.push_back(f);
      return true;
    });
    ASSERT_TRUE(r.ok());
    ASSERT_FALSE(seen.empty());
    EXPECT_LE(seen.size(), 300u);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    EXPECT_EQ(seen.back(), 1.0);
  }
}

TEST(VoxelizeControl, progressReturningFalseCancels) {
  const TriangleMesh mesh = test::icosphere({0, 0, 0}, 1.0, 3);
  for (FillMode mode : {FillMode::kParity, FillMode::kVote}) {
    int calls = 0;
    VoxelizeParams p;
    p.resolution = 400;
    p.mode = mode;
    auto r = voxelizeSolid(mesh, p, [&](double) { return ++calls < 3; });
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::kCancelled);
    EXPECT_EQ(calls, 3);
  }
}

TEST(VoxelizeControl, refusesGridsAboveTheMemoryLimitBeforeAllocating) {
  const TriangleMesh mesh = boxMesh({0, 0, 0}, {1, 1, 1});
  VoxelizeParams p;
  p.resolution = 4096;
  p.mode = FillMode::kParity;
  p.memory_limit_bytes = uint64_t(1) << 30;  // 4096^3 bits need 8 GiB
  auto r = voxelizeSolid(mesh, p);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kLimit);
  EXPECT_NE(r.error().message.find("memory limit of 1.00 GiB"), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("4096 x 4096 x 4096"), std::string::npos) << r.error().message;
  p.mode = FillMode::kVote;
  p.resolution = 2048;
  // One 2048^3 grid (1 GiB) fits in 1.5 GiB; with the disputed set at its largest (about another GiB) it does not.
  p.memory_limit_bytes = uint64_t(3) << 29;
  auto vote = voxelizeSolid(mesh, p);
  ASSERT_FALSE(vote.ok());
  EXPECT_NE(vote.error().message.find("for the disputed voxels"), std::string::npos) << vote.error().message;
  // The plan says the same without voxelizing.
  auto plan = planVoxelization(mesh.bounds(), p);
  ASSERT_TRUE(plan.ok());
  EXPECT_EQ(plan->bytes, estimateGridBytes(plan->placement.dims) + SparseVoxels::maxBytes(plan->placement.dims));
  EXPECT_EQ(plan->limit_bytes, p.memory_limit_bytes);
  p.memory_limit_bytes = 0;
  auto default_plan = planVoxelization(mesh.bounds(), p);
  ASSERT_TRUE(default_plan.ok());
  EXPECT_EQ(default_plan->limit_bytes, physicalMemoryBytes() / 5 * 4);
  EXPECT_GT(physicalMemoryBytes(), uint64_t(1) << 28);
}

TEST(VoxelizeControl, badParametersAreRejectedWithReasons) {
  const TriangleMesh mesh = test::icosphere({0, 0, 0}, 1.0, 1);
  auto fails = [&](VoxelizeParams p, ErrorCode code, const std::string& text) {
    auto r = voxelizeSolid(mesh, p);
    ASSERT_FALSE(r.ok()) << text;
    EXPECT_EQ(r.error().code, code) << r.error().message;
    EXPECT_NE(r.error().message.find(text), std::string::npos) << r.error().message;
  };
  VoxelizeParams p;
  p.resolution = 0;
  fails(p, ErrorCode::kInvalidArgument, "resolution 0");
  p.resolution = 16385;
  fails(p, ErrorCode::kInvalidArgument, "resolution 16385");
  p.resolution = 64;
  p.voxel_size = -1.0;
  fails(p, ErrorCode::kInvalidArgument, "voxel size");
  p.voxel_size = std::nan("");
  fails(p, ErrorCode::kInvalidArgument, "voxel size");
  p.voxel_size = 1e-6;  // 2e6 voxels along the longest axis
  fails(p, ErrorCode::kLimit, "at most 16384");
  p.voxel_size = 0.0;
  p.threads = -1;
  fails(p, ErrorCode::kInvalidArgument, "threads");
  p.threads = 0;
  auto empty = voxelizeSolid(TriangleMesh{}, p);
  ASSERT_FALSE(empty.ok());
  EXPECT_EQ(empty.error().code, ErrorCode::kParse);
  EXPECT_NE(empty.error().message.find("no triangles"), std::string::npos);
}

// The voxelize dialog says what auto will use from this function, before voxelizing (it said "vote" for meshes that
// close once exporter noise is welded, which auto voxelizes with nonzero).
TEST(VoxelizeAuto, resolvesAsVoxelizeSolidDoesAndSaysWhy) {
  MeshTopology closed;
  closed.edges = 18;
  EXPECT_EQ(resolveAutoMode(closed).mode, FillMode::kNonzero);
  MeshTopology noise;
  noise.edges = 18;
  noise.boundary_edges = 576;
  noise.unbalanced_edges = 576;
  noise.closes_when_noise_welded = true;
  const ModeChoice n = resolveAutoMode(noise);
  EXPECT_EQ(n.mode, FillMode::kNonzero);
  EXPECT_NE(n.reason.find("closes when vertices within 1e-9"), std::string::npos) << n.reason;
  noise.closes_when_noise_welded = false;
  EXPECT_EQ(resolveAutoMode(noise).mode, FillMode::kVote);
  // voxelizeSolid reports the same choice and words.
  auto r = voxelizeSolid(test::unitCubeMesh(), VoxelizeParams{.resolution = 4});
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->mode_reason, resolveAutoMode(analyzeTopology(test::unitCubeMesh())).reason);
}

}  // namespace
}  // namespace vox
