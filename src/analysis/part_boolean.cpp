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
    std::vector<uint64_t> bits_a(size_t(last_word) + 1), bits_b(size_t(last_word) + 1);
    for (int32_t z = int32_t(z0); z < int32_t(z1); ++z) {
      for (int32_t y = 0; y < s.y; ++y) {
        const uint64_t* ra = latticeRow(a, box.min.y + y, box.min.z + z);
        const uint64_t* rb = latticeRow(b, box.min.y + y, box.min.z + z);
        if (!ra && !rb) continue;
        if (!ra && (op == PartOp::kIntersection || op == PartOp::kDifference)) continue;
        if (!rb && op == PartOp::kIntersection) continue;
        if (ra) shiftedRowWords(ra, wa, shift_a, last_word + 1, bits_a.data());
        if (rb) shiftedRowWords(rb, wb, shift_b, last_word + 1, bits_b.data());
        if (!ra) std::fill(bits_a.begin(), bits_a.end(), 0);
        if (!rb) std::fill(bits_b.begin(), bits_b.end(), 0);
        bits_a[0] &= ~uint64_t(1);  // padding bits of the result stay zero
        bits_a[size_t(last_word)] &= last_mask;
        bits_b[0] &= ~uint64_t(1);
        bits_b[size_t(last_word)] &= last_mask;
        uint64_t any = 0;
        for (int64_t w = 0; w <= last_word; ++w) any |= combine(bits_a[size_t(w)], bits_b[size_t(w)], op);
        if (any == 0) continue;
        uint64_t* row = out.grid.mutableRowWords(y, z);
        for (int64_t w = 0; w <= last_word; ++w) row[w] = combine(bits_a[size_t(w)], bits_b[size_t(w)], op);
      }
    }
  });
  out.grid.releaseEmptyLayers();
  return out;
}

}  // namespace vox
