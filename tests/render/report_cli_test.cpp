// voxmod report (SPEC 12) as a user runs it: one self-contained HTML page with its pictures in it and the numbers of
// the part with their units; bad names, missing units and unwritable places refused with nothing written. Among the
// render tests: the page carries a view rendered headless (EGL), whose Mesa keeps allocations to the end.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "support/test_meshes.h"
#include "support/test_support.h"
#include "vox/io/stl.h"

namespace vox {
namespace {

using test::runVoxmod;

std::string readText(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The cantilever of the printability tests: a 10 x 10 x 20 mm column with a 30 x 10 x 5 mm arm at its top.
std::string cantileverStl(const test::TempDir& dir) {
  const TriangleMesh m = test::cantileverMesh();
  const std::string stl = (dir / "cantilever.stl").string();
  EXPECT_TRUE(io::saveStlBinary(m, stl).ok());
  return stl;
}

TEST(CliReport, aPartsReportIsOnePageWithItsPicturesAndNumbersInItsUnits) {
  test::TempDir dir;
  const std::string stl = cantileverStl(dir);
  const std::filesystem::path html = dir / "cantilever.html";
  auto r = runVoxmod({"report", stl, "--res", "80", "--units", "mm", "--min-wall", "6", "--material", "aluminium", "-o",
                      html.string(), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const double h = 0.5;  // 40 mm over 80 voxels
  EXPECT_NEAR(j["volume"].get<double>(), 10 * 10 * 20 + 30 * 10 * 5, 1e-6);
  EXPECT_NEAR(j["wall_min"].get<double>(), 5.0, 2 * h);  // the arm
  EXPECT_GE(j["thin_regions"].get<int64_t>(), 1);
  EXPECT_EQ(j["trapped_cavities"].get<int64_t>(), 0);
  EXPECT_NEAR(j["support_volume"].get<double>(), 4500.0, 45.0);
  const std::string page = readText(html);
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(page.find("</html>"), std::string::npos);
  // every picture in the page itself, as PNG (base64 of the PNG signature)
  EXPECT_EQ(count(page, "data:image/png;base64,iVBORw0KGgo"), size_t(j["pictures"].get<int64_t>()));
  EXPECT_EQ(count(page, "src=\"http"), 0u);
  for (const char* words : {"cantilever.stl", "Thinnest wall", "Hot spots", "Modulus", "Support", "kg", "mm&sup3;"}) {
    EXPECT_NE(page.find(words), std::string::npos) << words;
  }
}

TEST(CliReport, badNamesMissingUnitsAndUnwritablePlacesWriteNothing) {
  test::TempDir dir;
  const std::string stl = cantileverStl(dir);
  auto r = runVoxmod({"report", stl, "--res", "20", "-o", (dir / "r.txt").string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(".html"), std::string::npos) << r.err;
  r = runVoxmod({"report", stl, "--res", "20", "--material", "aluminium", "-o", (dir / "r.html").string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--units"), std::string::npos) << r.err;
  r = runVoxmod(
      {"report", stl, "--res", "20", "--material", "unobtainium", "--units", "mm", "-o", (dir / "r.html").string()});
  EXPECT_EQ(r.exit_code, 1);
  r = runVoxmod({"report", stl, "--res", "20", "-o", (dir / "missing" / "r.html").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_FALSE(std::filesystem::exists(dir / "r.html"));
  EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
}

// The box [lo, hi] as 12 outward-facing triangles.
TriangleMesh boxMesh(glm::vec3 lo, glm::vec3 hi) {
  TriangleMesh m = test::unitCubeMesh();
  for (Triangle& t : m.triangles)
    for (glm::vec3& v : t.v) v = lo + v * (hi - lo);
  return m;
}

// Three boxes in one file, its bodies the parts of an assembly, on a grid of 1 mm voxels (R = 25 over the 25 mm the
// boxes span in y): a = [0, 10]^3 and b = [6, 16] x [5, 15] x [4, 14] share a 4 x 5 x 6 block, 3 voxels thick by
// the exact distance; c = [9.2, 20] x [-10, 4] x [0, 10] shares a's last layer of voxels (x = 9), 1 voxel thick.
// With --contact 1 the second only touches.
TEST(CliReport, anAssemblysReportListsItsPartsAndTellsInterferenceFromContact) {
  test::TempDir dir;
  TriangleMesh all = boxMesh({0, 0, 0}, {10, 10, 10});
  for (const TriangleMesh& m : {boxMesh({6, 5, 4}, {16, 15, 14}), boxMesh({9.2f, -10, 0}, {20, 4, 10})}) {
    all.triangles.insert(all.triangles.end(), m.triangles.begin(), m.triangles.end());
  }
  const std::string stl = (dir / "three.stl").string();
  ASSERT_TRUE(io::saveStlBinary(all, stl).ok());
  const std::filesystem::path html = dir / "three.html";
  auto r = runVoxmod(
      {"report", stl, "--res", "25", "--units", "mm", "--bodies", "--contact", "1", "-o", html.string(), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["parts"], 3);
  EXPECT_EQ(j["interfering_pairs"], 1);
  EXPECT_EQ(j["contact_pairs"], 1);
  const std::string page = readText(html);
  for (const char* words :
       {"Assembly: 3 parts", "body 0", "body 1", "body 2", "1 pair of parts interfere",
        "1 only touch (overlapping 1 mm or less)", "<b>interference</b>", "<td>contact</td>",
        "<td>120 mm&sup3;</td><td>3 mm</td>", "<td>40 mm&sup3;</td><td>1 mm</td>", "<td>1000 mm&sup3;</td>"}) {
    EXPECT_NE(page.find(words), std::string::npos) << words;
  }
  // without the tolerance both overlaps interfere; without --bodies there are no parts, and --contact is refused
  r = runVoxmod({"report", stl, "--res", "25", "--units", "mm", "--bodies", "-o", html.string(), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["interfering_pairs"], 2);
  r = runVoxmod({"report", stl, "--res", "25", "--units", "mm", "-o", html.string(), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(nlohmann::json::parse(r.out).contains("parts"));
  EXPECT_EQ(readText(html).find("Assembly"), std::string::npos);
  r = runVoxmod({"report", stl, "--res", "25", "--contact", "1", "-o", (dir / "no.html").string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--bodies"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "no.html"));
}

}  // namespace
}  // namespace vox
