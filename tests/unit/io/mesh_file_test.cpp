// The mesh formats behind loadMeshFile (OBJ, PLY, 3MF, glTF / GLB, OFF through assimp; STL on voxmod's reader) on
// files written in the test, most with assimp's own exporters: geometry kept bit for bit, bodies, units, the
// reader chosen by extension and content, and the malformed files each format must refuse with a clear message.
#include "vox/io/mesh_file.h"

#include <algorithm>
#include <cstring>
#include <memory>

#include <assimp/Exporter.hpp>
#include <assimp/scene.h>
#include <glm/common.hpp>
#include <gtest/gtest.h>

#include "io/polygon_slivers.h"
#include "support/test_support.h"
#include "vox/io/stl.h"

namespace vox::io {
namespace {

std::vector<uint8_t> bytesOf(const std::string& s) { return {s.begin(), s.end()}; }

// The mesh as an assimp scene: one node per part, each with its own mesh and transform, triangles with their own
// corners shared by index (as the exporters expect).
std::unique_ptr<aiScene> sceneOf(const std::vector<TriangleMesh>& parts, const std::vector<aiMatrix4x4>& transforms) {
  auto scene = std::make_unique<aiScene>();
  scene->mRootNode = new aiNode("root");
  scene->mNumMaterials = 1;
  scene->mMaterials = new aiMaterial* [1] { new aiMaterial() };
  scene->mNumMeshes = unsigned(parts.size());
  scene->mMeshes = new aiMesh*[parts.size()];
  std::vector<aiNode*> nodes;
  for (size_t k = 0; k < parts.size(); ++k) {
    auto* m = new aiMesh();
    scene->mMeshes[k] = m;
    m->mName = aiString("part" + std::to_string(k + 1));
    m->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    m->mNumVertices = unsigned(3 * parts[k].triangles.size());
    m->mVertices = new aiVector3D[m->mNumVertices];
    m->mNumFaces = unsigned(parts[k].triangles.size());
    m->mFaces = new aiFace[m->mNumFaces];
    for (unsigned t = 0; t < m->mNumFaces; ++t) {
      m->mFaces[t].mNumIndices = 3;
      m->mFaces[t].mIndices = new unsigned[3]{3 * t, 3 * t + 1, 3 * t + 2};
      for (unsigned c = 0; c < 3; ++c) {
        const glm::vec3& v = parts[k].triangles[t].v[c];
        m->mVertices[3 * t + c] = aiVector3D(v.x, v.y, v.z);
      }
    }
    auto* node = new aiNode("part" + std::to_string(k + 1));
    node->mTransformation = k < transforms.size() ? transforms[k] : aiMatrix4x4();
    node->mNumMeshes = 1;
    node->mMeshes = new unsigned[1]{unsigned(k)};
    nodes.push_back(node);
  }
  scene->mRootNode->addChildren(unsigned(nodes.size()), nodes.data());
  return scene;
}

void exportScene(const aiScene& scene, const char* format_id, const std::filesystem::path& path) {
  Assimp::Exporter exporter;
  ASSERT_EQ(exporter.Export(&scene, format_id, path.string()), AI_SUCCESS) << exporter.GetErrorString();
}

MeshFileLoad loadOk(const std::filesystem::path& path, const MeshFileOptions& options = {}) {
  auto r = loadMeshFile(path, options);
  EXPECT_TRUE(r.ok()) << r.error().message;
  return r.ok() ? std::move(r).value() : MeshFileLoad{};
}

// A box whose corners are not round numbers in decimal, so a writer that prints too few digits is caught.
TriangleMesh oddBox() {
  TriangleMesh m = test::unitCubeMesh();
  for (Triangle& t : m.triangles) {
    for (glm::vec3& v : t.v) v = v * glm::vec3(0.1f, 1.0f / 3.0f, 2.7182817f) + glm::vec3(1e-3f, -7.25f, 1.1f);
  }
  return m;
}

// assimp 5.2's 3MF exporter prints coordinates with 6 significant digits, so its files hold the box to that
// precision only (the reader keeps what the file holds); every other writer here prints or stores floats exactly.
TEST(MeshFile, assimpFormatsKeepEveryFloatOfTheMesh) {
  test::TempDir tmp;
  const TriangleMesh box = oddBox();
  const auto scene = sceneOf({box}, {});
  struct Case {
    const char* exporter;
    const char* file;
    MeshFormat format;
    const char* units;
  };
  for (const Case& c :
       {Case{"objnomtl", "b.obj", MeshFormat::kObj, "model"}, Case{"ply", "b.ply", MeshFormat::kPly, "model"},
        Case{"plyb", "bb.ply", MeshFormat::kPly, "model"}, Case{"3mf", "b.3mf", MeshFormat::k3mf, "mm"},
        Case{"glb2", "b.glb", MeshFormat::kGlb, "m"}, Case{"gltf2", "b.gltf", MeshFormat::kGltf, "m"}}) {
    exportScene(*scene, c.exporter, tmp / c.file);
    const MeshFileLoad m = loadOk(tmp / c.file);
    EXPECT_EQ(m.format, c.format) << c.file;
    EXPECT_EQ(m.units, c.units) << c.file;
    ASSERT_EQ(m.mesh.triangles.size(), 12u) << c.file;
    for (size_t i = 0; i < 12; ++i) {
      for (int k = 0; k < 3; ++k) {
        if (c.format == MeshFormat::k3mf) {
          const glm::vec3 d = glm::abs(m.mesh.triangles[i].v[k] - box.triangles[i].v[k]);
          EXPECT_LE(std::max({d.x, d.y, d.z}), 1e-5f) << c.file << " triangle " << i << " corner " << k;
          continue;
        }
        EXPECT_EQ(std::memcmp(&m.mesh.triangles[i].v[k], &box.triangles[i].v[k], sizeof(glm::vec3)), 0)
            << c.file << " triangle " << i << " corner " << k;
      }
    }
    EXPECT_TRUE(m.topology.watertight()) << c.file;
    EXPECT_TRUE(m.warnings.empty()) << c.file << ": " << m.warnings.front();
    ASSERT_EQ(m.bodies.size(), 1u) << c.file;
  }
}

TEST(MeshFile, gltfBuffersAreFoundBesideTheFileOnly) {
  test::TempDir tmp;
  exportScene(*sceneOf({oddBox()}, {}), "gltf2", tmp / "b.gltf");
  ASSERT_TRUE(std::filesystem::exists(tmp / "b.bin"));
  EXPECT_EQ(loadOk(tmp / "b.gltf").mesh.triangles.size(), 12u);
  const std::string json = test::readFile(tmp / "b.gltf");
  auto r = parseMeshFile(bytesOf(json), "b.gltf");  // from memory: no files beside it
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kParse);
  EXPECT_EQ(r.error().message.rfind("b.gltf: not a readable glTF file (assimp: ", 0), 0u) << r.error().message;
}

TEST(MeshFile, sceneNodesAreBodiesPlacedByTheirTransforms) {
  test::TempDir tmp;
  aiMatrix4x4 shift, mirror;
  aiMatrix4x4::Translation(aiVector3D(5, 0, 0), shift);
  aiMatrix4x4::Scaling(aiVector3D(-1, 1, 1), mirror);  // a mirrored instance must stay outward-facing
  exportScene(*sceneOf({test::unitCubeMesh(), test::unitCubeMesh()}, {shift, mirror}), "glb2", tmp / "two.glb");
  const MeshFileLoad m = loadOk(tmp / "two.glb");
  ASSERT_EQ(m.bodies.size(), 2u);
  EXPECT_EQ(m.bodies[0].name, "part1");
  EXPECT_EQ(m.bodies[1].name, "part2");
  EXPECT_EQ(m.mesh.bounds().min, glm::dvec3(-1, 0, 0));
  EXPECT_EQ(m.mesh.bounds().max, glm::dvec3(6, 1, 1));
  EXPECT_DOUBLE_EQ(signedVolume(m.mesh), 2.0);
  EXPECT_TRUE(m.topology.closedOriented());
}

TEST(MeshFile, objObjectsAreBodies) {
  test::TempDir tmp;
  std::string obj = "o first\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  obj += "o second\nv 2 0 0\nv 3 0 0\nv 2 1 0\nv 2 0 1\nf 5 7 6\nf 5 6 8\nf 5 8 7\nf 6 7 8\n";
  test::writeFile(tmp / "two.obj", obj);
  const MeshFileLoad m = loadOk(tmp / "two.obj");
  ASSERT_EQ(m.bodies.size(), 2u);
  EXPECT_EQ(m.bodies[0].name, "first");
  EXPECT_EQ(m.bodies[1].name, "second");
  EXPECT_EQ(m.bodies[1].first_triangle, 4u);
  EXPECT_TRUE(m.topology.watertight());
}

// A 2 x 1 x 1 box whose top and front faces are pentagons: the corner (1, 0, 1) lies on the edge between them.
// Ear-clipping can cut the ear (0,0,1) (1,0,1) (2,0,1) of zero area; voxmod splits it away.
TEST(MeshFile, polygonsWithCollinearCornersGiveAWatertightMeshWithoutSlivers) {
  test::TempDir tmp;
  test::writeFile(tmp / "p.obj",
                  "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 2 0 1\nv 2 1 1\nv 0 1 1\n"
                  "f 1 4 3 2\n"    // bottom
                  "f 5 6 7 8 9\n"  // top, with the extra corner 6
                  "f 1 2 7 6 5\n"  // front, with the extra corner 6
                  "f 2 3 8 7\nf 3 4 9 8\nf 4 1 5 9\n");
  const MeshFileLoad m = loadOk(tmp / "p.obj");
  EXPECT_TRUE(m.topology.watertight());
  EXPECT_EQ(m.topology.degenerate_triangles, 0);
  EXPECT_DOUBLE_EQ(signedVolume(m.mesh), 2.0);
  EXPECT_TRUE(m.warnings.empty()) << m.warnings.front();
}

TEST(PolygonSlivers, theSpanningTriangleIsSplitAtTheCollinearCorner) {
  // Quad a, v, b, c with v the midpoint of ab, triangulated as the sliver (a, v, b) and (a, b, c).
  const std::vector<glm::dvec3> p = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1, 1, 0}};
  std::vector<TriangleIndices> t = {{0, 1, 2}, {0, 2, 3}};
  EXPECT_EQ(removePolygonSlivers(t, p), 1);
  EXPECT_EQ(t[0], (TriangleIndices{0, 1, 3}));
  EXPECT_EQ(t[1], (TriangleIndices{1, 2, 3}));
  EXPECT_EQ(removePolygonSlivers(t, p), 0);  // nothing left to split
}

