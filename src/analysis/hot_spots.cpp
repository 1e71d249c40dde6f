// Hot spots: regional maxima of the distance field, by a watershed over the filled voxels in decreasing distance
// (union-find, 26-connectivity). See vox/analysis/thickness.h and docs/accuracy.md.
//
// Voxels are taken from the largest distance down (a counting sort by squared distance). A voxel with no processed
// neighbour starts a component: a regional maximum. A voxel touching one component joins it (and, at the
// component's peak level, its plateau). A voxel touching several merges them at its own level, the saddle: the
// component with the highest peak survives and the others die there, with dynamic = peak radius - saddle radius.
// Components with equal peaks that meet at the peak level are one plateau, one maximum. A component that never dies
// holds the highest maximum of its connected body.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "analysis/huge_array.h"
#include "analysis/neighbours.h"
#include "analysis/progress_gate.h"
#include "vox/analysis/thickness.h"

namespace vox {
namespace {

// A regional maximum's component. Its union-find links are kept apart (parent and plateau in findHotSpots), 4 bytes
// a component: every voxel follows them from its neighbours' labels, and dense they stay in the caches.
struct Component {
  uint32_t peak = 0;    // squared distance at the maximum
  uint32_t saddle = 0;  // squared distance where it died (merged into a higher maximum)
  bool dead = false;
  int64_t count = 0;  // plateau voxels
  int64_t sx = 0, sy = 0, sz = 0;
};

// The root of i's set in a union-find forest (link[k] == k at a root), compressing the path.
uint32_t findRoot(std::vector<uint32_t>& link, uint32_t i) {
  uint32_t r = i;
  while (link[r] != r) r = link[r];
  while (link[i] != r) {
    const uint32_t next = link[i];
    link[i] = r;
    i = next;
  }
  return r;
}

}  // namespace

Result<std::vector<HotSpot>> findHotSpots(const DistanceField& distance, const HotSpotParams& params,
                                          const ProgressFn& progress) {
  std::vector<HotSpot> out;
  if (distance.outside() != 0) {
    return makeError(ErrorCode::kInvalidArgument, "hot spots need a distance field, not a clearance field");
  }
  const Dims d = distance.boxDims();
  if (d.count() == 0) return out;
  if (d.count() >= int64_t(UINT32_MAX)) {
    return makeError(ErrorCode::kLimit, "hot spots: the model's bounding box has more than 2^32 voxels");
  }
  const uint32_t max_s = distance.maxSquared();
  if (max_s > (1u << 26)) {
    return makeError(ErrorCode::kLimit, "hot spots: distances above 8192 voxels are not supported");
  }
  const int64_t nx = d.nx, ny = d.ny, nz = d.nz;
  const uint32_t* data = distance.data();
  analysis_detail::ProgressGate gate(progress);
  auto cancelled = [] { return makeError(ErrorCode::kCancelled, "hot spots cancelled"); };

  // Counting sort of the filled voxels by squared distance, largest first.
  std::vector<int64_t> start(size_t(max_s) + 2, 0);
  for (int64_t i = 0; i < d.count(); ++i) {
    if (data[i]) ++start[size_t(max_s - data[i]) + 1];
  }
  for (size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
  const int64_t filled = start.back();
  std::vector<uint32_t> order(static_cast<size_t>(filled));
  for (int64_t i = 0; i < d.count(); ++i) {
    if (data[i]) order[size_t(start[size_t(max_s - data[i])]++)] = uint32_t(i);
  }
  // Now start[k] ends the voxels at squared distance max_s - k in order: the loops below know each voxel's distance
  // from its place in order, and never read the field (the voxels come scattered over it, each read a miss in the
  // caches and in the address translations).
  const std::vector<int64_t>& level_end = start;
  auto levelRange = [&](uint32_t level) {  // the range of order at `level`
    const size_t k = max_s - level;
    return std::pair<int64_t, int64_t>(k == 0 ? 0 : level_end[k - 1], level_end[k]);
  };
  if (!gate.report(0.1)) return cancelled();

  // component + 1; 0: not processed yet. The voxels come in order of distance, scattered over the part, so each
  // reads its neighbours' labels from memory: the labels are stored by cells of 4 x 4 x 4 voxels (the 16 voxels of
  // a cell's layer in one 64-byte line), where the 27 voxels about one lie in about 7 lines (about 10 when stored
  // by rows); the lines about the voxel kAhead places on are asked for ahead; and the labels lie
  // on 2 MiB pages where the kernel gives them, so that the reads also find their address translations. (A cell is
  // one voxel wide along an axis of fewer than 16 voxels: rounding the box up to whole cells then adds at most 3/16
  // along any axis, where a plate one voxel thick would take four times its labels.)
  auto shift = [](int64_t n) { return n >= 16 ? 2 : 0; };
  const int sx = shift(nx), sy = shift(ny), sz = shift(nz);
  const int64_t mx = (int64_t(1) << sx) - 1, my = (int64_t(1) << sy) - 1, mz = (int64_t(1) << sz) - 1;
  const int64_t cx = (nx + mx) >> sx, cy = (ny + my) >> sy, cz = (nz + mz) >> sz;
  auto cell = [=](int64_t x, int64_t y, int64_t z) {
    return size_t(((((z >> sz) * cy + (y >> sy)) * cx + (x >> sx)) << (sx + sy + sz)) + ((z & mz) << (sx + sy)) +
                  ((y & my) << sx) + (x & mx));
  };
  const auto nx32 = uint32_t(nx), ny32 = uint32_t(ny);
  auto coordinates = [nx32, ny32](int64_t i, int64_t& x, int64_t& y, int64_t& z) {
    const uint32_t row = uint32_t(i) / nx32;  // (32-bit divisions: the box has fewer than 2^32 voxels)
    x = uint32_t(i) - row * nx32;
    y = row % ny32;
    z = row / ny32;
  };
  analysis_detail::HugeArray<uint32_t> label(size_t((cx * cy * cz) << (sx + sy + sz)));
  constexpr int64_t kAhead = 16;
  std::vector<Component> comps;
  std::vector<uint32_t> parent;   // union-find over all merges
  std::vector<uint32_t> plateau;  // union-find over plateau merges only (equal peaks meeting at the peak level)
  auto root = [&](uint32_t k) { return findRoot(parent, k); };
  uint32_t roots[26];
  size_t level = 0;  // the voxel's bucket: squared distance max_s - level
  for (int64_t n = 0; n < filled; ++n) {
    if (n + kAhead < filled) {
      const int64_t a = order[size_t(n + kAhead)];
      int64_t ax, ay, az;
      coordinates(a, ax, ay, az);
      const int64_t x0 = std::max<int64_t>(ax - 1, 0), x1 = std::min(ax + 1, nx - 1);
      const int64_t y0 = std::max<int64_t>(ay - 1, 0), y1 = std::min(ay + 1, ny - 1);
      for (int64_t z = std::max<int64_t>(az - 1, 0); z <= std::min(az + 1, nz - 1); ++z) {
        __builtin_prefetch(label.data() + cell(x0, y0, z));
        __builtin_prefetch(label.data() + cell(x1, y0, z));
        __builtin_prefetch(label.data() + cell(x0, y1, z));
        __builtin_prefetch(label.data() + cell(x1, y1, z));
      }
    }
    const int64_t i = order[size_t(n)];
    while (n >= level_end[level]) ++level;
    const auto s = uint32_t(max_s - level);
    int64_t x, y, z;
    coordinates(i, x, y, z);
    int nr = 0;
    analysis_detail::forEach26At(x, y, z, nx, ny, nz, [&](int64_t qx, int64_t qy, int64_t qz) {
      const uint32_t l = label[cell(qx, qy, qz)];
      if (!l) return;
      const uint32_t r = root(l - 1);
      if (std::find(roots, roots + nr, r) == roots + nr) roots[nr++] = r;
    });
    uint32_t own;
    if (nr == 0) {
      own = uint32_t(comps.size());
      Component c;
      c.peak = s;
      comps.push_back(c);
      parent.push_back(own);
      plateau.push_back(own);
    } else {
      own = roots[0];  // the highest peak survives; the oldest among equals
      for (int k = 1; k < nr; ++k) {
        const uint32_t r = roots[k];
        if (comps[r].peak > comps[own].peak || (comps[r].peak == comps[own].peak && r < own)) own = r;
      }
      for (int k = 0; k < nr; ++k) {
        const uint32_t r = roots[k];
        if (r == own) continue;
        Component& c = comps[r];
        parent[r] = own;
        if (c.peak == s && comps[own].peak == s) {  // one plateau
          const uint32_t pr = findRoot(plateau, r);
          Component& o = comps[own];
          o.count += comps[pr].count;
          o.sx += comps[pr].sx;
          o.sy += comps[pr].sy;
          o.sz += comps[pr].sz;
          plateau[pr] = own;
        } else {
          c.dead = true;
          c.saddle = s;
        }
      }
    }
    Component& c = comps[own];
    if (c.peak == s) {
      ++c.count;
      c.sx += x;
      c.sy += y;
      c.sz += z;
    }
    label[cell(x, y, z)] = own + 1;
    if ((n & 0xfffff) == 0 && !gate.report(0.1 + 0.8 * double(n) / double(filled))) return cancelled();
  }

  // Reported maxima: plateau roots that stand out by min_dynamic (survivors always do).
  const double h = distance.voxelSize();
  const GridFrame& frame = distance.frame();
  const glm::ivec3 lo = distance.boxMin();
  std::vector<int64_t> spot_of(comps.size(), -1);
  for (uint32_t k = 0; k < comps.size(); ++k) {
    const Component& c = comps[k];
    if (plateau[k] != k) continue;  // absorbed into another plateau
    const double r = std::sqrt(double(c.peak));
    const double dyn = c.dead ? r - std::sqrt(double(c.saddle)) : r;
    // A component that died at its own peak level was a plateau touching a higher voxel, not a maximum.
    if (c.dead && (c.saddle == c.peak || dyn < params.min_dynamic_voxels)) continue;
    HotSpot hs;
    const glm::dvec3 mean = glm::dvec3(double(c.sx), double(c.sy), double(c.sz)) / double(c.count);
    hs.centre = frame.origin + (glm::dvec3(lo) + mean + 0.5) * h;
    hs.plateau_voxels = c.count;
    hs.radius = r * h;
    hs.modulus = hs.radius / 3.0;
    hs.dynamic = dyn * h;
    hs.saddle = c.dead ? std::sqrt(double(c.saddle)) * h : 0.0;
    hs.isolated = !c.dead || dyn >= params.isolation_voxels;
    spot_of[k] = int64_t(out.size());
    out.push_back(hs);
  }
  // The plateau voxel nearest each reported centre, among the voxels at the levels of the reported peaks: the order is
  // by distance, so those lie in one range of it per level.
  std::vector<double> best(out.size(), INFINITY);
  std::vector<uint32_t> levels;
  for (uint32_t k = 0; k < comps.size(); ++k)
    if (spot_of[k] >= 0) levels.push_back(comps[k].peak);
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  for (const uint32_t peak : levels) {
    const auto range = levelRange(peak);
    for (int64_t n = range.first; n < range.second; ++n) {
      const int64_t i = order[size_t(n)];
      int64_t x, y, z;
      coordinates(i, x, y, z);
      const uint32_t k = findRoot(plateau, label[cell(x, y, z)] - 1);
      if (spot_of[k] < 0 || comps[k].peak != peak) continue;
      HotSpot& hs = out[size_t(spot_of[k])];
      const glm::ivec3 v = glm::ivec3(int32_t(x), int32_t(y), int32_t(z)) + lo;
      const glm::dvec3 p = frame.voxelCentre(v.x, v.y, v.z) - hs.centre;
      const double dd = p.x * p.x + p.y * p.y + p.z * p.z;
      if (dd < best[size_t(spot_of[k])]) {
        best[size_t(spot_of[k])] = dd;
        hs.voxel = v;
      }
    }
  }
  std::stable_sort(out.begin(), out.end(), [](const HotSpot& a, const HotSpot& b) { return a.radius > b.radius; });
  if (!gate.report(1.0)) return cancelled();
  return out;
}

}  // namespace vox
