// Parity and nonzero mode: one pass of rays along X, a row of rays per Z layer (thesis 4.3: scan-line voxelization
// along X, layer by layer). Each crossing becomes a toggle of the first voxel past it, written straight into the
// grid's layer; a prefix XOR along each row then turns the toggles into the voxels inside. Parity toggles at every
// crossing, in any order; nonzero sorts each ray's crossings along it and toggles only where the winding number
// changes between zero and nonzero.
#include <cstdint>
#include <string>
#include <vector>

#include "vox/voxelize/voxelize.h"
#include "voxelize/passes.h"
#include "voxelize/ray_caster.h"

namespace vox::voxelize_detail {

namespace {

enum class Rule { kParity, kNonzero };

// Per-thread scratch and counters of a pass.
struct PassScratch {
  std::vector<int32_t> by_first;  // counting sort of crossings by first voxel
  std::vector<Crossing> along;    // crossings sorted by first voxel
  std::vector<int32_t> winding;   // by ray: the winding number so far (zero between rows)
  std::vector<int32_t> seen;      // by ray: crossings so far (zero between rows)
  int64_t odd_rays = 0;           // rays with an odd number of crossings
  int64_t unbalanced_rays = 0;    // rays whose signed crossings do not sum to zero
};

struct PassStats {
  int64_t odd_rays = 0, unbalanced_rays = 0, rays = 0;
};

PassStats sumStats(const std::vector<PassScratch>& scratch, const RayCaster& caster) {
  PassStats s;
  for (const auto& p : scratch) {
    s.odd_rays += p.odd_rays;
    s.unbalanced_rays += p.unbalanced_rays;
  }
  s.rays = int64_t(caster.rows()) * caster.raysPerRow();
  return s;
}

// Rays along X, row = layer z (parity and nonzero mode): marks, for each ray y, the voxels x where being inside
// changes, as toggled bits in `layer` (the grid's layout: bit x + 1 of row y + 1, x = the first voxel past the
// crossing, 0..nx), and flags the row in `marked`; the voxels inside a ray are then those with an odd number of
// toggles up to them, a prefix XOR along the row (fillToggledRows). Parity toggles at every crossing, in any order.
// Nonzero needs each ray's crossings in order along it: the winding number from -infinity changes at each, and a
// toggle goes where it changes between zero and nonzero. Toggles at the same voxel cancel, so crossings with the
// same ray and first voxel may come in either order.
void markRowAlongX(int32_t ny, int32_t nx, const CrossingList& crossings, Rule rule, PassScratch& s, uint64_t* layer,
                   uint8_t* marked, int64_t wpr) {
  if (crossings.empty()) return;
  // Toggles bit x + 1 of padded row y + 1 when `on`.
  auto toggle = [layer, wpr](int32_t y, int32_t x, bool on) {
    const int64_t xp = int64_t(x) + 1;
    layer[(int64_t(y) + 1) * wpr + (xp >> 6)] ^= uint64_t(on) << (xp & 63);
  };
  if (rule == Rule::kParity) {
    for (const Crossing& c : crossings) {
      toggle(c.ray(), c.first(), true);
      marked[c.ray() + 1] = 1;
    }
    return;  // odd rays: the parity past the row's last voxel (fillToggledRows)
  }
  // All rays at once, in order along them: one counting sort by first voxel, O(nx + ny + crossings) without a
  // data-dependent branch, then each crossing updates its ray's winding number, kept per ray. The order across rays
  // does not matter, and within a ray it is the order along it. (An insertion sort per ray mispredicts on nearly
  // every step where rays cross many bodies; the state per ray saves the second counting sort, by ray, that
  // walking each ray in turn would need.)
  const size_t count = crossings.size();
  if (s.winding.size() != size_t(ny)) {
    s.winding.assign(size_t(ny), 0);
    s.seen.assign(size_t(ny), 0);
  }
  // Two halves counted and scattered side by side, each with its own counts: consecutive crossings often share a
  // first voxel, and one array of counts would make each increment wait for the one before.
  const size_t bins = size_t(nx) + 1, half = count / 2;
  s.by_first.assign(2 * bins, 0);
  int32_t* const h0 = s.by_first.data();
  int32_t* const h1 = h0 + bins;
  const Crossing* const c0 = crossings.begin();
  const Crossing* const c1 = c0 + half;
  for (size_t i = 0; i < half; ++i) {
    ++h0[c0[i].first()];
    ++h1[c1[i].first()];
  }
  if (count % 2 != 0) ++h1[c1[half].first()];
  // h0: where the first half's crossings of each voxel go, h1 the second half's (after the first half's).
  int32_t at = 0;
  for (size_t i = 0; i < bins; ++i) {
    const int32_t n0 = h0[i], n1 = h1[i];
    h0[i] = at;
    h1[i] = at + n0;
    at += n0 + n1;
  }
  s.along.resize(count);
  Crossing* const along = s.along.data();
  for (size_t i = 0; i < half; ++i) {
    along[h0[c0[i].first()]++] = c0[i];
    along[h1[c1[i].first()]++] = c1[i];
  }
  if (count % 2 != 0) along[h1[c1[half].first()]++] = c1[half];
  // Winding number from -infinity: entering a solid (normal pointing to -u, sign -1) adds one. Branch-free: where
  // rays cross many bodies, whether the winding is zero changes unpredictably.
  int32_t* const winding = s.winding.data();
  int32_t* const seen = s.seen.data();
  for (const Crossing& c : s.along) {
    const int32_t j = c.ray();
    const int32_t before = winding[j], after = before - c.sign();
    winding[j] = after;
    ++seen[j];
    toggle(j, c.first(), (before != 0) != (after != 0));
  }
  // Each ray's totals, and its state set back to zero for the next row (branch-free: a ray without crossings adds
  // nothing, and its row stays unmarked).
  int64_t unbalanced = 0, odd = 0;
  for (int32_t j = 0; j < ny; ++j) {
    marked[j + 1] |= seen[j] != 0 ? 1 : 0;
    unbalanced += winding[j] != 0 ? 1 : 0;
    odd += seen[j] & 1;
    winding[j] = 0;
    seen[j] = 0;
  }
  s.unbalanced_rays += unbalanced;
  s.odd_rays += odd;
}

// Turns the toggles of each marked row of `layer` (grid layout, rows 1..ny of wpr words), in place, into the voxels
// with an odd number of toggles up to them (a prefix XOR along the row, carried from word to word), masked to the
// row's voxels. Leaves `marked` zeroed.
struct FilledRows {
  int64_t odd = 0;   // marked rows with an odd number of toggles in all
  bool any = false;  // some voxel is inside
};
FilledRows fillToggledRows(uint64_t* layer, uint8_t* marked, int32_t ny, int64_t wpr,
                           const std::vector<uint64_t>& valid) {
  const uint64_t* const valid_bits = valid.data();
  FilledRows f;
  uint64_t any = 0;
  for (int64_t yp = 1; yp <= ny; ++yp) {
    if (marked[yp] == 0) continue;
    marked[yp] = 0;
    uint64_t* const row = layer + yp * wpr;
    uint64_t carry = 0;
    for (int64_t w = 0; w < wpr; ++w) {
      row[w] = parityWord(row[w], carry) & valid_bits[w];
      any |= row[w];
    }
    f.odd += int64_t(carry & 1);
  }
  f.any = any != 0;
  return f;
}

// The warnings of a pass along X: rays with an odd number of crossings, and in nonzero mode rays whose winding does
// not come back to zero (both 0 on a closed mesh).
void warnAboutRays(const PassStats& stats, Rule rule, std::vector<std::string>& warnings) {
  if (stats.odd_rays > 0) {
    warnings.push_back("odd number of crossings on " + std::to_string(stats.odd_rays) + " of " +
                       std::to_string(stats.rays) +
                       " rays along X: the mesh is not closed along them (a closed mesh gives 0)");
  }
  if (rule == Rule::kNonzero && stats.unbalanced_rays > 0) {
    warnings.push_back("nonzero total winding on " + std::to_string(stats.unbalanced_rays) + " of " +
                       std::to_string(stats.rays) +
                       " rays along X: the mesh is open or inconsistently oriented along them");
  }
}

}  // namespace

struct LayerFiller::State {
  State(const PassInput& in, FillMode mode, int64_t wpr)
      : rule(mode == FillMode::kParity ? Rule::kParity : Rule::kNonzero),
        caster(in.mesh, in.placement, kRaysAlongX, in.threads),
        scratch(static_cast<size_t>(in.threads)),
        marked(static_cast<size_t>(in.threads)),
        valid(validRowBits(wpr, in.placement.dims.nx)) {}
  Rule rule;
  RayCaster caster;
  std::vector<PassScratch> scratch;
  std::vector<std::vector<uint8_t>> marked;  // rows holding a toggle (by padded row), per thread
  std::vector<uint64_t> valid;
};

LayerFiller::LayerFiller(const PassInput& in, FillMode mode)
    : in_(in), state_(std::make_unique<State>(in, mode, VoxelGrid(Dims{in.placement.dims.nx, 1, 1}).wordsPerRow())) {}

LayerFiller::~LayerFiller() = default;

bool LayerFiller::fill(int32_t z0, int32_t z1, VoxelGrid& target, int32_t z_offset) {
  const Dims dims = in_.placement.dims;
  State& st = *state_;
  const int64_t wpr = target.wordsPerRow();
  // Each ray's toggles go straight into the grid's layer (allocated for a row of rays with any crossing, given
  // back if no voxel ends up inside); then each marked row becomes its inside voxels by a prefix XOR in place. Only
  // rows with a toggle are touched, so a page no such row lies in is never faulted in (VoxelGrid's layers start as
  // untouched zero memory), and nothing is copied. (A toggle is a read-modify-write of the word: on
  // cycloidal_assembly at R = 1000 it takes as many page faults as storing finished rows did, so a fresh page is
  // not faulted twice.)
  auto row = [&](int t, int32_t z, const auto& crossings) {
    if (crossings.empty()) return;
    std::vector<uint8_t>& m = st.marked[size_t(t)];
    if (m.empty()) m.assign(size_t(dims.ny) + 2, 0);
    uint64_t* const layer = target.mutableLayerWords(z - z_offset);  // only this thread writes layer z
    PassScratch& ps = st.scratch[size_t(t)];
    markRowAlongX(dims.ny, dims.nx, crossings, st.rule, ps, layer, m.data(), wpr);
    const FilledRows filled = fillToggledRows(layer, m.data(), dims.ny, wpr, st.valid);
    // Crossings that leave no voxel inside (all past every centre, or a wall between two centres): the layer goes
    // back to the shared zero layer, as if never allocated.
    if (!filled.any) target.releaseLayer(z - z_offset);
    if (st.rule == Rule::kParity) ps.odd_rays += filled.odd;
  };
  return castRows(st.caster, in_.threads, in_.gate, in_.out_of_memory, row, z0, z1);
}

void LayerFiller::warn(std::vector<std::string>& warnings) const {
  warnAboutRays(sumStats(state_->scratch, state_->caster), state_->rule, warnings);
}

RayCounts LayerFiller::counts() const {
  const PassStats s = sumStats(state_->scratch, state_->caster);
  return RayCounts{s.odd_rays, s.unbalanced_rays, s.rays};
}

void warnAboutRayCounts(const RayCounts& counts, FillMode mode, std::vector<std::string>& warnings) {
  warnAboutRays(PassStats{counts.odd, counts.unbalanced, counts.rays},
                mode == FillMode::kParity ? Rule::kParity : Rule::kNonzero, warnings);
}

bool fillAlongX(const PassInput& in, FillMode mode, VoxelizeResult& result) {
  VoxelGrid grid(in.placement.dims, in.frame);
  LayerFiller filler(in, mode);
  if (!filler.fill(0, grid.nz(), grid, 0)) return false;
  filler.warn(result.warnings);
  result.grid = std::move(grid);
  return true;
}

}  // namespace vox::voxelize_detail
