// Mass properties of a voxel model (thesis 2.6.1: volumetric properties come directly from the enumeration):
// volume, centroid, inertia tensor about the centroid and bounding box, treating every voxel as a solid cube of
// side h and unit density.
//
// Everything is summed in exact integers over voxel indices (count, sums of i, j, k, and of their squares and
// products) and converted to model units once at the end, so the result does not depend on summation order or
// thread count and matches the reference (../shared/reference/README.md section 6) to rounding. Sums over a row
// come from per-byte tables (count, sum and sum of squares of the set bit positions of each byte value), so a row
// costs O(words) regardless of how many voxels it holds; full words, the bulk of a solid, take a shortcut.
#include <algorithm>
#include <bit>
#include <climits>
#include <optional>
#include <cmath>
#include <cctype>

#include "analysis/layer_ops.h"
#include "vox/core/parallel.h"
#include "vox/analysis/analysis.h"

namespace vox {
namespace {

__extension__ typedef __int128 Int128;  // exact second moments: 16384^5 exceeds int64

struct WordSums {
  int64_t n = 0, s = 0, ss = 0;  // count, sum of bit positions, sum of squared bit positions (within the word)
};

// For each byte value: the number of set bits, the sum of their positions and the sum of the squared positions.
struct ByteTables {
  uint8_t n[256];
  uint16_t s[256];
  uint16_t ss[256];
  constexpr ByteTables() : n(), s(), ss() {
    for (int v = 0; v < 256; ++v) {
      for (int b = 0; b < 8; ++b) {
        if ((v >> b) & 1) {
          n[v] = uint8_t(n[v] + 1);
          s[v] = uint16_t(s[v] + b);
          ss[v] = uint16_t(ss[v] + b * b);
        }
      }
    }
  }
};
constexpr ByteTables kBytes;

WordSums wordSums(uint64_t w) {
  if (w == ~uint64_t(0)) return {64, 63 * 64 / 2, 63 * 64 * 127 / 6};
  WordSums r;
  // Byte k holds positions 8k + b: sum = 8k n + s, sum of squares = 64 k^2 n + 16 k s + ss.
  for (int64_t k = 0; k < 8; ++k, w >>= 8) {
    const unsigned v = unsigned(w & 0xFF);
    if (!v) continue;
    const int64_t n = kBytes.n[v], s = kBytes.s[v];
    r.n += n;
    r.s += 8 * k * n + s;
    r.ss += 64 * k * k * n + 16 * k * s + kBytes.ss[v];
  }
  return r;
}

}  // namespace

struct MassAccumulator::Sums {
  int64_t n = 0, interior = 0;
  Int128 sx = 0, sy = 0, sz = 0, sxx = 0, syy = 0, szz = 0, sxy = 0, sxz = 0, syz = 0;
  glm::ivec3 lo{INT32_MAX}, hi{-1};