TEST(MeshFile, offIsRead) {
  test::TempDir tmp;
  test::writeFile(tmp / "t.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const MeshFileLoad m = loadOk(tmp / "t.off");
  EXPECT_EQ(m.format, MeshFormat::kOff);
  EXPECT_EQ(m.mesh.triangles.size(), 4u);
  EXPECT_TRUE(m.topology.watertight());
  EXPECT_NEAR(signedVolume(m.mesh), 1.0 / 6.0, 1e-7);
}

TEST(MeshFile, unitsComeFromTheFileOrTheCaller) {
  test::TempDir tmp;
  exportScene(*sceneOf({test::unitCubeMesh()}, {}), "3mf", tmp / "b.3mf");
  EXPECT_EQ(loadOk(tmp / "b.3mf").file_units, "millimeter");
  MeshFileOptions inches;
  inches.units = "in";
  const MeshFileLoad m = loadOk(tmp / "b.3mf", inches);
  EXPECT_EQ(m.units, "in");
  EXPECT_EQ(m.mesh.bounds().max, glm::dvec3(1, 1, 1));  // labelled, not scaled
  ASSERT_FALSE(m.notes.empty());
  EXPECT_EQ(m.notes[0], (tmp / "b.3mf").string() + ": coordinates taken as in (the file says millimeter)");
  MeshFileOptions bad;
  bad.units = "furlong";
  auto r = loadMeshFile(tmp / "b.3mf", bad);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kInvalidArgument);
}

