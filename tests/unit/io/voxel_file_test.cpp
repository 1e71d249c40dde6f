// .vxm and .binvox codecs on grids built in code: bit-exact round trips over awkward sizes (rows that end inside
// a word, exactly on a word, one voxel wide), frames, damaged files, and dispatch by extension.
#include "vox/io/voxel_file.h"

#include <array>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "support/test_support.h"
#include "vox/io/file_util.h"

namespace vox::io {
namespace {

// A grid with a random fill of density `p`, a filled box (long runs that cross rows and layers) and empty layers
// at both ends (unallocated layers in the middle of the run stream).
VoxelGrid randomGrid(Dims d, double p, uint32_t seed) {
  GridFrame f;
  f.origin = {-1.5, 0.125, 1e-3};
  f.voxel_size = 0.1;
  f.units = "mm";
  f.source = "random.stl";
  VoxelGrid g(d, f);
  std::mt19937 rng(seed);
  std::bernoulli_distribution fill(p);
  for (int z = d.nz / 4; z < d.nz - d.nz / 4; ++z)
    for (int y = 0; y < d.ny; ++y)
      for (int x = 0; x < d.nx; ++x)
        if (fill(rng)) g.set(x, y, z);
  for (int z = d.nz / 3; z < d.nz / 2; ++z)
    for (int y = d.ny / 4; y < d.ny; ++y) g.fillRun(y, z, d.nx / 5, d.nx);
  return g;
}

// Every voxel compared, plus dims; the mismatch count is the message.
void expectSameVoxels(const VoxelGrid& a, const VoxelGrid& b) {
  ASSERT_EQ(a.dims(), b.dims());
  int64_t mismatches = 0;
  for (int z = 0; z < a.nz(); ++z)
    for (int y = 0; y < a.ny(); ++y)
      for (int x = 0; x < a.nx(); ++x) mismatches += a.get(x, y, z) != b.get(x, y, z);
  EXPECT_EQ(mismatches, 0);
  EXPECT_EQ(a.filledCount(), b.filledCount());
}

// A grid read back from .binvox: `g` padded with empty voxels to the cube of its largest dimension.
void expectSamePaddedToCube(const VoxelGrid& g, const VoxelGrid& cube) {
  const int32_t n = std::max({g.nx(), g.ny(), g.nz()});
  ASSERT_EQ(cube.dims(), (Dims{n, n, n}));
  int64_t mismatches = 0;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) mismatches += cube.get(x, y, z) != (g.inBounds(x, y, z) && g.get(x, y, z));
  EXPECT_EQ(mismatches, 0);
}

const Dims kAwkwardDims[] = {{1, 1, 1},   {1, 7, 5},   {62, 3, 4},   {63, 5, 6},  {64, 4, 4},   {65, 3, 9},
                             {126, 2, 3}, {127, 4, 4}, {130, 11, 7}, {200, 1, 3}, {33, 40, 17}, {5, 64, 64}};

TEST(Vxm, roundTripIsBitExactForAwkwardDimsAndDensities) {
  uint32_t seed = 1;
  for (const Dims& d : kAwkwardDims) {
    for (double p : {0.0, 0.03, 0.5, 0.97, 1.0}) {
      SCOPED_TRACE(std::to_string(d.nx) + "x" + std::to_string(d.ny) + "x" + std::to_string(d.nz) +
                   " p=" + std::to_string(p));
      const VoxelGrid g = randomGrid(d, p, seed++);
      const auto r = decodeVxm(encodeVxm(g), "t.vxm");
      ASSERT_TRUE(r.ok()) << r.error().message;
      expectSameVoxels(g, r.value());
      EXPECT_EQ(r->frame(), g.frame());  // origin, voxel size, units and source, bit for bit
    }
  }
}

TEST(Vxm, fullAndEmptyGridsAreTinyFiles) {
  VoxelGrid full(Dims{100, 100, 100});
  for (int z = 0; z < 100; ++z)
    for (int y = 0; y < 100; ++y) full.fillRun(y, z, 0, 100);
  const std::vector<uint8_t> f = encodeVxm(full);
  const VoxelGrid empty(Dims{100, 100, 100});
  const std::vector<uint8_t> e = encodeVxm(empty);
  EXPECT_LT(f.size(), 150u);  // header + two runs (0 empty, 10^6 filled) + CRC
  EXPECT_LT(e.size(), 150u);
  const auto rf = decodeVxm(f, "f.vxm");
  ASSERT_TRUE(rf.ok()) << rf.error().message;
  EXPECT_EQ(rf->filledCount(), 1000000);
  const auto re = decodeVxm(e, "e.vxm");
  ASSERT_TRUE(re.ok()) << re.error().message;
  EXPECT_EQ(re->filledCount(), 0);
  EXPECT_EQ(re->allocatedLayers(), 0);  // reading an empty grid allocates no layers
}

TEST(Vxm, flippedByteIsReportedAsCrcMismatch) {
  std::vector<uint8_t> b = encodeVxm(randomGrid({40, 30, 20}, 0.3, 7));
  b[b.size() - 10] ^= 0x20;  // in the body
  const auto r = decodeVxm(b, "part.vxm");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kCorrupt);
  EXPECT_EQ(r.error().message.rfind("part.vxm: .vxm file is corrupt: CRC-32 mismatch (stored ", 0), 0u)
      << r.error().message;
}

