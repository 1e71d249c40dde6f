// Booleans between parts on one lattice with different boxes: the result covers the union of the boxes; each of its
// rows is built word by word from the operands' rows read at the lattice position of the word (rowBitsAt shifts
// across word boundaries), so parts never need to be resampled or padded to a common size first. Equal boxes take
// booleanOp's path, which shares the layers only one operand has.
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "vox/analysis/analysis.h"
#include "vox/analysis/assembly.h"
#include "vox/core/parallel.h"

namespace vox {
namespace {

uint64_t combine(uint64_t a, uint64_t b, PartOp op) {
  switch (op) {
    case PartOp::kUnion:
      return a | b;
    case PartOp::kIntersection:
      return a & b;
    case PartOp::kDifference:
      return a & ~b;
    case PartOp::kXor:
      return a ^ b;
  }
  return 0;
}

template <PartOp kOp>
uint64_t combineRowAs(uint64_t* a, const uint64_t* b, int64_t n) {
  uint64_t any = 0;
  for (int64_t w = 0; w < n; ++w) {
    a[w] = combine(a[w], b[w], kOp);
    any |= a[w];
  }
  return any;
}

// a[w] = a[w] op b[w] for w in [0, n), the loop compiled once per operation; returns the OR of the results.
uint64_t combineRow(uint64_t* a, const uint64_t* b, int64_t n, PartOp op) {
  switch (op) {
    case PartOp::kUnion:
      return combineRowAs<PartOp::kUnion>(a, b, n);
    case PartOp::kIntersection:
      return combineRowAs<PartOp::kIntersection>(a, b, n);
    case PartOp::kDifference:
      return combineRowAs<PartOp::kDifference>(a, b, n);
    case PartOp::kXor:
      return combineRowAs<PartOp::kXor>(a, b, n);
  }
  return 0;
}

BoolOp toBoolOp(PartOp op) {
  switch (op) {
    case PartOp::kUnion:
      return BoolOp::kUnion;
    case PartOp::kIntersection:
      return BoolOp::kIntersection;
    case PartOp::kDifference:
      return BoolOp::kDifference;
    case PartOp::kXor:
      return BoolOp::kXor;
  }
  return BoolOp::kUnion;
}

}  // namespace

const char* partOpName(PartOp op) {
  switch (op) {
    case PartOp::kUnion:
      return "union";
    case PartOp::kIntersection:
      return "intersection";
    case PartOp::kDifference:
      return "difference";
    case PartOp::kXor:
      return "xor";
  }
  return "union";
}

std::optional<PartOp> parsePartOp(const std::string& s) {
  for (PartOp op : {PartOp::kUnion, PartOp::kIntersection, PartOp::kDifference, PartOp::kXor}) {
    if (s == partOpName(op)) return op;
  }
  return std::nullopt;
}

LatticeGrid booleanParts(const LatticeGrid& a, const LatticeGrid& b, PartOp op, const Lattice& lattice) {
  if (a.box() == b.box()) {
    VoxelGrid fa = a.grid, fb = b.grid;  // copies of layer pointers: the frames must agree for booleanOp
    fa.frame() = fb.frame() = lattice.frameAt(a.first, a.grid.frame().source);
    auto r = booleanOp(fa, fb, toBoolOp(op));
    if (r) return LatticeGrid{std::move(r).value(), a.first};
  }
  const Box3i box = unite(a.box(), b.box());
  LatticeGrid out;
  out.first = box.min;
  const glm::ivec3 s = box.size();
  out.grid = VoxelGrid(Dims{s.x, s.y, s.z}, lattice.frameAt(box.min, a.grid.frame().source));
  const int64_t wpr = out.grid.wordsPerRow(), wa = a.grid.wordsPerRow(), wb = b.grid.wordsPerRow();
  const int64_t shift_a = int64_t(box.min.x) - a.first.x, shift_b = int64_t(box.min.x) - b.first.x;
  const int64_t last_word = (int64_t(s.x) + 1) >> 6;
  const uint64_t last_mask = (uint64_t(1) << ((int64_t(s.x) + 1) & 63)) - 1;  // bits below padding bit nx + 1
  const int threads = threadsFor(int64_t(s.y) * s.z * wpr);
  parallelChunks(0, s.z, 4, threads, [&](int, int64_t z0, int64_t z1) {
    std::vector<uint64_t> bits_b(size_t(last_word) + 1);
    for (int32_t z = int32_t(z0); z < int32_t(z1); ++z) {
      uint64_t* layer = nullptr;  // allocated at the first row either operand has, given back if nothing is left
      uint64_t layer_any = 0;
      for (int32_t y = 0; y < s.y; ++y) {
        const uint64_t* ra = latticeRow(a, box.min.y + y, box.min.z + z);
        const uint64_t* rb = latticeRow(b, box.min.y + y, box.min.z + z);
        if (!ra && !rb) continue;
        if (!ra && (op == PartOp::kIntersection || op == PartOp::kDifference)) continue;
        if (!rb && op == PartOp::kIntersection) continue;
        if (!layer) layer = out.grid.freshLayerWords(z);
        uint64_t* row = layer + (int64_t(y) + 1) * wpr;  // the result row; a's bits first, then combined in place
        if (ra) shiftedRowWords(ra, wa, shift_a, last_word + 1, row);
        if (rb) {
          shiftedRowWords(rb, wb, shift_b, last_word + 1, bits_b.data());
        } else {
          std::fill(bits_b.begin(), bits_b.end(), 0);
        }
        layer_any |= combineRow(row, bits_b.data(), last_word + 1, op);
        row[0] &= ~uint64_t(1);  // padding bits of the result stay zero (the operands have none there)
        row[last_word] &= last_mask;
      }
      if (layer && layer_any == 0) out.grid.releaseLayer(z);
    }
  });
  return out;
}

}  // namespace vox
