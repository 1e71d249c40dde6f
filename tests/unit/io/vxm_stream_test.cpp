// .vxm files written a slab and read a window of Z layers at a time (vox/io/vxm_stream.h), and converted to .binvox
// in passes: the same bytes as the whole-grid encoders, the same voxels as the grid, for any slab and window sizes.
#include <filesystem>
#include <string>
#include <vector>

#include "support/grids.h"
#include "support/test_support.h"
#include "vox/io/file_util.h"
#include "vox/io/voxel_file.h"
#include "vox/io/vxm_stream.h"

namespace vox {
namespace {

// A random grid with an empty layer, a full layer and a layer with one voxel, so runs cross slab boundaries
// in every way; nx > 64 so rows span words.
VoxelGrid testGrid(Dims d) {
  VoxelGrid g = test::randomGrid(d, 0.4, 7);
  for (int32_t y = 0; y < d.ny; ++y) {
    for (int32_t x = 0; x < d.nx; ++x) {
      g.set(x, y, 2, false);
      g.set(x, y, 3, true);
      g.set(x, y, 4, false);
    }
  }
  g.set(d.nx - 1, d.ny - 1, 4);
  g.frame().origin = {1.5, -2.0, 0.25};
  g.frame().voxel_size = 0.125;
  g.frame().units = "mm";
  g.frame().source = "test.stl";
  return g;
}

bool sameLayer(const VoxelGrid& a, int32_t za, const VoxelGrid& b, int32_t zb) {
  for (int32_t y = 0; y < a.ny(); ++y) {
    for (int32_t x = 0; x < a.nx(); ++x) {
      if (a.get(x, y, za) != b.get(x, y, zb)) return false;
    }
  }
  return true;
}

TEST(VxmStream, slabsGiveTheBytesOfTheWholeGridEncoder) {
  const VoxelGrid g = testGrid(Dims{70, 9, 13});
  const std::vector<uint8_t> whole = io::encodeVxm(g);
  test::TempDir tmp;
  for (int32_t slab : {1, 2, 5, 13}) {
    SCOPED_TRACE(slab);
    const auto path = tmp / "s.vxm";
    auto s = io::saveVxmInSlabs(path, g.dims(), g.frame(), [&](io::VxmLayerWriter& w) {
      for (int32_t z0 = 0; z0 < g.nz(); z0 += slab) {
        // Each slab as its own grid, as the voxelizer hands them over.
        const int32_t z1 = std::min(g.nz(), z0 + slab);
        VoxelGrid part(Dims{g.nx(), g.ny(), z1 - z0}, g.frame());
        for (int32_t z = z0; z < z1; ++z)
          for (int32_t y = 0; y < g.ny(); ++y)
            for (int32_t x = 0; x < g.nx(); ++x)
              if (g.get(x, y, z)) part.set(x, y, z - z0);
        if (Status st = w.append(part, 0, z1 - z0); !st) return st;
      }
      return Status(Ok{});
    });
    ASSERT_TRUE(s.ok()) << s.error().message;
    const std::string bytes = test::readFile(path);
    EXPECT_TRUE(std::vector<uint8_t>(bytes.begin(), bytes.end()) == whole);
  }
}

// Slabs encoded on their own (as other MPI ranks encode them) and appended as runs, mixed with slabs appended as
// layers: the runs join across every boundary, so the bytes are the whole-grid encoder's.
TEST(VxmStream, slabsEncodedElsewhereGiveTheBytesOfTheWholeGridEncoder) {
  const VoxelGrid g = testGrid(Dims{70, 9, 13});
  const std::vector<uint8_t> whole = io::encodeVxm(g);
  test::TempDir tmp;
  for (int32_t slab : {1, 2, 3, 13}) {
    SCOPED_TRACE(slab);
    const auto path = tmp / "s.vxm";
    auto s = io::saveVxmInSlabs(path, g.dims(), g.frame(), [&](io::VxmLayerWriter& w) {
      for (int32_t z0 = 0, k = 0; z0 < g.nz(); z0 += slab, ++k) {
        const int32_t z1 = std::min(g.nz(), z0 + slab);
        if (Status st = k % 3 == 0 ? w.append(g, z0, z1) : w.appendRuns(io::encodeVxmLayers(g, z0, z1), z1 - z0); !st)
          return st;
      }
      return Status(Ok{});
    });
    ASSERT_TRUE(s.ok()) << s.error().message;
    const std::string bytes = test::readFile(path);
    EXPECT_TRUE(std::vector<uint8_t>(bytes.begin(), bytes.end()) == whole);
  }
  // Runs that do not cover the layers they stand for are refused, and no file is left.
  std::filesystem::remove(tmp / "s.vxm");
  const std::vector<uint8_t> two = io::encodeVxmLayers(g, 0, 2);
  for (int32_t layers : {1, 3}) {
    auto s = io::saveVxmInSlabs(tmp / "bad.vxm", g.dims(), g.frame(), [&](io::VxmLayerWriter& w) {
      if (Status st = w.appendRuns(two, layers); !st) return st;
      return w.append(g, layers, g.nz());
    });
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().code, ErrorCode::kCorrupt) << s.error().message;
  }
  EXPECT_TRUE(std::filesystem::is_empty(tmp.path()));
}

TEST(VxmStream, writerRefusesAnIncompleteGridAndLeavesNoFile) {
  const VoxelGrid g = testGrid(Dims{70, 9, 13});
  test::TempDir tmp;
  auto s = io::saveVxmInSlabs(tmp / "part.vxm", g.dims(), g.frame(),
                              [&](io::VxmLayerWriter& w) { return w.append(g, 0, 12); });
  EXPECT_FALSE(s.ok());
  EXPECT_TRUE(std::filesystem::is_empty(tmp.path()));
}

TEST(VxmStream, windowsHoldTheGridsLayersWithTheirHalo) {
  const VoxelGrid g = testGrid(Dims{70, 9, 13});
  test::TempDir tmp;
  ASSERT_TRUE(io::saveVxm(g, tmp / "g.vxm").ok());
  for (int32_t layers : {1, 2, 5, 13, 40}) {
    for (int32_t halo : {0, 1, 2}) {
      SCOPED_TRACE(std::to_string(layers) + " layers, halo " + std::to_string(halo));
      int32_t next = 0;
      auto s = io::readVxmInWindows(tmp / "g.vxm", layers, halo, [&](const io::VxmWindow& w) {
        EXPECT_EQ(w.core_begin, next);
        EXPECT_EQ(w.core_end, std::min(g.nz(), next + layers));
        EXPECT_EQ(w.z_offset, std::max(0, w.core_begin - halo));
        EXPECT_EQ(w.z_offset + w.grid.nz(), std::min(g.nz(), w.core_end + halo));
        EXPECT_EQ(w.grid.frame(), g.frame());
        for (int32_t z = 0; z < w.grid.nz(); ++z) EXPECT_TRUE(sameLayer(w.grid, z, g, z + w.z_offset)) << z;
        next = w.core_end;
        return Status(Ok{});
      });
      ASSERT_TRUE(s.ok()) << s.error().message;
      EXPECT_EQ(next, g.nz());
    }
  }
}

TEST(VxmStream, binvoxInPassesIsTheInMemoryEncoding) {
  test::TempDir tmp;
  // x longest (several passes, the last partial), then y and z longest (padding along x and z).
  for (Dims d : {Dims{150, 9, 13}, Dims{20, 70, 13}, Dims{20, 9, 40}}) {
    const VoxelGrid g = testGrid(d);
    ASSERT_TRUE(io::saveVxm(g, tmp / "g.vxm").ok());
    const std::vector<uint8_t> expected = io::encodeBinvox(g);
    for (uint64_t buffer : {uint64_t(1), uint64_t(1) << 20}) {
      SCOPED_TRACE(std::to_string(d.nx) + " x " + std::to_string(d.ny) + " x " + std::to_string(d.nz) + ", buffer " +
                   std::to_string(buffer));
      ASSERT_TRUE(io::convertVxmToBinvox(tmp / "g.vxm", tmp / "g.binvox", buffer, 3).ok());
      const std::string bytes = test::readFile(tmp / "g.binvox");
      EXPECT_TRUE(std::vector<uint8_t>(bytes.begin(), bytes.end()) == expected);
    }
  }
}

}  // namespace
}  // namespace vox

