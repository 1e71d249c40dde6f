#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/test_support.h"
#include "vox/io/file_util.h"
#include "vox/io/nrrd.h"

namespace vox::io {
namespace {

GridFrame frame() {
  return GridFrame{.origin = glm::dvec3(-1.0, 2.0, 0.5), .voxel_size = 0.25, .units = "mm", .source = ""};
}

std::string headerOf(const std::vector<uint8_t>& bytes) {
  const std::string text(bytes.begin(), bytes.end());
  return text.substr(0, text.find("\n\n"));
}

TEST(Nrrd, aGridIsUint8WithItsPlacementInTheHeader) {
  VoxelGrid g(Dims{5, 3, 2}, frame());
  g.set(0, 0, 0, true);
  g.set(4, 2, 1, true);
  auto bytes = encodeNrrd(g, NrrdEncoding::kRaw);
  ASSERT_TRUE(bytes.ok()) << bytes.error().message;
  const std::string h = headerOf(*bytes);
  EXPECT_NE(h.find("type: unsigned char"), std::string::npos) << h;
  EXPECT_NE(h.find("dimension: 3"), std::string::npos) << h;
  EXPECT_NE(h.find("sizes: 5 3 2"), std::string::npos) << h;
  EXPECT_NE(h.find("space directions: (0.25,0,0) (0,0.25,0) (0,0,0.25)"), std::string::npos) << h;
  // The centre of voxel (0, 0, 0): origin + half a voxel.
  EXPECT_NE(h.find("space origin: (-0.875,2.125,0.625)"), std::string::npos) << h;
  EXPECT_NE(h.find("encoding: raw"), std::string::npos) << h;
  // Raw data follows the blank line: x fastest, then y, then z.
  ASSERT_EQ(bytes->size(), h.size() + 2 + 30);
  const uint8_t* data = bytes->data() + h.size() + 2;
  EXPECT_EQ(data[0], 1);
  EXPECT_EQ(data[4 + 5 * (2 + 3 * 1)], 1);
  int ones = 0;
  for (int i = 0; i < 30; ++i) ones += data[i];
  EXPECT_EQ(ones, 2);
}

TEST(Nrrd, aFieldRoundTripsThroughAFileGzipped) {
  test::TempDir dir;
  ScalarField f(Dims{7, 4, 3}, frame());
  for (int z = 0; z < 3; ++z) {
    for (int y = 0; y < 4; ++y) {
      for (int x = 0; x < 7; ++x) f.at(x, y, z) = float(x) * 0.5f + float(y * 10 + z * 100);
    }
  }
  ASSERT_TRUE(saveNrrd(f, dir / "f.nrrd").ok());
  auto bytes = readFileBytes(dir / "f.nrrd");
  ASSERT_TRUE(bytes.ok());
  EXPECT_NE(headerOf(*bytes).find("encoding: gzip"), std::string::npos);
  EXPECT_NE(headerOf(*bytes).find("type: float"), std::string::npos);
  auto back = loadNrrdField(dir / "f.nrrd");
  ASSERT_TRUE(back.ok()) << back.error().message;
  EXPECT_EQ(back->dims, f.dims);
  EXPECT_EQ(back->values, f.values);
  EXPECT_NEAR(back->frame.voxel_size, 0.25, 1e-12);
  EXPECT_NEAR(back->frame.origin.x, -1.0, 1e-12);
  EXPECT_NEAR(back->frame.origin.y, 2.0, 1e-12);
  EXPECT_NEAR(back->frame.origin.z, 0.5, 1e-12);
}

TEST(Nrrd, brokenFilesAreErrorsNamingTheFile) {
  test::TempDir dir;
  ASSERT_TRUE(
      writeFileAtomic(dir / "bad.nrrd", std::string("NRRD0004\ntype: float\ndimension: 3\nsizes: 9 9\n\n")).ok());
  auto r = loadNrrdField(dir / "bad.nrrd");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("bad.nrrd"), std::string::npos) << r.error().message;
  auto missing = loadNrrdField(dir / "missing.nrrd");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().message.find("missing.nrrd"), std::string::npos);
  ScalarField wrong(Dims{2, 2, 2}, frame());
  wrong.values.pop_back();
  EXPECT_FALSE(encodeNrrd(wrong).ok());
}

TEST(Nrrd, aFailedSaveLeavesThePreviousFile) {
  test::TempDir dir;
  ASSERT_TRUE(writeFileAtomic(dir / "keep.nrrd", std::string("old")).ok());
  ScalarField f(Dims{2, 2, 2}, frame(), 1.0f);
  EXPECT_FALSE(saveNrrd(f, dir / "keep.nrrd" / "sub.nrrd").ok());
  auto old = readFileBytes(dir / "keep.nrrd");
  ASSERT_TRUE(old.ok());
  EXPECT_EQ(std::string(old->begin(), old->end()), "old");
}

}  // namespace
}  // namespace vox::io
