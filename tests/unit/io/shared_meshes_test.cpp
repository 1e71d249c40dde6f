// Every STL of the shared corpus (../shared/meshes) loads with the triangle count, encoding, header and topology
// that ../shared/meshes/manifest.json records (the table in ../shared/meshes/README.md).
#include <gtest/gtest.h>

#include "support/test_support.h"
#include "vox/io/stl.h"

namespace vox::io {
namespace {

struct MeshCase {
  const char* file;
  bool ascii;
  int64_t triangles;
  int64_t boundary_edges;
  int64_t nonmanifold_edges;
  const char* header;  // manifest "header": the binary header, or the first line of an ASCII file
};

// Copied from ../shared/meshes/manifest.json.
const MeshCase kMeshes[] = {
    {"featuretype.stl", false, 3476, 576, 0, "ddlid featuretype"},
    {"plate_holes.stl", false, 1252, 0, 0, "solid plate_holes"},
    {"rocker_arm.stl", false, 20088, 0, 0,
     "rocker_arm.stl from alecjacobson/common-3d-test-models:data/rocker-arm.obj"},
    {"fandisk.stl", false, 12946, 0, 0, "fandisk.stl from alecjacobson/common-3d-test-models:data/fandisk.obj"},
    {"tray_bottom_ascii.stl", true, 4520, 0, 0, "solid 1002_tray_bottom"},
    {"orion_capsule_ascii.stl", true, 51736, 0, 0, "solid orion_capsule_ascii"},
    {"stanford_bunny.stl", false, 69451, 223, 0,
     "stanford_bunny.stl from alecjacobson/common-3d-test-models:data/stanford-bunny.o"},
    {"armadillo.stl", false, 86482, 0, 0, "armadillo.stl from libigl/libigl-tutorial-data:armadillo.obj"},
    {"femur_right.stl", false, 75486, 0, 0, "Created by stlwrite.m 16-Jan-2013 16:13:42"},
    {"igea_refined_508k.stl", false, 508178, 0, 0,
     "igea_refined_508k.stl refined from alecjacobson/common-3d-test-models:data/igea."},
    {"cycloidal_assembly.stl", false, 43368, 0, 242, "cycloidal_assembly.stl from mikedh/trimesh:models/cycloidal.ply"},
    {"cube_axis_aligned.stl", false, 12, 0, 0, "cube_axis_aligned: box side 1.2345 at (0.1371,0.2459,0.3187)"},
    {"cube_rotated_45z.stl", false, 12, 0, 0, "cube_rotated_45z: same box rotated 45 deg about Z through its centre"},
    {"two_disjoint_cubes.stl", false, 24, 0, 0, "two_disjoint_cubes: two separate boxes, no shared vertices"},
};

class SharedMesh : public ::testing::TestWithParam<MeshCase> {};

TEST_P(SharedMesh, loadsWithManifestCountsEncodingAndTopology) {
  VOX_REQUIRE_SHARED(shared);
  const MeshCase& c = GetParam();
  const auto r = loadStl(shared / "meshes" / c.file);
  ASSERT_TRUE(r.ok()) << r.error().message;
  const StlLoad& s = r.value();
  EXPECT_EQ(int64_t(s.mesh.triangles.size()), c.triangles);
  EXPECT_EQ(s.ascii, c.ascii);
  EXPECT_EQ(s.ascii ? "solid " + s.header : s.header, c.header);
  EXPECT_EQ(s.topology.boundary_edges, c.boundary_edges);
  EXPECT_EQ(s.topology.nonmanifold_edges, c.nonmanifold_edges);
  EXPECT_EQ(s.topology.degenerate_triangles, 0);
  const bool watertight = c.boundary_edges == 0 && c.nonmanifold_edges == 0;
  EXPECT_EQ(s.topology.watertight(), watertight);
  // A warning exactly when the mesh is not watertight, and it gives both counts; a mesh open only by exporter noise
  // (featuretype) gets a note instead, saying it is treated as closed.
  if (watertight) {
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
    EXPECT_TRUE(s.notes.empty());
  } else if (s.topology.closes_when_noise_welded) {
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
    ASSERT_EQ(s.notes.size(), 1u);
    EXPECT_NE(s.notes[0].find("treated as closed: its " + std::to_string(c.boundary_edges + c.nonmanifold_edges) +
                              " open edges close"),
              std::string::npos)
        << s.notes[0];
  } else {
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("not watertight: " + std::to_string(c.boundary_edges) + " boundary edges, " +
                                 std::to_string(c.nonmanifold_edges) + " non-manifold edges"),
              std::string::npos)
        << s.warnings[0];
  }
  // Every vertex is finite and the bounding box is not empty.
  EXPECT_FALSE(s.mesh.bounds().empty());
}

INSTANTIATE_TEST_SUITE_P(Corpus, SharedMesh, ::testing::ValuesIn(kMeshes),
                         [](const ::testing::TestParamInfo<MeshCase>& p) {
                           std::string n = p.param.file;
                           n = n.substr(0, n.find('.'));
                           for (char& ch : n) {
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           }
                           return n;
                         });

TEST(SharedMeshDetails, plateHolesIsBinaryAlthoughItsHeaderStartsWithSolid) {
  VOX_REQUIRE_SHARED(shared);
  const std::string bytes = test::readFile(shared / "meshes" / "plate_holes.stl");
  ASSERT_EQ(bytes.substr(0, 5), "solid");
  const auto r = loadStl(shared / "meshes" / "plate_holes.stl");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_FALSE(r->ascii);
  const Box3d b = r->mesh.bounds();
  EXPECT_EQ(b.min, glm::dvec3(0.0));
  EXPECT_EQ(b.max, glm::dvec3(203.1999969482422, 304.8000183105469, 12.699999809265137));  // manifest bbox_max
}

TEST(SharedMeshDetails, trayBottomAsciiHasCrlfThreeDigitExponentsAndBareEndsolid) {
  VOX_REQUIRE_SHARED(shared);
  const std::string bytes = test::readFile(shared / "meshes" / "tray_bottom_ascii.stl");
  // The traps the file is in the corpus for, checked so the test keeps meaning something.
  ASSERT_NE(bytes.find("\r\n"), std::string::npos);
  ASSERT_NE(bytes.find("e+000"), std::string::npos);
  ASSERT_EQ(bytes.substr(bytes.size() - 10), "\r\nendsolid");
  const auto r = loadStl(shared / "meshes" / "tray_bottom_ascii.stl");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_TRUE(r->ascii);
  const Box3d b = r->mesh.bounds();
  EXPECT_EQ(b.min, glm::dvec3(0.0, 0.0, double(-355.6f)));
  EXPECT_EQ(b.max, glm::dvec3(double(355.6f), double(3.175f), 0.0));
}

TEST(SharedMeshDetails, asciiAndBinaryCopiesOfAMeshLoadTheSameVertices) {
  VOX_REQUIRE_SHARED(shared);
  // orion was written with %.9g from float32, so parsing must give back the float bits exactly: write it as
  // binary, reload, compare.
  const auto a = loadStl(shared / "meshes" / "orion_capsule_ascii.stl");
  ASSERT_TRUE(a.ok()) << a.error().message;
  test::TempDir tmp;
  ASSERT_TRUE(saveStlBinary(a->mesh, tmp / "orion.stl").ok());
  const auto b = loadStl(tmp / "orion.stl");
  ASSERT_TRUE(b.ok()) << b.error().message;
  EXPECT_FALSE(b->ascii);
  ASSERT_EQ(a->mesh.triangles.size(), b->mesh.triangles.size());
  for (size_t i = 0; i < a->mesh.triangles.size(); ++i) {
    for (int c = 0; c < 3; ++c) ASSERT_EQ(a->mesh.triangles[i].v[c], b->mesh.triangles[i].v[c]) << i;
  }
}

}  // namespace
}  // namespace vox::io
