#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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
// (every time half of them have). Each walk: SSE2 on any processor, AVX2 and AVX-512 where this one has them (the
// same voxels, the same order).
void checkWalk(OpenVoxels::Simd simd) {
  for (const Dims box : {Dims{70, 37, 133}, Dims{45, 140, 30}})
    for (const int threads : {1, 2, 3}) {
      std::mt19937 rng(uint32_t(11 + threads));
      std::vector<uint8_t> filled(size_t(box.count()));
      for (auto& f : filled) f = rng() % 5 != 0;
      auto index = [&](int64_t x, int64_t y, int64_t z) { return size_t(x + box.nx * (y + int64_t(box.ny) * z)); };
      OpenVoxels open(
          box, threads, [&](int64_t x, int64_t y, int64_t z) { return filled[index(x, y, z)] != 0; }, simd);
      ASSERT_EQ(open.walk(), simd);
      std::vector<int32_t> got(filled.size(), -1), want(filled.size(), -1);
      int64_t cx = 0, cy = 0, cz = 0, s = 1;
      int64_t big = 0, again = 0;  // voxels painted by balls past s = 1500, and by balls that come again
      for (int ball = 0; ball < 240; ++ball) {
        // Two balls in three step along one axis from the one before, the same size: as balls of one size come to
        // local thickness, in Morton order, so that the walk reuses an axis's distances from the ball before.
        if (ball % 3 == 0) {
          cx = int64_t(rng() % uint32_t(box.nx + 20)) - 10;
          cy = int64_t(rng() % uint32_t(box.ny + 12)) - 6;
          cz = int64_t(rng() % uint32_t(box.nz + 16)) - 8;
          s = 1 + int64_t(rng() % 1500);  // up to a radius of 38
          if (rng() % 8 == 0) {
            // a ball of radius 40 to 150 (wider than the box), its centre far enough out on the low x side that it
            // reaches 10 to 30 voxels into the box
            const int64_t r = 40 + int64_t(rng() % 111);
            s = r * r + int64_t(rng() % uint32_t(2 * r));
            cx = 10 + int64_t(rng() % 21) - r;
          }
        } else {
          (ball % 3 == 1 ? cx : rng() % 2 ? cy : cz) += 1 + int64_t(rng() % 3);
        }
        // A quarter of the balls come with a window of whole bricks, whose open voxels alone they paint (the rest
        // stay open for later balls); a quarter with the box of the open voxels they paint, as local thickness passes
        // it, made wider by up to two voxels on a side or left as it is (empty where they paint none); a quarter with
        // none; a quarter with the bricks that meet a box half the ball's radius about its centre, and at once again
        // with none.
        const int kind = ball % 3 == 2 ? int(rng() % 4) : 2;
        OpenVoxels::Window window{{-1000, -1000, -1000}, {1000, 1000, 1000}};
        const int64_t c[3] = {cx, cy, cz}, n[3] = {box.nx, box.ny, box.nz};
        if (kind == 0) {
          for (int a = 0; a < 3; ++a) {
            const int64_t b0 = int64_t(rng() % uint32_t(n[a] / 4 + 1)), b1 = b0 + int64_t(rng() % 6);
            window.lo[a] = 4 * b0 - c[a];
            window.hi[a] = 4 * b1 + 3 - c[a];
          }
        } else if (kind == 3) {
          // the whole bricks that meet it (floor division: a centre may lie outside the box)
          const auto half = int64_t(std::sqrt(double(s)) / 2);
          auto brick = [](int64_t v) { return (v >= 0 ? v : v - 3) / 4; };
          for (int a = 0; a < 3; ++a) {
            window.lo[a] = 4 * brick(c[a] - half) - c[a];
            window.hi[a] = 4 * brick(c[a] + half) + 3 - c[a];
          }
        }
        // The open voxels of the ball in window `win` by a plain scan, marked in want as ball number id, and their
        // box about the centre (lo > hi when there are none).
        int64_t lo[3], hi[3];
        auto scan = [&](const OpenVoxels::Window& win, int32_t id) {
          for (int a = 0; a < 3; ++a) lo[a] = 1000, hi[a] = -1000;
          for (int64_t z = 0; z < box.nz; ++z)
            for (int64_t y = 0; y < box.ny; ++y)
              for (int64_t x = 0; x < box.nx; ++x) {
                const size_t i = index(x, y, z);
                const int64_t p[3] = {x, y, z};
                bool inside = true;
                for (int a = 0; a < 3; ++a) inside = inside && p[a] - c[a] >= win.lo[a] && p[a] - c[a] <= win.hi[a];
                if (filled[i] && want[i] < 0 && (x - cx) * (x - cx) + (y - cy) * (y - cy) + (z - cz) * (z - cz) < s &&
                    inside) {
                  want[i] = id;
                  for (int a = 0; a < 3; ++a) {
                    lo[a] = std::min(lo[a], p[a] - c[a]);
                    hi[a] = std::max(hi[a], p[a] - c[a]);
                  }
                }
              }
        };
        auto paint = [&](const OpenVoxels::Window& win, int32_t id) {
          for (int t = 0; t < threads; ++t)
            open.paintBall(t, cx, cy, cz, s, win, [&](int64_t x, int64_t y, int64_t z) {
              const size_t i = index(x, y, z);
              EXPECT_EQ(got[i], -1) << x << " " << y << " " << z << " painted twice";
              EXPECT_EQ(open.owner(x / 64, y / 64, z / 64), t);
              got[i] = id;
              big += s > 1500;
              again += id % 2;
            });
        };
        scan(window, 2 * ball);
        if (kind == 1) {
          const int64_t wider = int64_t(rng() % 3);
          for (int a = 0; a < 3; ++a) {
            window.lo[a] = lo[a] > hi[a] ? 1 : lo[a] - wider;
            window.hi[a] = lo[a] > hi[a] ? 0 : hi[a] + wider;
          }
        }
        paint(window, 2 * ball);
        // The ball again at once, the same centre and size, with no window: the walk must not take the narrow
        // window's distances for the wide one's (the second paints what the first left open in the ball).
        if (kind == 3) {
          const OpenVoxels::Window all{{-1000, -1000, -1000}, {1000, 1000, 1000}};
          scan(all, 2 * ball + 1);
          paint(all, 2 * ball + 1);
        }
      }
      EXPECT_GT(big, 0);
      EXPECT_GT(again, 0);
      EXPECT_EQ(got, want) << threads << " owners, box " << box.nx << " x " << box.ny << " x " << box.nz;
      // every owner's bricks were packed again as they closed (the walk read them from arrays of several sizes)
      for (int t = 0; t < threads; ++t) EXPECT_GE(open.packings(t), 3) << "owner " << t;
    }
}