TEST(Vxm, flippedHeaderByteIsReportedAsCorruptHeader) {
  std::vector<uint8_t> b = encodeVxm(randomGrid({40, 30, 20}, 0.3, 7));
  b[17] ^= 0x01;  // ny
  const auto r = decodeVxm(b, "part.vxm");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kCorrupt);
  EXPECT_EQ(r.error().message, "part.vxm: .vxm header is corrupt (CRC-32 mismatch)");
}

TEST(Vxm, everyTruncationIsReportedAsTruncated) {
  const std::vector<uint8_t> b = encodeVxm(randomGrid({40, 30, 20}, 0.3, 8));
  for (size_t keep = 1; keep < b.size(); keep += (keep < 200 ? 1 : 97)) {
    const auto r = decodeVxm(std::span<const uint8_t>(b.data(), keep), "part.vxm");
    ASSERT_FALSE(r.ok()) << keep;
    EXPECT_EQ(r.error().code, ErrorCode::kParse) << keep;
    EXPECT_NE(r.error().message.find("part.vxm: .vxm file truncated"), std::string::npos)
        << keep << ": " << r.error().message;
  }
}

TEST(Vxm, newerFormatVersionIsRefusedAsSuch) {
  std::vector<uint8_t> b = encodeVxm(randomGrid({8, 8, 8}, 0.3, 9));
  b[8] = 2;  // version field, little-endian
  const auto r = decodeVxm(b, "part.vxm");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kUnsupported);
  EXPECT_EQ(r.error().message, "part.vxm: written by a newer voxmod (format version 2; this build reads up to 1)");
}

TEST(Vxm, badMagicIsRefusedAsNotAVxmFile) {
  std::vector<uint8_t> b = encodeVxm(randomGrid({8, 8, 8}, 0.3, 9));
  b[1] = 'X';
  const auto r = decodeVxm(b, "part.vxm");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, "part.vxm: not a voxmod .vxm file (bad magic bytes)");
  // A binvox file given the wrong extension says the same.
  const auto rb = decodeVxm(encodeBinvox(randomGrid({8, 8, 8}, 0.3, 9)), "part.vxm");
  ASSERT_FALSE(rb.ok());
  EXPECT_EQ(rb.error().message, "part.vxm: not a voxmod .vxm file (bad magic bytes)");
}

TEST(Vxm, encodingStartsWithTheMagicAndVersionOne) {
  const std::vector<uint8_t> b = encodeVxm(VoxelGrid(Dims{2, 2, 2}));
  ASSERT_GE(b.size(), 12u);
  const uint8_t head[12] = {0x89, 'V', 'X', 'M', '\r', '\n', 0x1A, '\n', 1, 0, 0, 0};
  EXPECT_EQ(std::vector<uint8_t>(b.begin(), b.begin() + 12), std::vector<uint8_t>(head, head + 12));
}

TEST(Binvox, roundTripOfCubicGridIsBitExact) {
  uint32_t seed = 100;
  for (int n : {1, 2, 31, 64, 65, 100}) {
    for (double p : {0.0, 0.2, 1.0}) {
      SCOPED_TRACE(std::to_string(n) + " p=" + std::to_string(p));
      const VoxelGrid g = randomGrid({n, n, n}, p, seed++);
      const auto r = decodeBinvox(encodeBinvox(g), "dir/t.binvox");
      ASSERT_TRUE(r.ok()) << r.error().message;
      expectSameVoxels(g, r.value());
      EXPECT_EQ(r->frame().origin, g.frame().origin);
      EXPECT_NEAR(r->frame().voxel_size, g.frame().voxel_size, 1e-15 * g.frame().voxel_size);
      EXPECT_EQ(r->frame().units, "model");  // binvox has no units
      EXPECT_EQ(r->frame().source, "t.binvox");
    }
  }
}

