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

}  // namespace
}  // namespace vox
