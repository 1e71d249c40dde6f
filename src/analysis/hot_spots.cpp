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
#include <vector>

#include <glm/vec3.hpp>

#include "analysis/neighbours.h"
#include "analysis/progress_gate.h"
#include "vox/analysis/thickness.h"

namespace vox {
namespace {

struct Component {
  uint32_t parent = 0;   // union-find over all merges
  uint32_t plateau = 0;  // union-find over plateau merges only (equal peaks meeting at the peak level)
  uint32_t peak = 0;     // squared distance at the maximum
  uint32_t saddle = 0;   // squared distance where it died (merged into a higher maximum)
  bool dead = false;
  int64_t count = 0;  // plateau voxels
  int64_t sx = 0, sy = 0, sz = 0;
};

uint32_t findRoot(std::vector<Component>& c, uint32_t i, bool plateau) {
  auto link = [&](uint32_t k) -> uint32_t& { return plateau ? c[k].plateau : c[k].parent; };
  uint32_t r = i;
  while (link(r) != r) r = link(r);
  while (link(i) != r) {  // path compression
    const uint32_t next = link(i);
    link(i) = r;
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
  const int64_t nx = d.nx, ny = d.ny, nz = d.nz, plane = nx * ny;
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
  start.clear();
  start.shrink_to_fit();
  if (!gate.report(0.1)) return cancelled();

  std::vector<uint32_t> label(size_t(d.count()), 0);  // component + 1; 0: not processed yet
  std::vector<Component> comps;
  auto root = [&](uint32_t k) { return findRoot(comps, k, false); };
  uint32_t roots[26];
  for (int64_t n = 0; n < filled; ++n) {
    const int64_t i = order[size_t(n)];
    const uint32_t s = data[i];
    const int64_t x = i % nx, y = (i / nx) % ny, z = i / plane;
    int nr = 0;
    analysis_detail::forEach26(x, y, z, nx, ny, nz, [&](int64_t j) {
      const uint32_t l = label[size_t(j)];
      if (!l) return;
      const uint32_t r = root(l - 1);
      if (std::find(roots, roots + nr, r) == roots + nr) roots[nr++] = r;
    });
    uint32_t own;
    if (nr == 0) {
      own = uint32_t(comps.size());
      Component c;
      c.parent = c.plateau = own;
      c.peak = s;
      comps.push_back(c);
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
        c.parent = own;
        if (c.peak == s && comps[own].peak == s) {  // one plateau
          const uint32_t pr = findRoot(comps, r, true);
          Component& o = comps[own];
          o.count += comps[pr].count;
          o.sx += comps[pr].sx;
          o.sy += comps[pr].sy;
          o.sz += comps[pr].sz;
          comps[pr].plateau = own;
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
    label[size_t(i)] = own + 1;
    if ((n & 0xfffff) == 0 && !gate.report(0.1 + 0.8 * double(n) / double(filled))) return cancelled();
  }

  // Reported maxima: plateau roots that stand out by min_dynamic (survivors always do).
  const double h = distance.voxelSize();
  const GridFrame& frame = distance.frame();
  const glm::ivec3 lo = distance.boxMin();
  std::vector<int64_t> spot_of(comps.size(), -1);
  for (uint32_t k = 0; k < comps.size(); ++k) {
    const Component& c = comps[k];
    if (c.plateau != k) continue;  // absorbed into another plateau
    const double r = std::sqrt(double(c.peak));
    const double dyn = c.dead ? r - std::sqrt(double(c.saddle)) : r;
    if (c.dead && dyn < params.min_dynamic_voxels) continue;
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
  // The plateau voxel nearest each reported centre.
  std::vector<double> best(out.size(), INFINITY);
  for (int64_t n = 0; n < filled; ++n) {
    const int64_t i = order[size_t(n)];
    const uint32_t k = findRoot(comps, label[size_t(i)] - 1, true);
    if (spot_of[k] < 0 || comps[k].peak != data[i]) continue;
    HotSpot& hs = out[size_t(spot_of[k])];
    const glm::ivec3 v = glm::ivec3(int32_t(i % nx), int32_t((i / nx) % ny), int32_t(i / plane)) + lo;
    const glm::dvec3 p = frame.voxelCentre(v.x, v.y, v.z) - hs.centre;
    const double dd = p.x * p.x + p.y * p.y + p.z * p.z;
    if (dd < best[size_t(spot_of[k])]) {
      best[size_t(spot_of[k])] = dd;
      hs.voxel = v;
    }
  }
  std::stable_sort(out.begin(), out.end(), [](const HotSpot& a, const HotSpot& b) { return a.radius > b.radius; });
  if (!gate.report(1.0)) return cancelled();
  return out;
}

}  // namespace vox
