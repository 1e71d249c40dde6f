// Surface-voxel point sets for the renderer (thesis 5.1: surface voxels and their neighbour codes; thesis 6.2:
// voxels displayed as points, and its closing remark on a "display list" of visible voxels). Extraction runs on
// whole 64-bit row words (vox/core/surface.h); here the points are packed, sliced per Z layer and grouped by code.
#include "vox/render/point_cloud.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstddef>
#include <cmath>
#include <limits>
#include <thread>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "vox/core/surface.h"

namespace vox::render {

LayerSlice extractLayer(const VoxelGrid& grid, int32_t z) {
  LayerSlice slice;
  std::array<uint32_t, kCodeGroups> counts{};
  std::vector<PackedPoint> unsorted;
  forEachSurfaceVoxel(
      grid,
      [&](int32_t x, int32_t y, int32_t zz, uint8_t code) {
        unsorted.push_back({uint16_t(x), uint16_t(y), uint16_t(zz), code, 0});
        ++counts[code];
      },
      z, z + 1);
  // Counting sort by code keeps z, y, x order inside each group (the extraction order).
  slice.group_first[0] = 0;
  for (size_t c = 0; c < size_t(kCodeGroups); ++c) slice.group_first[c + 1] = slice.group_first[c] + counts[c];
  std::array<uint32_t, kCodeGroups> next{};
  std::copy(slice.group_first.begin(), slice.group_first.end() - 1, next.begin());
  slice.points.resize(unsorted.size());
  for (const PackedPoint& p : unsorted) slice.points[next[p.code]++] = p;
  return slice;
}

void PointCloud::build(const VoxelGrid& grid, int threads) {
  dims_ = grid.dims();
  layers_.assign(size_t(grid.nz()), LayerSlice{});
  unsigned n_threads = threads > 0 ? unsigned(threads) : std::max(1u, std::thread::hardware_concurrency());
  n_threads = std::min<unsigned>(n_threads, unsigned(std::max(1, grid.nz())));
  // Layers are handed out one at a time: their cost varies a lot (empty layers are skipped by the extractor).
  std::atomic<int32_t> next_layer{0};
  auto work = [&] {
    for (int32_t z = next_layer++; z < grid.nz(); z = next_layer++) layers_[size_t(z)] = extractLayer(grid, z);
  };
  if (n_threads <= 1) {
    work();
  } else {
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < n_threads; ++t) pool.emplace_back(work);
    work();
    for (auto& t : pool) t.join();
  }
  recount();
}

void PointCloud::rebuildLayers(const VoxelGrid& grid, int32_t z0, int32_t z1) {
  if (layers_.empty() || grid.dims() != dims_) {
    build(grid);
    return;
  }
  // A voxel's code reads its z-1 and z+1 neighbours, so the layers just outside the edit change too.
  const int32_t lo = std::max(0, z0 - 1), hi = std::min(grid.nz(), z1 + 1);
  for (int32_t z = lo; z < hi; ++z) layers_[size_t(z)] = extractLayer(grid, z);
  recount();
}

void PointCloud::recount() {
  group_totals_.fill(0);
  total_ = 0;
  for (const LayerSlice& s : layers_) {
    for (int c = 0; c < kCodeGroups; ++c) group_totals_[size_t(c)] += s.groupSize(c);
    total_ += int64_t(s.points.size());
  }
  ++version_;
}

void PointCloud::assemble(PointBuffer& out) const {
  out.points.resize(size_t(total_));
  out.group_first[0] = 0;
  size_t pos = 0;
  for (int c = 0; c < kCodeGroups; ++c) {
    for (const LayerSlice& s : layers_) {
      const uint32_t n = s.groupSize(c);
      if (n == 0) continue;
      std::copy_n(s.points.begin() + s.group_first[size_t(c)], n, out.points.begin() + std::ptrdiff_t(pos));
      pos += n;
    }
    out.group_first[size_t(c) + 1] = int64_t(pos);
  }
}

Box3 PointCloud::bounds() const { return bounds(CutAway{}); }

