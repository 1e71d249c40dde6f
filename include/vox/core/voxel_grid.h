#pragma once
// The binary voxel grid of thesis section 4.2.1: a stack of Z "planes", each a bit array with one empty padding
// voxel on every side, plus one empty plane below and above, so neighbour look-ups never branch at borders.
//
// Layout (docs/architecture.md has a picture):
//  - voxel coordinates (x, y, z): 0 <= x < nx, 0 <= y < ny, 0 <= z < nz. Files, images and the CLI use these.
//  - padded coordinates: xp = x + 1, yp = y + 1, zp = z + 1. A layer holds (ny + 2) rows; a row holds nx + 2 bits
//    packed in wordsPerRow() 64-bit words, bit (xp & 63) of word (xp >> 6), least significant bit first.
//    Padding bits, rows and layers are always zero. Layers zp = 0 and zp = nz + 1 are padding.
//  - Layers are shared, copy-on-write: copying a VoxelGrid copies a vector of pointers (an undo snapshot or a
//    copy for a background thread costs O(nz)). A layer with no filled voxel may point at one shared zero layer,
//    so layers exist only for the Z range the model occupies.
//  - 64-bit indices throughout: 4096^3 (and more) does not overflow.
//
// Thread safety: const member functions may be called concurrently. Mutating different layers (different z) of
// one grid from different threads is allowed (the voxelizer does it); mutating the same layer is not.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

namespace vox {

struct Dims {
  int32_t nx = 0, ny = 0, nz = 0;
  int64_t count() const { return int64_t(nx) * ny * nz; }
  bool operator==(const Dims&) const = default;
};

// Where the grid sits in model space (docs/conventions.md, "Grid placement"): the centre of voxel (i, j, k) is
// origin + ((i + 0.5) * voxel_size, (j + 0.5) * voxel_size, (k + 0.5) * voxel_size).
struct GridFrame {
  glm::dvec3 origin{0.0};
  double voxel_size = 1.0;
  std::string units = "model";  // STL has no units; "mm", "in", ... when the user says so
  std::string source;           // name of the file the grid came from (mesh or voxel file), may be empty
  bool operator==(const GridFrame&) const = default;

  glm::dvec3 voxelCentre(int64_t i, int64_t j, int64_t k) const {
    return origin +
           glm::dvec3((double(i) + 0.5) * voxel_size, (double(j) + 0.5) * voxel_size, (double(k) + 0.5) * voxel_size);
  }
};

// The six face directions, in the thesis's neighbour order 1..6 (docs/conventions.md, "Face-neighbour code").
enum class Direction : uint8_t { kYMinus = 0, kXMinus, kXPlus, kYPlus, kZMinus, kZPlus };
glm::ivec3 directionStep(Direction d);

class VoxelGrid {
 public:
  // Largest dimension on any axis. Renderer packing uses 16-bit coordinates; 4096 is the product's ceiling for
  // voxelization, 16384 leaves room for grids read from files.
  static constexpr int32_t kMaxDim = 16384;

  VoxelGrid() = default;
  // An empty grid. dims must each lie in [1, kMaxDim] (asserted; callers validate untrusted sizes first, e.g.
  // with estimateGridBytes()). Allocates only the shared zero layer.
  explicit VoxelGrid(Dims dims, GridFrame frame = {});

  const Dims& dims() const { return dims_; }
  int32_t nx() const { return dims_.nx; }
  int32_t ny() const { return dims_.ny; }
  int32_t nz() const { return dims_.nz; }
  const GridFrame& frame() const { return frame_; }
  GridFrame& frame() { return frame_; }
  double voxelSize() const { return frame_.voxel_size; }
  bool empty() const { return dims_.count() == 0; }

  bool inBounds(int64_t x, int64_t y, int64_t z) const {
    return x >= 0 && y >= 0 && z >= 0 && x < dims_.nx && y < dims_.ny && z < dims_.nz;
  }
  // Linear index of a voxel: x fastest, then y, then z (x + nx * (y + ny * z)), 64-bit.
  int64_t index(int64_t x, int64_t y, int64_t z) const { return x + int64_t(dims_.nx) * (y + int64_t(dims_.ny) * z); }
  glm::ivec3 coordinates(int64_t index) const;

  // Read a voxel. Coordinates may lie one outside the grid on any axis (the padding), which reads as empty.
  bool get(int64_t x, int64_t y, int64_t z) const {
    const uint64_t* row = rowWords(int32_t(y), int32_t(z));
    const int64_t xp = x + 1;
    return (row[xp >> 6] >> (xp & 63)) & 1u;
  }
  // Set or reset a voxel inside the grid (asserted). Copies the layer first if it is shared.
  void set(int64_t x, int64_t y, int64_t z, bool filled = true);
  void reset(int64_t x, int64_t y, int64_t z) { set(x, y, z, false); }
  // Fill voxels x0 <= x < x1 of row (y, z) with word operations (clamped to [0, nx)).
  void fillRun(int32_t y, int32_t z, int64_t x0, int64_t x1);

  // Face-neighbour code (docs/conventions.md, "Face-neighbour code"): bit 32 y-1, 16 x-1, 8 x+1, 4 y+1, 2 z-1, 1 z+1,
  // set where that neighbour is filled. 63 = interior. Meaningful for filled voxels; x, y, z inside the grid.
  uint8_t neighbourCode(int64_t x, int64_t y, int64_t z) const;

  // The voxel `distance` steps from (x, y, z) along d, or nullopt when that lies outside the grid.
  std::optional<glm::ivec3> neighbourAt(glm::ivec3 voxel, Direction d, int32_t distance = 1) const;

