#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "analysis/open_voxels.h"

namespace vox::analysis_detail {
namespace {

// Balls painted through the bit pyramid reach exactly the open voxels a plain scan finds, each once, by the first
// ball that covers it, whatever the box (not a multiple of the brick, node or block; owners by layers across Z, and
// across Y where the box has more blocks along Y) and however many owners.
// A ball may come with a window about its centre: it then paints the open voxels of the bricks that meet the window
// (with a window of whole bricks, those in the window alone). Each owner's brick words are packed again as they close
// (every time half of them have). Both walks: SSE2 on any processor, AVX-512 where this one has it (the same voxels,
// the same order).
void checkWalk(OpenVoxels::Simd simd) {
  for (const Dims box : {Dims{70, 37, 133}, Dims{45, 140, 30}})
    for (const int threads : {1, 2, 3}) {
      std::mt19937 rng(uint32_t(11 + threads));
      std::vector<uint8_t> filled(size_t(box.count()));
      for (auto& f : filled) f = rng() % 5 != 0;
      auto index = [&](int64_t x, int64_t y, int64_t z) { return size_t(x + box.nx * (y + int64_t(box.ny) * z)); };
      OpenVoxels open(
          box, threads, [&](int64_t x, int64_t y, int64_t z) { return filled[index(x, y, z)] != 0; }, simd);
      ASSERT_EQ(open.usesAvx512(), simd == OpenVoxels::Simd::kAvx512);
      std::vector<int32_t> got(filled.size(), -1), want(filled.size(), -1);
      int64_t cx = 0, cy = 0, cz = 0, s = 1;
      for (int ball = 0; ball < 240; ++ball) {
        // Two balls in three step along one axis from the one before, the same size: as balls of one size come to
        // local thickness, in Morton order, so that the walk reuses an axis's distances from the ball before.
        if (ball % 3 == 0) {
          cx = int64_t(rng() % uint32_t(box.nx + 20)) - 10;
          cy = int64_t(rng() % uint32_t(box.ny + 12)) - 6;
          cz = int64_t(rng() % uint32_t(box.nz + 16)) - 8;
          s = 1 + int64_t(rng() % 1500);
        } else {
          (ball % 3 == 1 ? cx : rng() % 2 ? cy : cz) += 1 + int64_t(rng() % 3);
        }
        // A third of the balls come with a window of whole bricks, whose open voxels alone they paint (the rest stay
        // open for later balls); a third with the box of the open voxels they paint, as local thickness passes it,
        // made wider by up to two voxels on a side or left as it is (empty where they paint none); a third with none.
        const int kind = ball % 3 == 2 ? int(rng() % 3) : 2;
        OpenVoxels::Window window{{-1000, -1000, -1000}, {1000, 1000, 1000}};
        const int64_t c[3] = {cx, cy, cz}, n[3] = {box.nx, box.ny, box.nz};
        if (kind == 0) {
          for (int a = 0; a < 3; ++a) {
            const int64_t b0 = int64_t(rng() % uint32_t(n[a] / 4 + 1)), b1 = b0 + int64_t(rng() % 6);
            window.lo[a] = 4 * b0 - c[a];
            window.hi[a] = 4 * b1 + 3 - c[a];
          }
        }
        auto inWindow = [&](int64_t x, int64_t y, int64_t z) {
          const int64_t p[3] = {x, y, z};
          for (int a = 0; a < 3; ++a)
            if (p[a] - c[a] < window.lo[a] || p[a] - c[a] > window.hi[a]) return false;
          return true;
        };
        int64_t lo[3] = {1000, 1000, 1000}, hi[3] = {-1000, -1000, -1000};
        for (int64_t z = 0; z < box.nz; ++z)
          for (int64_t y = 0; y < box.ny; ++y)
            for (int64_t x = 0; x < box.nx; ++x) {
              const size_t i = index(x, y, z);
              if (filled[i] && want[i] < 0 && (x - cx) * (x - cx) + (y - cy) * (y - cy) + (z - cz) * (z - cz) < s &&
                  inWindow(x, y, z)) {
                want[i] = ball;
                const int64_t p[3] = {x, y, z};
                for (int a = 0; a < 3; ++a) {
                  lo[a] = std::min(lo[a], p[a] - c[a]);
                  hi[a] = std::max(hi[a], p[a] - c[a]);
                }
              }
            }
        if (kind == 1) {
          const int64_t wider = int64_t(rng() % 3);
          for (int a = 0; a < 3; ++a) {
            window.lo[a] = lo[a] > hi[a] ? 1 : lo[a] - wider;
            window.hi[a] = lo[a] > hi[a] ? 0 : hi[a] + wider;
          }
        }
        for (int t = 0; t < threads; ++t)
          open.paintBall(t, cx, cy, cz, s, window, [&](int64_t x, int64_t y, int64_t z) {
            const size_t i = index(x, y, z);
            EXPECT_EQ(got[i], -1) << x << " " << y << " " << z << " painted twice";
            EXPECT_EQ(open.owner(x / 64, y / 64, z / 64), t);
            got[i] = ball;
          });
      }
      EXPECT_EQ(got, want) << threads << " owners, box " << box.nx << " x " << box.ny << " x " << box.nz;
      // every owner's bricks were packed again as they closed (the walk read them from arrays of several sizes)
      for (int t = 0; t < threads; ++t) EXPECT_GE(open.packings(t), 3) << "owner " << t;
    }
}

TEST(OpenVoxels, paintsEveryOpenVoxelOfEachBallOnceAndOnlyByItsOwner) { checkWalk(OpenVoxels::Simd::kSse2); }

TEST(OpenVoxels, theAvx512WalkPaintsTheSameVoxels) {
  if (!OpenVoxels::avx512Available()) GTEST_SKIP() << "this processor has no AVX-512: the SSE2 walk alone is tested";
  checkWalk(OpenVoxels::Simd::kAvx512);
}

}  // namespace
}  // namespace vox::analysis_detail
