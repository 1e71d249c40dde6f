// A few bytes of run-length data can describe a huge full grid: decoders check the memory the grid needs against a
// limit before allocating (the fuzzers and small machines depend on it).
#include <gtest/gtest.h>

#include "vox/io/voxel_file.h"

namespace vox {
namespace {

VoxelGrid fullGrid(int32_t n) {
  VoxelGrid g(Dims{n, n, n});
  for (int32_t z = 0; z < n; ++z)
    for (int32_t y = 0; y < n; ++y) g.fillRun(y, z, 0, n);
  return g;
}

TEST(DecodeLimit, vxmFullGridOverTheLimitIsRefusedBeforeAllocating) {
  const auto bytes = io::encodeVxm(fullGrid(256));  // 2 MiB of voxels in a tiny file
  EXPECT_LT(bytes.size(), 4096u);
  auto refused = io::decodeVxm(bytes, "big.vxm", uint64_t(1) << 20);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, ErrorCode::kLimit);
  EXPECT_NE(refused.error().message.find(
                "big.vxm: grid 256 x 256 x 256 with 256 occupied layers needs 2.5 MiB of memory; the limit is 1.0 MiB"),
            std::string::npos)
      << refused.error().message;
  EXPECT_NE(refused.error().message.find("the limit is"), std::string::npos) << refused.error().message;
  auto accepted = io::decodeVxm(bytes, "big.vxm", uint64_t(64) << 20);
  ASSERT_TRUE(accepted.ok()) << accepted.error().message;
  EXPECT_EQ(accepted->filledCount(), int64_t(256) * 256 * 256);
}

TEST(DecodeLimit, binvoxOverTheLimitIsRefused) {
  const auto bytes = io::encodeBinvox(fullGrid(128));
  auto refused = io::decodeBinvox(bytes, "big.binvox", uint64_t(64) << 10);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, ErrorCode::kLimit);
  EXPECT_TRUE(io::decodeBinvox(bytes, "big.binvox").ok());
}

}  // namespace
}  // namespace vox
