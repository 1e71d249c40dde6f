// Bodies of a mesh voxelized on the whole mesh's lattice (docs/conventions.md, "Assemblies"): each body's voxels
// equal what the body voxelized alone on the whole lattice gives, and their union equals nonzero on the whole mesh.
#include "vox/voxelize/bodies.h"

#include <gtest/gtest.h>

#include <string>

#include "support/test_support.h"
#include "support/test_meshes.h"
#include "vox/core/bits.h"
#include "vox/core/mesh_bodies.h"
#include "vox/io/stl.h"

namespace vox {
namespace {

using test::boxMesh;
using test::combined;

// Voxels where two grids of the same dims differ, by words.
int64_t wordMismatches(const VoxelGrid& a, const VoxelGrid& b) {
  EXPECT_EQ(a.dims(), b.dims());
  int64_t n = 0;
  for (int32_t z = 0; z < a.nz(); ++z)
    for (int32_t y = 0; y < a.ny(); ++y) {
      const uint64_t *ra = a.rowWords(y, z), *rb = b.rowWords(y, z);
      for (int64_t w = 0; w < a.wordsPerRow(); ++w) n += popcount64(ra[w] ^ rb[w]);
    }
  return n;
}

VoxelGrid voxelizeOn(const TriangleMesh& mesh, const GridPlacement& placement, FillMode mode) {
  VoxelizeParams p;
  p.placement = placement;
  p.mode = mode;
  auto r = voxelizeSolid(mesh, p);
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message);
  return r.ok() ? std::move(r->grid) : VoxelGrid();
}

// The body's voxels on the whole grid (its box placed at `first`), and the union of all bodies, word by word.
VoxelGrid onWholeGrid(const LatticeGrid& body, const GridPlacement& whole, const Lattice& lattice) {
  const Box3i box{glm::ivec3(0), glm::ivec3(whole.dims.nx, whole.dims.ny, whole.dims.nz)};
  return reframe(body, box, lattice).grid;
}

void orInto(VoxelGrid& into, const VoxelGrid& g) {
  for (int32_t z = 0; z < g.nz(); ++z) {
    if (!g.layerAllocated(z)) continue;
    uint64_t* w = into.mutableLayerWords(z);
    const uint64_t* v = g.layerWords(z);
    for (int64_t i = 0; i < g.wordsPerLayer(); ++i) w[i] |= v[i];
  }
}

// Checks every body against itself voxelized alone on the whole lattice, and the union against the whole mesh.
void expectBodiesExact(const TriangleMesh& mesh, const BodiesResult& r, const MeshBodies& bodies) {
  const GridPlacement& whole = r.placement;
  VoxelGrid all(whole.dims);
  for (size_t i = 0; i < r.bodies.size(); ++i) {
    const VoxelGrid mine = onWholeGrid(r.bodies[i].voxels, whole, r.lattice);
    const VoxelGrid alone = voxelizeOn(bodyMesh(mesh, bodies, i), whole, FillMode::kNonzero);
    EXPECT_EQ(wordMismatches(mine, alone), 0) << "body " << i;
    EXPECT_EQ(r.bodies[i].filled, alone.filledCount()) << "body " << i;
    orInto(all, mine);
  }
  const VoxelGrid nonzero = voxelizeOn(mesh, whole, FillMode::kNonzero);
  EXPECT_EQ(wordMismatches(all, nonzero), 0);
}

TEST(MeshBodies, numberedByFirstTriangleInTheFile) {
  TriangleMesh a = boxMesh({0, 0, 0}, {1, 1, 1}), b = boxMesh({2, 0, 0}, {3, 1, 1});
  TriangleMesh mesh;
  // Interleave: b's first triangle comes first, then a's, then the rest.
  mesh.triangles = {b.triangles[0], a.triangles[0]};
  for (size_t i = 1; i < 12; ++i) mesh.triangles.push_back(a.triangles[i]);
  for (size_t i = 1; i < 12; ++i) mesh.triangles.push_back(b.triangles[i]);
  const MeshBodies bodies = splitBodies(mesh);
  ASSERT_EQ(bodies.count(), 2u);
  EXPECT_EQ(bodies.body_of[0], 0u);  // b
  EXPECT_EQ(bodies.body_of[1], 1u);  // a
  EXPECT_EQ(bodies.triangles[0].size(), 12u);
  EXPECT_EQ(bodies.triangles[1].size(), 12u);
  EXPECT_EQ(bodies.triangles[0][1], 13u);
}

TEST(MeshBodies, touchingAtOneVertexIsOneBody) {
  // Two boxes sharing the corner (1, 1, 1) exactly: connected through a shared vertex.
  const TriangleMesh mesh = combined(boxMesh({0, 0, 0}, {1, 1, 1}), boxMesh({1, 1, 1}, {2, 2, 2}));
  EXPECT_EQ(splitBodies(mesh).count(), 1u);
}

TEST(VoxelizeBodies, overlappingBoxesMatchAloneAndUnion) {
  // Three boxes, two overlapping in a block, the third apart: ties on faces at voxel centres included (R = 40
  // puts centres on x = 1.0 planes).
  TriangleMesh mesh = combined(boxMesh({0, 0, 0}, {2, 1, 1}), boxMesh({1.5, 0.25, 0.5}, {3, 1.5, 2}));
  mesh = combined(mesh, boxMesh({3.5, 0, 0}, {4, 2, 0.5}));
  VoxelizeParams p;
  p.resolution = 40;
  auto r = voxelizeBodies(mesh, p);
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(r->bodies.size(), 3u);
  expectBodiesExact(mesh, *r, splitBodies(mesh));
  // Bodies keep to their own boxes (plus a voxel of margin), not the whole grid.
  EXPECT_LT(r->bodies[2].voxels.grid.nx(), 10);
}

TEST(VoxelizeBodies, cycloidalAssemblyHas100BodiesEachExact) {
  VOX_REQUIRE_SHARED(shared);
  auto stl = io::loadStl(shared / "meshes" / "cycloidal_assembly.stl");
  ASSERT_TRUE(stl.ok()) << stl.error().message;
  const TriangleMesh& mesh = stl->mesh;
  const MeshBodies bodies = splitBodies(mesh);
  ASSERT_EQ(bodies.count(), 100u);
  VoxelizeParams p;
  p.resolution = 160;
  auto r = voxelizeBodies(mesh, p, {}, &bodies);
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(r->bodies.size(), 100u);
  int64_t triangles = 0;
  for (const BodyVoxels& b : r->bodies) triangles += b.triangles;
  EXPECT_EQ(triangles, int64_t(mesh.triangles.size()));
  expectBodiesExact(mesh, *r, bodies);
}

}  // namespace
}  // namespace vox