TEST(Binvox, nonCubicGridIsPaddedToTheLargestDimension) {
  const VoxelGrid g = randomGrid({20, 45, 7}, 0.4, 5);
  const std::vector<uint8_t> bytes = encodeBinvox(g);
  const std::string head(bytes.begin(), bytes.begin() + 64);
  EXPECT_EQ(head.rfind("#binvox 1\ndim 45 45 45\ntranslate -1.5 0.125 0.001\n", 0), 0u) << head;
  const auto r = decodeBinvox(bytes, "t.binvox");
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(r->dims(), (Dims{45, 45, 45}));
  int64_t mismatches = 0;
  for (int z = 0; z < 45; ++z)
    for (int y = 0; y < 45; ++y)
      for (int x = 0; x < 45; ++x) {
        const bool want = x < 20 && z < 7 && g.get(x, y, z);
        mismatches += r->get(x, y, z) != want;
      }
  EXPECT_EQ(mismatches, 0);
  EXPECT_EQ(r->filledCount(), g.filledCount());
  EXPECT_NEAR(r->frame().voxel_size, 0.1, 1e-16);
}

TEST(Binvox, paddedRoundTripIsBitExactForAwkwardNonCubicDims) {
  // Blocks of 64 x values and 64 y values are transposed inside the codec: sizes either side of 64 on every axis.
  uint32_t seed = 200;
  for (const Dims& d : {Dims{130, 3, 70}, Dims{3, 130, 70}, Dims{70, 70, 130}, Dims{65, 63, 1}, Dims{1, 1, 129}}) {
    SCOPED_TRACE(std::to_string(d.nx) + "x" + std::to_string(d.ny) + "x" + std::to_string(d.nz));
    const VoxelGrid g = randomGrid(d, 0.3, seed++);
    const auto r = decodeBinvox(encodeBinvox(g), "t.binvox");
    ASSERT_TRUE(r.ok()) << r.error().message;
    expectSamePaddedToCube(g, r.value());
  }
}

TEST(Binvox, decoderAgreesWithTheIndexFormulaOnRandomFiles) {
  // Random run streams over non-cubic "dim d w h" files, checked against index = x * w * h + z * w + y.
  std::mt19937 rng(42);
  for (const auto& [dx, dy, dz] : {std::array{70, 130, 5}, std::array{5, 70, 130}, std::array{129, 1, 65}}) {
    const int64_t total = int64_t(dx) * dy * dz;
    std::string file =
        "#binvox 1\ndim " + std::to_string(dx) + " " + std::to_string(dy) + " " + std::to_string(dz) + "\ndata\n";
    std::vector<uint8_t> voxels;
    while (int64_t(voxels.size()) < total) {
      const uint8_t v = uint8_t(rng() % 2);
      const int64_t n = std::min<int64_t>(1 + rng() % 255, total - int64_t(voxels.size()));
      file += char(v);
      file += char(n);
      voxels.insert(voxels.end(), size_t(n), v);
    }
    const auto r = decodeBinvox(std::vector<uint8_t>(file.begin(), file.end()), "r.binvox");
    ASSERT_TRUE(r.ok()) << r.error().message;
    ASSERT_EQ(r->dims(), (Dims{dx, dy, dz}));
    int64_t mismatches = 0;
    for (int x = 0; x < dx; ++x)
      for (int z = 0; z < dz; ++z)
        for (int y = 0; y < dy; ++y)
          mismatches += r->get(x, y, z) != (voxels[size_t(int64_t(x) * dy * dz + int64_t(z) * dy + y)] == 1);
    EXPECT_EQ(mismatches, 0) << dx << "x" << dy << "x" << dz;
  }
}

TEST(Binvox, scaleIsTheCubeEdgeAndIndexOrderIsYThenZThenX) {
  // One voxel at (x, y, z) = (1, 2, 3) of a 4^3 grid: binvox index 1*16 + 3*4 + 2 = 30.
  GridFrame f;
  f.origin = {10, 20, 30};
  f.voxel_size = 0.5;
  VoxelGrid g(Dims{4, 4, 4}, f);
  g.set(1, 2, 3);
  const std::vector<uint8_t> bytes = encodeBinvox(g);
  const std::string expected_header = "#binvox 1\ndim 4 4 4\ntranslate 10 20 30\nscale 2\ndata\n";
  ASSERT_EQ(std::string(bytes.begin(), bytes.begin() + std::ptrdiff_t(expected_header.size())), expected_header);
  const std::vector<uint8_t> runs(bytes.begin() + std::ptrdiff_t(expected_header.size()), bytes.end());
  EXPECT_EQ(runs, (std::vector<uint8_t>{0, 30, 1, 1, 0, 33}));
}

