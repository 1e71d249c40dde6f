#pragma once
// A sparse set of voxels on a grid's dims and frame, kept as the rows that hold any: for each such row, its words
// from the first nonzero one to the last, in VoxelGrid's padded row layout (bit xp & 63 of word xp >> 6, xp = x + 1).
// For sets that touch a few words of each of many rows, such as vote mode's disputed voxels: a VoxelGrid holding them
// would fault in a page (4 KiB, 32 rows of a 1000-voxel grid) for every few words, and the voxelizer would pay for
// pages it barely uses. Here a row costs one header word plus its span, written one after another.
//
// Built in chunks, each appended to by one thread (one per slab of layers, say) and then handed over; chunks may hold
// rows in any order, and a set's rows must be distinct. toGrid() expands the set into a VoxelGrid for the renderer
// or a voxel file.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "vox/core/voxel_grid.h"

namespace vox {

class SparseVoxels {
 public:
  // Rows appended by one thread. Aligned to a cache line: the chunks of a vector are written by different threads.
  class alignas(64) Chunk {
   public:
    // Adds row (y, z) (0 <= y < ny, 0 <= z < nz): `n` words starting at word `first` of the padded row, in the
    // grid's row layout, padding bits zero. Zero words at either end are trimmed; an all-zero row adds nothing.
    void addRow(int32_t y, int32_t z, int64_t first, int64_t n, const uint64_t* words);
    int64_t count() const { return count_; }
    bool empty() const { return blocks_.empty(); }

   private:
    friend class SparseVoxels;
    // Rows go into blocks, a row never straddling two, so a full block is never copied (as a growing array's
    // would be) and a block's pages are faulted in only as rows are written. Blocks double from kFirstBlockWords
    // words up to kBlockWords (so a small set stays small). Per row: a header word (y, z, first word, word count,
    // 16 bits each from the low end), then the words.
    static constexpr int64_t kFirstBlockWords = 64, kBlockWords = 8192;
    struct Block {
      std::unique_ptr<uint64_t[]> words;  // `capacity` words, written up to `used`
      int64_t used = 0, capacity = 0;
    };
    std::vector<Block> blocks_;
    int64_t count_ = 0;  // voxels
  };

  SparseVoxels() = default;
  // The set of the voxels in `chunks`, on a grid of these dims and frame (dims as VoxelGrid's).
  SparseVoxels(Dims dims, GridFrame frame, std::vector<Chunk> chunks);
  // Move-only. Out of line: inlined into moves of a std::optional inside a std::variant (a Result), GCC 12 warns
  // that the members may be used uninitialized.
  SparseVoxels(SparseVoxels&&) noexcept;
  SparseVoxels& operator=(SparseVoxels&&) noexcept;
  ~SparseVoxels();

  const Dims& dims() const { return dims_; }
  const GridFrame& frame() const { return frame_; }
  // Number of voxels in the set.
  int64_t count() const { return count_; }
  bool empty() const { return count_ == 0; }
  // Rows holding a voxel.
  int64_t rows() const;
  // Bytes held (the chunks' storage and bookkeeping).
  size_t memoryBytes() const;
  // A grid of the same dims and frame holding exactly these voxels (an empty VoxelGrid for a default-constructed set).
  VoxelGrid toGrid() const;
  // Calls f(y, z, first, n, words) for every stored row: n words of the padded row from word `first`.
  template <class F>
  void forEachRow(F&& f) const {
    for (const Chunk& c : chunks_) {
      for (const Chunk::Block& b : c.blocks_) {
        const uint64_t* p = b.words.get();
        const uint64_t* const end = p + b.used;
        while (p != end) {
          const uint64_t h = *p++;
          const int64_t n = int64_t(h >> 48);
          f(int32_t(h & 0xFFFF), int32_t((h >> 16) & 0xFFFF), int64_t((h >> 32) & 0xFFFF), n, p);
          p += n;
        }
      }
    }
  }
  // About the most bytes a set on a grid of these dims takes, for refusing before allocating: every row stored whole
  // (its header word and the words of a padded row) and the ends of full blocks a row did not fit. Each chunk's
  // blocks smaller than a full one, and the unused end of its last block, add at most 128 KiB per chunk, which is
  // not counted: those ends are never written, so never faulted in.
  static uint64_t maxBytes(const Dims& dims);

 private:
  Dims dims_{};
  GridFrame frame_{};
  std::vector<Chunk> chunks_;
  int64_t count_ = 0;
};

}  // namespace vox