  // Remove every voxel (thesis: "delete entire voxel body"). Keeps dims and frame; frees the layers.
  void clear();
  // Number of filled voxels (popcount over the allocated layers). O(allocated words).
  int64_t filledCount() const;
  // Bytes held by this grid's layers plus bookkeeping (a layer shared with a copy counts in both).
  size_t memoryBytes() const;
  // Layers with storage of their own (not the shared zero layer).
  int64_t allocatedLayers() const;
  // Return all-zero layers to the shared zero layer (after removal operations). O(allocated words).
  void releaseEmptyLayers();
  // Return layer z (0 <= z < nz) to the shared zero layer, emptying it; its storage is freed unless a copy shares it.
  void releaseLayer(int32_t z);

  // ---- Word-level access for bulk algorithms (surface extraction, voxelizer, I/O). ----
  int64_t wordsPerRow() const { return words_per_row_; }
  int64_t wordsPerLayer() const { return words_per_row_ * (int64_t(dims_.ny) + 2); }
  // Row y (-1..ny) of layer z (-1..nz), wordsPerRow() words. Never null: padding rows and unallocated layers
  // read as zeros.
  const uint64_t* rowWords(int32_t y, int32_t z) const {
    return layers_[size_t(z + 1)]->data() + (int64_t(y) + 1) * words_per_row_;
  }
  // Mutable row (0 <= y < ny, 0 <= z < nz). Copies the layer if shared. The caller keeps padding bits zero.
  uint64_t* mutableRowWords(int32_t y, int32_t z);
  // Whole layer z (-1..nz) as wordsPerLayer() words, row yp = y + 1 at offset yp * wordsPerRow().
  const uint64_t* layerWords(int32_t z) const { return layers_[size_t(z + 1)]->data(); }
  uint64_t* mutableLayerWords(int32_t z);
  // Layer z (0 <= z < nz) replaced by a new all-zero layer of its own, nothing copied (for writers that set every
  // word: a copy on write would be wasted).
  uint64_t* freshLayerWords(int32_t z);
  bool layerAllocated(int32_t z) const { return layers_[size_t(z + 1)] != zero_layer_; }
  // True when layer z shares storage with `other`'s layer z (both snapshots of the same data).
  bool sharesLayerWith(const VoxelGrid& other, int32_t z) const;
  // True when `other` has the same dims and the same filled voxels (frames are not compared): O(1) a layer the two
  // share, O(words) one they do not.
  bool sameVoxels(const VoxelGrid& other) const;
  // Makes layer z (0 <= z < nz) share `other`'s layer z (copy on write, O(1)); the grids must have the same dims.
  void shareLayerFrom(const VoxelGrid& other, int32_t z);

 private:
  // Layer storage (core/voxel_grid.cpp, layer memory): a layer made for a writer that may leave words untouched comes
  // from calloc and is not written when allocated: memory fresh from the system is already zero, so its pages are
  // only faulted in where something is written (a sparse layer touches few of them). A layer every word of which is
  // written (freshLayerWords, a copy on write) reuses, where it can, the storage of such a layer of the same size
  // freed before: a bounded pool keeps them so that an operation producing a whole grid (a Boolean) does not fault
  // in fresh pages each time. Layers from calloc go back to the system when freed, so that a sparse or streamed
  // grid's memory is not held.
  enum class LayerFill { kSparseZero, kDenseZero, kOverwritten };
  static uint64_t* allocateLayerWords(size_t words, LayerFill fill);
  static void releaseLayerWords(uint64_t* p, size_t words, LayerFill fill);
  template <class T>
  struct LayerAllocator {
    using value_type = T;
    LayerFill fill = LayerFill::kSparseZero;
    LayerAllocator() = default;
    explicit LayerAllocator(LayerFill f) : fill(f) {}
    template <class U>
    LayerAllocator(const LayerAllocator<U>& o) : fill(o.fill) {}  // NOLINT(google-explicit-constructor): rebinding
    T* allocate(size_t n) {
      static_assert(sizeof(T) == sizeof(uint64_t));
      return reinterpret_cast<T*>(allocateLayerWords(n, fill));
    }
    void deallocate(T* p, size_t n) { releaseLayerWords(reinterpret_cast<uint64_t*>(p), n, fill); }
    // A copy writes every word: its storage need not be zeroed first.
    LayerAllocator select_on_container_copy_construction() const { return LayerAllocator(LayerFill::kOverwritten); }
    // Value-initialising a word writes nothing: the storage is already zero.
    template <class U>
    void construct(U* p) noexcept {
      ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
      ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
    bool operator==(const LayerAllocator&) const { return true; }  // any of them frees what another allocated
  };
  using Layer = std::vector<uint64_t, LayerAllocator<uint64_t>>;
  Dims dims_{};
  GridFrame frame_{};
  int64_t words_per_row_ = 0;
  std::shared_ptr<Layer> zero_layer_;
  std::vector<std::shared_ptr<Layer>> layers_;  // nz + 2 entries, padding layers first and last
};

// Memory a grid of these dims needs with every layer allocated, in bytes (for refusing before allocating).
uint64_t estimateGridBytes(const Dims& dims);

// Cell distance between two voxels: the number of face steps (L1 / Manhattan distance), and the largest
// per-axis difference (Chebyshev distance).
int64_t cellDistance(const glm::ivec3& a, const glm::ivec3& b);
int64_t chebyshevDistance(const glm::ivec3& a, const glm::ivec3& b);

}  // namespace vox