TEST(MeshFile, stlStaysOnVoxmodsReader) {
  test::TempDir tmp;
  ASSERT_TRUE(saveStlBinary(oddBox(), tmp / "b.stl").ok());
  const auto stl = loadStl(tmp / "b.stl");
  const MeshFileLoad m = loadOk(tmp / "b.stl");
  EXPECT_EQ(m.format, MeshFormat::kStl);
  EXPECT_EQ(m.format_detail, "binary STL");
  EXPECT_EQ(m.units, "model");
  ASSERT_EQ(m.mesh.triangles.size(), stl->mesh.triangles.size());
  EXPECT_EQ(std::memcmp(m.mesh.triangles.data(), stl->mesh.triangles.data(), 12 * sizeof(Triangle)), 0);
  // A name without a known extension is read by its content, and as STL when it has none (binary STL).
  std::filesystem::copy_file(tmp / "b.stl", tmp / "b.dat");
  EXPECT_EQ(loadOk(tmp / "b.dat").format, MeshFormat::kStl);
  exportScene(*sceneOf({oddBox()}, {}), "plyb", tmp / "p.ply");
  std::filesystem::copy_file(tmp / "p.ply", tmp / "p.dat");
  EXPECT_EQ(loadOk(tmp / "p.dat").format, MeshFormat::kPly);
}

