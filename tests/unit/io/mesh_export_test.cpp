#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include "support/grids.h"
#include "support/test_support.h"
#include "vox/analysis/surface_mesh.h"
#include "vox/io/mesh_export.h"
#include "vox/io/mesh_file.h"
#include "vox/io/stl.h"
#include "vox/voxelize/voxelize.h"

namespace vox::io {
namespace {

// A unit cube at (1.25, -2, 3) with 8 shared vertices, outward.
IndexedMesh cube() {
  IndexedMesh m;
  m.name = "cube";
  for (int k = 0; k < 8; ++k) m.vertices.push_back(glm::dvec3(1.25 + (k & 1), -2.0 + ((k >> 1) & 1), 3.0 + (k >> 2)));
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

TEST(MeshExport, plyObjAnd3mfKeepTheSharedVerticesAndTriangles) {
  const test::TempDir dir;
  const IndexedMesh m = cube();
  for (const std::string ext : {".ply", ".obj", ".3mf", ".PLY"}) {
    SCOPED_TRACE(ext);
    const auto path = dir.path() / ("cube" + ext);
    ASSERT_TRUE(isMeshExportFile(path));
    ASSERT_TRUE(saveMesh(m, path).ok());
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path.string(), 0);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    ASSERT_EQ(scene->mNumMeshes, 1u);
    const aiMesh* read = scene->mMeshes[0];
    EXPECT_EQ(read->mNumFaces, 12u);
    if (ext == ".obj") {  // assimp's OBJ reader gives each face its own vertices: count the file's own lines
      const std::string text = test::readFile(path);
      size_t v = 0, f = 0;
      for (size_t at = 0; at < text.size(); at = text.find('\n', at) + 1) {
        v += text.compare(at, 2, "v ") == 0;
        f += text.compare(at, 2, "f ") == 0;
        if (text.find('\n', at) == std::string::npos) break;
      }
      EXPECT_EQ(v, 8u);
      EXPECT_EQ(f, 12u);
    } else {
      EXPECT_EQ(read->mNumVertices, 8u);
    }
    // the same corners, each face with the same corners in the same turning order
    for (unsigned f = 0; f < read->mNumFaces; ++f) {
      ASSERT_EQ(read->mFaces[f].mNumIndices, 3u);
      for (int c = 0; c < 3; ++c) {
        const aiVector3D& v = read->mVertices[read->mFaces[f].mIndices[c]];
        const glm::dvec3 want = m.vertices[m.triangles[f][size_t(c)]];
        EXPECT_NEAR(v.x, want.x, 1e-5);
        EXPECT_NEAR(v.y, want.y, 1e-5);
        EXPECT_NEAR(v.z, want.z, 1e-5);
      }
    }
  }
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 4);  // no temporary left behind
}

// The surface of `g` written as `ext` and read back by loadMeshFile.
MeshFileLoad roundTrip(const VoxelGrid& g, const std::filesystem::path& path) {
  auto mesh = extractSurfaceMesh(g, SurfaceMeshParams{});
  EXPECT_TRUE(mesh.ok());
  EXPECT_TRUE(saveMesh(*mesh, path, g.frame().units).ok());
  auto read = loadMeshFile(path);
  EXPECT_TRUE(read.ok()) << read.error().message;
  return read.ok() ? std::move(read).value() : MeshFileLoad{};
}

// Voxels touching along an edge and at a corner far from the origin (x about 100, h = 0.1): the surface's vertices
// split 1/256 of a voxel apart there must stay apart in the file, or the mesh read back has non-manifold edges.
TEST(MeshExport, threeMfKeepsTheSplitVerticesOfEdgeAndCornerContactsFarFromTheOrigin) {
  const test::TempDir dir;
  VoxelGrid g(Dims{3, 3, 3});
  g.set(0, 0, 0);
  g.set(1, 1, 0);  // along an edge
  g.set(2, 2, 1);  // at a corner
  g.frame().origin = glm::dvec3(100.3, 100.7, 100.1);
  g.frame().voxel_size = 0.1;
  g.frame().units = "mm";
  for (const std::string ext : {".3mf", ".stl"}) {  // STL stores floats: the reference
    SCOPED_TRACE(ext);
    const MeshFileLoad read = roundTrip(g, dir.path() / ("contacts" + ext));
    EXPECT_EQ(read.topology.boundary_edges, 0);
    EXPECT_EQ(read.topology.nonmanifold_edges, 0);
    EXPECT_EQ(read.topology.inconsistent_edges, 0);
  }
}

// The model's unit is the 3MF model's unit, read back as the same unit; a model without one is millimetres (3MF's
// default), its numbers unchanged.
TEST(MeshExport, threeMfWritesTheModelsUnit) {
  const test::TempDir dir;
  const std::pair<const char*, const char*> cases[] = {
      {"in", "inch"}, {"cm", "centimeter"}, {"m", "meter"}, {"mm", "millimeter"}, {"model", "millimeter"}};
  for (const auto& [units, file_units] : cases) {
    SCOPED_TRACE(units);
    const auto path = dir.path() / (std::string("cube_") + units + ".3mf");
    ASSERT_TRUE(saveMesh(cube(), path, units).ok());
    auto read = loadMeshFile(path);
    ASSERT_TRUE(read.ok()) << read.error().message;
    EXPECT_EQ(read->file_units, file_units);
    EXPECT_EQ(read->units, std::string(units) == "model" ? "mm" : units);
    EXPECT_NEAR(signedVolume(read->mesh), 1.0, 1e-6);  // the numbers as they were
    EXPECT_EQ(read->mesh.bounds().min.x, 1.25f);
  }
}

// Voxels to a 3MF surface and back, far from the origin: voxelized on the grid's lattice, the same grid voxel for
// voxel; and the very triangles an STL of the surface gives (both float), so any grid voxelizes them alike (6
// significant digits moved the mesh's box, and the grid fitted to it at the same voxel size grew a layer).
TEST(MeshExport, voxelsThroughThreeMfAndVoxelizedAgainAreTheSameVoxels) {
  const test::TempDir dir;
  VoxelGrid g = test::randomGrid(Dims{31, 31, 64}, 0.6, 7);
  for (int c = 0; c < 8; ++c) g.set((c & 1) * 30, ((c >> 1) & 1) * 30, (c >> 2) * 63);  // the box is the grid's
  g.frame().origin = glm::dvec3(96.55, 101.35, 93.95);
  g.frame().voxel_size = 0.1;
  g.frame().units = "mm";
  const MeshFileLoad three = roundTrip(g, dir.path() / "random.3mf");
  const MeshFileLoad stl = roundTrip(g, dir.path() / "random.stl");
  ASSERT_EQ(three.mesh.triangles.size(), stl.mesh.triangles.size());
  int64_t moved = 0;
  for (size_t i = 0; i < stl.mesh.triangles.size(); ++i)
    for (int c = 0; c < 3; ++c) moved += three.mesh.triangles[i].v[c] != stl.mesh.triangles[i].v[c];
  EXPECT_EQ(moved, 0);
  EXPECT_EQ(three.topology.boundary_edges, 0);
  EXPECT_EQ(three.topology.nonmanifold_edges, 0);

  VoxelizeParams p;
  p.mode = FillMode::kNonzero;
  p.placement = placeGridOnLattice(g.frame(), glm::ivec3(0), g.dims());
  auto again = voxelizeSolid(three.mesh, p);
  ASSERT_TRUE(again.ok());
  ASSERT_EQ(again->grid.dims(), g.dims());
  int64_t mismatches = 0;
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x) mismatches += again->grid.get(x, y, z) != g.get(x, y, z);
  EXPECT_EQ(mismatches, 0);
}

TEST(MeshExport, stlIsTheSoupOfTheSameTriangles) {
  const test::TempDir dir;
  const auto path = dir.path() / "cube.stl";
  ASSERT_TRUE(saveMesh(cube(), path).ok());
  auto stl = loadStl(path);
  ASSERT_TRUE(stl.ok());
  EXPECT_EQ(stl->mesh.triangles.size(), 12u);
  EXPECT_TRUE(stl->topology.watertight());
  EXPECT_NEAR(signedVolume(stl->mesh), 1.0, 1e-6);
}

TEST(MeshExport, unknownFormatsAndUnwritablePlacesAreRefusedAndLeaveNothing) {
  const test::TempDir dir;
  auto bad = saveMesh(cube(), dir.path() / "cube.xyz");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("cube.xyz"), std::string::npos);
  for (const std::string ext : {".stl", ".ply", ".3mf"}) {
    const auto path = dir.path() / "missing" / ("cube" + ext);
    auto s = saveMesh(cube(), path);
    ASSERT_FALSE(s.ok()) << ext;
    EXPECT_NE(s.error().message.find(path.string()), std::string::npos) << s.error().message;
  }
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 0);
}

}  // namespace
}  // namespace vox::io
