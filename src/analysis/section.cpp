// Progressive sectional display (thesis 5.2.1, 6.3): planar sections normal to a coordinate axis.
// A Z section is one stored layer. For X and Y sections the thesis notes that "more recursions are required";
// here a Y section reads one row per layer (whole words, popcount) and an X section one word per row, so stepping
// a slider through a 1000^3 model touches about a million words per step at most.
#include <algorithm>
#include <bit>
#include <string>
#include <vector>

#include "analysis/layer_ops.h"
#include "vox/core/parallel.h"
#include "vox/analysis/analysis.h"

namespace vox {
namespace {

int32_t axisLength(const VoxelGrid& grid, Axis axis) {
  switch (axis) {
    case Axis::kX:
      return grid.nx();
    case Axis::kY:
      return grid.ny();
    case Axis::kZ:
      return grid.nz();
  }
  return 0;
}

}  // namespace

int64_t sectionCount(const VoxelGrid& grid, Axis axis, int32_t index) {
  if (index < 0 || index >= axisLength(grid, axis)) return 0;
  const int64_t wpr = grid.wordsPerRow();
  int64_t count = 0;
  switch (axis) {
    case Axis::kZ:
      if (!grid.layerAllocated(index)) return 0;
      return analysis_detail::popcountWords(grid.layerWords(index) + wpr, wpr * grid.ny());
    case Axis::kY:
      for (int32_t z = 0; z < grid.nz(); ++z) {
        if (grid.layerAllocated(z)) count += analysis_detail::popcountWords(grid.rowWords(index, z), wpr);
      }
      return count;
    case Axis::kX: {
      // One word per row, each in its own cache line: memory bound, so both cores help on large grids.
      const int64_t xp = int64_t(index) + 1;
      const int64_t word = xp >> 6;
      const int shift = int(xp & 63);
      const int threads = threadsFor(grid.allocatedLayers() * grid.ny());
      std::vector<int64_t> counts(static_cast<size_t>(threads), 0);
      parallelChunks(0, grid.nz(), 16, threads, [&](int t, int64_t z0, int64_t z1) {
        int64_t c = 0;
        for (int32_t z = int32_t(z0); z < int32_t(z1); ++z) {
          if (!grid.layerAllocated(z)) continue;
          const uint64_t* w = grid.layerWords(z) + wpr + word;  // row y = 0
          for (int32_t y = 0; y < grid.ny(); ++y, w += wpr) c += int64_t((*w >> shift) & 1);
        }
        counts[size_t(t)] += c;
      });
      for (int64_t c : counts) count += c;
      return count;
    }
  }
  return 0;
}

Result<Section> computeSection(const VoxelGrid& grid, const SectionParams& params) {
  const int32_t n = axisLength(grid, params.axis);
  if (grid.empty() || params.index < 0 || params.index >= n) {
    return makeError(ErrorCode::kInvalidArgument, std::string("section index ") + std::to_string(params.index) +
                                                      " is outside 0.." + std::to_string(n - 1) + " along " +
                                                      axisName(params.axis));
  }
  Section s;
  s.axis = params.axis;
  s.index = params.index;
  const int a = int(params.axis);
  s.position = grid.frame().origin[a] + (double(params.index) + 0.5) * grid.voxelSize();

  const int64_t wpr = grid.wordsPerRow();
  // Image rows run from the largest "up" index down (row 0 at the top).
  switch (params.axis) {
    case Axis::kZ: {  // x right, y up: one layer, decoded row by row
      s.mask = Image2D<uint8_t>(grid.nx(), grid.ny(), 0);
      if (!grid.layerAllocated(params.index)) break;
      for (int32_t y = 0; y < grid.ny(); ++y) {
        const uint64_t* row = grid.rowWords(y, params.index);
        uint8_t* out = &s.mask.at(0, grid.ny() - 1 - y);
        for (int64_t w = 0; w < wpr; ++w) {
          for (uint64_t bits = row[w]; bits; bits &= bits - 1) {
            const int64_t x = w * 64 + std::countr_zero(bits) - 1;
            out[x] = 1;
            ++s.filled;
          }
        }
      }
      break;
    }
    case Axis::kY: {  // x right, z up: one row per layer
      s.mask = Image2D<uint8_t>(grid.nx(), grid.nz(), 0);
      for (int32_t z = 0; z < grid.nz(); ++z) {
        if (!grid.layerAllocated(z)) continue;
        const uint64_t* row = grid.rowWords(params.index, z);
        uint8_t* out = &s.mask.at(0, grid.nz() - 1 - z);
        for (int64_t w = 0; w < wpr; ++w) {
          for (uint64_t bits = row[w]; bits; bits &= bits - 1) {
            out[w * 64 + std::countr_zero(bits) - 1] = 1;
            ++s.filled;
          }
        }
      }
      break;
    }
    case Axis::kX: {  // y right, z up: one bit of one word per row
      s.mask = Image2D<uint8_t>(grid.ny(), grid.nz(), 0);
      const int64_t xp = int64_t(params.index) + 1;
      const int shift = int(xp & 63);
      const int threads = threadsFor(grid.allocatedLayers() * grid.ny());
      std::vector<int64_t> counts(static_cast<size_t>(threads), 0);
      parallelChunks(0, grid.nz(), 16, threads, [&](int t, int64_t z0, int64_t z1) {
        int64_t c = 0;
        for (int32_t z = int32_t(z0); z < int32_t(z1); ++z) {
          if (!grid.layerAllocated(z)) continue;
          const uint64_t* w = grid.layerWords(z) + wpr + (xp >> 6);
          uint8_t* out = &s.mask.at(0, grid.nz() - 1 - z);
          for (int32_t y = 0; y < grid.ny(); ++y, w += wpr) {
            const uint8_t bit = uint8_t((*w >> shift) & 1);
            out[y] = bit;
            c += bit;
          }
        }
        counts[size_t(t)] += c;
      });
      for (int64_t c : counts) s.filled += c;
      break;
    }
  }
  return s;
}

Result<SectionAccumulator> SectionAccumulator::start(const Dims& dims, const GridFrame& frame,
                                                     const SectionParams& params) {
  // The checks, the position and the image's shape from a grid of these dims that holds no voxel (one shared zero
  // layer).
  auto empty = computeSection(VoxelGrid(dims, frame), params);
  if (!empty) return empty.error();
  SectionAccumulator acc;
  acc.dims_ = dims;
  acc.s_ = std::move(empty).value();
  return acc;
}

void SectionAccumulator::add(const VoxelGrid& window, int32_t z0, int32_t z1, int32_t z_offset) {
  if (s_.axis == Axis::kZ) {
    const int32_t z = s_.index - z_offset;
    if (z < z0 || z >= z1) return;
    auto part = computeSection(window, SectionParams{Axis::kZ, z});
    s_.mask = std::move(part->mask);
    s_.filled = part->filled;
    return;
  }
  // Sections along X and Y hold a row per layer: the window's rows go where their layers belong.
  auto part = computeSection(window, SectionParams{s_.axis, s_.index});
  for (int32_t z = z0; z < z1; ++z) {
    const uint8_t* from = &part->mask.at(0, window.nz() - 1 - z);
    std::copy_n(from, s_.mask.width, &s_.mask.at(0, dims_.nz - 1 - (z + z_offset)));
    s_.filled += std::count(from, from + s_.mask.width, uint8_t(1));
  }
}

}  // namespace vox
