// OpenVDB export through libopenvdb. The trees are built a leaf node (8^3 voxels) at a time rather than a voxel at a
// time: each 8^3 block of the grid is read as 64 bytes (one per row of 8 voxels), a full block becomes an active
// tile, a partial one a leaf whose value mask is set from those bytes. Blocks are gathered in parallel, one slab of
// 8 layers per task, and added to the tree in order on the calling thread (a tree is not safe to grow from several
// threads).
#include "vox/io/vdb.h"

#include <algorithm>
#include <array>
#include <bit>
#include <exception>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <utility>

#include <oneapi/tbb/global_control.h>
#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>

#include "vox/core/parallel.h"

namespace vox::io {
namespace {

using Leaf = openvdb::FloatTree::LeafNodeType;
constexpr int32_t kBlock = 8;  // Leaf::DIM

static_assert(Leaf::DIM == kBlock, "an OpenVDB leaf node is 8^3 voxels");

void initializeOpenVdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

openvdb::math::Transform::Ptr transformOf(const GridFrame& frame) {
  auto t = openvdb::math::Transform::createLinearTransform(frame.voxel_size);
  const glm::dvec3 c = frame.voxelCentre(0, 0, 0);
  t->postTranslate(openvdb::Vec3d(c.x, c.y, c.z));
  return t;
}

// The 8 voxels x0 .. x0 + 7 of a row as the bits of a byte (x0 a multiple of 8; voxels past nx read as padding 0).
uint8_t rowByte(const VoxelGrid& grid, int32_t y, int32_t z, int32_t x0) {
  const uint64_t* row = grid.rowWords(y, z);
  const int64_t xp = int64_t(x0) + 1;
  const int64_t w = xp >> 6;
  const int s = int(xp & 63);
  uint64_t bits = row[w] >> s;
  if (s > 56 && w + 1 < grid.wordsPerRow()) bits |= row[w + 1] << (64 - s);
  return uint8_t(bits & 0xFF);
}

// What one slab of 8 layers adds to a tree: leaves (owned until added) and the origins of full blocks (tiles).
struct Slab {
  std::vector<std::unique_ptr<Leaf>> leaves;
  std::vector<openvdb::Coord> tiles;
};

// The voxels of the block at (x0, y0, z0) as a leaf, a tile, or nothing when it is empty.
void addVoxelBlock(const VoxelGrid& grid, int32_t x0, int32_t y0, int32_t z0, Slab& slab) {
  std::array<uint8_t, kBlock * kBlock> rows{};  // [dy * 8 + dz]: bit dx
  bool any = false, full = true;
  for (int32_t dy = 0; dy < kBlock; ++dy) {
    for (int32_t dz = 0; dz < kBlock; ++dz) {
      const int32_t y = y0 + dy, z = z0 + dz;
      const uint8_t b = (y < grid.ny() && z < grid.nz()) ? rowByte(grid, y, z, x0) : 0;
      rows[size_t(dy * kBlock + dz)] = b;
      any |= b != 0;
      full &= b == 0xFF;
    }
  }
  const openvdb::Coord origin(x0, y0, z0);
  if (full) {
    slab.tiles.push_back(origin);
  } else if (any) {
    auto leaf = std::make_unique<Leaf>(origin, 0.0f, false);
    for (int32_t i = 0; i < kBlock * kBlock; ++i) {
      for (uint32_t b = rows[size_t(i)]; b != 0; b &= b - 1) {
        const int dx = std::countr_zero(b);
        // A leaf's offset is x * 64 + y * 8 + z: here dx * 64 + (dy * 8 + dz).
        leaf->setValueOn(openvdb::Index(dx * 64 + i), 1.0f);
      }
    }
    slab.leaves.push_back(std::move(leaf));
  }
}

// The field's values in the block at (x0, y0, z0) as a leaf (active where not 0), or nothing when all are 0.
void addFieldBlock(const ScalarField& f, int32_t x0, int32_t y0, int32_t z0, Slab& slab) {
  std::unique_ptr<Leaf> leaf;
  const int32_t x1 = std::min(x0 + kBlock, f.dims.nx), y1 = std::min(y0 + kBlock, f.dims.ny),
                z1 = std::min(z0 + kBlock, f.dims.nz);
  for (int32_t z = z0; z < z1; ++z) {
    for (int32_t y = y0; y < y1; ++y) {
      for (int32_t x = x0; x < x1; ++x) {
        const float v = f.at(x, y, z);
        if (v == 0.0f) continue;
        if (!leaf) leaf = std::make_unique<Leaf>(openvdb::Coord(x0, y0, z0), 0.0f, false);
        leaf->setValueOn(openvdb::Index((x - x0) * 64 + (y - y0) * 8 + (z - z0)), v);
      }
    }
  }
  if (leaf) slab.leaves.push_back(std::move(leaf));
}

// A tree over `dims` built from its 8^3 blocks: `block(x0, y0, z0, slab)` adds each block's leaf or tile.
template <class BlockFn>
Status buildTree(openvdb::FloatTree& tree, const Dims& dims, const ProgressFn& progress, BlockFn block) {
  const int32_t slabs = (dims.nz + kBlock - 1) / kBlock;
  std::vector<Slab> built(static_cast<size_t>(slabs));
  forLayers(slabs, threadsFor(dims.count() / 64), [&](int, int32_t s) {
    for (int32_t y0 = 0; y0 < dims.ny; y0 += kBlock) {
      for (int32_t x0 = 0; x0 < dims.nx; x0 += kBlock) block(x0, y0, s * kBlock, built[size_t(s)]);
    }
  });
  for (int32_t s = 0; s < slabs; ++s) {
    Slab& slab = built[size_t(s)];
    for (std::unique_ptr<Leaf>& leaf : slab.leaves) tree.addLeaf(leaf.release());  // the tree owns it now
    // Level 1 is the node whose children are leaves: a tile there covers one leaf's 8^3 voxels.
    for (const openvdb::Coord& c : slab.tiles) tree.addTile(1, c, 1.0f, true);
    slab = Slab{};  // frees the emptied vectors
    if (progress && !progress(0.8 * double(s + 1) / slabs)) return makeError(ErrorCode::kCancelled, "cancelled");
  }
  return Ok{};
}

openvdb::FloatGrid::Ptr newGrid(const std::string& name, const Dims& dims, const GridFrame& frame) {
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->setName(name);
  grid->setTransform(transformOf(frame));
  grid->setCreator("voxmod");
  grid->insertMeta("units", openvdb::StringMetadata(frame.units));
  // A VDB grid is unbounded: the lattice it came from is recorded so that a reader knows the full extent.
  grid->insertMeta("dims", openvdb::Vec3IMetadata(openvdb::Vec3i(dims.nx, dims.ny, dims.nz)));
  return grid;
}

Result<openvdb::GridPtrVec> buildGrids(const VolumeContent& content, const ProgressFn& progress) {
  openvdb::GridPtrVec grids;
  const size_t volumes = (content.voxels ? 1 : 0) + content.fields.size();
  size_t done = 0;
  // Progress of the volume in hand, as a part of all of them.
  auto part = [&](double f) { return !progress || progress((double(done) + f) / double(volumes)); };
  if (content.voxels) {
    const VoxelGrid& g = *content.voxels;
    auto grid = newGrid("voxels", g.dims(), g.frame());
    grid->setGridClass(openvdb::GRID_FOG_VOLUME);
    auto block = [&](int32_t x0, int32_t y0, int32_t z0, Slab& s) { addVoxelBlock(g, x0, y0, z0, s); };
    if (Status s = buildTree(grid->tree(), g.dims(), part, block); !s) return s.error();
    grids.push_back(grid);
    ++done;
  }
  for (const NamedField& nf : content.fields) {
    const ScalarField& f = *nf.field;
    auto grid = newGrid(nf.name, f.dims, f.frame);
    auto block = [&](int32_t x0, int32_t y0, int32_t z0, Slab& s) { addFieldBlock(f, x0, y0, z0, s); };
    if (Status s = buildTree(grid->tree(), f.dims, part, block); !s) return s.error();
    grids.push_back(grid);
    ++done;
  }
  return grids;
}

}  // namespace

Result<std::vector<uint8_t>> encodeVdb(const VolumeContent& content, const ProgressFn& progress) {
  if (const std::string why = volumeContentProblem(content, VolumeFormat::kVdb); !why.empty()) {
    return makeError(ErrorCode::kInvalidArgument, why);
  }
  try {
    // OpenVDB runs some of its work as TBB tasks (the file's statistics, freeing a tree). Here they stay on the
    // calling thread: the trees are built in parallel above, the window already runs the export as a background job
    // beside its own threads, and the thread sanitizer cannot follow TBB's synchronisation between its workers.
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    initializeOpenVdb();
    auto grids = buildGrids(content, progress);
    if (!grids) return grids.error();
    std::ostringstream out(std::ios_base::binary);
    openvdb::MetaMap file_meta;
    file_meta.insertMeta("creator", openvdb::StringMetadata("voxmod"));
    openvdb::io::Stream(out).write(*grids, file_meta);
    if (!out) return makeError(ErrorCode::kIo, "OpenVDB: the file could not be written to memory");
    std::string bytes = std::move(out).str();
    if (progress && !progress(1.0)) return makeError(ErrorCode::kCancelled, "cancelled");
    return std::vector<uint8_t>(bytes.begin(), bytes.end());
  } catch (const std::bad_alloc&) {
    return makeError(ErrorCode::kLimit, "OpenVDB: out of memory building the volume");
  } catch (const std::exception& e) {  // openvdb::Exception and what the standard library throws through it
    return makeError(ErrorCode::kIo, std::string("OpenVDB: ") + e.what());
  }
}

}  // namespace vox::io
