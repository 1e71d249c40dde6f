// Vote mode, for meshes with holes (F. S. Nooruddin and G. Turk, "Simplification and Repair of Polygonal Models Using
// Volumetric Techniques", IEEE TVCG 9(2):191-205, 2003: parity counts along several directions and a per-voxel vote
// make a solid out of a mesh with holes; voxmod uses the three axis directions and a majority of three).
//
// The parity along each axis comes from toggles, as in fill.cpp, with the prefix XOR running within a row's words for
// rays along X, over the rows for rays along Y, and over the layers for rays along Z (whose toggles are listed by
// layer and XORed into a running layer as the layer pass goes up). The voxels where the three disagree are kept as
// the disputed set.
#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "vox/core/bits.h"
#include "vox/core/sparse_voxels.h"
#include "vox/voxelize/voxelize.h"
#include "vox/core/parallel.h"
#include "voxelize/passes.h"
#include "voxelize/ray_caster.h"

namespace vox::voxelize_detail {

namespace {

// Per-thread scratch of vote mode's layer pass.
struct VoteScratch {
  std::vector<uint64_t> tx, ty;         // toggles along X and along Y, one layer in the grid's layout
  std::vector<uint8_t> x_rows, y_rows;  // which rows of tx and ty hold a toggle (by padded row)
  std::vector<uint64_t> y_run;          // the running Y parity, one row
  std::vector<uint64_t> d_row;          // the disputed voxels of the current row
  VoteScratch(int64_t wpl, int64_t wpr, int32_t ny)
      : tx(size_t(wpl), 0),
        ty(size_t(wpl), 0),
        x_rows(size_t(ny) + 2, 0),
        y_rows(size_t(ny) + 2, 0),
        y_run(size_t(wpr), 0),
        d_row(size_t(wpr), 0) {}
};

// Rays along X and Y in vote mode, row = layer z: each crossing toggles the bit of the first voxel past it in a
// zeroed scratch layer (the grid's layout: ny + 2 rows of wpr words, one padding bit or row on either side). The
// parity of a voxel along the ray is then the XOR of the toggles up to it: a prefix XOR within each row for rays
// along X, over the rows for rays along Y, which voteLayer computes as it reads the layer. A crossing past every
// centre toggles the padding bit (X: bit nx + 1 < wpr * 64) or row (Y: row ny + 1) just past the end, so the parity
// at the end of each ray says whether its count was odd.
void toggleAlongX(VoteScratch& s, int64_t wpr, const CrossingList& crossings) {
  for (const Crossing& c : crossings) {
    const int64_t xp = int64_t(c.first()) + 1, yp = int64_t(c.ray()) + 1;
    s.tx[size_t(yp * wpr + (xp >> 6))] ^= uint64_t(1) << (xp & 63);
    s.x_rows[size_t(yp)] = 1;
  }
}

void toggleAlongY(VoteScratch& s, int64_t wpr, const CrossingList& crossings) {
  for (const Crossing& c : crossings) {
    const int64_t xp = int64_t(c.ray()) + 1, yp = int64_t(c.first()) + 1;
    s.ty[size_t(yp * wpr + (xp >> 6))] ^= uint64_t(1) << (xp & 63);
    s.y_rows[size_t(yp)] = 1;
  }
}

struct VoteCounts {
  int64_t odd_x = 0, odd_y = 0;
};

// One layer of vote mode, in one pass over its words: s.tx and s.ty hold the layer's toggles along X and Y
// (toggleAlongX/Y), bz the parity along Z. Row by row, the X parity is the prefix XOR of tx's row (carried from
// word to word), the Y parity a running row that each row of ty is XORed into; the majority of the three goes to
// layer z of `grid` (allocated at its first nonzero word), the voxels where they differ to `disputed`, a row at a
// time.
// Rows where all three parities are zero are skipped. `valid` masks each word of a row to the voxels 0..nx - 1.
// Leaves the scratch zeroed for the next layer.
void voteLayer(int32_t z, int32_t ny, int64_t wpr, const std::vector<uint64_t>& valid, VoteScratch& s,
               const uint64_t* bz, VoxelGrid& grid, SparseVoxels::Chunk& disputed_rows, VoteCounts& counts) {
  uint64_t* c = nullptr;
  uint64_t* const d_row = s.d_row.data();
  uint64_t* const y_run = s.y_run.data();
  const uint64_t* const valid_bits = valid.data();
  uint8_t* const x_rows = s.x_rows.data();
  uint8_t* const y_rows = s.y_rows.data();
  uint64_t* const tx = s.tx.data();
  uint64_t* const ty = s.ty.data();
  std::fill(s.y_run.begin(), s.y_run.end(), 0);
  bool y_any = false;  // some word of y_run is nonzero
  int64_t odd_x = 0;
  for (int64_t yp = 1; yp <= ny; ++yp) {
    uint64_t* const tx_row = tx + yp * wpr;
    const uint64_t* z_row = bz + yp * wpr;
    if (y_rows[yp] != 0) {
      y_rows[yp] = 0;
      uint64_t* const ty_row = ty + yp * wpr;
      uint64_t any = 0;
      for (int64_t w = 0; w < wpr; ++w) {
        y_run[w] ^= ty_row[w];
        ty_row[w] = 0;
        any |= y_run[w];
      }
      y_any = any != 0;
    }
    const bool x_any = x_rows[yp] != 0;
    if (!x_any && !y_any) {
      uint64_t z_any = 0;
      for (int64_t w = 0; w < wpr; ++w) z_any |= z_row[w];
      if (z_any == 0) continue;  // all three parities are zero on this row
    }
    x_rows[yp] = 0;
    uint64_t carry = 0;                  // the X parity
    int64_t d_first = wpr, d_last = -1;  // words of the row holding a disputed voxel
    for (int64_t w = 0; w < wpr; ++w) {
      const uint64_t t = tx_row[w];
      if (t != 0) tx_row[w] = 0;  // leave the scratch zeroed, storing only where there was a toggle
      const uint64_t a = parityWord(t, carry) & valid_bits[w];
      const uint64_t b = y_run[w], zz = z_row[w];
      const uint64_t r = (a & b) | (zz & (a | b));
      if (r != 0) {
        if (!c) c = grid.mutableLayerWords(z);
        c[yp * wpr + w] = r;
      }
      const uint64_t d = (a ^ b) | (a ^ zz);
      d_row[w] = d;
      if (d != 0) {
        d_first = std::min(d_first, w);
        d_last = w;
      }
    }
    if (d_last >= 0) disputed_rows.addRow(int32_t(yp - 1), z, d_first, d_last - d_first + 1, d_row + d_first);
    odd_x += int64_t(carry & 1);
  }
  // Row ny + 1: the crossings past every centre along Y. The running row is then each ray's total parity.
  const int64_t past_row = int64_t(ny) + 1;
  uint64_t* past = s.ty.data() + past_row * wpr;
  int64_t odd_y = 0;
  for (int64_t w = 0; w < wpr; ++w) {
    odd_y += popcount64(y_run[w] ^ past[w]);
    past[w] = 0;
  }
  s.y_rows[size_t(past_row)] = 0;
  counts.odd_x += odd_x;
  counts.odd_y += odd_y;
}

// Rays along Z, row = y, rays step along x: each crossing toggles bit (x, y) of the parity of every layer from
// `first` up. The toggles are kept, not applied: each slab of rows of the Z pass lists them by layer `first`, as the
// bit's position in a layer ((y + 1) * wpr * 64 + x + 1, below 2^32 for any grid voxmod accepts), and the layer pass
// XORs them into a running parity layer as it goes up in z. So the Z parity never needs a grid of its own.
// Crossings past every centre go to layer nz: no layer uses them, but with them the running layer ends as each
// ray's total parity.
struct ZToggles {
  std::vector<uint32_t> bits;  // by layer: layer z's are bits[start[z]] .. bits[start[z + 1] - 1]
  std::vector<size_t> start;   // nz + 2 entries
};

// Lists the crossings of rows r0.. of the Z pass (all of them in `crossings`, row r's from row_start[r - r0]) by
// layer: a counting sort on the layer.
void listTogglesAlongZ(int32_t r0, const CrossingList& crossings, const std::vector<size_t>& row_start, int32_t nz,
                       int64_t wpr, ZToggles& out) {
  out.start.assign(size_t(nz) + 2, 0);
  for (const Crossing& c : crossings) ++out.start[size_t(c.first()) + 1];
  for (int32_t z = 0; z <= nz; ++z) out.start[size_t(z) + 1] += out.start[size_t(z)];
  out.bits.resize(crossings.size());
  std::vector<size_t> pos(out.start.begin(), out.start.end() - 1);
  for (size_t r = 0; r + 1 < row_start.size(); ++r) {
    const int64_t row_bit = (int64_t(r0) + int64_t(r) + 1) * wpr * 64 + 1;
    for (size_t i = row_start[r]; i < row_start[r + 1]; ++i) {
      const Crossing c = crossings[i];
      out.bits[pos[size_t(c.first())]++] = uint32_t(row_bit + c.ray());
    }
  }
}

// XORs layer z's toggles of every slab into `layer`.
void applyTogglesAlongZ(const std::vector<ZToggles>& toggles, int32_t z, uint64_t* layer) {
  for (const ZToggles& t : toggles) {
    for (size_t i = t.start[size_t(z)]; i < t.start[size_t(z) + 1]; ++i) {
      const uint32_t bit = t.bits[i];
      layer[bit >> 6] ^= uint64_t(1) << (bit & 63);
    }
  }
}

// The Z pass: casts the rays along Z and lists their crossings as toggles by layer, one ZToggles per slab of rows
// (listTogglesAlongZ). Progress: one unit per row (ny). False when cancelled or out of memory.
bool listCrossingsAlongZ(const PassInput& in, int64_t wpr, std::vector<ZToggles>& toggles) {
  const int32_t nz = in.placement.dims.nz;
  const RayCaster caster(in.mesh, in.placement, kRaysAlongZ, in.threads);
  const int32_t rows = caster.rows(), row_slab = slabRows(rows, in.threads);
  toggles.resize(size_t((rows + row_slab - 1) / row_slab));
  return runSlabs(rows, in.threads, in.gate, in.out_of_memory, [&](int, int32_t r0, int32_t r1) {
    CrossingList crossings;
    std::vector<size_t> row_start{0};
    RayCaster::RowSweep sweep(caster, r0, r1);
    for (int32_t r = r0; r < r1 && !in.gate.cancelled(); ++r) {
      sweep.next(crossings);  // appends
      row_start.push_back(crossings.size());
      in.gate.advance(1);
    }
    listTogglesAlongZ(r0, crossings, row_start, nz, wpr, toggles[size_t(r0 / row_slab)]);
  });
}

// The running Z parity at the first layer of every slab (of `slab` layers) of the layer pass: each slab's toggles
// XORed together (in parallel), then accumulated over the slabs. Adds the rays along Z with an odd number of
// crossings to `odd_z`.
std::vector<std::vector<uint64_t>> zParitySnapshots(const std::vector<ZToggles>& toggles, int32_t nz, int64_t wpl,
                                                    int32_t slab, int threads, int64_t& odd_z) {
  const int32_t slabs = (nz + slab - 1) / slab;
  std::vector<std::vector<uint64_t>> snapshots(static_cast<size_t>(slabs));
  std::vector<uint64_t> last(static_cast<size_t>(wpl), 0);  // the last slab's toggles and those past it
  forLayers(slabs, threads, [&](int, int32_t k) {
    std::vector<uint64_t>& sum = k + 1 < slabs ? snapshots[size_t(k) + 1] : last;
    sum.assign(size_t(wpl), 0);
    for (int32_t z = k * slab; z < std::min(nz, (k + 1) * slab); ++z) {
      applyTogglesAlongZ(toggles, z, sum.data());
    }
    if (k + 1 == slabs) applyTogglesAlongZ(toggles, nz, sum.data());
  });
  snapshots[0].assign(size_t(wpl), 0);
  for (int32_t k = 2; k < slabs; ++k) {
    for (int64_t w = 0; w < wpl; ++w) snapshots[size_t(k)][size_t(w)] ^= snapshots[size_t(k) - 1][size_t(w)];
  }
  // The running layer past the last crossings holds each ray's total parity.
  for (int64_t w = 0; w < wpl; ++w) odd_z += popcount64(snapshots[size_t(slabs) - 1][size_t(w)] ^ last[size_t(w)]);
  return snapshots;
}

// The layer pass: casts the rays along X and Y layer by layer and votes each layer (voteLayer) into `grid`, the
// disputed rows into `disputed` (a chunk per slab), each slab of `slab` layers starting from its snapshot of the
// running Z parity (taken from `snapshots`). Progress: two units per layer. False when cancelled or out of memory.
bool voteLayers(const PassInput& in, const std::vector<ZToggles>& toggles,
                std::vector<std::vector<uint64_t>>& snapshots, int32_t slab, VoxelGrid& grid,
                std::vector<SparseVoxels::Chunk>& disputed, std::vector<VoteCounts>& counts) {
  const Dims dims = in.placement.dims;
  const int64_t wpr = grid.wordsPerRow(), wpl = grid.wordsPerLayer();
  const RayCaster along_x(in.mesh, in.placement, kRaysAlongX, in.threads);
  const RayCaster along_y(in.mesh, in.placement, kRaysAlongY, in.threads);
  const std::vector<uint64_t> valid = validRowBits(wpr, dims.nx);
  return runSlabs(dims.nz, in.threads, in.gate, in.out_of_memory, [&](int t, int32_t z0, int32_t z1) {
    CrossingList cx, cy;
    VoteScratch scratch(wpl, wpr, dims.ny);
    std::vector<uint64_t> bz = std::move(snapshots[size_t(z0 / slab)]);
    RayCaster::RowSweep sweep_x(along_x, z0, z1), sweep_y(along_y, z0, z1);
    for (int32_t z = z0; z < z1 && !in.gate.cancelled(); ++z) {
      cx.clear();
      cy.clear();
      sweep_x.next(cx);
      sweep_y.next(cy);
      toggleAlongX(scratch, wpr, cx);
      toggleAlongY(scratch, wpr, cy);
      applyTogglesAlongZ(toggles, z, bz.data());
      voteLayer(z, dims.ny, wpr, valid, scratch, bz.data(), grid, disputed[size_t(z0 / slab)], counts[size_t(t)]);
      in.gate.advance(2);  // two rows of rays (X and Y) per layer
    }
  });
}

// The warnings of vote mode: rays with an odd number of crossings along each axis (`odd`: X, Y, Z), and voxels the
// axes disagreed on.
void warnAboutVote(const std::vector<int64_t>& odd, int64_t disputed_count, std::vector<std::string>& warnings) {
  const char* axes[3] = {"X", "Y", "Z"};
  std::string odd_text;
  for (int a = 0; a < 3; ++a) {
    if (odd[size_t(a)] == 0) continue;
    if (!odd_text.empty()) odd_text += ", ";
    odd_text += std::to_string(odd[size_t(a)]) + " along " + axes[a];
  }
  if (!odd_text.empty()) {
    warnings.push_back("rays with an odd number of crossings (the mesh is open along them): " + odd_text);
  }
  if (disputed_count > 0) {
    warnings.push_back("vote: the X, Y and Z parity grids disagree on " + plural(disputed_count, "voxel") +
                       " (filled by majority; see the disputed mask)");
  }
}

}  // namespace

// Rays along Z first: their crossings become per-layer toggle lists (listTogglesAlongZ). Then, layer by layer going
// up, the toggles along X and along Y into two cache-sized scratch layers and the parity along Z in a running layer
// (the toggles of this layer XORed in); one pass over the layer's words (voteLayer) turns the toggles into parities
// and writes the per-word majority of the three into the grid (layers allocated where a word is filled), and the
// rows of voxels where the axes disagree into the slab's chunk of the disputed set (a SparseVoxels: they are usually
// few words of many rows, which as a grid would fault in a page every few words). Each slab of layers starts from a
// snapshot of the running Z parity at its first layer. Peak: the grid, the disputed rows, 4 bytes per crossing along
// Z (8 while a slab's are being listed), and a layer per slab.
bool fillByVote(const PassInput& in, VoxelizeResult& result) {
  const Dims dims = in.placement.dims;
  VoxelGrid grid(dims, in.frame);
  std::vector<int64_t> odd(3, 0);
  const int64_t wpr = grid.wordsPerRow(), wpl = grid.wordsPerLayer();
  std::vector<ZToggles> toggles;  // per slab of rows of the Z pass
  if (!listCrossingsAlongZ(in, wpr, toggles)) return false;
  const int32_t slab = slabRows(dims.nz, in.threads);
  std::vector<std::vector<uint64_t>> snapshots = zParitySnapshots(toggles, dims.nz, wpl, slab, in.threads, odd[2]);
  std::vector<VoteCounts> counts(static_cast<size_t>(in.threads));
  std::vector<SparseVoxels::Chunk> disputed(snapshots.size());  // per slab of the layer pass
  if (!voteLayers(in, toggles, snapshots, slab, grid, disputed, counts)) return false;
  result.disputed = SparseVoxels(dims, in.frame, std::move(disputed));
  result.disputed_count = result.disputed->count();
  for (const VoteCounts& c : counts) {
    odd[0] += c.odd_x;
    odd[1] += c.odd_y;
  }
  warnAboutVote(odd, result.disputed_count, result.warnings);
  result.grid = std::move(grid);
  return true;
}

}  // namespace vox::voxelize_detail
