// Casting solidification on the voxel lattice (vox/analysis/casting.h; docs/conventions.md, "Casting").
//  - The box: the part with its feeders, and an envelope of mould about them; its outer faces are insulated (the
//    envelope is thick enough that the heat never reaches them in the time the metal takes to freeze).
//  - The state is each cell's enthalpy per volume H. Metal: H = rho c (T - Ts) below the solidus, rising by
//    rho (c (Tl - Ts) + L) over the freezing range (linearly in T; at once for a pure metal), rho c (T - Tl) more
//    above the liquidus. Mould: H = rho c T.
//  - A step: the capacity C = dH/dT of each cell taken from its enthalpy at the step's start (a pure metal's
//    plateau as though it froze over 1 K), then the change of temperature dT under conduction between face
//    neighbours (harmonic mean conductivities), implicit along x, then y, then z (locally one-dimensional splitting:
//    each a backward Euler step along its lines, a tridiagonal solve per line, which keeps every temperature between
//    its neighbours' whatever the step and however metal and sand differ), then H += C dT, which the fluxes balance
//    exactly, and T from H. Latent heat is therefore never skipped; the step is a fixed share of Chvorinov's
//    estimate of the freezing time, so that it shrinks with neither the voxels nor the metal's speed.
//  - A metal cell's solidification time is when its H falls through the solidus (interpolated within the step);
//    Niyama's criterion G / sqrt(cooling rate) is taken as it falls through the temperature 10% of the freezing
//    range above the solidus (Carlson and Beckermann).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <glm/common.hpp>
#include <glm/vector_relational.hpp>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "analysis/casting_detail.h"
#include "analysis/progress_gate.h"
#include "vox/analysis/casting.h"
#include "vox/core/parallel.h"
#include "vox/core/text.h"
#include "vox/core/units.h"

