// The command line as scripts use it (docs/conventions.md, "Command line"): exit codes, JSON keys, images, error
// messages.
#include <cmath>
#include <numbers>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "support/test_support.h"
#include "vox/core/mesh.h"
#include "vox/io/image_io.h"
#include "vox/io/mesh_file.h"
#include "vox/io/stl.h"

namespace vox {
namespace {

using test::runVoxmod;
using test::TempDir;
using json = nlohmann::json;

// Every test writes the unit cube [0, 1]^3 as box.stl: at --res n it fills an n^3 grid exactly (centres are
// strictly inside), so peel, mass and X-ray have closed-form answers.
class Cli : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(io::saveStlBinary(test::unitCubeMesh(), box_stl()).ok()); }
  std::string box_stl() const { return (tmp_ / "box.stl").string(); }
  std::string path(const std::string& name) const { return (tmp_ / name).string(); }
  TempDir tmp_;
};

json parse(const test::RunResult& r) {
  EXPECT_FALSE(r.out.empty()) << r.err;
  return json::parse(r.out);
}

TEST_F(Cli, helpListsEverySubcommandAndExitsZero) {
  auto r = runVoxmod({"--help"});
  EXPECT_EQ(r.exit_code, 0);
  for (const char* sub : {"voxelize", "info", "section", "peel", "xray", "mass", "thickness", "convert"})
    EXPECT_NE(r.out.find(sub), std::string::npos) << sub;
}

TEST_F(Cli, unknownOptionIsUsageError) {
  auto r = runVoxmod({"info", box_stl(), "--bogus"});
  EXPECT_EQ(r.exit_code, 1);
}