struct Refusal {
  const char* name;
  std::string bytes;
  ErrorCode code;
  const char* message;
};

std::string plyHeader(const char* format, int vertices, int faces) {
  return std::string("ply\nformat ") + format + " 1.0\nelement vertex " + std::to_string(vertices) +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " + std::to_string(faces) +
         "\nproperty list uchar int vertex_indices\nend_header\n";
}

std::string binaryTriangle() {
  std::string s;
  for (float f : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) s.append(reinterpret_cast<const char*>(&f), 4);
  s += '\3';
  for (int32_t i : {0, 1, 2}) s.append(reinterpret_cast<const char*>(&i), 4);
  return s;
}

TEST(MeshFile, malformedFilesAreRefusedWithAMessageNamingThem) {
  const std::string tri = "0 0 0\n1 0 0\n0 1 0\n";
  const Refusal cases[] = {
      {"a.ply", plyHeader("ascii", 8, 1) + tri + "3 0 1 2\n", ErrorCode::kParse,
       "a.ply:13: PLY vertex 4 of 8 has 4 values where the header declares 3: its counts do not match the data"},
      {"b.ply", plyHeader("ascii", 3, 5) + tri + "3 0 1 2\n", ErrorCode::kParse,
       "b.ply: PLY data ends in face 2 of 5 (after line 13): the header declares more elements than the file holds"},
      {"c.ply", plyHeader("ascii", 2, 1) + tri + "3 0 1 2\n", ErrorCode::kParse,
       "c.ply:12: PLY face 1 of 1 has 3 values where the header declares 1: its counts do not match the data"},
      {"d.ply", plyHeader("ascii", 3, 1) + tri + "3 0 1 2\n3 0 2 1\n", ErrorCode::kParse,
       "d.ply: more data after the elements the header declares (line 14): it declares fewer than the file holds"},
      {"e.ply", plyHeader("binary_little_endian", 1000, 2000) + binaryTriangle(), ErrorCode::kParse,
       "e.ply: PLY data ends in vertex 5 of 1000 (byte 49 of the body): the header declares more elements than the "
       "file holds"},
      {"f.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n", ErrorCode::kParse,
       "f.ply: PLY file has no 'vertex' element with x, y and z"},
      {"f2.ply", plyHeader("ascii", 3, 1) + tri + "3 0 1 7\n", ErrorCode::kParse,
       "f2.ply: not a readable PLY file (assimp: 'Validation failed: aiMesh::mFaces[0]::mIndices[2] is out of "
       "range')"},
      {"g.ply", "ply\nformat ascii 1.0\nelement vertex 3\n", ErrorCode::kParse,
       "g.ply: PLY header has no 'end_header' line"},
      {"h.obj", "", ErrorCode::kParse, "h.obj: file is empty"},
      {"i.obj", "# exported by nothing at all\n# just comments, no vertex, no face, nothing to voxelize here\n",
       ErrorCode::kParse, "i.obj: OBJ file contains no triangles"},
      {"j.obj", std::string("v 0 0 0\0\0\0\1", 11), ErrorCode::kParse,
       "j.obj: not an OBJ file: it holds binary data (OBJ is text)"},
      {"k.3mf", "<?xml version=\"1.0\"?><model unit=\"millimeter\"></model>", ErrorCode::kParse,
       "k.3mf: not a 3MF file: it does not start with a zip signature ('PK')"},
      {"l.3mf", "PK\3\4 and then nothing a zip reader could use", ErrorCode::kParse,
       "l.3mf: not a 3MF file: it is not a zip archive"},
      {"m.step", plyHeader("ascii", 3, 1) + tri + "3 0 1 2\n", ErrorCode::kParse,
       "m.step: not a STEP file: it looks like a PLY file (name it .ply to read it as one)"},
      {"n.ply", "ISO-10303-21;\nHEADER;\n", ErrorCode::kParse,
       "n.ply: not a PLY file: it looks like a STEP file (name it .step to read it as one)"},
      {"o.glb", "glTF\2\0\0\0", ErrorCode::kParse, nullptr},
      {"p.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n", ErrorCode::kParse, nullptr},
      {"q.stl", "PK\3\4", ErrorCode::kParse,
       "q.stl: not an STL file: it looks like a zip archive (3MF) (name it .3mf to read it as one)"},
  };
  for (const Refusal& c : cases) {
    auto r = parseMeshFile(bytesOf(c.bytes), c.name);
    ASSERT_FALSE(r.ok()) << c.name << " was accepted";
    EXPECT_EQ(r.error().code, c.code) << c.name << ": " << r.error().message;
    if (c.message) {
      EXPECT_EQ(r.error().message, c.message);
    } else {
      EXPECT_EQ(r.error().message.rfind(std::string(c.name) + ": ", 0), 0u) << r.error().message;
    }
  }
}