  void add(const Sums& o) {
    n += o.n;
    interior += o.interior;
    sx += o.sx, sy += o.sy, sz += o.sz;
    sxx += o.sxx, syy += o.syy, szz += o.szz;
    sxy += o.sxy, sxz += o.sxz, syz += o.syz;
    lo = glm::min(lo, o.lo);
    hi = glm::max(hi, o.hi);
  }
};

namespace {

using Sums = MassAccumulator::Sums;

// Sums over layers [z0, z1) of `grid`, which holds the model's layers from z_offset on.
Sums sumLayers(const VoxelGrid& grid, int32_t z0, int32_t z1, int32_t z_offset) {
  const int64_t wpr = grid.wordsPerRow();
  const int threads = threadsFor(grid.allocatedLayers() * grid.wordsPerLayer());
  std::vector<Sums> partial(static_cast<size_t>(threads));
  parallelChunks(z0, z1, 4, threads, [&](int t, int64_t zl0, int64_t zl1) {
    Sums& s = partial[size_t(t)];
    for (int32_t zl = int32_t(zl0); zl < int32_t(zl1); ++zl) {
      if (!grid.layerAllocated(zl)) continue;
      const int32_t z = zl + z_offset;
      const uint64_t* below = grid.layerWords(zl - 1);
      const uint64_t* cur = grid.layerWords(zl);
      const uint64_t* above = grid.layerWords(zl + 1);
      for (int32_t y = 0; y < grid.ny(); ++y) {
        const int64_t base = (int64_t(y) + 1) * wpr;
        int64_t n = 0, sp = 0, spp = 0;  // padded positions p = x + 1
        int64_t first = -1, last = -1;
        for (int64_t w = 0; w < wpr; ++w) {
          const uint64_t c = cur[base + w];
          if (!c) continue;
          s.interior += analysis_detail::popcount64(analysis_detail::interiorWord(below, cur, above, wpr, base + w));
          const WordSums ws = wordSums(c);
          const int64_t off = 64 * w;
          n += ws.n;
          sp += off * ws.n + ws.s;
          spp += off * off * ws.n + 2 * off * ws.s + ws.ss;
          if (first < 0) first = off + std::countr_zero(c);
          last = off + 63 - std::countl_zero(c);
        }
        if (n == 0) continue;
        const int64_t sx = sp - n;             // x = p - 1
        const int64_t sxx = spp - 2 * sp + n;  // (p - 1)^2
        s.n += n;
        s.sx += sx;
        s.sxx += sxx;
        s.sy += Int128(y) * n;
        s.syy += Int128(int64_t(y) * y) * n;
        s.sz += Int128(z) * n;
        s.szz += Int128(int64_t(z) * z) * n;
        s.sxy += Int128(y) * sx;
        s.sxz += Int128(z) * sx;
        s.syz += Int128(int64_t(y) * z) * n;
        s.lo = glm::min(s.lo, glm::ivec3(int32_t(first - 1), y, z));
        s.hi = glm::max(s.hi, glm::ivec3(int32_t(last - 1), y, z));
      }
    }
  });
  Sums s;
  for (const Sums& p : partial) s.add(p);
  return s;
}

MassProperties massFromSums(const Sums& s, const GridFrame& frame) {
  MassProperties mp;
  mp.filled = s.n;
  if (s.n == 0) return mp;
  const double h = frame.voxel_size;
  const glm::dvec3 origin = frame.origin;
  const double n = double(s.n);
  mp.volume = n * h * h * h;
  mp.centroid = origin + (glm::dvec3(double(s.sx), double(s.sy), double(s.sz)) / n + 0.5) * h;
  // Central second moments in voxel units: (N * S_ab - S_a * S_b) / N, the numerator exact in 128 bits.
  auto central = [&](Int128 sab, Int128 sa, Int128 sb) { return double(Int128(s.n) * sab - sa * sb) / n; };
  const double cxx = central(s.sxx, s.sx, s.sx), cyy = central(s.syy, s.sy, s.sy), czz = central(s.szz, s.sz, s.sz);
  const double cxy = central(s.sxy, s.sx, s.sy), cxz = central(s.sxz, s.sx, s.sz), cyz = central(s.syz, s.sy, s.sz);
  const double h5 = h * h * h * h * h;
  const double own = n / 6.0;  // each cube about its own centre: m (h^2 + h^2) / 12 with m = h^3
  glm::dmat3 inertia(0.0);     // glm is column-major: inertia[col][row]; the tensor is symmetric anyway
  inertia[0][0] = h5 * (cyy + czz + own);
  inertia[1][1] = h5 * (cxx + czz + own);
  inertia[2][2] = h5 * (cxx + cyy + own);
  inertia[0][1] = inertia[1][0] = -h5 * cxy;
  inertia[0][2] = inertia[2][0] = -h5 * cxz;
  inertia[1][2] = inertia[2][1] = -h5 * cyz;
  mp.inertia = inertia;
  mp.bbox_min_ijk = s.lo;
  mp.bbox_max_ijk = s.hi;
  mp.bbox.min = origin + glm::dvec3(s.lo) * h;
  mp.bbox.max = origin + (glm::dvec3(s.hi) + 1.0) * h;
  mp.volume_error_bound = double(s.n - s.interior) * h * h * h;
  return mp;
}

}  // namespace

MassAccumulator::MassAccumulator() : sums_(std::make_unique<Sums>()) {}
MassAccumulator::~MassAccumulator() = default;

void MassAccumulator::add(const VoxelGrid& window, int32_t z0, int32_t z1, int32_t z_offset) {
  sums_->add(sumLayers(window, z0, z1, z_offset));
}

MassProperties MassAccumulator::result(const GridFrame& frame) const { return massFromSums(*sums_, frame); }

MassProperties computeMassProperties(const VoxelGrid& grid) {
  if (grid.empty()) return {};
  MassAccumulator acc;
  acc.add(grid, 0, grid.nz(), 0);
  return acc.result(grid.frame());
}

PrincipalAxes principalAxes(const glm::dmat3& inertia) {
  // Cyclic Jacobi: each sweep zeroes the off-diagonal elements one after another with plane rotations; a symmetric
  // 3 x 3 matrix converges to machine precision in a handful of sweeps.
  glm::dmat3 a = inertia;
  glm::dmat3 v(1.0);
  for (int sweep = 0; sweep < 50; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const double scale = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
    if (off <= 1e-30 * scale || off == 0.0) break;
    for (int p = 0; p < 2; ++p) {
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0.0) continue;
        const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), sn = t * c;
        glm::dmat3 r(1.0);  // a <- r^T a r zeroes a[p][q]
        r[p][p] = c;
        r[q][q] = c;
        r[q][p] = sn;   // column q, row p
        r[p][q] = -sn;  // column p, row q
        a = glm::transpose(r) * a * r;
        a[p][q] = a[q][p] = 0.0;
        v = v * r;
      }
    }
  }
  // Sort ascending, axes along.
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int i, int j) { return a[i][i] < a[j][j]; });
  PrincipalAxes out;
  for (int i = 0; i < 3; ++i) {
    out.moments[i] = a[order[i]][order[i]];
    out.axes[i] = glm::normalize(v[order[i]]);
  }
  out.axes[2] = glm::cross(out.axes[0], out.axes[1]);  // right-handed
  return out;
}

const std::vector<Material>& commonMaterials() {
  static const std::vector<Material> table = {
      {"steel", 7850.0},    {"stainless steel", 8000.0}, {"cast iron", 7200.0},   {"aluminium", 2700.0},
      {"titanium", 4430.0}, {"copper", 8960.0},          {"brass", 8500.0},       {"ABS", 1040.0},
      {"PLA", 1240.0},      {"nylon (PA12)", 1010.0},    {"resin (SLA)", 1180.0}, {"water", 1000.0},
  };
  return table;
}

std::optional<double> materialDensity(const std::string& name) {
  const auto lower = [](std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
  };
  const std::string n = lower(name);
  for (const Material& m : commonMaterials()) {
    const std::string mn = lower(m.name);
    if (n == mn || n == mn.substr(0, mn.find(" ("))) return m.density_kg_m3;
  }
  if (n == "aluminum") return 2700.0;
  return std::nullopt;
}

}  // namespace vox
