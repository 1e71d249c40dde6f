#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include "support/test_support.h"
#include "vox/io/mesh_export.h"
#include "vox/io/stl.h"

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
