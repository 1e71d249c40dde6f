// Mesh and CAD files on the command line (docs/conventions.md, "Command line"; docs/file-format.md, "Mesh and CAD
// input"): every subcommand reads them, the file's unit comes along, and malformed files of each format are input
// errors (exit 2) whose message names the file, with nothing written.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "support/cad_parts.h"
#include "support/test_support.h"

namespace vox {
namespace {

using json = nlohmann::json;
using test::CadShape;
using test::runVoxmod;

class CliImport : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return (tmp_ / name).string(); }
  test::TempDir tmp_;
};

json parse(const test::RunResult& r) {
  EXPECT_FALSE(r.out.empty()) << r.err;
  return r.out.empty() ? json() : json::parse(r.out);
}

// The unit cube as an ASCII PLY scan: 8 vertices, 6 quads.
const char* const kCubePly =
    "ply\nformat ascii 1.0\ncomment a scan\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 6\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
    "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";

TEST_F(CliImport, infoDescribesAStepPart) {
  test::writeStep(tmp_ / "part.step", {{CadShape::kCylinder, {0, 0, 0}, {10, 0, 40}}}, "INCH");
  auto r = runVoxmod({"info", path("part.step"), "--res", "80", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = parse(r);
  EXPECT_EQ(j["format"], "STEP (AUTOMOTIVE_DESIGN)");
  EXPECT_EQ(j["bodies"], 1);
  EXPECT_EQ(j["units"], "mm");
  EXPECT_EQ(j["file_units"], "INCH");
  EXPECT_EQ(j["watertight"], true);
  EXPECT_EQ(j["dims"], json::array({40, 40, 80}));
  EXPECT_NEAR(j["voxel_size"].get<double>(), 0.5, 1e-9);
  EXPECT_NEAR(j["deflection"].get<double>(), 0.04 * 0.5, 1e-9);
  // The summary of the file comes as a note.
  EXPECT_NE(r.err.find("part.step: STEP (AUTOMOTIVE_DESIGN), unit 'INCH' (read as mm), 1 solid"), std::string::npos)
      << r.err;
}

TEST_F(CliImport, voxelizeAPlyScanAndTheGridKeepsWhatItIs) {
  test::writeFile(path("scan.ply"), kCubePly);
  auto r = runVoxmod({"voxelize", path("scan.ply"), "--res", "10", "-o", path("x.vxm"), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = parse(r);
  EXPECT_EQ(j["format"], "PLY");
  EXPECT_EQ(j["triangles"], 12);
  EXPECT_EQ(j["filled"], 1000);
  EXPECT_EQ(j["mode"], "nonzero");
  EXPECT_EQ(j["units"], "model");
  auto info = runVoxmod({"info", path("x.vxm"), "--json"});
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_EQ(parse(info)["source"], "scan.ply");
}

TEST_F(CliImport, aCadFilesMillimetresGiveAMassInKilograms) {
  test::writeStep(tmp_ / "cube.step", {{CadShape::kBox, {0, 0, 0}, {100, 100, 100}}});
  auto r = runVoxmod({"mass", path("cube.step"), "--res", "20", "--material", "water", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = parse(r);
  EXPECT_EQ(j["units"], "mm");
  EXPECT_NEAR(j["mass_kg"].get<double>(), 1.0, 1e-9);  // a litre of water
  auto v = runVoxmod({"voxelize", path("cube.step"), "--res", "20", "-o", path("cube.vxm")});
  ASSERT_EQ(v.exit_code, 0) << v.err;
  EXPECT_EQ(parse(runVoxmod({"info", path("cube.vxm"), "--json"}))["units"], "mm");
}

TEST_F(CliImport, unitsOptionOverridesTheFilesUnit) {
  test::writeStep(tmp_ / "cube.step", {{CadShape::kBox, {0, 0, 0}, {1, 1, 1}}});
  const json j = parse(runVoxmod({"info", path("cube.step"), "--res", "10", "--units", "in", "--json"}));
  EXPECT_NEAR(j["voxel_size"].get<double>(), 2.54, 1e-6);  // the 1 "mm" of the file taken as inches
  EXPECT_EQ(j["units"], "mm");
  test::writeFile(path("scan.ply"), kCubePly);
  EXPECT_EQ(parse(runVoxmod({"info", path("scan.ply"), "--res", "4", "--units", "cm", "--json"}))["units"], "cm");
}

TEST_F(CliImport, malformedFilesAreInputErrorsNamingTheFile) {
  test::writeStep(tmp_ / "good.step", {{CadShape::kBox, {0, 0, 0}, {1, 1, 1}}});
  const std::string step = test::readFile(tmp_ / "good.step");
  test::writeFile(path("truncated.step"), step.substr(0, step.size() / 2));
  test::writeFile(path("notzip.3mf"), "<?xml version=\"1.0\"?><model/>");
  std::string lying = kCubePly;
  lying.replace(lying.find("element vertex 8"), 16, "element vertex 9");
  test::writeFile(path("lying.ply"), lying);
  test::writeFile(path("empty.obj"), "");
  test::writeFile(path("step.ply"), step);
  for (const char* file : {"truncated.step", "notzip.3mf", "lying.ply", "empty.obj", "step.ply"}) {
    for (const char* sub : {"info", "voxelize"}) {
      std::vector<std::string> args = {sub, path(file), "--json"};
      if (std::string(sub) == "voxelize") args.insert(args.end(), {"-o", path("out.vxm")});
      auto r = runVoxmod(args);
      EXPECT_EQ(r.exit_code, 2) << sub << " " << file << ": " << r.err;
      EXPECT_NE(r.err.find(path(file)), std::string::npos) << sub << " " << file << ": " << r.err;
      EXPECT_TRUE(parse(r).contains("error")) << file;
      EXPECT_FALSE(std::filesystem::exists(path("out.vxm"))) << file;
    }
  }
}

}  // namespace
}  // namespace vox