namespace vox {
namespace {

using casting_detail::kFeeder;
using casting_detail::kMetal;
using casting_detail::kMould;

// Volumetric enthalpy of the metal about its solidus (J/m^3), and back.
struct MetalPhase {
  double rc = 0.0;  // rho c
  double ts = 0.0, tl = 0.0;
  double hl = 0.0;       // H at the liquidus
  double mushy_c = 0.0;  // dH/dT over the freezing range
  double h_crit = 0.0;   // H at the Niyama temperature
  explicit MetalPhase(const Alloy& a)
      : rc(a.density_kg_m3 * a.specific_heat_j_kgk),
        ts(a.solidus_c),
        tl(a.liquidus_c),
        hl(a.density_kg_m3 * (a.specific_heat_j_kgk * (a.liquidus_c - a.solidus_c) + a.latent_heat_j_kg)),
        mushy_c(hl / std::max(a.liquidus_c - a.solidus_c, 1.0)),
        h_crit(0.1 * hl) {}
  double temperature(double h) const {
    if (h < 0.0) return ts + h / rc;
    if (h <= hl) return tl > ts ? ts + (tl - ts) * h / hl : ts;
    return tl + (h - hl) / rc;
  }
  double enthalpy(double t) const {
    if (t < ts) return rc * (t - ts);
    if (t <= tl) return tl > ts ? hl * (t - ts) / (tl - ts) : hl;
    return hl + rc * (t - tl);
  }
  double capacity(double h) const { return h < 0.0 || h > hl ? rc : mushy_c; }
};

// Chvorinov's rule from the semi-infinite mould (Flemings): t = pi / 4 (rho L' / dT)^2 M^2 / (k rho c)_mould, the
// metal's superheat and half its freezing range counted in L'. M in metres.
double chvorinovSeconds(const CastingParams& p, double modulus_m) {
  const Alloy& a = p.alloy;
  const double latent =
      a.latent_heat_j_kg + a.specific_heat_j_kgk * (p.superheat_k + 0.5 * (a.liquidus_c - a.solidus_c));
  const double dt = std::max(0.5 * (a.liquidus_c + a.solidus_c) - p.mould.temperature_c, 1.0);
  const double q = a.density_kg_m3 * latent / dt;
  const double kpc = p.mould.conductivity_w_mk * p.mould.density_kg_m3 * p.mould.specific_heat_j_kgk;
  return std::numbers::pi / 4.0 * q * q * modulus_m * modulus_m / kpc;
}

std::string shortNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

std::string pointText(glm::dvec3 p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g)", p.x, p.y, p.z);
  return buf;
}

// The conductance between two cells of kinds a and b (bit 0: metal) without a branch or a table, so that the lines'
// loops vectorize: g00 + a (g10 - g00) + b (g01 - g00) + a b (g11 - g10 - g01 + g00).
using V4 = float __attribute__((vector_size(16)));
V4 load4(const float* p) {
  V4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
void store4(float* p, V4 v) { std::memcpy(p, &v, sizeof v); }
V4 metalOf(const uint8_t* kind) {  // 1 for metal, 0 for mould
  return V4{float(kind[0] & 1), float(kind[1] & 1), float(kind[2] & 1), float(kind[3] & 1)};
}

struct Conductance {
  float g00 = 0, da = 0, db = 0, dab = 0;
  float operator()(float a, float b) const { return g00 + a * da + b * db + a * b * dab; }
  V4 operator()(V4 a, V4 b) const { return g00 + a * da + b * db + a * b * dab; }
};

// Rows of `width` lines side by side: row k's cells at t + k stride (and d, kind, c likewise), k < n.
struct LineRows {
  const float* t;
  const float* d;
  const uint8_t* kind;
  const float* c;
  int64_t stride, n, width;
};

class Solidifier {
 public:
  Solidifier(const VoxelGrid& part, const CastingParams& params, const ProgressFn& progress)
      : part_(part), p_(params), metal_(params.alloy), gate_(progress) {}

  Result<CastingResult> run() {
    if (Status s = layout(); !s) return s.error();
    if (Status s = build(); !s) return s.error();
    const double start = nowSeconds();
    if (Status s = simulate(); !s) return s.error();
    out_.simulate_s = nowSeconds() - start;
    collect();
    return std::move(out_);
  }

  // The box, the envelope and the step (no allocation): also what estimateCastingBytes reads.
  Status layout();
  Status checkParams() const;
  // Floats of scratch each thread's two arrays hold: the largest plane of lines a sweep solves at once.
  int64_t scratchFloats() const { return std::max({nx_ * 16, nx_ * ny_, nx_ * nz_}); }
  int64_t cells() const { return box_.count(); }
  int64_t scratchBytes() const {
    const int64_t nx = box_.nx, ny = box_.ny, nz = box_.nz;
    return 2 * threadsFor(box_.count()) * std::max({nx * 16, nx * ny, nx * nz}) * int64_t(sizeof(float));
  }

 private:
  Status build();
  Status simulate();
  Status markFeeders(glm::ivec3 off);
  bool partNear(glm::ivec3 v) const;
  void capacities(double dt);
  void solveLines(int64_t base, int64_t stride, int64_t n, int64_t width, float* cp, float* dp);
  void sweeps();
  int64_t update(double t, double dt);
  void collect();
  void verdict();

  // A block of rows along x, laid across (solveXRows).
  struct XBlock {
    std::vector<float> t, d, c;
    std::vector<uint8_t> kind;
  };
  void solveXRows(int64_t row, int64_t rows, float* cp, float* dp, XBlock& block);
  // Thread `thread`'s scratch array `which` (0 or 1) of at least n values.
  float* scratch(int thread, int which, int64_t n) {
    std::vector<float>& v = scratch_[size_t(2 * thread + which)];
    if (int64_t(v.size()) < n) v.resize(size_t(n));
    return v.data();
  }

  const VoxelGrid& part_;
  const CastingParams& p_;
  const MetalPhase metal_;
  analysis_detail::ProgressGate gate_;
  CastingResult out_;
  Dims box_;
  int64_t nx_ = 0, ny_ = 0, nz_ = 0, layer_ = 0;
  glm::ivec3 result_lo_{0};  // the result's box within the simulated one
  double h_m_ = 0.0;         // voxel size, metres
  double mould_rc_ = 0.0;
  int threads_ = 1;
  std::vector<uint8_t> kind_;
  std::vector<float> t_, h_, c_, d_, time_, niyama_;
  int64_t metal_cells_ = 0;
  std::vector<std::vector<float>> scratch_;  // two per thread, for the sweeps
  std::vector<XBlock> xblocks_;              // one per thread
  Conductance conductance_;
};

Status Solidifier::checkParams() const {
  const Alloy& a = p_.alloy;
  const MouldMaterial& m = p_.mould;
  for (const double v : {a.density_kg_m3, a.latent_heat_j_kg, a.conductivity_w_mk, a.specific_heat_j_kgk,
                         m.conductivity_w_mk, m.density_kg_m3, m.specific_heat_j_kgk}) {
    if (!(v > 0.0) || !std::isfinite(v)) {
      return makeError(ErrorCode::kInvalidArgument, "casting: material properties must be positive");
    }
  }
  if (!std::isfinite(a.liquidus_c) || !std::isfinite(a.solidus_c) || a.liquidus_c < a.solidus_c ||
      !(m.temperature_c > -273.15) || m.temperature_c >= a.solidus_c || !(p_.superheat_k >= 0.0) ||
      !std::isfinite(p_.superheat_k)) {
    return makeError(ErrorCode::kInvalidArgument,
                     "casting: the mould must start between -273.15 C and the solidus, the liquidus not below the "
                     "solidus, and the superheat must be a number of kelvin, not negative");
  }
  if (!(p_.metres_per_unit > 0.0) || !std::isfinite(p_.metres_per_unit)) {
    return makeError(ErrorCode::kInvalidArgument, "casting needs the part's length units");
  }
  if (part_.empty() || part_.filledCount() == 0) {
    return makeError(ErrorCode::kInvalidArgument, "casting: the part has no voxels");
  }
  if (p_.modulus && (p_.modulus->dims != part_.dims())) {
    return makeError(ErrorCode::kInvalidArgument, "casting: the modulus field is not over the part's grid");
  }
  return Ok{};
}

// V/A of the whole part from its voxels and their exposed faces (when no modulus field is given): the time estimate
// and the envelope then follow the part's bulk.
double facesModulus(const VoxelGrid& g) {
  int64_t voxels = 0, faces = 0;
  for (int32_t z = 0; z < g.nz(); ++z)
    for (int32_t y = 0; y < g.ny(); ++y)
      for (int32_t x = 0; x < g.nx(); ++x) {
        if (!g.get(x, y, z)) continue;
        ++voxels;
        faces += !g.get(x - 1, y, z) + !g.get(x + 1, y, z) + !g.get(x, y - 1, z) + !g.get(x, y + 1, z) +
                 !g.get(x, y, z - 1) + !g.get(x, y, z + 1);
      }
  // a staircase's faces are about 1.5 times the smooth surface they stand for
  return faces > 0 ? 1.5 * double(voxels) / double(faces) * g.voxelSize() : g.voxelSize();
}

Status Solidifier::layout() {
  if (Status s = checkParams(); !s) return s;
  const MouldMaterial& m = p_.mould;
  // The result box: the part's grid grown to hold the feeders.
  const GridFrame& frame = part_.frame();
  glm::ivec3 lo(0), hi(part_.nx() - 1, part_.ny() - 1, part_.nz() - 1);
  double modulus = 0.0;
  for (const Feeder& f : p_.feeders) {
    glm::ivec3 flo, fhi;
    if (!feederBox(f, frame, flo, fhi)) {
      return makeError(ErrorCode::kInvalidArgument, "casting: a feeder lies too far from the part to hold");
    }
    if (glm::any(glm::greaterThan(flo, fhi))) {
      return makeError(ErrorCode::kInvalidArgument, "casting: a feeder holds no voxel (smaller than a voxel)");
    }
    lo = glm::min(lo, flo);
    hi = glm::max(hi, fhi);
    modulus = std::max(modulus, feederModulus(f));
  }
  if (p_.modulus) {
    for (const float v : p_.modulus->values) modulus = std::max(modulus, double(v));
  } else {
    modulus = std::max(modulus, facesModulus(part_));
  }
  modulus = std::max(modulus, part_.voxelSize());
  h_m_ = part_.voxelSize() * p_.metres_per_unit;
  out_.estimate_s = chvorinovSeconds(p_, modulus * p_.metres_per_unit);
  if (!(out_.estimate_s > 0.0) || !std::isfinite(out_.estimate_s)) {
    return makeError(ErrorCode::kInvalidArgument, "casting: these materials and temperatures give no freezing time");
  }
  out_.time_step_s = out_.estimate_s / std::max(p_.steps_per_estimate, 8);
  const double alpha = m.conductivity_w_mk / (m.density_kg_m3 * m.specific_heat_j_kgk);
  const double envelope =
      p_.envelope > 0.0 ? p_.envelope * p_.metres_per_unit : 3.5 * std::sqrt(alpha * 1.5 * out_.estimate_s);
  const auto e = int32_t(std::clamp(std::ceil(envelope / h_m_), 2.0, 4096.0));
  out_.envelope_voxels = e;
  const glm::ivec3 size = hi - lo + 1;
  for (int axis = 0; axis < 3; ++axis) {
    if (int64_t(size[axis]) + 2 * e > VoxelGrid::kMaxDim) {
      return makeError(ErrorCode::kLimit, "casting: the part with its feeders and mould is over " +
                                              std::to_string(VoxelGrid::kMaxDim) + " voxels along an axis");
    }
  }
  out_.dims = Dims{size.x, size.y, size.z};
  out_.part_offset = -lo;
  out_.frame = frame;
  out_.frame.origin = frame.origin + glm::dvec3(lo) * frame.voxel_size;
  result_lo_ = glm::ivec3(p_.symmetry.x ? 0 : e, p_.symmetry.y ? 0 : e, p_.symmetry.z ? 0 : e);
  box_ = Dims{size.x + 2 * result_lo_.x, size.y + 2 * result_lo_.y, size.z + 2 * result_lo_.z};
  out_.box = box_;
  if (box_.count() > p_.max_cells) {
    return makeError(ErrorCode::kLimit, "casting: the part with its mould is " + std::to_string(box_.nx) + " x " +
                                            std::to_string(box_.ny) + " x " + std::to_string(box_.nz) +
                                            " voxels, more than this machine can hold; use fewer voxels");
  }
  return Ok{};
}

Status Solidifier::build() {
  nx_ = box_.nx;
  ny_ = box_.ny;
  nz_ = box_.nz;
  layer_ = nx_ * ny_;
  const size_t n = size_t(box_.count());
  try {
    kind_.assign(n, kMould);
    for (auto* v : {&t_, &h_, &c_, &d_}) v->assign(n, 0.0f);
    time_.assign(n, 0.0f);
    niyama_.assign(n, 0.0f);
    threads_ = threadsFor(box_.count());
    scratch_.assign(size_t(2 * threads_), std::vector<float>(size_t(scratchFloats())));
    xblocks_.resize(size_t(threads_));
    for (XBlock& b : xblocks_) {
      for (auto* v : {&b.t, &b.d, &b.c}) v->resize(size_t(nx_ * 16));
      b.kind.resize(size_t(nx_ * 16));
    }
  } catch (const std::bad_alloc&) {
    return makeError(ErrorCode::kLimit, "casting: cannot allocate " +
                                            std::to_string(estimateCastingBytes(part_, p_) >> 20) +
                                            " MiB for the simulation");
  }
  const glm::ivec3 off = result_lo_ + out_.part_offset;  // the part's voxel (0, 0, 0) in the box
  for (int32_t z = 0; z < part_.nz(); ++z)
    for (int32_t y = 0; y < part_.ny(); ++y)
      for (int32_t x = 0; x < part_.nx(); ++x)
        if (part_.get(x, y, z)) kind_[size_t((x + off.x) + nx_ * ((y + off.y) + ny_ * (z + off.z)))] = kMetal;
  out_.feeders.clear();
  if (Status st = markFeeders(off); !st) return st;
  const double pour = p_.alloy.liquidus_c + p_.superheat_k, h_pour = metal_.enthalpy(pour);
  mould_rc_ = p_.mould.density_kg_m3 * p_.mould.specific_heat_j_kgk;
  for (size_t i = 0; i < n; ++i) {
    if (kind_[i] & kMetal) {
      ++metal_cells_;
      t_[i] = float(pour);
      h_[i] = float(h_pour);
    } else {
      t_[i] = float(p_.mould.temperature_c);
      h_[i] = float(mould_rc_ * p_.mould.temperature_c);
    }
  }
  const double k[2] = {p_.mould.conductivity_w_mk, p_.alloy.conductivity_w_mk};
  double g[2][2];  // face conductances k / h^2 (W / m^3 K), mould or metal on each side
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) g[a][b] = 2.0 * k[a] * k[b] / (k[a] + k[b]) / (h_m_ * h_m_);
  conductance_ = Conductance{float(g[0][0]), float(g[1][0] - g[0][0]), float(g[0][1] - g[0][0]),
                             float(g[1][1] - g[1][0] - g[0][1] + g[0][0])};
  return Ok{};
}

// Whether voxel v (any index) or one of its face neighbours is the part's.
bool Solidifier::partNear(glm::ivec3 v) const {
  const auto filled = [&](glm::ivec3 q) { return part_.inBounds(q.x, q.y, q.z) && part_.get(q.x, q.y, q.z); };
  return filled(v) || filled(v + glm::ivec3(1, 0, 0)) || filled(v - glm::ivec3(1, 0, 0)) ||
         filled(v + glm::ivec3(0, 1, 0)) || filled(v - glm::ivec3(0, 1, 0)) || filled(v + glm::ivec3(0, 0, 1)) ||
         filled(v - glm::ivec3(0, 0, 1));
}

// The feeders' voxels outside the part (kMetal | kFeeder); each must touch the part (a voxel of it, or one beside it).
Status Solidifier::markFeeders(glm::ivec3 off) {
  const double h3 = std::pow(part_.voxelSize(), 3);
  for (size_t n = 0; n < p_.feeders.size(); ++n) {
    const Feeder& f = p_.feeders[n];
    glm::ivec3 lo, hi;
    feederBox(f, part_.frame(), lo, hi);
    int64_t added = 0;
    bool touches = false;
    for (int32_t z = lo.z; z <= hi.z; ++z)
      for (int32_t y = lo.y; y <= hi.y; ++y)
        for (int32_t x = lo.x; x <= hi.x; ++x) {
          if (!inFeeder(f, part_.frame(), glm::ivec3(x, y, z))) continue;
          touches = touches || partNear(glm::ivec3(x, y, z));
          uint8_t& k = kind_[size_t((x + off.x) + nx_ * ((y + off.y) + ny_ * (z + off.z)))];
          if (k == kMould) {
            k = kMetal | kFeeder;
            ++added;
          }
        }
    if (!touches) {
      char where[96];
      std::snprintf(where, sizeof where, "(%.4g, %.4g, %.4g)", f.base.x, f.base.y, f.base.z);
      return makeError(ErrorCode::kInvalidArgument, "casting: feeder " + std::to_string(n + 1) + " at " + where +
                                                        " does not touch the part, so it cannot feed it");
    }
    out_.feeders.push_back(FeederResult{f, feederModulus(f), double(added) * h3});
  }
  return Ok{};
}

// The capacity over the step: C / dt (W / m^3 K) into c_; d_ zeroed for the sweeps' sums.
void Solidifier::capacities(double dt) {
  parallelChunks(0, nz_, 4, threads_, [&](int, int64_t zb, int64_t ze) {
    for (int64_t i = layer_ * zb; i < layer_ * ze; ++i) {
      const double c = (kind_[size_t(i)] & kMetal) ? metal_.capacity(h_[size_t(i)]) : mould_rc_;
      c_[size_t(i)] = float(c / dt);
      d_[size_t(i)] = 0.0f;
    }
  });
}

// One direction's implicit step for the lines of `r`: with the temperature so far T = t + d, the change E solving
// (C / dt - L) E = L T along them (L the conduction between neighbours along the line; Thomas's algorithm), left in
// dp (n rows of width). Temperature differences are taken as (t - t') + (d - d'), which keeps float's precision.
void solveRows(const LineRows& r, const Conductance& conductance, float* cp, float* dp) {
  const Conductance g = conductance;  // a copy: no store in the loops can change it
  const int64_t w_n = r.width;
  std::fill(cp, cp + w_n, 0.0f);
  std::fill(dp, dp + w_n, 0.0f);
  for (int64_t k = 0; k < r.n; ++k) {
    const int64_t below = k > 0 ? -r.stride : 0, above = k + 1 < r.n ? r.stride : 0;
    const float has_below = k > 0 ? 1.0f : 0.0f, has_above = k + 1 < r.n ? 1.0f : 0.0f;
    const float* t = r.t + k * r.stride;
    const float* d = r.d + k * r.stride;
    const uint8_t* kind = r.kind + k * r.stride;
    const float* c = r.c + k * r.stride;
    const float* pc = cp + (k > 0 ? k - 1 : 0) * w_n;  // k = 0: the row itself, zeroed first
    const float* pd = dp + (k > 0 ? k - 1 : 0) * w_n;
    float* oc = cp + k * w_n;
    float* od = dp + k * w_n;
    int64_t w = 0;
    for (; w + 4 <= w_n; w += 4) {  // four lines at a time (GCC's vector extension: SSE on any x86-64)
      const V4 ki = metalOf(kind + w), kb = metalOf(kind + w + below), ka = metalOf(kind + w + above);
      const V4 gb = has_below * g(ki, kb), ga = has_above * g(ki, ka);
      const V4 ti = load4(t + w), di = load4(d + w);
      const V4 rhs = gb * ((load4(t + w + below) - ti) + (load4(d + w + below) - di)) +
                     ga * ((load4(t + w + above) - ti) + (load4(d + w + above) - di));
      const V4 inv = 1.0f / (load4(c + w) + gb + ga + gb * load4(pc + w));
      const V4 pdw = load4(pd + w);
      store4(oc + w, -ga * inv);
      store4(od + w, (rhs + gb * pdw) * inv);
    }
    for (; w < w_n; ++w) {
      const float ki = float(kind[w] & 1), kb = float(kind[w + below] & 1), ka = float(kind[w + above] & 1);
      const float gb = has_below * g(ki, kb), ga = has_above * g(ki, ka);
      const float rhs =
          gb * ((t[w + below] - t[w]) + (d[w + below] - d[w])) + ga * ((t[w + above] - t[w]) + (d[w + above] - d[w]));
      const float inv = 1.0f / (c[w] + gb + ga + gb * pc[w]);
      const float pdw = pd[w];
      oc[w] = -ga * inv;
      od[w] = (rhs + gb * pdw) * inv;
    }
  }
  for (int64_t k = r.n - 2; k >= 0; --k) {
    float* od = dp + k * w_n;
    const float* oc = cp + k * w_n;
    const float* next = dp + (k + 1) * w_n;
    for (int64_t w = 0; w < w_n; ++w) od[w] -= oc[w] * next[w];
  }
}

// The span [w0, w1) of lines not all within kSameKelvin of their first cell (the cold mould far out gains nothing
// from a solve); cp holds width values of scratch.
std::pair<int64_t, int64_t> changingLines(const LineRows& r, float* cp, float* first) {
  constexpr float kSameKelvin = 1e-4f;
  for (int64_t w = 0; w < r.width; ++w) {
    first[w] = r.t[w] + r.d[w];
    cp[w] = 0.0f;
  }
  for (int64_t k = 1; k < r.n; ++k) {
    const float* t = r.t + k * r.stride;
    const float* d = r.d + k * r.stride;
    for (int64_t w = 0; w < r.width; ++w) cp[w] = std::max(cp[w], std::abs((t[w] + d[w]) - first[w]));
  }
  int64_t w0 = 0, w1 = r.width;
  while (w0 < w1 && cp[w0] <= kSameKelvin) ++w0;
  while (w1 > w0 && cp[w1 - 1] <= kSameKelvin) --w1;
  return {w0, w1};
}

// Lines side by side in the box (cells base + k stride + w): solved where they change, E added to d_.
void Solidifier::solveLines(int64_t base, int64_t stride, int64_t n, int64_t width, float* cp, float* dp) {
  LineRows r{t_.data() + base, d_.data() + base, kind_.data() + base, c_.data() + base, stride, n, width};
  const auto [w0, w1] = changingLines(r, cp, dp);
  if (w0 >= w1) return;
  r.t += w0;
  r.d += w0;
  r.kind += w0;
  r.c += w0;
  r.width = w1 - w0;
  solveRows(r, conductance_, cp, dp);
  for (int64_t k = 0; k < n; ++k) {
    float* d = d_.data() + base + w0 + k * stride;
    const float* e = dp + k * r.width;
    for (int64_t w = 0; w < r.width; ++w) d[w] += e[w];
  }
}

// Rows along x, kRowBlock at a time: copied across into lines side by side (x becomes the row, the rows the
// width), solved, and E added back.
void Solidifier::solveXRows(int64_t row, int64_t rows, float* cp, float* dp, XBlock& b) {
  const size_t cells = size_t(nx_ * rows);
  b.t.resize(cells);
  b.d.resize(cells);
  b.kind.resize(cells);
  b.c.resize(cells);
  for (int64_t r = 0; r < rows; ++r) {
    const int64_t from = row + r * nx_;
    for (int64_t x = 0; x < nx_; ++x) {
      const size_t to = size_t(x * rows + r);
      b.t[to] = t_[size_t(from + x)];
      b.d[to] = d_[size_t(from + x)];
      b.kind[to] = kind_[size_t(from + x)];
      b.c[to] = c_[size_t(from + x)];
    }
  }
  const LineRows lines{b.t.data(), b.d.data(), b.kind.data(), b.c.data(), rows, nx_, rows};
  solveRows(lines, conductance_, cp, dp);
  for (int64_t r = 0; r < rows; ++r) {
    const int64_t to = row + r * nx_;
    for (int64_t x = 0; x < nx_; ++x) d_[size_t(to + x)] += dp[x * rows + r];
  }
}

// The three directions, one after another (each a backward Euler step along its lines: a convex combination of the
// temperatures about each cell, so no direction can overshoot, whatever the step and the materials).
void Solidifier::sweeps() {
  constexpr int64_t kRowBlock = 16;
  parallelChunks(0, nz_, 1, threads_, [&](int thread, int64_t zb, int64_t ze) {
    float* cp = scratch(thread, 0, nx_ * kRowBlock);
    float* dp = scratch(thread, 1, nx_ * kRowBlock);
    XBlock& block = xblocks_[size_t(thread)];
    for (int64_t z = zb; z < ze; ++z)
      for (int64_t y = 0; y < ny_; y += kRowBlock) {
        solveXRows(nx_ * (y + ny_ * z), std::min(kRowBlock, ny_ - y), cp, dp, block);
      }
  });
  parallelChunks(0, nz_, 1, threads_, [&](int thread, int64_t zb, int64_t ze) {
    float* cp = scratch(thread, 0, layer_);
    float* dp = scratch(thread, 1, layer_);
    for (int64_t z = zb; z < ze; ++z) solveLines(layer_ * z, nx_, ny_, nx_, cp, dp);
  });
  parallelChunks(0, ny_, 1, threads_, [&](int thread, int64_t yb, int64_t ye) {
    float* cp = scratch(thread, 0, nx_ * nz_);
    float* dp = scratch(thread, 1, nx_ * nz_);
    for (int64_t y = yb; y < ye; ++y) solveLines(nx_ * y, layer_, nz_, nx_, cp, dp);
  });
}

// H += C dT, T from H (into d_, swapped with t_ by the caller), and the metal's freezing as it happens. Returns the
// metal cells still above the solidus.
int64_t Solidifier::update(double t, double dt) {
  std::vector<int64_t> liquid(size_t(threads_), 0);
  const double h_m = h_m_;
  parallelChunks(0, nz_, 4, threads_, [&](int thread, int64_t zb, int64_t ze) {
    int64_t count = 0;
    for (int64_t z = zb; z < ze; ++z)
      for (int64_t y = 0; y < ny_; ++y)
        for (int64_t x = 0; x < nx_; ++x) {
          const int64_t i = x + nx_ * (y + ny_ * z);
          const double old_h = h_[size_t(i)];
          const double new_h = old_h + double(c_[size_t(i)]) * dt * double(d_[size_t(i)]);
          h_[size_t(i)] = float(new_h);
          if (!(kind_[size_t(i)] & kMetal)) {
            d_[size_t(i)] = float(new_h / mould_rc_);
            continue;
          }
          const double new_t = metal_.temperature(new_h);
          d_[size_t(i)] = float(new_t);
          if (new_h >= 0.0) ++count;
          if (old_h >= 0.0 && new_h < 0.0) time_[size_t(i)] = float(t + dt * old_h / (old_h - new_h));
          if (old_h >= metal_.h_crit && new_h < metal_.h_crit) {
            const auto at = [&](int64_t q) { return double(t_[size_t(q)]); };
            // the gradient within the metal: central where both neighbours along an axis are metal, one-sided
            // where one is (the mould's temperature jumps at the wall), none where neither is
            const auto axis = [&](bool has_lo, bool has_hi, int64_t step) {
              const bool lo = has_lo && (kind_[size_t(i - step)] & kMetal),
                         hi = has_hi && (kind_[size_t(i + step)] & kMetal);
              if (lo && hi) return (at(i + step) - at(i - step)) / 2.0;
              if (hi) return at(i + step) - at(i);
              if (lo) return at(i) - at(i - step);
              return 0.0;
            };
            const double gx = axis(x > 0, x + 1 < nx_, 1), gy = axis(y > 0, y + 1 < ny_, nx_),
                         gz = axis(z > 0, z + 1 < nz_, layer_);
            const double gradient = std::sqrt(gx * gx + gy * gy + gz * gz) / h_m / 1000.0;  // K / mm
            const double rate = std::max((at(i) - new_t) / dt, 1e-6);                       // K / s
            niyama_[size_t(i)] = float(gradient / std::sqrt(rate));
          }
        }
    liquid[size_t(thread)] += count;
  });
  int64_t total = 0;
  for (const int64_t v : liquid) total += v;
  return total;
}

Status Solidifier::simulate() {
  const double dt = out_.time_step_s, limit = 50.0 * out_.estimate_s;
  double t = 0.0;
  for (;;) {
    capacities(dt);
    sweeps();
    const int64_t liquid = update(t, dt);
    std::swap(t_, d_);
    t += dt;
    ++out_.steps;
    if (!gate_.report(0.98 * double(metal_cells_ - liquid) / double(metal_cells_))) {
      return makeError(ErrorCode::kCancelled, "casting simulation cancelled");
    }
    if (liquid == 0) break;
    if (t > limit) {
      return makeError(ErrorCode::kLimit, "casting: the metal had not frozen after " + shortNumber(t) +
                                              " s, 50 times Chvorinov's estimate; the mould cannot take its heat");
    }
  }
  return Ok{};
}

void Solidifier::collect() {
  const Dims& d = out_.dims;
  out_.time = ScalarField(d, out_.frame);
  out_.niyama = ScalarField(d, out_.frame);
  out_.metal = VoxelGrid(d, out_.frame);
  out_.feeder_voxels = VoxelGrid(d, out_.frame);
  int64_t casting = 0;
  for (int32_t z = 0; z < d.nz; ++z)
    for (int32_t y = 0; y < d.ny; ++y)
      for (int32_t x = 0; x < d.nx; ++x) {
        const size_t i = size_t((x + result_lo_.x) + nx_ * ((y + result_lo_.y) + ny_ * (z + result_lo_.z)));
        const uint8_t k = kind_[i];
        if (!(k & kMetal)) continue;
        out_.time.at(x, y, z) = time_[i];
        out_.niyama.at(x, y, z) = niyama_[i];
        out_.metal.set(x, y, z);
        if (k & kFeeder) {
          out_.feeder_voxels.set(x, y, z);
        } else {
          ++casting;
          out_.solidification_s = std::max(out_.solidification_s, double(time_[i]));
        }
        out_.last_metal_s = std::max(out_.last_metal_s, double(time_[i]));
      }
  const double h3 = std::pow(part_.voxelSize(), 3);
  out_.casting_volume = double(casting) * h3;
  for (const FeederResult& f : out_.feeders) out_.feeder_volume += f.volume;
  out_.yield = out_.casting_volume / (out_.casting_volume + out_.feeder_volume);
  for (auto* v : {&t_, &h_, &c_, &d_, &niyama_}) *v = {};
  GridFrame box_frame = out_.frame;
  box_frame.origin -= glm::dvec3(result_lo_) * box_frame.voxel_size;
  auto spots = casting_detail::findTimeSpots(box_, kind_, time_, box_frame, 3.0 * out_.time_step_s, 0.02,
                                             std::max<int64_t>(27, metal_cells_ / 500));
  const glm::ivec3 part_lo = result_lo_ + out_.part_offset;
  for (casting_detail::TimeSpot& found : spots) {
    CastingHotSpot& spot = found.spot;
    const int64_t cell = found.cell;
    const glm::ivec3 v(int32_t(cell % nx_), int32_t(cell / nx_ % ny_), int32_t(cell / layer_));
    if (spot.in_feeder) {
      for (const FeederResult& f : out_.feeders)
        if (inFeeder(f.feeder, part_.frame(), v - part_lo)) {
          spot.modulus = f.modulus;
          break;
        }
    } else if (p_.modulus) {
      const glm::ivec3 q = v - part_lo;
      spot.modulus = p_.modulus->at(q.x, q.y, q.z);
    }
    out_.hot_spots.push_back(spot);
  }
  verdict();
}

void Solidifier::verdict() {
  const CastingHotSpot* worst = nullptr;
  int64_t isolated = 0;
  for (const CastingHotSpot& s : out_.hot_spots) {
    if (!s.isolated || s.in_feeder) continue;
    ++isolated;
    if (!worst) worst = &s;
  }
  out_.sound = isolated == 0;
  if (out_.sound) {
    const CastingHotSpot& last = out_.hot_spots.front();
    out_.verdict = "Sound: the metal freezes last in a feeder, at " + pointText(last.centre) + " after " +
                   shortNumber(last.solidification_s) + " s, and every region of the casting feeds toward it.";
    return;
  }
  out_.verdict = "Not sound: " + countOf(isolated, "isolated hot spot") + " in the casting. The latest freezes at " +
                 pointText(worst->centre) + " after " + shortNumber(worst->solidification_s) + " s" +
                 (out_.feeders.empty() ? " with nothing to feed it"
                                       : ", cut off from the feeders by metal that freezes before it") +
                 (worst->modulus > 0.0
                      ? "; a feeder there needs a modulus of at least 1.2 x " + shortNumber(worst->modulus) + " = " +
                            shortNumber(1.2 * worst->modulus) + " " + unitsLabel(part_.frame().units) + "."
                      : ".");
}

}  // namespace

int64_t estimateCastingBytes(const VoxelGrid& part, const CastingParams& params) {
  const ProgressFn none;
  Solidifier s(part, params, none);
  if (!s.layout()) return 0;
  // kind 1, T H C D time niyama 4 each, then the hot spots' order, parents and sets (8 each); the sweeps' scratch
  return s.cells() * (1 + 6 * 4 + 24) + s.scratchBytes();
}

Status checkCasting(const VoxelGrid& part, const CastingParams& params) {
  const ProgressFn none;
  return Solidifier(part, params, none).layout();
}

Result<CastingResult> simulateCasting(const VoxelGrid& part, const CastingParams& params, const ProgressFn& progress) {
  return Solidifier(part, params, progress).run();
}

}  // namespace vox