namespace vox {
namespace {

TEST(VxmStream, coarseCopyFillsEachBlockThatHoldsAVoxel) {
  test::TempDir tmp;
  VoxelGrid g = test::randomGrid(Dims{150, 21, 13}, 0.01, 3);
  g.frame().voxel_size = 0.5;
  ASSERT_TRUE(io::saveVxm(g, tmp / "g.vxm").ok());
  for (int32_t level : {1, 2, 3, 4, 64}) {
    SCOPED_TRACE(level);
    auto c = io::readVxmCoarse(tmp / "g.vxm", level);
    ASSERT_TRUE(c.ok()) << c.error().message;
    EXPECT_EQ(c->dims(), (Dims{(150 + level - 1) / level, (21 + level - 1) / level, (13 + level - 1) / level}));
    EXPECT_DOUBLE_EQ(c->voxelSize(), 0.5 * level);
    VoxelGrid expected(c->dims());
    for (int32_t z = 0; z < g.nz(); ++z)
      for (int32_t y = 0; y < g.ny(); ++y)
        for (int32_t x = 0; x < g.nx(); ++x)
          if (g.get(x, y, z)) expected.set(x / level, y / level, z / level);
    for (int32_t z = 0; z < c->nz(); ++z)
      for (int32_t y = 0; y < c->ny(); ++y)
        for (int32_t x = 0; x < c->nx(); ++x) ASSERT_EQ(c->get(x, y, z), expected.get(x, y, z)) << x << " " << y;
  }
  EXPECT_EQ(io::coarseLevelFor(Dims{4096, 4096, 4096}, uint64_t(2) << 30), 2);  // 2048^3 bits and padding
  EXPECT_EQ(io::coarseLevelFor(Dims{100, 100, 100}, uint64_t(1) << 30), 1);
}

}  // namespace
}  // namespace vox
