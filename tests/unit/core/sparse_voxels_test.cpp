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
