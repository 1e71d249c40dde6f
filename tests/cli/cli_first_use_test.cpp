// What a new user meets in the first minutes at the command line: exit codes and messages for input that is
// wrong in ordinary ways, output names, commands that write several files, empty models, mistyped subcommands.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "support/test_support.h"
#include "vox/core/mesh.h"
#include "vox/io/image_io.h"
#include "vox/io/stl.h"

namespace vox {
namespace {

using test::runVoxmod;
using json = nlohmann::json;

class FirstUse : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(io::saveStlBinary(test::unitCubeMesh(), path("box.stl")).ok()); }
  std::string path(const std::string& name) const { return (tmp_ / name).string(); }
  bool exists(const std::string& name) const { return std::filesystem::exists(tmp_ / name); }
  test::TempDir tmp_;
};

TEST_F(FirstUse, aMeshOfZeroExtentIsAnInputErrorNotAUsageError) {
  TriangleMesh point;
  point.triangles.push_back(Triangle{{glm::vec3(1, 2, 3), glm::vec3(1, 2, 3), glm::vec3(1, 2, 3)}});
  ASSERT_TRUE(io::saveStlBinary(point, path("point.stl")).ok());
  const auto r = runVoxmod({"info", path("point.stl")});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("point.stl"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("zero extent"), std::string::npos) << r.err;
}

// A header line of bytes that are not UTF-8: the message quotes them as '?', and the JSON object stays valid
// (it was an "internal error", exit 70, when the JSON writer met the raw bytes).
TEST_F(FirstUse, errorsQuotingBytesThatAreNotTextStillPrintAsJson) {
  test::writeFile(path("bad.binvox"), "#binvox 1\ndim 2 2 2\n\xff\xfe garbage\ndata\n");
  const auto r = runVoxmod({"info", path("bad.binvox"), "--json"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  const json j = json::parse(r.out);
  EXPECT_NE(j["error"].get<std::string>().find("'?? garbage'"), std::string::npos) << r.out;
}

TEST_F(FirstUse, imagesAreWrittenOnlyUnderAPngName) {
  for (const auto& [args, file] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"section", path("box.stl"), "--res", "8", "--axis", "z", "--index", "3", "-o", path("s.bmp")}, "s.bmp"},
           {{"xray", path("box.stl"), "--res", "8", "--axis", "z", "--mode", "max", "-o", path("x.jpg")}, "x.jpg"},
           {{"render", path("box.stl"), "--res", "8", "-o", path("r.jpg")}, "r.jpg"}}) {
    const auto r = runVoxmod(args);
    EXPECT_EQ(r.exit_code, 1) << args[0] << ": " << r.err;
    EXPECT_NE(r.err.find(file + ": unknown image format"), std::string::npos) << r.err;
    EXPECT_FALSE(exists(file)) << file;
  }
  // Upper case is still PNG.
  const auto ok =
      runVoxmod({"section", path("box.stl"), "--res", "8", "--axis", "z", "--index", "3", "-o", path("S.PNG")});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_TRUE(io::loadPng(path("S.PNG")).ok());
}

// xray -o X.png --csv Y: both files or neither. A CSV that cannot be written leaves no new PNG, and an old PNG of
// the same name is kept as it was.
TEST_F(FirstUse, xrayWritesItsImageAndCsvTogetherOrNotAtAll) {
  const std::string unwritable = path("box.stl") + "/x.csv";  // below a regular file: cannot be created, even by root
  auto r = runVoxmod({"xray", path("box.stl"), "--res", "8", "--axis", "z", "--mode", "total", "-o", path("x.png"),
                      "--csv", unwritable});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("x.csv"), std::string::npos) << r.err;
  EXPECT_FALSE(exists("x.png"));

  test::writeFile(path("old.png"), "the user's old file");
  r = runVoxmod({"xray", path("box.stl"), "--res", "8", "--axis", "z", "--mode", "total", "-o", path("old.png"),
                 "--csv", unwritable});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(test::readFile(path("old.png")), "the user's old file");
  for (const auto& e : std::filesystem::directory_iterator(tmp_.path())) {
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << "left behind: " << e.path();
  }
}

