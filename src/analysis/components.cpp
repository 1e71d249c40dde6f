// Connected components of a voxel model: the filled voxels of each row form runs; union-find joins a run with the runs
// it touches in the rows already seen (the row below, the layer below, and for 26-connectivity the diagonal rows of
// the layer below), so the work is O(words + runs), not O(voxels).
#include <algorithm>
#include <bit>
#include <numeric>

#include <glm/common.hpp>

#include "vox/analysis/assembly.h"

namespace vox {
namespace {

using Run = Components::Run;

// Appends the runs of filled voxels of padded row `row` (wpr words) as [x0, x1) in voxel coordinates.
void appendRowRuns(const uint64_t* row, int64_t wpr, int32_t y, int32_t z, std::vector<Run>& out) {
  uint64_t carry = 0;  // the previous word's last bit, as bit 0
  int64_t start = -1;
  for (int64_t w = 0; w < wpr; ++w) {
    const uint64_t v = row[w];
    uint64_t t = v ^ ((v << 1) | carry);  // bits where filled/empty changes from the voxel before
    carry = v >> 63;
    while (t != 0) {
      const int64_t xp = w * 64 + std::countr_zero(t);
      t &= t - 1;
      if (start < 0) {
        start = xp;
      } else {
        out.push_back(Run{y, z, int32_t(start - 1), int32_t(xp - 1)});
        start = -1;
      }
    }
  }
}

struct UnionFind {
  std::vector<uint32_t> parent;
  uint32_t find(uint32_t v) {
    while (parent[v] != v) {
      parent[v] = parent[parent[v]];
      v = parent[v];
    }
    return v;
  }
  void join(uint32_t a, uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

// Joins every run of [a0, a1) with the runs of [b0, b1) it touches (x ranges overlapping, or within `reach` voxels).
void joinTouching(const std::vector<Run>& runs, size_t a0, size_t a1, size_t b0, size_t b1, int32_t reach,
                  UnionFind& uf) {
  size_t j = b0;
  for (size_t i = a0; i < a1; ++i) {
    while (j < b1 && runs[j].x1 + reach <= runs[i].x0) ++j;  // b runs wholly before run i never touch later runs
    for (size_t k = j; k < b1 && runs[k].x0 < runs[i].x1 + reach; ++k) uf.join(uint32_t(i), uint32_t(k));
  }
}

}  // namespace

Components findComponents(const VoxelGrid& grid, Connectivity connectivity) {
  Components out;
  if (grid.empty()) return out;
  const int32_t ny = grid.ny(), nz = grid.nz();
  const int64_t wpr = grid.wordsPerRow();
  // Runs in (z, y) order; row_start[z * ny + y] is the first run of that row.
  std::vector<size_t> row_start(size_t(ny) * nz + 1, 0);
  for (int32_t z = 0; z < nz; ++z) {
    for (int32_t y = 0; y < ny; ++y) {
      row_start[size_t(z) * ny + y] = out.runs.size();
      if (grid.layerAllocated(z)) appendRowRuns(grid.rowWords(y, z), wpr, y, z, out.runs);
    }
  }
  row_start.back() = out.runs.size();
  UnionFind uf;
  uf.parent.resize(out.runs.size());
  std::iota(uf.parent.begin(), uf.parent.end(), 0u);
  const bool all = connectivity == Connectivity::kAll;
  const int32_t reach = all ? 1 : 0;
  auto rowRange = [&](int32_t y, int32_t z, size_t& b, size_t& e) {
    if (y < 0 || y >= ny || z < 0) return false;
    b = row_start[size_t(z) * ny + y];
    e = row_start[size_t(z) * ny + y + 1];
    return b < e;
  };
  for (int32_t z = 0; z < nz; ++z) {
    for (int32_t y = 0; y < ny; ++y) {
      size_t a0, a1, b0, b1;
      if (!rowRange(y, z, a0, a1)) continue;
      if (rowRange(y - 1, z, b0, b1)) joinTouching(out.runs, a0, a1, b0, b1, reach, uf);
      if (rowRange(y, z - 1, b0, b1)) joinTouching(out.runs, a0, a1, b0, b1, reach, uf);
      if (!all) continue;
      if (rowRange(y - 1, z - 1, b0, b1)) joinTouching(out.runs, a0, a1, b0, b1, reach, uf);
      if (rowRange(y + 1, z - 1, b0, b1)) joinTouching(out.runs, a0, a1, b0, b1, reach, uf);
    }
  }
  // Number the components by first run, then order them largest first.
  constexpr uint32_t kNone = UINT32_MAX;
  std::vector<uint32_t> comp_of_root(out.runs.size(), kNone);
  std::vector<Component> comps;
  out.run_component.resize(out.runs.size());
  for (size_t i = 0; i < out.runs.size(); ++i) {
    const Run& r = out.runs[i];
    uint32_t& c = comp_of_root[uf.find(uint32_t(i))];
    if (c == kNone) {
      c = uint32_t(comps.size());
      comps.push_back(Component{0, glm::ivec3(r.x0, r.y, r.z), glm::ivec3(r.x1 - 1, r.y, r.z)});
    }
    Component& k = comps[c];
    k.voxels += r.x1 - r.x0;
    k.box_min = glm::min(k.box_min, glm::ivec3(r.x0, r.y, r.z));
    k.box_max = glm::max(k.box_max, glm::ivec3(r.x1 - 1, r.y, r.z));
    out.run_component[i] = c;
  }
  std::vector<uint32_t> order(comps.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](uint32_t a, uint32_t b) { return comps[a].voxels > comps[b].voxels; });
  std::vector<uint32_t> rank(comps.size());
  for (size_t i = 0; i < order.size(); ++i) {
    rank[order[i]] = uint32_t(i);
    out.components.push_back(comps[order[i]]);
  }
  for (uint32_t& c : out.run_component) c = rank[c];
  return out;
}

VoxelGrid componentGrid(const VoxelGrid& grid, const Components& components, size_t i) {
  VoxelGrid out(grid.dims(), grid.frame());
  for (size_t r = 0; r < components.runs.size(); ++r) {
    if (components.run_component[r] != i) continue;
    const Run& run = components.runs[r];
    out.fillRun(run.y, run.z, run.x0, run.x1);
  }
  return out;
}

}  // namespace vox