TEST(Binvox, runsLongerThan255AreSplit) {
  VoxelGrid g(Dims{10, 10, 10});
  for (int z = 0; z < 10; ++z)
    for (int y = 0; y < 10; ++y) g.fillRun(y, z, 0, 10);
  const std::vector<uint8_t> bytes = encodeBinvox(g);
  const size_t data = std::string(bytes.begin(), bytes.end()).find("data\n") + 5;
  // 1000 filled voxels: 255 + 255 + 255 + 235.
  EXPECT_EQ(std::vector<uint8_t>(bytes.begin() + std::ptrdiff_t(data), bytes.end()),
            (std::vector<uint8_t>{1, 255, 1, 255, 1, 255, 1, 235}));
}

TEST(Binvox, nonCubicFileReadsAsDepthWidthHeight) {
  // "dim 2 3 4": x has 2 voxels, y 3, z 4; index = x * 12 + z * 3 + y. Voxel 12 + 2 * 3 + 1 = 19 is (1, 1, 2).
  std::string file = "#binvox 1\ndim 2 3 4\ntranslate 0 0 0\nscale 8\ndata\n";
  file += std::string{0, 19, 1, 1, 0, 4};
  const auto r = decodeBinvox(std::vector<uint8_t>(file.begin(), file.end()), "t.binvox");
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(r->dims(), (Dims{2, 3, 4}));
  EXPECT_TRUE(r->get(1, 1, 2));
  EXPECT_EQ(r->filledCount(), 1);
  EXPECT_EQ(r->frame().voxel_size, 2.0);  // scale / largest dimension
}

// binvox writes run lengths 1..255; a 0 is a damaged file, refused rather than skipped in silence.
TEST(Binvox, countZeroRunIsRefused) {
  std::string file = "#binvox 1\ndim 2 2 2\ndata\n";
  file += std::string{0, 0, 1, 3, 1, 0, 0, 5};
  const auto r = decodeBinvox(std::vector<uint8_t>(file.begin(), file.end()), "t.binvox");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, "t.binvox: binvox data has a run of length 0 at byte 26 (run lengths are 1..255)");
}

TEST(VoxelFile, dispatchesByExtensionCaseInsensitively) {
  EXPECT_TRUE(isVoxelFile("a.vxm"));
  EXPECT_TRUE(isVoxelFile("dir/a.BinVox"));
  EXPECT_FALSE(isVoxelFile("a.stl"));
  EXPECT_FALSE(isVoxelFile("vxm"));
  test::TempDir tmp;
  const VoxelGrid g = randomGrid({16, 16, 16}, 0.3, 11);
  for (const char* name : {"a.vxm", "b.VXM", "c.binvox"}) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(saveVoxelFile(g, tmp / name).ok());
    const auto r = loadVoxelFile(tmp / name);
    ASSERT_TRUE(r.ok()) << r.error().message;
    expectSameVoxels(g, r.value());
  }
  // The extension decides: a .vxm file really holds .vxm bytes.
  EXPECT_EQ(test::readFile(tmp / "a.vxm").substr(1, 3), "VXM");
  EXPECT_EQ(test::readFile(tmp / "c.binvox").substr(0, 9), "#binvox 1");
}

TEST(VoxelFile, streamedSavesOfSeveralChunksEqualTheEncodingInMemory) {
  // A noisy grid encodes to megabytes in either format: the saves stream it in 1 MiB chunks (the .vxm
  // header and its CRC completed afterwards) and must write exactly the bytes the in-memory encoders return.
  test::TempDir tmp;
  const VoxelGrid g = randomGrid({300, 200, 160}, 0.5, 21);
  const std::vector<uint8_t> vxm = encodeVxm(g), binvox = encodeBinvox(g);
  ASSERT_GT(vxm.size(), size_t(3) << 19);  // more than one chunk
  ASSERT_GT(binvox.size(), size_t(3) << 19);
  ASSERT_TRUE(saveVxm(g, tmp / "g.vxm").ok());
  ASSERT_TRUE(saveBinvox(g, tmp / "g.binvox").ok());
  EXPECT_TRUE(test::readFile(tmp / "g.vxm") == std::string(vxm.begin(), vxm.end()));
  EXPECT_TRUE(test::readFile(tmp / "g.binvox") == std::string(binvox.begin(), binvox.end()));
  const auto r = loadVxm(tmp / "g.vxm");
  ASSERT_TRUE(r.ok()) << r.error().message;
  expectSameVoxels(g, r.value());
  const auto b = loadBinvox(tmp / "g.binvox");  // every chunk arrived, in order
  ASSERT_TRUE(b.ok()) << b.error().message;
  expectSamePaddedToCube(g, b.value());
}

