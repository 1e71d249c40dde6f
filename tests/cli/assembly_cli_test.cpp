// The assembly subcommands as scripts use them (docs/conventions.md, "Assemblies"; SPEC section 7): boolean, bodies,
// interfere and clearance on boxes whose overlaps and gaps are known, and their errors.
#include <filesystem>
#include <set>

#include <nlohmann/json.hpp>

#include "support/cad_parts.h"
#include "support/test_support.h"
#include "vox/core/mesh.h"
#include "vox/io/stl.h"
#include "vox/io/voxel_file.h"

namespace vox {
namespace {

using test::runVoxmod;
using test::TempDir;
using json = nlohmann::json;

// The box [lo, hi] as 12 outward-facing triangles.
TriangleMesh boxMesh(glm::vec3 lo, glm::vec3 hi) {
  TriangleMesh m = test::unitCubeMesh();
  for (Triangle& t : m.triangles)
    for (glm::vec3& v : t.v) v = lo + v * (hi - lo);
  return m;
}

// a.stl = [0, 10]^3 and b.stl = [6, 16] x [5, 15] x [4, 14]: on the pair's grid at R = 16 (h = 1, origin 0) they
// overlap in the block x 6..9, y 5..9, z 4..9 = 120 voxels, centred at (8, 7.5, 7).
class AssemblyCli : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(io::saveStlBinary(boxMesh({0, 0, 0}, {10, 10, 10}), path("a.stl")).ok());
    ASSERT_TRUE(io::saveStlBinary(boxMesh({6, 5, 4}, {16, 15, 14}), path("b.stl")).ok());
    TriangleMesh both = boxMesh({0, 0, 0}, {10, 10, 10});
    const TriangleMesh b = boxMesh({6, 5, 4}, {16, 15, 14});
    both.triangles.insert(both.triangles.end(), b.triangles.begin(), b.triangles.end());
    ASSERT_TRUE(io::saveStlBinary(both, path("ab.stl")).ok());
  }
  std::string path(const std::string& name) const { return (tmp_ / name).string(); }
  TempDir tmp_;
};

json parse(const test::RunResult& r) {
  EXPECT_FALSE(r.out.empty()) << r.err;
  return json::parse(r.out);
}