TEST_F(Cli, voxelizeReportsSpecKeysAndInfoAgrees) {
  auto r = runVoxmod({"voxelize", box_stl(), "--res", "10", "-o", path("box.vxm"), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = parse(r);
  for (const char* key : {"triangles", "dims", "voxel_size", "origin", "filled", "volume", "load_s", "voxelize_s",
                          "write_s", "total_s", "warnings"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["triangles"], 12);
  EXPECT_EQ(j["dims"], json::array({10, 10, 10}));
  EXPECT_EQ(j["filled"], 1000);
  EXPECT_DOUBLE_EQ(j["voxel_size"].get<double>(), 0.1);
  EXPECT_NEAR(j["volume"].get<double>(), 1.0, 1e-12);
  EXPECT_EQ(j["mode"], "nonzero");  // auto on a closed mesh

  auto info = runVoxmod({"info", path("box.vxm"), "--json"});
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const json i = parse(info);
  EXPECT_EQ(i["filled"], 1000);
  EXPECT_EQ(i["surface_voxels"], 1000 - 512);
  EXPECT_EQ(i["dims"], json::array({10, 10, 10}));
}

// The box without its two triangles at x = 0: rays along X now cross only the face at x = 1, so every voxel is
// outside along X and inside along Y and Z. The vote fills all 1000 voxels, each disputed, and --disputed writes
// them as a grid of the same dims.
TEST_F(Cli, voteOnAnOpenBoxWritesEveryDisputedVoxel) {
  TriangleMesh open = test::unitCubeMesh();
  std::erase_if(open.triangles, [](const Triangle& t) { return t.v[0].x == 0 && t.v[1].x == 0 && t.v[2].x == 0; });
  ASSERT_EQ(open.triangles.size(), 10u);
  ASSERT_TRUE(io::saveStlBinary(open, path("open.stl")).ok());
  auto r = runVoxmod({"voxelize", path("open.stl"), "--res", "10", "-o", path("open.vxm"), "--disputed",
                      path("disputed.vxm"), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = parse(r);
  EXPECT_EQ(j["mode"], "vote");  // auto on an open mesh
  EXPECT_EQ(j["filled"], 1000);
  EXPECT_EQ(j["disputed_voxels"], 1000);
  const json d = parse(runVoxmod({"info", path("disputed.vxm"), "--json"}));
  EXPECT_EQ(d["dims"], json::array({10, 10, 10}));
  EXPECT_EQ(d["filled"], 1000);
}

TEST_F(Cli, convertRoundTripsThroughBinvox) {
  ASSERT_EQ(runVoxmod({"voxelize", box_stl(), "--res", "12", "-o", path("a.vxm")}).exit_code, 0);
  ASSERT_EQ(runVoxmod({"convert", path("a.vxm"), path("b.binvox")}).exit_code, 0);
  ASSERT_EQ(runVoxmod({"convert", path("b.binvox"), path("c.vxm")}).exit_code, 0);
  const json a = parse(runVoxmod({"info", path("a.vxm"), "--json"}));
  const json c = parse(runVoxmod({"info", path("c.vxm"), "--json"}));
  EXPECT_EQ(a["filled"], c["filled"]);
  EXPECT_EQ(a["surface_voxels"], c["surface_voxels"]);
}

TEST_F(Cli, peelAllOfABoxRemovesShellsDownToTheCore) {
  auto r = runVoxmod({"peel", box_stl(), "--res", "10", "--all", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = parse(r);
  EXPECT_EQ(j["removed_per_layer"], json::array({488, 296, 152, 56, 8}));
  EXPECT_EQ(j["remaining"], 0);
  EXPECT_EQ(j["core_voxels"], 8);
}

// peel -o takes every output convert writes: a volume is the bytes convert writes from the peel's voxel file, a
// surface mesh reads back closed around the remaining voxels; an unknown extension is a usage error before any
// work, and an empty remainder has no surface (exit 2, nothing written).
TEST_F(Cli, peelWritesAnyFormatConvertWrites) {
  ASSERT_EQ(runVoxmod({"peel", box_stl(), "--res", "10", "--layers", "1", "-o", path("p.vxm")}).exit_code, 0);
  std::filesystem::create_directories(path("converted"));
  for (const char* ext : {".binvox", ".nrrd", ".vti", ".vox", ".vdb"}) {
    const std::string direct = path(std::string("p") + ext);
    auto r = runVoxmod({"peel", box_stl(), "--res", "10", "--layers", "1", "-o", direct});
    ASSERT_EQ(r.exit_code, 0) << ext << ": " << r.err;
    const std::string converted = path(std::string("converted/p") + ext);
    ASSERT_EQ(runVoxmod({"convert", path("p.vxm"), converted}).exit_code, 0) << ext;
    if (std::string(ext) == ".vdb") {  // OpenVDB writes a fresh UUID into every file: the same size
      EXPECT_EQ(test::readFile(direct).size(), test::readFile(converted).size());
    } else {
      EXPECT_TRUE(test::readFile(direct) == test::readFile(converted)) << ext;
    }
  }
  for (const char* ext : {".stl", ".ply", ".obj", ".3mf"}) {
    const std::string out = path(std::string("p") + ext);
    for (const char* how : {"--layers", "--distance"}) {  // 1 layer, or within 0.15: both leave the 8^3 inside
      auto r = runVoxmod({"peel", box_stl(), "--res", "10", how, how[2] == 'l' ? "1" : "0.15", "-o", out});
      ASSERT_EQ(r.exit_code, 0) << ext << ": " << r.err;
      auto m = io::loadMeshFile(out);
      ASSERT_TRUE(m.ok()) << ext << ": " << m.error().message;
      EXPECT_TRUE(m->topology.watertight()) << ext;
      EXPECT_NEAR(signedVolume(m->mesh), 512 * 1e-3, 1e-6) << ext;  // 8^3 voxels of 0.1
      EXPECT_EQ(glm::dvec3(m->mesh.bounds().min), glm::dvec3(glm::vec3(0.1f))) << ext;
    }
  }
  auto bad = runVoxmod({"peel", box_stl(), "--res", "10", "--layers", "1", "-o", path("p.xyz")});
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("surface: stl, ply, obj, 3mf"), std::string::npos) << bad.err;
  auto empty = runVoxmod({"peel", box_stl(), "--res", "10", "--all", "-o", path("none.stl")});
  EXPECT_EQ(empty.exit_code, 2);
  EXPECT_NE(empty.err.find("no filled voxels"), std::string::npos) << empty.err;
  EXPECT_FALSE(std::filesystem::exists(path("none.stl")));
}

// -o in any format and --depth are written as one: both, or neither (the old -o stays, no temporary file is left).
TEST_F(Cli, peelWritesASurfaceAndItsDepthTogetherOrNeither) {
  const std::string out = path("inner.stl"), depth = path("depth.nrrd");
  test::writeFile(out, "the user's own file");
  test::writeFile(path("blocker"), "a file where the depth volume's directory would be");
  auto failed =
      runVoxmod({"peel", box_stl(), "--res", "10", "--layers", "1", "-o", out, "--depth", path("blocker/depth.nrrd")});
  EXPECT_NE(failed.exit_code, 0);
  EXPECT_NE(failed.err.find("blocker"), std::string::npos) << failed.err;
  EXPECT_EQ(test::readFile(out), "the user's own file");
  auto ok = runVoxmod({"peel", box_stl(), "--res", "10", "--layers", "1", "-o", out, "--depth", depth});
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  auto m = io::loadMeshFile(out);
  ASSERT_TRUE(m.ok()) << m.error().message;
  EXPECT_NEAR(signedVolume(m->mesh), 512 * 1e-3, 1e-6);  // the 8^3 inside
  EXPECT_TRUE(std::filesystem::exists(depth));
  for (const auto& e : std::filesystem::directory_iterator(tmp_.path())) {
    EXPECT_EQ(e.path().filename().string().find(".voxmod"), std::string::npos) << e.path();
  }
}

// convert from a voxel file to each surface format, blocky and --smooth: exit 0, the file reads back closed and
// manifold with the triangles the JSON reports, in the voxel file's unit (3MF carries it).
TEST_F(Cli, convertWritesTheSurfaceInEveryMeshFormat) {
  ASSERT_EQ(runVoxmod({"voxelize", box_stl(), "--res", "10", "--units", "in", "-o", path("box.vxm")}).exit_code, 0);
  for (const char* ext : {".stl", ".ply", ".obj", ".3mf"}) {
    for (bool smooth : {false, true}) {
      SCOPED_TRACE(std::string(ext) + (smooth ? " smooth" : ""));
      const std::string out = path(std::string(smooth ? "smooth" : "box") + ext);
      std::vector<std::string> args = {"convert", path("box.vxm"), out, "--json"};
      if (smooth) args.push_back("--smooth");
      auto r = runVoxmod(args);
      ASSERT_EQ(r.exit_code, 0) << r.err;
      const json j = parse(r);
      auto m = io::loadMeshFile(out);
      ASSERT_TRUE(m.ok()) << m.error().message;
      EXPECT_EQ(int64_t(m->mesh.triangles.size()), j["triangles"].get<int64_t>());
      EXPECT_EQ(m->topology.boundary_edges, 0);
      EXPECT_EQ(m->topology.nonmanifold_edges, 0);
      EXPECT_EQ(m->topology.inconsistent_edges, 0);
      const double v = signedVolume(m->mesh);
      if (smooth) {  // a rounded block within half a voxel of the blocky surface (area 6)
        EXPECT_NEAR(v, 1.0, 6 * 0.05);
        EXPECT_GT(std::abs(v - 1.0), 1e-3);
      } else {
        EXPECT_NEAR(v, 1.0, 1e-6);  // the 10^3 voxels of 0.1
      }
      if (std::string(ext) == ".3mf") {
        EXPECT_EQ(m->units, "in");
      }
    }
  }
}

TEST_F(Cli, peelNeedsLayersOrAll) { EXPECT_EQ(runVoxmod({"peel", box_stl(), "--res", "10"}).exit_code, 1); }

// The unit cube at R = 10: a 10^3 block. Its deepest voxels are 5 voxels (0.5) from the outside, the largest
// inscribed ball spans the block (thickness 1), and the one hot spot is the plateau of the 8 central voxels.
TEST_F(Cli, thicknessOfABoxReportsSpecKeysAndWritesItsFilesTogether) {
  auto r = runVoxmod({"thickness", box_stl(), "--res", "10", "--json", "--min-wall", "0.45", "-o", path("t.nrrd"),
                      "--distance", path("d.nrrd"), "--signed", "--section-axis", "z", "--section-index", "5", "--png",
                      path("t.png")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = parse(r);
  for (const char* key : {"min", "max", "mean", "histogram", "distance_max", "wall_min", "thin_voxels", "thin_regions",
                          "specks", "hot_spots", "distance_s", "thickness_s", "walls_s"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_NEAR(j["max"].get<double>(), 1.0, 1e-9);
  EXPECT_NEAR(j["distance_max"].get<double>(), 0.5, 1e-9);
  EXPECT_EQ(j["histogram"]["edges"].size(), j["histogram"]["counts"].size() + 1);
  ASSERT_EQ(j["hot_spots"].size(), 1u);
  EXPECT_NEAR(j["hot_spots"][0]["radius"].get<double>(), 0.5, 1e-9);
  // Chvorinov's modulus V/A of the unit cube: a sixth, read within 10% from 10 voxels
  EXPECT_NEAR(j["hot_spots"][0]["modulus"].get<double>(), 1.0 / 6.0, 0.1 / 6.0);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(j["hot_spots"][0]["centre"][a].get<double>(), 0.5, 1e-9);
  // walls, not edges: no wall of the block is thinner than 0.45, and its thinnest wall is its size
  EXPECT_EQ(j["thin_voxels"].get<int64_t>(), 0);
  EXPECT_EQ(j["thin_regions"].size(), 0u);
  EXPECT_NEAR(j["wall_min"].get<double>(), 1.0, 0.2);
  // --edges: every voxel under the minimum, as local thickness reads the block's corners (no large ball reaches them)
  auto edges = runVoxmod({"thickness", box_stl(), "--res", "10", "--json", "--min-wall", "0.45", "--edges"});
  ASSERT_EQ(edges.exit_code, 0) << edges.err;
  const json je = parse(edges);
  EXPECT_GT(je["thin_voxels"].get<int64_t>(), 0);
  EXPECT_GT(je["thin_regions"].size(), 0u);
  for (const auto& region : je["thin_regions"]) {
    for (const char* key : {"voxels", "bbox", "min"}) EXPECT_TRUE(region.contains(key)) << key;
    EXPECT_LT(region["min"].get<double>(), 0.45);
  }
  EXPECT_NEAR(je["wall_min"].get<double>(), 1.0, 0.2);
  for (const char* f : {"t.nrrd", "d.nrrd", "t.png"}) EXPECT_TRUE(std::filesystem::exists(path(f))) << f;

  // A PNG that cannot be written: none of the three files is.
  auto bad = runVoxmod({"thickness", box_stl(), "--res", "10", "-o", path("t2.nrrd"), "--section-axis", "z",
                        "--section-index", "5", "--png", path("t.png/sub.png")});
  EXPECT_EQ(bad.exit_code, 2) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(path("t2.nrrd")));
  EXPECT_EQ(runVoxmod({"thickness", box_stl(), "--res", "10", "--png", path("x.png")}).exit_code, 1);
  EXPECT_EQ(runVoxmod({"thickness", box_stl(), "--res", "10", "--section-axis", "z", "--section-index", "5", "--png",
                       path("x.jpg")})
                .exit_code,
            1);
}

TEST_F(Cli, peelByDistanceRemovesEverythingWithinItOfTheOutside) {
  // In the 10^3 block the outer shell is 1 voxel (0.1) from the outside and the next shell 2 voxels: 0.15 takes
  // the outer shell only and leaves the 8^3 inside.
  auto r = runVoxmod({"peel", box_stl(), "--res", "10", "--distance", "0.15", "--json", "-o", path("p.vxm")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = parse(r);
  EXPECT_EQ(j["removed"], 1000 - 512);
  EXPECT_EQ(j["remaining"], 512);
  EXPECT_EQ(runVoxmod({"peel", box_stl(), "--res", "10", "--distance", "0.1", "--layers", "2"}).exit_code, 1);
}

TEST_F(Cli, massOfABoxIsItsVolumeAndCentre) {
  auto r = runVoxmod({"mass", box_stl(), "--res", "10", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = parse(r);
  EXPECT_NEAR(j["volume"].get<double>(), 1.0, 1e-12);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(j["centroid"][a].get<double>(), 0.5, 1e-12);
  // Solid unit cube about its centre: I = 1/6 on the diagonal (voxel cubes sum to the exact value).
  EXPECT_NEAR(j["inertia"][0][0].get<double>(), 1.0 / 6.0, 1e-12);
  EXPECT_NEAR(j["inertia"][0][1].get<double>(), 0.0, 1e-12);
  EXPECT_TRUE(j.contains("bbox"));
}

TEST_F(Cli, sectionWritesImageOfTheRightSize) {
  auto r =
      runVoxmod({"section", box_stl(), "--res", "10", "--axis", "x", "--index", "3", "-o", path("s.png"), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(parse(r)["filled"], 100);
  auto png = io::loadPng(path("s.png"));
  ASSERT_TRUE(png.ok()) << png.error().message;
  EXPECT_EQ(png->width, 10);
  EXPECT_EQ(png->height, 10);
}

// A section at any angle: the unit cube cut through its centre normal to a face diagonal is a 1 x sqrt(2) rectangle;
// the axis section reports its area too; a plane that is no plane is a usage error (exit 1) naming the option.
TEST_F(Cli, aSectionAtAnyAngleReportsItsSamplesAndArea) {
  auto r = runVoxmod(
      {"section", box_stl(), "--res", "40", "--normal", "1,1,0", "--pixel", "0.0125", "-o", path("o.png"), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = parse(r);
  EXPECT_NEAR(j["area"].get<double>(), std::sqrt(2.0), 0.02 * std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(j["pixel_size"].get<double>(), 0.0125);
  EXPECT_NEAR(j["normal"][0].get<double>(), std::sqrt(0.5), 1e-12);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(j["point"][a].get<double>(), 0.5, 1e-12);  // the grid's centre
  auto png = io::loadPng(path("o.png"));
  ASSERT_TRUE(png.ok()) << png.error().message;
  EXPECT_EQ(png->width, j["width"].get<int>());
  auto axis =
      runVoxmod({"section", box_stl(), "--res", "10", "--axis", "z", "--index", "3", "-o", path("a.png"), "--json"});
  ASSERT_EQ(axis.exit_code, 0) << axis.err;
  EXPECT_NEAR(parse(axis)["area"].get<double>(), 1.0, 1e-12);
  auto zero = runVoxmod({"section", box_stl(), "--res", "10", "--normal", "0,0,0", "-o", path("z.png")});
  EXPECT_EQ(zero.exit_code, 1);  // a usage error
  EXPECT_NE(zero.err.find("non-zero"), std::string::npos) << zero.err;
  auto words = runVoxmod({"section", box_stl(), "--res", "10", "--normal", "up", "-o", path("w.png")});
  EXPECT_EQ(words.exit_code, 1);  // a usage error
  EXPECT_NE(words.err.find("--normal"), std::string::npos) << words.err;
  auto both = runVoxmod(
      {"section", box_stl(), "--res", "10", "--normal", "0,0,1", "--axis", "z", "--index", "1", "-o", path("b.png")});
  EXPECT_EQ(both.exit_code, 1);  // a usage error
  auto none = runVoxmod({"section", box_stl(), "--res", "10", "-o", path("n.png")});
  EXPECT_EQ(none.exit_code, 1);  // a usage error
  EXPECT_NE(none.err.find("--normal"), std::string::npos) << none.err;
}

TEST_F(Cli, xrayReportsThicknessInVoxelsAndModelUnits) {
  auto r = runVoxmod({"xray", box_stl(), "--res", "10", "--axis", "z", "--mode", "total", "-o", path("x.png"), "--csv",
                      path("x.csv"), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = parse(r);
  EXPECT_EQ(j["min"], 10);
  EXPECT_EQ(j["max"], 10);
  EXPECT_DOUBLE_EQ(j["mean"].get<double>(), 10.0);
  EXPECT_NEAR(j["max_mm"].get<double>(), 1.0, 1e-12);
  EXPECT_TRUE(io::loadPng(path("x.png")).ok());
  EXPECT_NE(test::readFile(path("x.csv")).find('\n'), std::string::npos);
}

TEST_F(Cli, missingInputNamesTheFileAndExitsTwo) {
  auto r = runVoxmod({"info", path("nope.stl"), "--json"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("nope.stl"), std::string::npos) << r.err;
  EXPECT_TRUE(parse(r).contains("error"));
}

TEST_F(Cli, malformedStlIsAnInputError) {
  test::writeFile(path("bad.stl"), "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 nan\n");
  auto r = runVoxmod({"info", path("bad.stl")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bad.stl"), std::string::npos) << r.err;
}

TEST_F(Cli, absurdResolutionIsRefusedWithAReason) {
  auto r = runVoxmod({"voxelize", box_stl(), "--res", "0", "-o", path("x.vxm")});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("resolution"), std::string::npos) << r.err;
}

TEST_F(Cli, unwritableOutputFailsAndKeepsTheOldFile) {
  ASSERT_EQ(runVoxmod({"voxelize", box_stl(), "--res", "8", "-o", path("keep.vxm")}).exit_code, 0);
  const std::string before = test::readFile(path("keep.vxm"));
  // A path below a regular file cannot be created, even by root.
  auto r = runVoxmod({"voxelize", box_stl(), "--res", "9", "-o", path("keep.vxm") + "/sub.vxm"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("sub.vxm"), std::string::npos) << r.err;
  EXPECT_EQ(test::readFile(path("keep.vxm")), before);
}

}  // namespace
}  // namespace vox

namespace vox {
namespace {

// The unit cube's triangles scaled to [lo, hi] and turned by `yaw` about z, then `pitch` about x (degrees), about c.
void addTurnedBox(TriangleMesh& m, glm::dvec3 lo, glm::dvec3 hi, double yaw, double pitch, glm::dvec3 c) {
  const double a = yaw * std::numbers::pi / 180, b = pitch * std::numbers::pi / 180;
  for (Triangle t : test::unitCubeMesh().triangles) {
    for (auto& v : t.v) {
      glm::dvec3 p = lo + glm::dvec3(v) * (hi - lo) - c;
      p = {p.x * std::cos(a) - p.y * std::sin(a), p.x * std::sin(a) + p.y * std::cos(a), p.z};
      p = {p.x, p.y * std::cos(b) - p.z * std::sin(b), p.y * std::sin(b) + p.z * std::cos(b)};
      v = glm::vec3(p + c);
    }
    m.triangles.push_back(t);
  }
}

// The issue's own part: a 20 x 20 x 10 mm block with one fin 0.6 mm thick, turned 30 and 20 degrees. Local thickness
// alone lists every edge of the block (--edges); the walls are the fin, one region reading its thickness.
TEST(CliWalls, aTurnedBlockWithOneFinHasOneThinWallAtTheFinsThickness) {
  test::TempDir dir;
  TriangleMesh m;
  const glm::dvec3 c(10, 10, 8);
  addTurnedBox(m, {0, 0, 0}, {20, 20, 10}, 30, 20, c);
  addTurnedBox(m, {4, 9.7, 9.5}, {16, 10.3, 16}, 30, 20, c);  // the fin, its foot inside the block
  const std::string stl = (dir / "fin.stl").string();
  ASSERT_TRUE(io::saveStlBinary(m, stl).ok());
  for (const char* res : {"100", "200"}) {
    SCOPED_TRACE(std::string("R = ") + res);
    auto r = test::runVoxmod({"thickness", stl, "--res", res, "--units", "mm", "--min-wall", "1.0", "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const double h = j["voxel_size"].get<double>();
    ASSERT_EQ(j["thin_regions"].size(), 1u) << r.out;
    EXPECT_NEAR(j["thin_regions"][0]["min"].get<double>(), 0.6, 2 * h);
    EXPECT_NEAR(j["wall_min"].get<double>(), j["thin_regions"][0]["min"].get<double>(), 1e-9);
    auto edges =
        test::runVoxmod({"thickness", stl, "--res", res, "--units", "mm", "--min-wall", "1.0", "--edges", "--json"});
    ASSERT_EQ(edges.exit_code, 0) << edges.err;
    EXPECT_GT(nlohmann::json::parse(edges.out)["thin_regions"].size(), 1u);  // the edges, as local thickness reads them
  }
}

}  // namespace
}  // namespace vox

namespace vox {
namespace {

// A 2 mm plate (20 x 20 x 2 mm) turned 0, 30 and 45 degrees reads 2 mm by both methods: the ray thickness within a
// voxel in every voxel it reads, the walls within two (the sphere method samples voxel centres).
TEST(CliWalls, aPlateReadsTheSameByBothMethodsAtEveryAngle) {
  test::TempDir dir;
  for (double angle : {0.0, 30.0, 45.0}) {
    SCOPED_TRACE("plate at " + std::to_string(angle));
    TriangleMesh m;
    addTurnedBox(m, {0, 0, 0}, {20, 20, 2}, 0, angle, glm::dvec3(10, 10, 1));
    const std::string stl = (dir / "plate.stl").string();
    ASSERT_TRUE(io::saveStlBinary(m, stl).ok());
    auto r = test::runVoxmod({"thickness", stl, "--res", "100", "--units", "mm", "--min-wall", "3", "--method", "ray",
                              "--json", "-o", (dir / "ray.nrrd").string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const double h = j["voxel_size"].get<double>();
    EXPECT_EQ(j["method"], "ray");
    // every ray from a face meets the other face at 2 mm; rays from the rim run along the plate and read more
    EXPECT_NEAR(j["ray"]["min"].get<double>(), 2.0, h);
    EXPECT_GT(j["ray"]["voxels"].get<int64_t>(), 0);
    EXPECT_GT(j["ray"]["accepted"].get<int64_t>(), j["ray"]["rays"].get<int64_t>() / 2);
    ASSERT_EQ(j["thin_regions"].size(), 1u);
    EXPECT_NEAR(j["thin_regions"][0]["min"].get<double>(), 2.0, 2 * h);
    EXPECT_NEAR(j["wall_min"].get<double>(), j["ray"]["min"].get<double>(), 2 * h);
    EXPECT_TRUE(std::filesystem::exists(dir / "ray.nrrd"));
  }
}

TEST(CliWalls, theRayMethodNeedsAMesh) {
  test::TempDir dir;
  TriangleMesh m;
  addTurnedBox(m, {0, 0, 0}, {2, 2, 2}, 0, 0, glm::dvec3(0));
  ASSERT_TRUE(io::saveStlBinary(m, (dir / "c.stl").string()).ok());
  ASSERT_EQ(
      test::runVoxmod({"voxelize", (dir / "c.stl").string(), "--res", "20", "-o", (dir / "c.vxm").string()}).exit_code,
      0);
  auto r = test::runVoxmod({"thickness", (dir / "c.vxm").string(), "--method", "ray"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("voxel file"), std::string::npos) << r.err;
  EXPECT_EQ(test::runVoxmod({"thickness", (dir / "c.stl").string(), "--method", "cone"}).exit_code, 1);
  // the walls' options without the walls are refused, not ignored
  for (const std::vector<std::string>& alone :
       std::vector<std::vector<std::string>>{{"--edges"}, {"--min-area", "1"}, {"--ray-angle", "20"}}) {
    std::vector<std::string> args = {"thickness", (dir / "c.stl").string(), "--res", "20"};
    args.insert(args.end(), alone.begin(), alone.end());
    auto refused = test::runVoxmod(args);
    EXPECT_EQ(refused.exit_code, 1) << alone[0];
    EXPECT_NE(refused.err.find(alone[0] == "--ray-angle" ? "--ray-angle applies" : "--min-wall"), std::string::npos)
        << refused.err;
  }
  EXPECT_EQ(
      test::runVoxmod({"thickness", (dir / "c.stl").string(), "--res", "20", "--method", "ray", "--ray-angle", "20"})
          .exit_code,
      0);
}

}  // namespace
}  // namespace vox
