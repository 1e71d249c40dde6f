// A save that runs out of space must fail with the reason, remove its temporary file and leave the previous file
// intact. Uses a real 64 KiB tmpfs, which needs root (CI runs as root); elsewhere the test skips and says why.
#include <sys/mount.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "support/test_support.h"
#include "vox/io/file_util.h"
#include "vox/io/voxel_file.h"
#include "vox/io/vxm_stream.h"

namespace vox {
namespace {

class SmallDisk : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = tmp_.path() / "small";
    std::filesystem::create_directory(dir_);
    if (::mount("tmpfs", dir_.c_str(), "tmpfs", 0, "size=64k") != 0) {
      GTEST_SKIP() << "cannot mount a small tmpfs to fill (needs root): " << std::strerror(errno);
    }
    mounted_ = true;
  }
  void TearDown() override {
    if (mounted_) ::umount(dir_.c_str());
  }
  // Saves a small valid .vxm as `name` and returns its bytes (the file a failed save must leave untouched).
  std::string saveSmallFile(const char* name) {
    VoxelGrid small(Dims{8, 8, 8});
    small.set(1, 2, 3);
    EXPECT_TRUE(io::saveVxm(small, dir_ / name).ok());
    return test::readFile(dir_ / name);
  }
  int entries() const {
    int n = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir_)) ++n;
    return n;
  }
  test::TempDir tmp_;
  std::filesystem::path dir_;
  bool mounted_ = false;
};

TEST_F(SmallDisk, saveThatRunsOutOfSpaceKeepsTheOldFileAndSaysWhy) {
  const auto target = dir_ / "part.vxm";
  const std::string before = saveSmallFile("part.vxm");

  const std::string big(1 << 20, 'x');  // 1 MiB into a 64 KiB file system
  auto s = io::writeFileAtomic(target, big);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().code, ErrorCode::kIo);
  EXPECT_NE(s.error().message.find(target.string()), std::string::npos) << s.error().message;
  EXPECT_NE(s.error().message.find("No space left on device"), std::string::npos) << s.error().message;

  EXPECT_EQ(test::readFile(target), before);  // the previous file is untouched
  EXPECT_EQ(entries(), 1) << "the temporary file was not removed";
  auto reread = io::loadVxm(target);
  ASSERT_TRUE(reread.ok()) << reread.error().message;
  EXPECT_TRUE(reread->get(1, 2, 3));
}

TEST_F(SmallDisk, streamedSaveThatRunsOutOfSpaceMidwayKeepsTheOldFile) {
  // A noisy grid whose .vxm is far larger than the file system: the failure comes while the body streams.
  const auto target = dir_ / "part.vxm";
  const std::string before = saveSmallFile("part.vxm");

  VoxelGrid noisy(Dims{256, 256, 64});
  uint32_t state = 12345;
  for (int z = 0; z < 64; ++z)
    for (int y = 0; y < 256; ++y)
      for (int x = 0; x < 256; ++x)
        if (((state = state * 1664525u + 1013904223u) >> 31) != 0) noisy.set(x, y, z);
  for (const char* name : {"part.vxm", "part.binvox"}) {
    SCOPED_TRACE(name);
    const auto s = io::saveVoxelFile(noisy, dir_ / name);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().code, ErrorCode::kIo);
    EXPECT_NE(s.error().message.find("No space left on device"), std::string::npos) << s.error().message;
  }
  EXPECT_EQ(test::readFile(target), before);
  EXPECT_EQ(entries(), 1) << "a temporary file was not removed";
}

TEST_F(SmallDisk, saveInSlabsThatRunsOutOfSpaceKeepsTheOldFile) {
  // The streamed voxelizer's save (io::saveVxmInSlabs): slabs of a noisy grid, the disk full after a few of them.
  const auto target = dir_ / "part.vxm";
  const std::string before = saveSmallFile("part.vxm");
  VoxelGrid slab(Dims{256, 256, 4});
  uint32_t state = 54321;
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < 256; ++y)
      for (int x = 0; x < 256; ++x)
        if (((state = state * 1664525u + 1013904223u) >> 31) != 0) slab.set(x, y, z);
  const auto s = io::saveVxmInSlabs(target, Dims{256, 256, 64}, slab.frame(), [&](io::VxmLayerWriter& w) {
    for (int i = 0; i < 16; ++i) {
      if (Status st = w.append(slab, 0, 4); !st) return st;
    }
    return Status(Ok{});
  });
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().code, ErrorCode::kIo);
  EXPECT_NE(s.error().message.find("No space left on device"), std::string::npos) << s.error().message;
  EXPECT_EQ(test::readFile(target), before);
  EXPECT_EQ(entries(), 1) << "the temporary file was not removed";
}

}  // namespace
}  // namespace vox
