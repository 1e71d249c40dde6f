#include "vox/core/sparse_voxels.h"

#include <algorithm>
#include <cassert>
#include <utility>

#include "vox/core/bits.h"

namespace vox {

void SparseVoxels::Chunk::addRow(int32_t y, int32_t z, int64_t first, int64_t n, const uint64_t* words) {
  while (n > 0 && words[0] == 0) {
    ++words;
    ++first;
    --n;
  }
  while (n > 0 && words[n - 1] == 0) --n;
  if (n == 0) return;
  assert(y >= 0 && z >= 0 && y < VoxelGrid::kMaxDim && z < VoxelGrid::kMaxDim && first >= 0 && first + n <= 0xFFFF);
  if (blocks_.empty() || blocks_.back().used + 1 + n > blocks_.back().capacity) {
    const int64_t capacity =
        std::max(1 + n, blocks_.empty() ? kFirstBlockWords : std::min(2 * blocks_.back().capacity, kBlockWords));
    // Not value-initialised: only the words written are ever read (and so faulted in).
    blocks_.push_back(Block{std::unique_ptr<uint64_t[]>(new uint64_t[size_t(capacity)]), 0, capacity});
  }
  Block& b = blocks_.back();
  uint64_t* out = b.words.get() + b.used;
  out[0] = uint64_t(uint16_t(y)) | uint64_t(uint16_t(z)) << 16 | uint64_t(first) << 32 | uint64_t(n) << 48;
  std::copy_n(words, n, out + 1);
  b.used += 1 + n;
  count_ += popcountWords(words, n);
}

SparseVoxels::SparseVoxels(Dims dims, GridFrame frame, std::vector<Chunk> chunks)
    : dims_(dims), frame_(std::move(frame)) {
  for (Chunk& c : chunks) {
    if (c.empty()) continue;
    count_ += c.count_;
    chunks_.push_back(std::move(c));
  }
}

SparseVoxels::SparseVoxels(SparseVoxels&&) noexcept = default;
SparseVoxels& SparseVoxels::operator=(SparseVoxels&&) noexcept = default;
SparseVoxels::~SparseVoxels() = default;

int64_t SparseVoxels::rows() const {
  int64_t n = 0;
  forEachRow([&](int32_t, int32_t, int64_t, int64_t, const uint64_t*) { ++n; });
  return n;
}

size_t SparseVoxels::memoryBytes() const {
  size_t bytes = sizeof(*this) + chunks_.capacity() * sizeof(Chunk);
  for (const Chunk& c : chunks_) {
    bytes += c.blocks_.capacity() * sizeof(Chunk::Block);
    for (const Chunk::Block& b : c.blocks_) bytes += size_t(b.capacity) * sizeof(uint64_t);
  }
  return bytes;
}

VoxelGrid SparseVoxels::toGrid() const {
  if (dims_.count() == 0) return VoxelGrid();
  VoxelGrid grid(dims_, frame_);
  forEachRow([&](int32_t y, int32_t z, int64_t first, int64_t n, const uint64_t* words) {
    std::copy_n(words, n, grid.mutableRowWords(y, z) + first);
  });
  return grid;
}

uint64_t SparseVoxels::maxBytes(const Dims& dims) {
  const uint64_t words_per_row = (uint64_t(dims.nx) + 2 + 63) / 64;
  const uint64_t words = uint64_t(dims.ny) * uint64_t(dims.nz) * (words_per_row + 1);
  // A block is left for the next only when a row (at most words_per_row + 1 words, at most 258) does not fit: at
  // most 1/31 of a full block (8192 words) is left unused.
  return (words + words / 31 + uint64_t(Chunk::kBlockWords)) * sizeof(uint64_t);
}

}  // namespace vox