// tests/data/mesh: the unit cube in every format assimp reads for voxmod, written by tests/data/make_io_data.py
// independently of assimp's exporters (quads, an embedded glTF buffer, a GLB container, a 3MF in microns).
TEST(MeshFile, theCubeOfEveryFormatInTestData) {
  const auto dir = test::sourceDir() / "tests" / "data" / "mesh";
  for (const char* file :
       {"cube.obj", "cube_ascii.ply", "cube_binary.ply", "cube.off", "cube.gltf", "cube.glb", "cube_micron.3mf"}) {
    const MeshFileLoad m = loadOk(dir / file);
    ASSERT_EQ(m.mesh.triangles.size(), 12u) << file;
    EXPECT_TRUE(m.topology.watertight()) << file;
    EXPECT_EQ(m.topology.degenerate_triangles, 0) << file;
    const bool micron = std::string(file) == "cube_micron.3mf";
    const double side = micron ? 0.001 : 1.0;  // 1 micron, converted to millimetres
    EXPECT_NEAR(signedVolume(m.mesh), side * side * side, 1e-6 * side * side * side) << file;
    EXPECT_EQ(m.mesh.bounds().max, glm::dvec3(double(float(side)))) << file;
    if (micron) {
      EXPECT_EQ(m.units, "mm");
      EXPECT_EQ(m.file_units, "micron");
      ASSERT_FALSE(m.notes.empty());
      EXPECT_EQ(m.notes[0], (dir / file).string() + ": unit micron (from the file), converted to millimetres");
    }
  }
}

TEST(MeshFile, extensionsListEveryReadableFormat) {
  const std::vector<std::string>& e = meshFileExtensions();
  for (const char* ext : {".stl", ".obj", ".ply", ".3mf", ".gltf", ".glb", ".off", ".step", ".stp", ".iges", ".igs"})
    EXPECT_NE(std::find(e.begin(), e.end(), ext), e.end()) << ext;
  EXPECT_EQ(meshFormatFromExtension("PART.STP"), MeshFormat::kStep);
  EXPECT_EQ(meshFormatFromExtension("scan.PLY"), MeshFormat::kPly);
  EXPECT_EQ(meshFormatFromExtension("x.vxm"), MeshFormat::kUnknown);
}

}  // namespace
}  // namespace vox::io
