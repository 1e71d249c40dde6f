// The real files of ../shared/meshes/cad (its README gives the counts, units and traps asserted here) open through
// loadMeshFile and voxelize; the part that comes in four formats (featuretype) gives the same solid in each.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <string>

#include "support/test_support.h"
#include "support/test_meshes.h"
#include "vox/io/mesh_file.h"
#include "vox/io/stl.h"
#include "vox/voxelize/voxelize.h"

namespace vox {
namespace {

struct CorpusFile {
  const char* file;
  io::MeshFormat format;
  size_t bodies;
  const char* units;       // the mesh's, after reading
  const char* file_units;  // as the file names it
  bool watertight;         // by exact welding
  const char* mode;        // what auto picks
};

const CorpusFile kCorpus[] = {
    // 18 placed instances of 5 solids, transforms nested 3 deep.
    {"as1-oc-214.stp", io::MeshFormat::kStep, 18, "mm", "millimetre", true, "nonzero"},
    // SolidWorks assembly in inches: 10 instances of 6 solids, neighbouring panels touching.
    {"box_sides.STEP", io::MeshFormat::kStep, 10, "mm", "INCH", true, "nonzero"},
    {"featuretype.STEP", io::MeshFormat::kStep, 1, "mm", "INCH", true, "nonzero"},
    // Pre-IS AP214 CC1 schema, tori and cones.
    {"screw.step", io::MeshFormat::kStep, 1, "mm", "millimetre", true, "nonzero"},
    // Surface models: 45 faces that sew into one closed shell; 213 faces that stay open (a half model).
    {"hammer.iges", io::MeshFormat::kIges, 1, "mm", "MM", true, "nonzero"},
    {"bearing.iges", io::MeshFormat::kIges, 1, "mm", "MM", false, "vote"},
    // T-junctions on the pocket rims: closed geometrically, open by its edges.
    {"featuretype.3MF", io::MeshFormat::k3mf, 1, "in", "inch", false, "vote"},
    // 9 build items, one of them a composed object of 2 components: 12 mesh instances.
    {"pyramids.3mf", io::MeshFormat::k3mf, 12, "mm", "millimeter", true, "nonzero"},
    {"fandisk.obj", io::MeshFormat::kObj, 1, "model", "", true, "nonzero"},
    // Non-convex 11-gons, CRLF line continuations.
    {"wallhole.obj", io::MeshFormat::kObj, 1, "model", "", true, "nonzero"},
    {"featuretype.ply", io::MeshFormat::kPly, 1, "model", "", true, "nonzero"},
    // Near-duplicate vertices (3.6e-16 apart): closed once exporter noise is welded.
    {"octagonal_pocket.ply", io::MeshFormat::kPly, 1, "model", "", false, "nonzero"},
};

class SharedCadFile : public ::testing::TestWithParam<CorpusFile> {};

TEST_P(SharedCadFile, opensWithItsBodiesAndUnitsAndVoxelizes) {
  VOX_REQUIRE_SHARED(shared);
  const CorpusFile& c = GetParam();
  io::MeshFileOptions options;
  options.resolution = 128;
  auto m = io::loadMeshFile(shared / "meshes" / "cad" / c.file, options);
  ASSERT_TRUE(m.ok()) << m.error().message;
  EXPECT_EQ(m->format, c.format);
  EXPECT_EQ(m->bodies.size(), c.bodies);
  EXPECT_EQ(m->units, c.units);
  EXPECT_EQ(m->file_units, c.file_units);
  EXPECT_EQ(m->topology.watertight(), c.watertight)
      << m->topology.boundary_edges << " boundary, " << m->topology.nonmanifold_edges << " non-manifold";
  uint64_t covered = 0;
  for (const io::MeshBody& b : m->bodies) {
    EXPECT_EQ(b.first_triangle, covered) << b.name;
    EXPECT_GT(b.triangle_count, 0u) << b.name;
    covered += b.triangle_count;
  }
  EXPECT_EQ(covered, m->mesh.triangles.size());
  VoxelizeParams params;
  params.resolution = 128;
  auto g = voxelizeSolid(m->mesh, params, {}, &m->topology);
  ASSERT_TRUE(g.ok()) << g.error().message;
  EXPECT_EQ(fillModeName(g->mode_used), std::string(c.mode));
  EXPECT_GT(g->grid.filledCount(), 0);
}

INSTANTIATE_TEST_SUITE_P(Corpus, SharedCadFile, ::testing::ValuesIn(kCorpus),
                         [](const ::testing::TestParamInfo<CorpusFile>& param) {
                           std::string name = param.param.file;
                           for (char& ch : name) {
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           }
                           return name;
                         });

TEST(SharedCadFiles, readmeFactsHold) {
  VOX_REQUIRE_SHARED(shared);
  const auto cad = shared / "meshes" / "cad";
  // wallhole.obj: 1000 - 100 (slot) + 166.67 (roof); bbox 10 x 15 x 10.
  auto wall = io::loadMeshFile(cad / "wallhole.obj");
  ASSERT_TRUE(wall.ok()) << wall.error().message;
  EXPECT_NEAR(signedVolume(wall->mesh), 1066.67, 0.01);
  EXPECT_EQ(wall->mesh.bounds().extent(), glm::dvec3(10, 15, 10));
  EXPECT_EQ(wall->topology.degenerate_triangles, 0);
  // octagonal_pocket.ply: metre scale, closed after merging within 1e-9.
  auto pocket = io::loadMeshFile(cad / "octagonal_pocket.ply");
  ASSERT_TRUE(pocket.ok());
  EXPECT_TRUE(pocket->topology.closes_when_noise_welded);
  EXPECT_NEAR(signedVolume(pocket->mesh), 2.5035e-4, 1e-7);
  // featuretype.3MF: 2208 triangles, 18 boundary edges, 11.636 in^3.
  auto f3mf = io::loadMeshFile(cad / "featuretype.3MF");
  ASSERT_TRUE(f3mf.ok());
  EXPECT_EQ(f3mf->mesh.triangles.size(), 2208u);
  EXPECT_EQ(f3mf->topology.boundary_edges, 18);
  EXPECT_NEAR(signedVolume(f3mf->mesh), 11.636, 1e-3);
  // hammer.iges: the sewn shell is a solid, outward (positive volume).
  auto hammer = io::loadMeshFile(cad / "hammer.iges");
  ASSERT_TRUE(hammer.ok());
  EXPECT_GT(signedVolume(hammer->mesh), 0.0);
  // bearing.iges: open, said so.
  auto bearing = io::loadMeshFile(cad / "bearing.iges");
  ASSERT_TRUE(bearing.ok());
  ASSERT_FALSE(bearing->warnings.empty());
  EXPECT_NE(bearing->warnings[0].find("open surface: 213 faces"), std::string::npos) << bearing->warnings[0];
}

// featuretype in four formats: the STL and PLY hold the same triangles (inches), the STEP file the exact part (read in
// millimetres): at the same resolution their grids have the same dims and agree but for the voxels the STEP
// tessellation's 0.1 voxel moves.
TEST(SharedCadFiles, featuretypeIsTheSameSolidInEveryFormat) {
  VOX_REQUIRE_SHARED(shared);
  const int64_t r = 128;
  VoxelizeParams params;
  params.resolution = r;
  const auto stl = io::loadStl(shared / "meshes" / "featuretype.stl");
  ASSERT_TRUE(stl.ok());
  const auto want = voxelizeSolid(stl->mesh, params, {}, &stl->topology);
  ASSERT_TRUE(want.ok());

  auto ply = io::loadMeshFile(shared / "meshes" / "cad" / "featuretype.ply");
  ASSERT_TRUE(ply.ok());
  const auto from_ply = voxelizeSolid(ply->mesh, params, {}, &ply->topology);
  ASSERT_TRUE(from_ply.ok());
  EXPECT_EQ(from_ply->grid.dims(), want->grid.dims());
  EXPECT_LE(test::mismatches(from_ply->grid, want->grid), want->grid.filledCount() / 1000);

  io::MeshFileOptions options;
  options.resolution = r;
  auto step = io::loadMeshFile(shared / "meshes" / "cad" / "featuretype.STEP", options);
  ASSERT_TRUE(step.ok());
  const auto from_step = voxelizeSolid(step->mesh, params, {}, &step->topology);
  ASSERT_TRUE(from_step.ok());
  EXPECT_EQ(from_step->grid.dims(), want->grid.dims());
  EXPECT_NEAR(from_step->grid.voxelSize(), 25.4 * want->grid.voxelSize(), 1e-3 * from_step->grid.voxelSize());
  const double rel = std::abs(double(from_step->grid.filledCount()) - double(want->grid.filledCount())) /
                     double(want->grid.filledCount());
  EXPECT_LT(rel, 0.005);
}

}  // namespace
}  // namespace vox
