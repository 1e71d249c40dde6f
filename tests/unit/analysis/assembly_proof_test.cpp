// Proofs on the shared meshes (docs/conventions.md, "Assemblies"): Booleans of parts voxelized over their own boxes
// equal the set operations on the meshes voxelized separately on the whole pair's grid, voxel for voxel; the
// interference of every pair of the cycloidal drive's bodies equals the slow count over bodies voxelized alone.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/test_support.h"
#include "vox/analysis/assembly.h"
#include "vox/core/bits.h"
#include "vox/core/mesh_bodies.h"
#include "vox/io/stl.h"
#include "vox/voxelize/bodies.h"
#include "vox/voxelize/voxelize.h"

namespace vox {
namespace {

VoxelGrid voxelizeOn(const TriangleMesh& mesh, const GridPlacement& placement) {
  VoxelizeParams p;
  p.placement = placement;
  auto r = voxelizeSolid(mesh, p);
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message);
  return r.ok() ? std::move(r->grid) : VoxelGrid();
}

// The mesh over its own box of the whole grid (as the CLI places each mesh of a pair).
LatticeGrid voxelizeOwnBox(const TriangleMesh& mesh, const GridPlacement& whole) {
  glm::ivec3 begin, end;
  latticeRange(whole, mesh.bounds(), begin, end);
  const glm::ivec3 size = end - begin;
  const GridPlacement own = placeGridOnLattice(whole.frame, begin, Dims{size.x, size.y, size.z});
  return LatticeGrid{voxelizeOn(mesh, own), begin};
}

uint64_t combine(uint64_t a, uint64_t b, PartOp op) {
  switch (op) {
    case PartOp::kUnion:
      return a | b;
    case PartOp::kIntersection:
      return a & b;
    case PartOp::kDifference:
      return a & ~b;
    case PartOp::kXor:
      return a ^ b;
  }
  return 0;
}

TriangleMesh load(const std::filesystem::path& shared, const std::string& name) {
  auto stl = io::loadStl(shared / "meshes" / name);
  EXPECT_TRUE(stl.ok()) << name;
  return stl.ok() ? std::move(stl->mesh) : TriangleMesh{};
}

TEST(AssemblyProof, booleansEqualSetOperationsOnSeparateGrids) {
  VOX_REQUIRE_SHARED(shared);
  const std::pair<const char*, const char*> pairs[] = {{"cube_axis_aligned.stl", "cube_rotated_45z.stl"},
                                                       {"two_disjoint_cubes.stl", "cube_rotated_45z.stl"},
                                                       {"armadillo.stl", "stanford_bunny.stl"},
                                                       {"fandisk.stl", "rocker_arm.stl"}};
  for (const auto& [name_a, name_b] : pairs) {
    const TriangleMesh a = load(shared, name_a), b = load(shared, name_b);
    Box3d both = a.bounds();
    both.expand(b.bounds().min);
    both.expand(b.bounds().max);
    const GridPlacement whole = *placeGridByResolution(both, 128);  // SPEC 7: the pair's grid
    const Lattice lattice{whole.frame.origin, whole.frame.voxel_size, "model"};
    const VoxelGrid ga = voxelizeOn(a, whole), gb = voxelizeOn(b, whole);
    const LatticeGrid pa = voxelizeOwnBox(a, whole), pb = voxelizeOwnBox(b, whole);
    const Box3i box{glm::ivec3(0), glm::ivec3(whole.dims.nx, whole.dims.ny, whole.dims.nz)};
    for (PartOp op : {PartOp::kUnion, PartOp::kIntersection, PartOp::kDifference, PartOp::kXor}) {
      const VoxelGrid r = reframe(booleanParts(pa, pb, op, lattice), box, lattice).grid;
      int64_t mismatches = 0, want = 0;
      for (int32_t z = 0; z < r.nz(); ++z)
        for (int32_t y = 0; y < r.ny(); ++y)
          for (int64_t w = 0; w < r.wordsPerRow(); ++w) {
            const uint64_t expect = combine(ga.rowWords(y, z)[w], gb.rowWords(y, z)[w], op);
            want += popcount64(expect);
            mismatches += popcount64(expect ^ r.rowWords(y, z)[w]);
          }
      EXPECT_EQ(mismatches, 0) << name_a << " " << partOpName(op) << " " << name_b;
      EXPECT_EQ(r.filledCount(), want);
    }
  }
}

TEST(AssemblyProof, cycloidalInterferenceEqualsTheSlowCount) {
  VOX_REQUIRE_SHARED(shared);
  const TriangleMesh mesh = load(shared, "cycloidal_assembly.stl");
  const MeshBodies bodies = splitBodies(mesh);
  ASSERT_EQ(bodies.count(), 100u);
  VoxelizeParams params;
  params.resolution = 120;
  auto r = voxelizeBodies(mesh, params, {}, &bodies);
  ASSERT_TRUE(r.ok()) << r.error().message;
  std::vector<LatticeGrid> parts;
  for (BodyVoxels& b : r->bodies) parts.push_back(b.voxels);
  const Interference found = findInterference(parts, r->lattice);
  // The slow way: every body voxelized alone on the whole grid, every pair ANDed word by word.
  std::vector<VoxelGrid> alone;
  for (size_t i = 0; i < bodies.count(); ++i) alone.push_back(voxelizeOn(bodyMesh(mesh, bodies, i), r->placement));
  std::vector<int64_t> want(100 * 100, 0);
  for (size_t i = 0; i < 100; ++i)
    for (size_t j = i + 1; j < 100; ++j) {
      const VoxelGrid &a = alone[i], &b = alone[j];
      int64_t n = 0;
      for (int32_t z = 0; z < a.nz(); ++z) {
        if (!a.layerAllocated(z) || !b.layerAllocated(z)) continue;
        const uint64_t *wa = a.layerWords(z), *wb = b.layerWords(z);
        for (int64_t k = 0; k < a.wordsPerLayer(); ++k) n += popcount64(wa[k] & wb[k]);
      }
      want[i * 100 + j] = n;
    }
  size_t pairs = 0;
  for (int64_t n : want) pairs += n > 0 ? 1 : 0;
  ASSERT_EQ(found.pairs.size(), pairs);
  for (const InterferencePair& p : found.pairs)
    EXPECT_EQ(p.voxels, want[size_t(p.a) * 100 + size_t(p.b)]) << p.a << " " << p.b;
  EXPECT_GT(pairs, 20u);  // the drive's bodies interpenetrate (36 pairs at R = 120, 207 at R = 1000)
  // overlap_voxels: voxels in two or more bodies, counted with three bit planes over the whole grid.
  int64_t twos = 0, threes = 0;
  const VoxelGrid& first = alone[0];
  for (int32_t z = 0; z < first.nz(); ++z)
    for (int64_t k = 0; k < first.wordsPerLayer(); ++k) {
      uint64_t ones = 0, two = 0, three = 0;
      for (const VoxelGrid& g : alone) {
        const uint64_t x = g.layerWords(z)[k];
        three |= two & x;
        two |= ones & x;
        ones |= x;
      }
      twos += popcount64(two);
      threes += popcount64(three);
    }
  EXPECT_EQ(found.overlap_voxels, twos);
  EXPECT_EQ(found.multiple_overlap_voxels, threes);
}

}  // namespace
}  // namespace vox