TEST_F(AssemblyCli, booleanOfTwoMeshesOnThePairsGrid) {
  const std::pair<const char*, int> cases[] = {
      {"union", 1880}, {"intersection", 120}, {"difference", 880}, {"xor", 1760}};
  for (const auto& [op, filled] : cases) {
    auto r = runVoxmod(
        {"boolean", path("a.stl"), path("b.stl"), "--op", op, "--res", "16", "-o", path("out.vxm"), "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json j = parse(r);
    for (const char* key : {"filled", "filled_a", "filled_b", "dims", "origin", "voxel_size"})
      EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_EQ(j["filled"], filled) << op;
    EXPECT_EQ(j["filled_a"], 1000);
    EXPECT_EQ(j["filled_b"], 1000);
    EXPECT_EQ(j["dims"], json::array({16, 15, 14}));
    EXPECT_DOUBLE_EQ(j["voxel_size"].get<double>(), 1.0);
    auto g = io::loadVoxelFile(path("out.vxm"));
    ASSERT_TRUE(g.ok());
    EXPECT_EQ(g->filledCount(), filled) << op;
  }
}

TEST_F(AssemblyCli, booleanWritesAnyFormatConvertWritesAsConvertWritesIt) {
  // The intersection as a voxel file, then as a surface and as a volume: each the bytes `convert` writes from it.
  auto r =
      runVoxmod({"boolean", path("a.stl"), path("b.stl"), "--op", "intersection", "--res", "16", "-o", path("x.vxm")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* ext : {".stl", ".nrrd", ".vti"}) {
    const std::string direct = path(std::string("x") + ext);
    r = runVoxmod({"boolean", path("a.stl"), path("b.stl"), "--op", "intersection", "--res", "16", "-o", direct});
    ASSERT_EQ(r.exit_code, 0) << ext << ": " << r.err;
    const std::string converted = path(std::string("converted/x") + ext);
    std::filesystem::create_directories(path("converted"));
    r = runVoxmod({"convert", path("x.vxm"), converted});
    ASSERT_EQ(r.exit_code, 0) << ext << ": " << r.err;
    EXPECT_EQ(test::readFile(direct), test::readFile(converted)) << ext;
    EXPECT_GT(test::readFile(direct).size(), 100u) << ext;
  }
  // A Boolean with no voxels has no surface: a clear error, exit 2.
  ASSERT_TRUE(io::saveStlBinary(boxMesh({20, 0, 0}, {30, 10, 10}), path("far.stl")).ok());
  r = runVoxmod(
      {"boolean", path("a.stl"), path("far.stl"), "--op", "intersection", "--res", "16", "-o", path("none.stl")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no filled voxels"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(path("none.stl")));
}

TEST_F(AssemblyCli, interfereReportsTheKnownBlock) {
  for (bool bodies : {false, true}) {
    auto r = bodies ? runVoxmod({"interfere", path("ab.stl"), "--bodies", "--res", "16", "--json"})
                    : runVoxmod({"interfere", path("a.stl"), path("b.stl"), "--res", "16", "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json j = parse(r);
    EXPECT_EQ(j["parts"], bodies ? json::array({"body 0", "body 1"}) : json::array({"a.stl", "b.stl"}));
    ASSERT_EQ(j["pairs"].size(), 1u);
    const json& p = j["pairs"][0];
    EXPECT_EQ(p["a"], 0);
    EXPECT_EQ(p["b"], 1);
    EXPECT_EQ(p["voxels"], 120);
    EXPECT_DOUBLE_EQ(p["volume"].get<double>(), 120.0);
    EXPECT_EQ(p["bbox"]["min"], json::array({6.0, 5.0, 4.0}));
    EXPECT_EQ(p["bbox"]["max"], json::array({10.0, 10.0, 10.0}));
    EXPECT_EQ(p["centre"], json::array({8.0, 7.5, 7.0}));
    EXPECT_EQ(j["overlap_voxels"], 120);
  }
}

TEST_F(AssemblyCli, bodiesWritesEveryBodyOnOneLattice) {
  auto r = runVoxmod({"bodies", path("ab.stl"), "--res", "16", "-o", path("bodies"), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = parse(r);
  ASSERT_EQ(j["bodies"].size(), 2u);
  for (int i = 0; i < 2; ++i) {
    const json& b = j["bodies"][size_t(i)];
    EXPECT_EQ(b["index"], i);
    EXPECT_EQ(b["triangles"], 12);
    EXPECT_EQ(b["filled"], 1000);
    EXPECT_DOUBLE_EQ(b["volume"].get<double>(), 1000.0);
  }
  EXPECT_EQ(j["bodies"][1]["bbox"]["min"], json::array({6.0, 5.0, 4.0}));
  EXPECT_TRUE(std::filesystem::exists(path("bodies/body_000.vxm")));
  // The body files share the lattice: their intersection is the block.
  auto i = runVoxmod({"boolean", path("bodies/body_000.vxm"), path("bodies/body_001.vxm"), "--op", "intersection", "-o",
                      path("i.binvox"), "--json"});
  ASSERT_EQ(i.exit_code, 0) << i.err;
  EXPECT_EQ(parse(i)["filled"], 120);
}

// A STEP file's solids are its bodies, named as the reader names them, even where they touch: two boxes sharing the
// face x = 10 have equal vertices there, and splitting by welded shells would make them one body.
TEST_F(AssemblyCli, aStepFilesTouchingSolidsStayTwoBodies) {
  using test::CadShape;
  test::writeStep(tmp_ / "pair.step",
                  {{CadShape::kBox, {0, 0, 0}, {10, 10, 10}}, {CadShape::kBox, {10, 0, 0}, {10, 10, 10}}});
  auto r = runVoxmod({"bodies", path("pair.step"), "--res", "20", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = parse(r);
  ASSERT_EQ(j["bodies"].size(), 2u);
  for (int i = 0; i < 2; ++i) {
    const json& b = j["bodies"][size_t(i)];
    EXPECT_EQ(b["name"], "solid " + std::to_string(i + 1));
    EXPECT_EQ(b["filled"], 1000) << i;  // h = 1: each box is 10 x 10 x 10 voxels
    EXPECT_DOUBLE_EQ(b["bbox"]["min"][0].get<double>(), 10.0 * i);
  }
  auto f = runVoxmod({"interfere", path("pair.step"), "--bodies", "--res", "20", "--json"});
  ASSERT_EQ(f.exit_code, 0) << f.err;
  const json k = parse(f);
  EXPECT_EQ(k["parts"], json::array({"body 0", "body 1"}));
  EXPECT_TRUE(k["pairs"].empty());  // touching, not overlapping
}

// Contact: c.stl overlaps a.stl in one layer of voxels (x = 9, where a ends at 10 and c starts at 9.2), a sheet 1
// voxel thick; a and b overlap in a 4 x 5 x 6 block, 3 voxels thick by the exact distance ((2 d - 1), d = 2). With
// --contact 1 the first only touches.
TEST_F(AssemblyCli, interfereTellsContactFromInterference) {
  ASSERT_TRUE(io::saveStlBinary(boxMesh({9.2f, -10, 0}, {20, 4, 10}), path("c.stl")).ok());
  for (const char* contact : {"0", "1"}) {
    auto r = runVoxmod(
        {"interfere", path("a.stl"), path("b.stl"), path("c.stl"), "--res", "25", "--contact", contact, "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json j = parse(r);
    ASSERT_DOUBLE_EQ(j["voxel_size"].get<double>(), 1.0);
    ASSERT_EQ(j["pairs"].size(), 2u);
    const json& ab = j["pairs"][0];  // the larger overlap first
    const json& ac = j["pairs"][1];
    EXPECT_EQ(ab["a"], 0);
    EXPECT_EQ(ab["b"], 1);
    EXPECT_EQ(ab["voxels"], 120);
    EXPECT_DOUBLE_EQ(ab["thickness"].get<double>(), 3.0);
    EXPECT_EQ(ac["a"], 0);
    EXPECT_EQ(ac["b"], 2);
    EXPECT_EQ(ac["voxels"], 40);
    EXPECT_DOUBLE_EQ(ac["thickness"].get<double>(), 1.0);
    const bool tolerant = std::string(contact) == "1";
    EXPECT_FALSE(ab["contact"].get<bool>());
    EXPECT_EQ(ac["contact"].get<bool>(), tolerant);
    EXPECT_EQ(j["interfering_pairs"], tolerant ? 1 : 2);
  }
  auto bad = runVoxmod({"interfere", path("a.stl"), path("b.stl"), "--contact", "-1"});
  EXPECT_NE(bad.exit_code, 0);
}

// The shared assembly's 18 solids (brackets with the bolts and nuts that touch them) stay 18 bodies and 18 parts,
// each named by its product in the file (PRODUCT('nut', ...): eight nuts, six bolts, two l-brackets, a rod and a
// plate), a product placed more than once numbered.
TEST_F(AssemblyCli, theSharedStepAssemblyKeepsItsEighteenSolids) {
  VOX_REQUIRE_SHARED(shared);
  const std::string as1 = (shared / "meshes/cad/as1-oc-214.stp").string();
  auto r = runVoxmod({"bodies", as1, "--res", "200", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = parse(r);
  ASSERT_EQ(j["bodies"].size(), 18u);
  std::set<std::string> names;
  for (size_t i = 0; i < 18; ++i) {
    names.insert(j["bodies"][i]["name"].get<std::string>());
    EXPECT_GT(j["bodies"][i]["filled"].get<int64_t>(), 0) << i;
  }
  std::set<std::string> expected = {"rod", "plate", "l-bracket 1", "l-bracket 2"};
  for (int k = 1; k <= 8; ++k) expected.insert("nut " + std::to_string(k));
  for (int k = 1; k <= 6; ++k) expected.insert("bolt " + std::to_string(k));
  EXPECT_EQ(names, expected);
  auto f = runVoxmod({"interfere", as1, "--bodies", "--res", "200", "--json"});
  ASSERT_EQ(f.exit_code, 0) << f.err;
  EXPECT_EQ(parse(f)["parts"].size(), 18u);
}

TEST_F(AssemblyCli, clearanceBetweenSeparateBoxes) {
  ASSERT_TRUE(io::saveStlBinary(boxMesh({13, 0, 0}, {20, 10, 10}), path("d.stl")).ok());
  // h = 1: a fills x 0..9, d fills x 13..19; closest centres 4 apart, a gap of 3 (the faces at 10 and 13).
  auto r = runVoxmod({"clearance", path("a.stl"), path("d.stl"), "--voxel-size", "1", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = parse(r);
  EXPECT_EQ(j["touching"], false);
  EXPECT_DOUBLE_EQ(j["distance"].get<double>(), 4.0);
  EXPECT_DOUBLE_EQ(j["gap"].get<double>(), 3.0);
  EXPECT_DOUBLE_EQ(j["point_a"][0].get<double>(), 9.5);
  EXPECT_DOUBLE_EQ(j["point_b"][0].get<double>(), 13.5);
  auto t = runVoxmod({"clearance", path("a.stl"), path("b.stl"), "--res", "16", "--json"});
  ASSERT_EQ(t.exit_code, 0) << t.err;
  EXPECT_EQ(parse(t)["touching"], true);
}

TEST_F(AssemblyCli, voxelFilesOnDifferentLatticesAreRefused) {
  ASSERT_EQ(runVoxmod({"voxelize", path("a.stl"), "--res", "10", "-o", path("a10.vxm")}).exit_code, 0);
  ASSERT_EQ(runVoxmod({"voxelize", path("b.stl"), "--res", "20", "-o", path("b20.vxm")}).exit_code, 0);
  auto r = runVoxmod({"boolean", path("a10.vxm"), path("b20.vxm"), "--op", "union", "-o", path("u.vxm"), "--json"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("b20.vxm is not on the lattice of a10.vxm: voxel sizes differ"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(path("u.vxm")));
  // Same voxel size, origins half a voxel apart.
  ASSERT_TRUE(io::saveStlBinary(boxMesh({0.5f, 0, 0}, {10.5f, 10, 10}), path("c.stl")).ok());
  ASSERT_EQ(runVoxmod({"voxelize", path("c.stl"), "--res", "10", "-o", path("c10.vxm")}).exit_code, 0);
  r = runVoxmod({"interfere", path("a10.vxm"), path("c10.vxm")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("not a whole number of voxels"), std::string::npos) << r.err;
}

TEST_F(AssemblyCli, badInputAndOutputAreClearErrors) {
  test::writeFile(path("bad.stl"), "garbage");
  auto r = runVoxmod({"interfere", path("a.stl"), path("bad.stl"), "--json"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bad.stl"), std::string::npos) << r.err;
  EXPECT_TRUE(parse(r).contains("error"));
  r = runVoxmod({"boolean", path("a.stl"), path("b.stl"), "--op", "union", "-o", path("u.png")});
  EXPECT_EQ(r.exit_code, 1);
  r = runVoxmod({"boolean", path("a.stl"), path("b.stl"), "--op", "nand", "-o", path("u.vxm")});
  EXPECT_EQ(r.exit_code, 1);
  // A directory that cannot be made (a file is in the way): exit 2, nothing written.
  test::writeFile(path("file"), "x");
  r = runVoxmod({"bodies", path("ab.stl"), "--res", "16", "-o", path("file/sub")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("file/sub"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace vox

namespace vox {
namespace {

TEST_F(AssemblyCli, voxelFileBodiesAreComponentsAndMeshesJoinItsLattice) {
  // ab.stl voxelized as one grid: the two boxes overlap, so the grid is one 6-connected component.
  ASSERT_EQ(runVoxmod({"voxelize", path("ab.stl"), "--res", "16", "-o", path("ab.vxm")}).exit_code, 0);
  auto r = runVoxmod({"bodies", path("ab.vxm"), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  json j = parse(r);
  ASSERT_EQ(j["bodies"].size(), 1u);
  EXPECT_EQ(j["bodies"][0]["filled"], 1880);
  EXPECT_TRUE(j["bodies"][0]["triangles"].is_null());
  // a.stl voxelized alone on its own grid (h = 1, origin 0): b.stl joins that lattice and overlaps it in the block.
  ASSERT_EQ(runVoxmod({"voxelize", path("a.stl"), "--res", "10", "-o", path("a10.vxm")}).exit_code, 0);
  r = runVoxmod({"interfere", path("a10.vxm"), path("b.stl"), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  j = parse(r);
  ASSERT_EQ(j["pairs"].size(), 1u);
  EXPECT_EQ(j["pairs"][0]["voxels"], 120);
  // Two cubes touching only along an edge: two components through faces, one through edges.
  VoxelGrid g(Dims{4, 4, 1}, GridFrame{});
  g.set(0, 0, 0);
  g.set(1, 1, 0);
  ASSERT_TRUE(io::saveVoxelFile(g, path("diag.vxm")).ok());
  EXPECT_EQ(parse(runVoxmod({"bodies", path("diag.vxm"), "--json"}))["bodies"].size(), 2u);
  EXPECT_EQ(parse(runVoxmod({"bodies", path("diag.vxm"), "--connectivity", "26", "--json"}))["bodies"].size(), 1u);
}

}  // namespace
}  // namespace vox