Box3 PointCloud::bounds(const CutAway& section) const {
  glm::ivec3 lo(std::numeric_limits<int32_t>::max()), hi(std::numeric_limits<int32_t>::min());
  const SectionPlane plane = sectionPlane(section);
  for (const LayerSlice& s : layers_) {
    for (const PackedPoint& p : s.points) {
      const glm::ivec3 v(p.x, p.y, p.z);
      if (section.active() && sectionSlab(plane, v) != 0 && !keepsPoint(section, v)) continue;
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
  }
  if (lo.x > hi.x) {
    if (section.active()) return bounds();
    return Box3{glm::dvec3(0.0), glm::dvec3(dims_.nx, dims_.ny, dims_.nz)};
  }
  return Box3{glm::dvec3(lo), glm::dvec3(hi) + 1.0};
}

std::array<bool, 6> visibleFaceDirections(const Camera& camera, const Box3& box) {
  std::array<bool, 6> visible{};
  if (camera.projection == Projection::kOrthographic) {
    const glm::dvec3 to_eye = camera.eyeDirection();
    for (size_t f = 0; f < 6; ++f) {
      const glm::dvec3 n(kFaceNormals[f][0], kFaceNormals[f][1], kFaceNormals[f][2]);
      visible[f] = glm::dot(n, to_eye) > 1e-12;
    }
    return visible;
  }
  // A face with normal +X of a voxel inside the box lies on a plane x = c, box.min.x < c <= box.max.x; some such face
  // is in front of the eye when eye.x > box.min.x. Likewise for the other five directions.
  const glm::dvec3 eye = camera.eyePosition();
  for (size_t f = 0; f < 6; ++f) {
    for (int a = 0; a < 3; ++a) {
      const int n = kFaceNormals[f][size_t(a)];
      if (n > 0) visible[f] = eye[a] > box.min[a];
      if (n < 0) visible[f] = eye[a] < box.max[a];
    }
  }
  return visible;
}

std::array<bool, kCodeGroups> visibleCodes(const std::array<bool, 6>& visible_directions) {
  std::array<bool, kCodeGroups> v{};
  for (int c = 0; c < 63; ++c) {
    for (size_t f = 0; f < 6; ++f) {
      if (!(uint8_t(c) & kFaceBits[f]) && visible_directions[f]) v[size_t(c)] = true;
    }
  }
  return v;
}

SectionPlane sectionPlane(const CutAway& section, int level) {
  if (section.axis == SectionAxis::kPlane) {
    return sectionPlaneOf(section.normal, section.offset / float(int64_t(1) << level));
  }
  SectionPlane p;
  if (section.active()) {
    const int axis = int(section.axis) - 1;
    p.normal = glm::vec3(0.0f);
    p.normal[axis] = 1.0f;
    p.offset = float(section.index >> level) + 0.5f;
  }
  return p;
}

bool keepsPoint(const CutAway& section, const glm::ivec3& voxel) {
  if (!section.active()) return true;
  const int slab = sectionSlab(sectionPlane(section), voxel);
  return section.side == SectionSide::kBelow ? slab < 0 : slab > 0;
}

namespace {

// The filled voxels of a plane's slab: along the normal's largest component, each line of voxels crosses the slab in
// at most a few voxels, found from the plane's equation and checked by sectionSlab.
template <class Add>
void slabVoxels(const VoxelGrid& grid, const SectionPlane& p, Add add) {
  const int a = dominantAxis(p.normal);
  const int b = (a + 1) % 3, c = (a + 2) % 3;
  if (!(std::abs(p.normal[a]) > 0.0f) || !std::isfinite(p.normal[a]) || !std::isfinite(p.offset)) return;
  const glm::ivec3 dims(grid.nx(), grid.ny(), grid.nz());
  for (int32_t vc = 0; vc < dims[c]; ++vc) {
    if (c == 2 && !grid.layerAllocated(vc)) continue;
    for (int32_t vb = 0; vb < dims[b]; ++vb) {
      const float rest = p.normal[b] * (float(vb) + 0.5f) + p.normal[c] * (float(vc) + 0.5f) - p.offset;
      float lo = (-p.half - rest) / p.normal[a] - 0.5f, hi = (p.half - rest) / p.normal[a] - 0.5f;
      if (lo > hi) std::swap(lo, hi);
      // clamped as floats first: a plane far outside the grid gives bounds no int32 holds
      const int32_t from = int32_t(std::clamp(std::floor(lo) - 1.0f, 0.0f, float(dims[a])));
      const int32_t to = int32_t(std::clamp(std::ceil(hi) + 1.0f, -1.0f, float(dims[a] - 1)));
      glm::ivec3 v;
      v[b] = vb;
      v[c] = vc;
      for (v[a] = from; v[a] <= to; ++v[a]) {
        if (sectionSlab(p, v) == 0 && grid.get(v.x, v.y, v.z)) add(v.x, v.y, v.z);
      }
    }
  }
}

}  // namespace

std::vector<PackedPoint> sectionPoints(const VoxelGrid& grid, const CutAway& section) {
  std::vector<PackedPoint> out;
  if (!section.active() || grid.empty()) return out;
  const int32_t i = section.index;
  auto add = [&](int64_t x, int64_t y, int64_t z) {
    out.push_back({uint16_t(x), uint16_t(y), uint16_t(z), grid.neighbourCode(x, y, z), kPointFlagCut});
  };
  // Visits the filled voxels of row (y, z) by its words.
  auto row = [&](int32_t y, int32_t z) {
    const uint64_t* w = grid.rowWords(y, z);
    for (int64_t k = 0; k < grid.wordsPerRow(); ++k) {
      for (uint64_t bits = w[k]; bits; bits &= bits - 1) add(k * 64 + std::countr_zero(bits) - 1, y, z);
    }
  };
  switch (section.axis) {
    case SectionAxis::kX:
      if (i < 0 || i >= grid.nx()) break;
      for (int32_t z = 0; z < grid.nz(); ++z) {
        if (!grid.layerAllocated(z)) continue;
        for (int32_t y = 0; y < grid.ny(); ++y) {
          if (grid.get(i, y, z)) add(i, y, z);
        }
      }
      break;
    case SectionAxis::kY:
      if (i < 0 || i >= grid.ny()) break;
      for (int32_t z = 0; z < grid.nz(); ++z) {
        if (grid.layerAllocated(z)) row(i, z);
      }
      break;
    case SectionAxis::kZ:
      if (i < 0 || i >= grid.nz() || !grid.layerAllocated(i)) break;
      for (int32_t y = 0; y < grid.ny(); ++y) row(y, i);
      break;
    case SectionAxis::kPlane:
      slabVoxels(grid, sectionPlane(section), add);
      break;
    case SectionAxis::kNone:
      break;
  }
  return out;
}

namespace {

// Gathers the even bits of x into its low 32 bits (bit 2i -> bit i).
uint64_t compactEvenBits(uint64_t x) {
  x &= 0x5555555555555555ull;
  x = (x | (x >> 1)) & 0x3333333333333333ull;
  x = (x | (x >> 2)) & 0x0F0F0F0F0F0F0F0Full;
  x = (x | (x >> 4)) & 0x00FF00FF00FF00FFull;
  x = (x | (x >> 8)) & 0x0000FFFF0000FFFFull;
  x = (x | (x >> 16)) & 0x00000000FFFFFFFFull;
  return x;
}

Dims halfDims(const Dims& d) { return {(d.nx + 1) / 2, (d.ny + 1) / 2, (d.nz + 1) / 2}; }

}  // namespace

void downsample2Layers(const VoxelGrid& fine, VoxelGrid& coarse, int32_t z0, int32_t z1) {
  const int64_t fine_words = fine.wordsPerRow(), coarse_words = coarse.wordsPerRow();
  std::vector<uint64_t> merged(static_cast<size_t>(fine_words)), out(static_cast<size_t>(coarse_words));
  z0 = std::max(0, z0);
  z1 = std::min(coarse.nz(), z1);
  for (int32_t cz = z0; cz < z1; ++cz) {
    if (coarse.layerAllocated(cz)) {
      uint64_t* layer = coarse.mutableLayerWords(cz);
      std::fill_n(layer, coarse.wordsPerLayer(), 0);
    }
    const int32_t fz = 2 * cz;  // fz + 1 may be nz: the padding layer, which reads as empty
    if (!fine.layerAllocated(fz) && (fz + 1 >= fine.nz() || !fine.layerAllocated(fz + 1))) continue;
    for (int32_t cy = 0; cy < coarse.ny(); ++cy) {
      const int32_t fy = 2 * cy;  // fy + 1 may be ny: a padding row
      const uint64_t* r[4] = {fine.rowWords(fy, fz), fine.rowWords(fy + 1, fz), fine.rowWords(fy, fz + 1),
                              fine.rowWords(fy + 1, fz + 1)};
      uint64_t any = 0;
      for (int64_t w = 0; w < fine_words; ++w) {
        merged[size_t(w)] = r[0][w] | r[1][w] | r[2][w] | r[3][w];
        any |= merged[size_t(w)];
      }
      if (!any) continue;
      std::fill(out.begin(), out.end(), 0);
      for (int64_t k = 0; k < fine_words; ++k) {
        // Fine voxels x = 64k .. 64k + 63 (unpadded), then pairs OR-ed and packed: coarse x = 32k .. 32k + 31.
        const uint64_t next = k + 1 < fine_words ? merged[size_t(k) + 1] : 0;
        const uint64_t u = (merged[size_t(k)] >> 1) | (next << 63);
        const uint64_t half = compactEvenBits(u | (u >> 1));
        if (!half) continue;
        const int64_t bit = 32 * k + 1;  // padded position of coarse x = 32k
        const int64_t word = bit >> 6, shift = bit & 63;
        out[size_t(word)] |= half << shift;
        // Bits that spill over belong to real voxels (x < nx), so the next word exists whenever they are set.
        if (shift + 32 > 64 && (half >> (64 - shift)) != 0) out[size_t(word) + 1] |= half >> (64 - shift);
      }
      uint64_t* dst = coarse.mutableRowWords(cy, cz);
      std::copy(out.begin(), out.end(), dst);
    }
  }
}

VoxelGrid downsample2(const VoxelGrid& fine) {
  GridFrame frame = fine.frame();
  frame.voxel_size *= 2.0;
  VoxelGrid coarse(halfDims(fine.dims()), frame);
  downsample2Layers(fine, coarse, 0, coarse.nz());
  return coarse;
}

}  // namespace vox::render
