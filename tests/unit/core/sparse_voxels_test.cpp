#include "vox/core/sparse_voxels.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "vox/core/bits.h"

namespace vox {
namespace {

// Voxels that differ between two grids of the same dims.
int64_t differences(const VoxelGrid& a, const VoxelGrid& b) {
  int64_t n = 0;
  for (int32_t z = 0; z < a.nz(); ++z)
    for (int32_t y = 0; y < a.ny(); ++y)
      for (int64_t w = 0; w < a.wordsPerRow(); ++w) n += popcount64(a.rowWords(y, z)[w] ^ b.rowWords(y, z)[w]);
  return n;
}

TEST(SparseVoxels, holdsExactlyTheRowsAddedAndExpandsToTheSameGrid) {
  const Dims d{150, 7, 5};  // 3 words per row
  GridFrame frame;
  frame.origin = glm::dvec3(1.0, 2.0, 3.0);
  frame.voxel_size = 0.25;
  VoxelGrid expected(d, frame);
  std::mt19937 rng(7);
  std::vector<SparseVoxels::Chunk> chunks(3);
  for (int32_t z = 0; z < d.nz; ++z) {
    for (int32_t y = 0; y < d.ny; ++y) {
      std::vector<uint64_t> row(size_t(expected.wordsPerRow()), 0);
      // Some rows empty, some with voxels in one word only (so the span is trimmed), some across the row.
      const int kind = int(rng() % 4);
      for (int32_t x = 0; x < d.nx; ++x) {
        const bool on = kind == 1 ? (x >= 70 && x < 75) : kind >= 2 && rng() % 3 == 0;
        if (!on) continue;
        expected.set(x, y, z);
        row[size_t((x + 1) >> 6)] |= uint64_t(1) << ((x + 1) & 63);
      }
      // Chunks get rows in any order: chunk by (y + z) % 3, whole rows given with zero words at both ends.
      chunks[size_t((y + z) % 3)].addRow(y, z, 0, expected.wordsPerRow(), row.data());
    }
  }
  chunks.emplace_back();  // an empty chunk is dropped
  const SparseVoxels set(d, frame, std::move(chunks));
  EXPECT_EQ(set.dims(), d);
  EXPECT_EQ(set.frame(), frame);
  EXPECT_EQ(set.count(), expected.filledCount());
  EXPECT_GT(set.count(), 0);
  int64_t rows = 0, stored_words = 0;
  set.forEachRow([&](int32_t y, int32_t z, int64_t first, int64_t n, const uint64_t* words) {
    ++rows;
    stored_words += n;
    // Trimmed: the span starts and ends with a nonzero word, and matches the grid's row there.
    ASSERT_GT(n, 0);
    EXPECT_NE(words[0], 0u);
    EXPECT_NE(words[n - 1], 0u);
    for (int64_t w = 0; w < n; ++w) EXPECT_EQ(words[w], expected.rowWords(y, z)[first + w]);
  });
  EXPECT_EQ(rows, set.rows());
  int64_t nonzero_rows = 0;
  for (int32_t z = 0; z < d.nz; ++z)
    for (int32_t y = 0; y < d.ny; ++y) nonzero_rows += popcountWords(expected.rowWords(y, z), 3) > 0;
  EXPECT_EQ(rows, nonzero_rows);
  EXPECT_LT(stored_words, rows * expected.wordsPerRow());  // the one-word rows were trimmed
  const VoxelGrid grid = set.toGrid();
  EXPECT_EQ(grid.dims(), d);
  EXPECT_EQ(grid.frame(), frame);
  EXPECT_EQ(differences(grid, expected), 0);
  EXPECT_GE(set.memoryBytes(), size_t(stored_words + rows) * sizeof(uint64_t));
}

TEST(SparseVoxels, emptyRowsAndSetsAddNothing) {
  const Dims d{10, 4, 3};
  SparseVoxels::Chunk chunk;
  const uint64_t zeros[2] = {0, 0};
  chunk.addRow(1, 2, 0, 2, zeros);
  EXPECT_TRUE(chunk.empty());
  EXPECT_EQ(chunk.count(), 0);
  std::vector<SparseVoxels::Chunk> chunks;
  chunks.push_back(std::move(chunk));
  const SparseVoxels set(d, {}, std::move(chunks));
  EXPECT_TRUE(set.empty());
  EXPECT_EQ(set.rows(), 0);
  const VoxelGrid grid = set.toGrid();
  EXPECT_EQ(grid.filledCount(), 0);
  EXPECT_EQ(grid.allocatedLayers(), 0);
}

// The header's 16-bit fields at their largest (y, z up to VoxelGrid::kMaxDim - 1, a 257-word row), rows longer than
// the first small blocks, and many full blocks across several chunks.
TEST(SparseVoxels, largestRowsAndManyBlocksDecodeExactly) {
  const int32_t top = VoxelGrid::kMaxDim - 1;
  const int64_t wpr = (int64_t(VoxelGrid::kMaxDim) + 2 + 63) / 64;  // 257
  std::vector<uint64_t> row(static_cast<size_t>(wpr));
  for (int64_t w = 0; w < wpr; ++w) row[size_t(w)] = 0x9E3779B97F4A7C15ull * uint64_t(w + 1);
  row[0] &= ~uint64_t(1);                                                        // padding bit x = -1
  row[size_t(wpr) - 1] &= (uint64_t(1) << ((VoxelGrid::kMaxDim + 1) & 63)) - 1;  // bits past x = kMaxDim - 1
  int64_t expected_count = 0;
  for (uint64_t w : row) expected_count += popcount64(w);
  std::vector<SparseVoxels::Chunk> chunks(3);
  int64_t rows_added = 0;
  for (int32_t i = 0; i < 100; ++i) {  // 100 rows of 258 words: over three full blocks in each chunk
    for (size_t c = 0; c < chunks.size(); ++c) {
      chunks[c].addRow(top - i, top - int32_t(c), 0, wpr, row.data());
      ++rows_added;
    }
  }
  const Dims d{VoxelGrid::kMaxDim, VoxelGrid::kMaxDim, VoxelGrid::kMaxDim};
  const SparseVoxels set(d, {}, std::move(chunks));
  EXPECT_EQ(set.count(), expected_count * rows_added);
  int64_t rows = 0;
  set.forEachRow([&](int32_t y, int32_t z, int64_t first, int64_t n, const uint64_t* words) {
    EXPECT_GE(y, top - 99);
    EXPECT_LE(y, top);
    EXPECT_GE(z, top - 2);
    EXPECT_LE(z, top);
    ASSERT_EQ(first, 0);
    ASSERT_EQ(n, wpr);
    for (int64_t w = 0; w < n; ++w) ASSERT_EQ(words[w], row[size_t(w)]) << "word " << w;
    ++rows;
  });
  EXPECT_EQ(rows, rows_added);
  // Written words plus what the blocks leave unused: under maxBytes for the rows stored, plus 128 KiB per chunk.
  EXPECT_GE(set.memoryBytes(), size_t(rows_added * (wpr + 1)) * sizeof(uint64_t));
  EXPECT_LE(set.memoryBytes(), size_t(rows_added * (wpr + 1)) * sizeof(uint64_t) * 33 / 31 + 3 * (size_t(128) << 10));
}

TEST(SparseVoxels, maxBytesBoundsAFullSet) {
  const Dims d{200, 9, 4};  // 4 words per row
  VoxelGrid full(d);
  std::vector<SparseVoxels::Chunk> chunks(1);
  for (int32_t z = 0; z < d.nz; ++z) {
    for (int32_t y = 0; y < d.ny; ++y) {
      full.fillRun(y, z, 0, d.nx);
      chunks[0].addRow(y, z, 0, full.wordsPerRow(), full.rowWords(y, z));
    }
  }
  const SparseVoxels set(d, {}, std::move(chunks));
  EXPECT_EQ(set.count(), d.count());
  // Every row stored whole: a header word and four words per row, the most a set on these dims can hold.
  uint64_t stored = 0;
  set.forEachRow([&](int32_t, int32_t, int64_t, int64_t n, const uint64_t*) { stored += uint64_t(n + 1) * 8; });
  EXPECT_EQ(stored, uint64_t(d.ny) * uint64_t(d.nz) * 5 * 8);
  EXPECT_LE(set.memoryBytes(), SparseVoxels::maxBytes(d));
  EXPECT_EQ(differences(set.toGrid(), full), 0);
}

}  // namespace
}  // namespace vox