// Peeled to nothing: an empty model has no centroid, inertia or box. JSON says null, the text says why; never the
// +/-1e300 of an empty box.
TEST_F(FirstUse, massOfAnEmptyModelHasNoCentroidOrBox) {
  ASSERT_EQ(runVoxmod({"peel", path("box.stl"), "--res", "6", "--all", "-o", path("empty.vxm")}).exit_code, 0);
  const auto r = runVoxmod({"mass", path("empty.vxm"), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["filled"], 0);
  EXPECT_EQ(j["volume"], 0.0);
  for (const char* key : {"centroid", "inertia", "bbox", "bbox_min_ijk", "bbox_max_ijk"}) {
    EXPECT_TRUE(j[key].is_null()) << key << ": " << j[key];
  }
  const auto text = runVoxmod({"mass", path("empty.vxm")});
  EXPECT_NE(text.out.find("the model is empty"), std::string::npos) << text.out;
  EXPECT_EQ(text.out.find("e+300"), std::string::npos) << text.out;
}

TEST_F(FirstUse, smallNumbersKeepTheirSignificantDigits) {
  // A 1 mm cube scaled to 1e-3: the volume 1e-9 printed with %f would read 0.000000.
  TriangleMesh tiny = test::unitCubeMesh();
  for (Triangle& t : tiny.triangles) {
    for (glm::vec3& v : t.v) v *= 1e-3f;
  }
  ASSERT_TRUE(io::saveStlBinary(tiny, path("tiny.stl")).ok());
  const auto r = runVoxmod({"mass", path("tiny.stl"), "--res", "10"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("volume   1e-09"), std::string::npos) << r.out;
  const auto info = runVoxmod({"info", path("tiny.stl"), "--res", "10"});
  EXPECT_NE(info.out.find("voxel size  0.0001 "), std::string::npos) << info.out;
}

TEST_F(FirstUse, aMistypedSubcommandIsNamedWithASuggestion) {
  const auto r = runVoxmod({"secton", path("box.stl")});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("'secton' is neither a subcommand nor a file; did you mean 'section'?"), std::string::npos)
      << r.err;
}

TEST_F(FirstUse, meshOptionsGivenWithAVoxelFileAreReportedAsIgnored) {
  ASSERT_EQ(runVoxmod({"voxelize", path("box.stl"), "--res", "8", "-o", path("box.vxm")}).exit_code, 0);
  const auto r = runVoxmod({"info", path("box.vxm"), "--res", "50", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["dims"], json::array({8, 8, 8}));
  ASSERT_EQ(j["warnings"].size(), 1u) << r.out;
  EXPECT_NE(j["warnings"][0].get<std::string>().find("--res is ignored: box.vxm is a voxel file"), std::string::npos);
}

// The CLI and the window say the same thing: L skin layers, the last is the core.
TEST_F(FirstUse, peelSaysHowManySkinLayersAndWhichIsTheCore) {
  const auto r = runVoxmod({"peel", path("box.stl"), "--res", "10", "--all"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("5 layers peeled, 0 voxels remain; the model has 5 skin layers and the core (layer 5, the "
                       "thickest region) had 8 voxels"),
            std::string::npos)
      << r.out;
}

// A 2 x 2 x 2 cube in millimetres of steel: 8000 mm^3 = 8e-6 m^3, 0.0628 kg. Principal moments of a cube are
// equal: m a^2 / 6 with a = 0.002 m (m^2 units: kg m^2).
TEST_F(FirstUse, massInKilogramsFromUnitsAndAMaterial) {
  TriangleMesh cube = test::unitCubeMesh();
  for (Triangle& t : cube.triangles) {
    for (glm::vec3& v : t.v) v *= 20.0f;
  }
  ASSERT_TRUE(io::saveStlBinary(cube, path("cube20.stl")).ok());
  auto r = runVoxmod({"mass", path("cube20.stl"), "--res", "20", "--units", "mm", "--material", "steel", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["units"], "mm");
  EXPECT_EQ(j["density_kg_m3"], 7850.0);
  const double mass = 8000e-9 * 7850.0;
  EXPECT_NEAR(j["mass_kg"].get<double>(), mass, 1e-12);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(j["principal_moments_kg_m2"][i].get<double>(), mass * 0.02 * 0.02 / 6.0, 1e-12);
  }
  // Without units there is no kg: a usage error that says what to add.
  r = runVoxmod({"mass", path("cube20.stl"), "--res", "20", "--density", "7850"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--units"), std::string::npos) << r.err;
}

// xray's *_mm keys are millimetres when the units are known (here centimetres: 10 mm each), model units otherwise.
TEST_F(FirstUse, xrayMillimetreKeysAreMillimetres) {
  auto r = runVoxmod({"xray", path("box.stl"), "--res", "10", "--axis", "z", "--mode", "max", "-o", path("x.png"),
                      "--units", "cm", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  json j = json::parse(r.out);
  EXPECT_EQ(j["units"], "mm");
  EXPECT_NEAR(j["max_mm"].get<double>(), 10.0, 1e-9);
  r = runVoxmod(
      {"xray", path("box.stl"), "--res", "10", "--axis", "z", "--mode", "max", "-o", path("x.png"), "--json"});
  j = json::parse(r.out);
  EXPECT_EQ(j["units"], "model");
  EXPECT_NEAR(j["max_mm"].get<double>(), 1.0, 1e-9);
}

// --units is one of the mesh options every voxelizing subcommand shares: voxelize keeps it in the file too.
TEST_F(FirstUse, voxelizeKeepsTheUnitsGiven) {
  ASSERT_EQ(runVoxmod({"voxelize", path("box.stl"), "--res", "8", "--units", "mm", "-o", path("mm.vxm")}).exit_code, 0);
  const json j = json::parse(runVoxmod({"info", path("mm.vxm"), "--json"}).out);
  EXPECT_EQ(j["units"], "mm");
}

}  // namespace
}  // namespace vox