TEST(VoxelFile, unknownExtensionNamesTheSupportedOnes) {
  test::TempDir tmp;
  const auto r = loadVoxelFile(tmp / "a.vox");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kUnsupported);
  EXPECT_EQ(r.error().message,
            (tmp / "a.vox").string() + ": unknown voxel file type '.vox' (supported: .vxm, .binvox)");
  const Status s = saveVoxelFile(VoxelGrid(Dims{2, 2, 2}), tmp / "a.txt");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().code, ErrorCode::kUnsupported);
  EXPECT_FALSE(std::filesystem::exists(tmp / "a.txt"));
}

TEST(VoxelFile, missingFileNamesThePathAndTheReason) {
  const auto r = loadVxm("/nonexistent-dir/part.vxm");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kIo);
  EXPECT_EQ(r.error().message, "/nonexistent-dir/part.vxm: cannot open: No such file or directory");
}

TEST(VoxelFile, emptyGridIsNotSaved) {
  test::TempDir tmp;
  const Status s = saveVxm(VoxelGrid(), tmp / "e.vxm");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().code, ErrorCode::kInvalidArgument);
}

TEST(VoxelFiles, severalGridsAreWrittenEachByItsExtensionIntoNewFolders) {
  test::TempDir tmp;
  VoxelGrid a(Dims{5, 3, 2}), b(Dims{4, 4, 4});
  a.fillRun(1, 1, 0, 5);
  b.fillRun(2, 3, 1, 3);
  b.frame().origin = glm::dvec3(2.0, 0.0, 0.0);
  const std::vector<VoxelFileToWrite> files{{tmp / "out" / "a.vxm", a}, {tmp / "out" / "deep" / "b.binvox", b}};
  ASSERT_TRUE(saveVoxelFiles(files).ok());
  auto ra = loadVoxelFile(tmp / "out" / "a.vxm");
  auto rb = loadVoxelFile(tmp / "out" / "deep" / "b.binvox");
  ASSERT_TRUE(ra.ok());
  ASSERT_TRUE(rb.ok());
  EXPECT_EQ(ra->dims(), a.dims());
  EXPECT_EQ(ra->filledCount(), 5);
  EXPECT_EQ(rb->filledCount(), 2);
  EXPECT_EQ(rb->frame().origin, b.frame().origin);
}

TEST(VoxelFiles, nothingIsWrittenWhenOneFileCannotBe) {
  test::TempDir tmp;
  VoxelGrid g(Dims{3, 3, 3});
  g.fillRun(0, 0, 0, 3);
  // An unknown extension is refused before any file is written.
  const std::vector<VoxelFileToWrite> bad_ext{{tmp / "a.vxm", g}, {tmp / "b.txt", g}};
  const Status s1 = saveVoxelFiles(bad_ext);
  ASSERT_FALSE(s1.ok());
  EXPECT_NE(s1.error().message.find("b.txt"), std::string::npos) << s1.error().message;
  EXPECT_FALSE(std::filesystem::exists(tmp / "a.vxm"));
  // A folder that cannot be made (a file stands where it would be): neither file appears.
  ASSERT_TRUE(writeFileAtomic(tmp / "blocker", std::string("not a folder")).ok());
  const std::vector<VoxelFileToWrite> bad_dir{{tmp / "ok" / "a.vxm", g}, {tmp / "blocker" / "b.vxm", g}};
  const Status s2 = saveVoxelFiles(bad_dir);
  ASSERT_FALSE(s2.ok());
  EXPECT_NE(s2.error().message.find("blocker"), std::string::npos) << s2.error().message;
  EXPECT_FALSE(std::filesystem::exists(tmp / "ok" / "a.vxm"));
}

}  // namespace
}  // namespace vox::io