TEST(OpenVoxels, paintsEveryOpenVoxelOfEachBallOnceAndOnlyByItsOwner) { checkWalk(OpenVoxels::Simd::kSse2); }

TEST(OpenVoxels, theAvx2WalkPaintsTheSameVoxels) {
  if (!OpenVoxels::avx2Available()) GTEST_SKIP() << "this processor has no AVX2: its walk cannot be tested here";
  checkWalk(OpenVoxels::Simd::kAvx2);
}

TEST(OpenVoxels, theAvx512WalkPaintsTheSameVoxels) {
  if (!OpenVoxels::avx512Available()) GTEST_SKIP() << "this processor has no AVX-512: its walk cannot be tested here";
  checkWalk(OpenVoxels::Simd::kAvx512);
}

// The walk asked for where the processor has it, else the next narrower one it has; kAuto the widest.
TEST(OpenVoxels, takesTheWidestWalkAskedForThatTheProcessorHas) {
  using Simd = OpenVoxels::Simd;
  const bool avx512 = OpenVoxels::avx512Available(), avx2 = OpenVoxels::avx2Available();
  const Simd widest = avx512 ? Simd::kAvx512 : avx2 ? Simd::kAvx2 : Simd::kSse2;
  auto walkFor = [](Simd asked) {
    return OpenVoxels(
               Dims{8, 8, 8}, 1, [](int64_t, int64_t, int64_t) { return true; }, asked)
        .walk();
  };
  EXPECT_EQ(walkFor(Simd::kAuto), widest);
  EXPECT_EQ(walkFor(Simd::kAvx512), widest);
  EXPECT_EQ(walkFor(Simd::kAvx2), avx2 ? Simd::kAvx2 : Simd::kSse2);
  EXPECT_EQ(walkFor(Simd::kSse2), Simd::kSse2);
}

}  // namespace
}  // namespace vox::analysis_detail
