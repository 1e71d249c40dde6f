// STL reader and writer on meshes built in code: the binary/ASCII decision, the writer round trip, warnings.
#include "vox/io/stl.h"

#include <cstring>

#include <gtest/gtest.h>

#include "support/test_support.h"

namespace vox::io {
namespace {

std::vector<uint8_t> bytesOf(const std::string& s) { return {s.begin(), s.end()}; }

TEST(Stl, binaryWriterRoundTripsEveryFloatBit) {
  TriangleMesh m = test::unitCubeMesh();
  m.triangles[3].v[1] = {1e-38f, -0.0f, 3.4e38f};  // a denormal-adjacent value, negative zero, near FLT_MAX
  test::TempDir tmp;
  ASSERT_TRUE(saveStlBinary(m, tmp / "c.stl").ok());
  EXPECT_EQ(std::filesystem::file_size(tmp / "c.stl"), 84u + 50u * 12u);
  const auto r = loadStl(tmp / "c.stl");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_FALSE(r->ascii);
  ASSERT_EQ(r->mesh.triangles.size(), 12u);
  for (size_t i = 0; i < 12; ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(std::memcmp(&r->mesh.triangles[i].v[c], &m.triangles[i].v[c], sizeof(glm::vec3)), 0) << i;
  EXPECT_EQ(r->mesh.name, (tmp / "c.stl").string());
  // The header does not start with "solid", so naive readers do not take the file for ASCII.
  EXPECT_NE(test::readFile(tmp / "c.stl").substr(0, 5), "solid");
}

TEST(Stl, closedCubeHasNoWarningsAndAnOpenOneSaysHowOpen) {
  test::TempDir tmp;
  ASSERT_TRUE(saveStlBinary(test::unitCubeMesh(), tmp / "c.stl").ok());
  auto r = loadStl(tmp / "c.stl");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_TRUE(r->topology.watertight());
  EXPECT_TRUE(r->warnings.empty());

  TriangleMesh open = test::unitCubeMesh();
  open.triangles.pop_back();
  ASSERT_TRUE(saveStlBinary(open, tmp / "o.stl").ok());
  r = loadStl(tmp / "o.stl");
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(r->warnings.size(), 1u);
  EXPECT_EQ(r->warnings[0], (tmp / "o.stl").string() +
                                ": not watertight: 3 boundary edges, 0 non-manifold edges (vertices welded by exact "
                                "equality)");
}

TEST(Stl, binaryIsChosenBySizeEvenWhenTheHeaderSaysSolid) {
  // An 84 + 50 * 1 byte file whose header is ASCII-looking text: the size rule wins.
  std::string b = "solid looks like text";
  b.resize(80, ' ');
  b += std::string("\x01\x00\x00\x00", 4);
  b += std::string(12, '\0');
  for (float f : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) b += std::string(reinterpret_cast<char*>(&f), 4);
  b += std::string(2, '\0');
  const auto r = parseStl(bytesOf(b), "x.stl");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_FALSE(r->ascii);
  EXPECT_EQ(r->header, "solid looks like text");
  EXPECT_EQ(r->mesh.triangles[0].v[1], glm::vec3(1, 0, 0));
}

TEST(Stl, asciiWithoutTrailingNewlineAndWithSpacesEverywhereLoads) {
  const std::string s =
      "  solid   my part  \n facet normal 0 0 1 outer loop vertex 0 0 0 vertex 1 0 0 vertex 0 1 0 endloop endfacet "
      "endsolid my part";
  const auto r = parseStl(bytesOf(s), "x.stl");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_TRUE(r->ascii);
  EXPECT_EQ(r->header, "my part");
  EXPECT_EQ(r->mesh.triangles.size(), 1u);
}

// A file cut short says so, naming the cut token, only when the token is cut: a keyword's beginning or a number;
// a whole but wrong last token (no newline after it) is named as found.
TEST(Stl, aTruncatedAsciiFileSaysItEndsEarlyOnlyWhenItDoes) {
  const std::string head =
      "solid t\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n ";
  const auto message = [](const std::string& text) {
    const auto r = parseStl(bytesOf(text), "t.stl");
    return r.ok() ? std::string("(loaded)") : r.error().message;
  };
  EXPECT_EQ(message(head + "endlo"), "t.stl:7: the file ends early, in 'endlo' (truncated?): expected 'endloop'");
  EXPECT_EQ(message(head + "endfacet"), "t.stl:7: expected 'endloop', found 'endfacet'");
  EXPECT_EQ(message(head.substr(0, head.size() - 16) + "vertex 1 0 -1.29e"),
            "t.stl:6: the file ends early, in '-1.29e' (truncated?): expected a number");
  EXPECT_EQ(message(head.substr(0, head.size() - 16) + "vertex 1 0 x"), "t.stl:6: expected a number, found 'x'");
}

TEST(Stl, asciiNumbersParseToTheNearestFloat) {
  // 0.1 is not a float; from_chars must round the decimal once, to the nearest float (not via double).
  const std::string s =
      "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0.1 1e-3 -2.5E+01\nvertex 16777217 0 0\nvertex 0 .5 0\n"
      "endloop\nendfacet\nendsolid t\n";
  const auto r = parseStl(bytesOf(s), "x.stl");
  ASSERT_TRUE(r.ok()) << r.error().message;
  const Triangle& t = r->mesh.triangles[0];
  EXPECT_EQ(t.v[0], glm::vec3(0.1f, 1e-3f, -25.0f));
  EXPECT_EQ(t.v[1].x, 16777216.0f);  // ties to even
  EXPECT_EQ(t.v[2].y, 0.5f);
}

TEST(Stl, errorsComeFromParseStlWithTheGivenName) {
  const auto r = parseStl(bytesOf("solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nendloop\n"), "part.stl");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, "part.stl:5: expected 'vertex', found 'endloop'");
}

TEST(Stl, missingFileIsAnIoError) {
  const auto r = loadStl("/nonexistent-dir/part.stl");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kIo);
  EXPECT_EQ(r.error().message, "/nonexistent-dir/part.stl: cannot open: No such file or directory");
}

}  // namespace
}  // namespace vox::io
