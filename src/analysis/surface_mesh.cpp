// The boundary of a voxel model as a closed manifold mesh, see vox/analysis/surface_mesh.h and docs/accuracy.md.
//
// 1. Faces: for each plane between two voxel layers (X, Y and Z) and each facing, a bit image of the faces between
//    a filled and an empty voxel, from the row words (X planes by transposing the rows' bit changes).
// 2. Rectangles: each image merged greedily (a run of a row, extended over the rows below that hold it whole).
// 3. Vertices: a lattice corner has one vertex per fan of faces around it (CornerFans: faces joined across the
//    corner's edges; at a checkerboard edge, the two faces of the same filled voxel), made for every rectangle
//    corner. A rectangle keeps every vertex of its own fan that lies on its sides, and a checkerboard edge on its
//    side gets a middle vertex per filled voxel, so neighbouring rectangles share every vertex of their common
//    edges. A rectangle with only its corners is two triangles, otherwise a fan around its centre.
#include "vox/analysis/surface_mesh.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <optional>
#include <unordered_map>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "vox/core/parallel.h"

namespace vox {

namespace {

constexpr double kSplitMove = 1.0 / 256.0;  // how far (in voxels) a split vertex moves towards its material

// The 8 voxels around a lattice corner p are voxel p - 1 + (i, j, k), bit i + 2j + 4k of the configuration. The 12
// voxel faces through p are f = 4a + 2qb + qc: the face across axis a whose extent on axes b = a+1, c = a+2 (mod 3)
// is on the negative (0) or positive (1) side of p.
struct CornerFans {
  uint8_t count[256] = {};
  int8_t fan[256][12] = {};
  glm::dvec3 move[256][12] = {};  // per fan: unit direction towards its material (used when count > 1)

  CornerFans() {
    for (int cfg = 0; cfg < 256; ++cfg) build(cfg);
  }
  static std::array<int, 3> faceVoxel(int f, int side) {
    std::array<int, 3> v{};
    const int a = f / 4;
    v[size_t(a)] = side;
    v[size_t((a + 1) % 3)] = (f >> 1) & 1;
    v[size_t((a + 2) % 3)] = f & 1;
    return v;
  }
  static int faceIndex(int a, const std::array<int, 3>& quadrant) {
    return 4 * a + 2 * quadrant[size_t((a + 1) % 3)] + quadrant[size_t((a + 2) % 3)];
  }

 private:
  void build(int cfg) {
    auto filled = [cfg](const std::array<int, 3>& v) { return (cfg >> (v[0] + 2 * v[1] + 4 * v[2])) & 1; };
    bool boundary[12];
    int parent[12];
    for (int f = 0; f < 12; ++f) {
      boundary[f] = filled(faceVoxel(f, 0)) != filled(faceVoxel(f, 1));
      parent[f] = f;
    }
    auto root = [&](int f) {
      while (parent[f] != f) f = parent[f] = parent[parent[f]];
      return f;
    };
    auto solid = [&](int f) { return filled(faceVoxel(f, 0)) ? faceVoxel(f, 0) : faceVoxel(f, 1); };
    for (int e = 0; e < 3; ++e)
      for (int s = 0; s < 2; ++s) {
        int faces[4], n = 0;  // the boundary faces holding the half edge from p along axis e, side s
        for (int a = 0; a < 3; ++a) {
          if (a == e) continue;
          const int o = 3 - a - e;
          for (int t = 0; t < 2; ++t) {
            std::array<int, 3> q{};
            q[size_t(e)] = s;
            q[size_t(o)] = t;
            const int f = faceIndex(a, q);
            if (boundary[f]) faces[n++] = f;
          }
        }
        for (int i = 0; i < n; ++i)
          for (int j = i + 1; j < n; ++j)
            if (n == 2 || solid(faces[i]) == solid(faces[j])) parent[root(faces[i])] = root(faces[j]);
      }
    int ids[12];
    std::fill(ids, ids + 12, -1);
    glm::dvec3 sum[12] = {};
    for (int f = 0; f < 12; ++f) {
      fan[cfg][f] = -1;
      if (!boundary[f]) continue;
      const int r = root(f);
      if (ids[r] < 0) ids[r] = count[cfg]++;
      fan[cfg][f] = int8_t(ids[r]);
      const auto v = solid(f);
      sum[ids[r]] += glm::dvec3(v[0] - 0.5, v[1] - 0.5, v[2] - 0.5);
    }
    for (int k = 0; k < count[cfg]; ++k)
      move[cfg][k] = glm::length(sum[k]) > 0 ? glm::normalize(sum[k]) : glm::dvec3(0);
  }
};

const CornerFans& cornerFans() {
  static const CornerFans table;
  return table;
}

// Axes of a plane's image: bits along u, rows along v.
constexpr int kU[3] = {1, 0, 0}, kV[3] = {2, 2, 1};

struct Rect {
  int8_t a;   // axis across the plane
  bool neg;   // facing -a (the filled voxel is on the plane's positive side)
  int32_t c;  // plane coordinate (between voxel c - 1 and c)
  int32_t u0, u1, v0, v1;
};

using P3 = std::array<int64_t, 3>;
P3 point(int a, int64_t c, int64_t u, int64_t v) {
  P3 p{};
  p[size_t(a)] = c;
  p[size_t(kU[a])] = u;
  p[size_t(kV[a])] = v;
  return p;
}

bool rangeSet(const uint64_t* row, int64_t b0, int64_t b1) {
  for (int64_t b = b0; b < b1;) {
    const int64_t w = b >> 6, lo = b & 63, hi = std::min<int64_t>(64, lo + (b1 - b));
    const uint64_t m = (hi == 64 ? ~uint64_t(0) : (uint64_t(1) << hi) - 1) & (~uint64_t(0) << lo);
    if ((row[w] & m) != m) return false;
    b += hi - lo;
  }
  return true;
}
void clearRange(uint64_t* row, int64_t b0, int64_t b1) {
  for (int64_t b = b0; b < b1;) {
    const int64_t w = b >> 6, lo = b & 63, hi = std::min<int64_t>(64, lo + (b1 - b));
    row[w] &= ~((hi == 64 ? ~uint64_t(0) : (uint64_t(1) << hi) - 1) & (~uint64_t(0) << lo));
    b += hi - lo;
  }
}

// Emits the rectangles of a bit image (rows of `words` words) and clears it: greedy, or one per bit.
template <class Emit>
int64_t rectangles(std::vector<uint64_t>& img, int64_t rows, int64_t words, bool merge, Emit&& emit) {
  int64_t faces = 0;
  for (int64_t r = 0; r < rows; ++r) {
    uint64_t* row = img.data() + r * words;
    for (int64_t w = 0; w < words; ++w) {
      while (row[w]) {
        const int64_t b0 = w * 64 + std::countr_zero(row[w]);
        int64_t b1 = b0 + 1, r1 = r + 1;
        if (merge) {
          while (b1 < words * 64 && (row[b1 >> 6] >> (b1 & 63) & 1)) ++b1;
          while (r1 < rows && rangeSet(img.data() + r1 * words, b0, b1)) ++r1;
        }
        for (int64_t rr = r; rr < r1; ++rr) clearRange(img.data() + rr * words, b0, b1);
        faces += (b1 - b0) * (r1 - r);
        emit(b0, b1, r, r1);
      }
    }
  }
  return faces;
}

// The lattice corners that have vertices: one bit per corner in x-fastest order (the corner's index), a count of
// the bits before every word (per block of 8 words, and within it), and per set bit (in index order) the corner's
// configuration and first vertex (one per fan, consecutive). A corner is found by its rank among the set bits: the
// lookups along a rectangle's sides touch memory near its plane, where a hash table would scatter them over all of it.
class CornerIndex {
 public:
  static constexpr uint32_t kNone = ~uint32_t(0);
  explicit CornerIndex(uint64_t lattice) : bits_(size_t((lattice + 63) / 64), 0) {}
  void mark(uint64_t key) { bits_[size_t(key >> 6)] |= uint64_t(1) << (key & 63); }
  bool has(uint64_t key) const { return (bits_[size_t(key >> 6)] >> (key & 63)) & 1; }
  // After every mark: the ranks, and room for each corner's vertices.
  void freeze() {
    block_rank_.resize(bits_.size() / 8 + 1);
    word_rank_.resize(bits_.size());
    uint64_t n = 0;
    for (size_t w = 0; w < bits_.size(); ++w) {
      if (w % 8 == 0) block_rank_[w / 8] = n;
      word_rank_[w] = uint16_t(n - block_rank_[w / 8]);
      n += uint64_t(std::popcount(bits_[w]));
    }
    base_.assign(size_t(n), kNone);
    cfg_.assign(size_t(n), 0);
  }
  size_t rank(uint64_t key) const {
    const size_t w = size_t(key >> 6);
    return size_t(block_rank_[w / 8] + word_rank_[w] +
                  uint64_t(std::popcount(bits_[w] & ((uint64_t(1) << (key & 63)) - 1))));
  }
  size_t words() const { return bits_.size(); }
  uint64_t word(size_t w) const { return bits_[w]; }
  size_t wordRank(size_t w) const { return size_t(block_rank_[w / 8] + word_rank_[w]); }
  uint32_t& base(size_t rank) { return base_[rank]; }
  uint32_t base(size_t rank) const { return base_[rank]; }
  uint8_t& cfg(size_t rank) { return cfg_[rank]; }
  uint8_t cfg(size_t rank) const { return cfg_[rank]; }

 private:
  std::vector<uint64_t> bits_;
  std::vector<uint64_t> block_rank_;  // set bits before each block of 8 words
  std::vector<uint16_t> word_rank_;   // set bits before each word within its block
  std::vector<uint32_t> base_;
  std::vector<uint8_t> cfg_;
};

class Mesher {
 public:
  Mesher(const VoxelGrid& g, const SurfaceMeshParams& p) : g_(g), params_(p), fans_(cornerFans()) {}

  // Steps 1 and 2: every plane's rectangles. Returns false when cancelled.
  bool collect(const ProgressFn& progress);
  // Step 3: vertices and triangles.
  Result<IndexedMesh> build();
  SurfaceMeshStats stats;

 private:
  // The rectangles of one face image, appended to `out`; returns its voxel faces.
  int64_t addPlane(int a, int32_t c, bool neg, std::vector<uint64_t>& img, int64_t rows, int64_t words, int shift,
                   std::vector<Rect>& out) const;
  // Z (a = 2) or Y (a = 1) planes, in parallel over blocks of planes, appended in plane order.
  bool collectPlanes(int a, const ProgressFn& progress);
  int cfgAt(const P3& p) const {
    int cfg = 0;
    for (int k = 0; k < 8; ++k)
      cfg |= int(g_.get(p[0] - 1 + (k & 1), p[1] - 1 + ((k >> 1) & 1), p[2] - 1 + (k >> 2))) << k;
    return cfg;
  }
  static constexpr uint64_t kMiddle = uint64_t(1) << 63;  // a ring entry naming a middle vertex by its key
  uint64_t cornerIndex(const P3& p) const {
    return uint64_t(p[0] + (g_.nx() + 1) * (p[1] + int64_t(g_.ny() + 1) * p[2]));
  }
  // Makes the vertices of corner p (one per fan) unless it has them.
  void makeCorner(const P3& p);
  // The vertex at corner p for the fan of rectangle r's voxel face with min corner (uf, vf), -1 when p has none.
  int64_t findCorner(const Rect& r, const P3& p, int64_t uf, int64_t vf) const;
  // The key of the middle vertex of the voxel edge from (u, v) along axis e of r's plane on r's filled side, when
  // that edge is a checkerboard; the vertex of a key, made at first use.
  std::optional<uint64_t> middleKey(const Rect& r, int64_t u, int64_t v, int e) const;
  uint32_t middleVertex(uint64_t key);
  // The vertices around r, counter-clockwise in its plane; then its triangles.
  void ring(const Rect& r, std::vector<uint64_t>& out) const;
  void emit(const Rect& r, const uint64_t* refs, size_t n, std::vector<uint32_t>& ids);
  glm::dvec3 model(const glm::dvec3& p) const { return g_.frame().origin + p * g_.voxelSize(); }
  uint32_t add(const glm::dvec3& p) {
    mesh_.vertices.push_back(model(p));
    return uint32_t(mesh_.vertices.size() - 1);
  }

  const VoxelGrid& g_;
  SurfaceMeshParams params_;
  const CornerFans& fans_;
  std::vector<Rect> rects_;
  std::optional<CornerIndex> corners_;
  std::unordered_map<uint64_t, uint32_t> middles_;
  IndexedMesh mesh_;
};

int64_t Mesher::addPlane(int a, int32_t c, bool neg, std::vector<uint64_t>& img, int64_t rows, int64_t words, int shift,
                         std::vector<Rect>& out) const {
  return rectangles(img, rows, words, params_.merge_coplanar, [&](int64_t b0, int64_t b1, int64_t r0, int64_t r1) {
    out.push_back(Rect{int8_t(a), neg, c, int32_t(b0 - shift), int32_t(b1 - shift), int32_t(r0), int32_t(r1)});
  });
}

bool Mesher::collectPlanes(int a, const ProgressFn& progress) {
  const int64_t wpr = g_.wordsPerRow();
  const int64_t planes = (a == 2 ? g_.nz() : g_.ny()) + 1, rows = a == 2 ? g_.ny() : g_.nz();
  constexpr int64_t kGrain = 8;
  struct Block {
    std::vector<Rect> rects;
    int64_t faces = 0;
  };
  std::vector<Block> blocks(size_t((planes + kGrain - 1) / kGrain));
  std::atomic<bool> cancelled{false};
  std::atomic<int64_t> done{0};
  parallelChunks(0, planes, kGrain, threadsFor(planes * rows * wpr), [&](int t, int64_t c0, int64_t c1) {
    if (cancelled.load(std::memory_order_relaxed)) return;
    Block& block = blocks[size_t(c0 / kGrain)];
    std::vector<uint64_t> pos(size_t(rows * wpr)), neg(size_t(rows * wpr));
    for (int64_t c = c0; c < c1; ++c) {
      for (int64_t r = 0; r < rows; ++r) {
        const uint64_t* lo = a == 2 ? g_.rowWords(int32_t(r), int32_t(c - 1)) : g_.rowWords(int32_t(c - 1), int32_t(r));
        const uint64_t* hi = a == 2 ? g_.rowWords(int32_t(r), int32_t(c)) : g_.rowWords(int32_t(c), int32_t(r));
        for (int64_t w = 0; w < wpr; ++w) {
          pos[size_t(r * wpr + w)] = lo[w] & ~hi[w];
          neg[size_t(r * wpr + w)] = ~lo[w] & hi[w];
        }
      }
      block.faces += addPlane(a, int32_t(c), false, pos, rows, wpr, 1, block.rects);
      block.faces += addPlane(a, int32_t(c), true, neg, rows, wpr, 1, block.rects);
    }
    const int64_t d = done.fetch_add(c1 - c0) + (c1 - c0);
    if (t == 0 && progress && !progress((a == 2 ? 0.0 : 0.25) + 0.25 * double(d) / double(planes))) cancelled = true;
  });
  if (cancelled) return false;
  for (Block& b : blocks) {
    rects_.insert(rects_.end(), b.rects.begin(), b.rects.end());
    stats.voxel_faces += b.faces;
  }
  return true;
}

bool Mesher::collect(const ProgressFn& progress) {
  const int64_t nx = g_.nx(), ny = g_.ny(), nz = g_.nz(), wpr = g_.wordsPerRow();
  // Z planes (rows y, bits padded x) and Y planes (rows z, bits padded x).
  for (int a : {2, 1})
    if (!collectPlanes(a, progress)) return false;
  // X planes: rows z, bits y, from the bit changes along each row; 64 planes at a time (those of one word of the
  // rows), so the images hold 64 planes, not all of them; the words of the rows in parallel, appended in order.
  const int64_t wy = (ny + 63) / 64, xwords = std::min(wpr, nx / 64 + 1);
  std::vector<std::vector<Rect>> xrects(static_cast<size_t>(xwords));
  std::vector<int64_t> xfaces(static_cast<size_t>(xwords), 0);
  parallelChunks(0, xwords, 1, threadsFor(nz * ny * xwords), [&](int, int64_t w0, int64_t w1) {
    std::vector<std::vector<uint64_t>> xpos(64), xneg(64);
    for (int64_t w = w0; w < w1; ++w) {
      for (int64_t z = 0; z < nz; ++z) {
        for (int64_t y = 0; y < ny; ++y) {
          const uint64_t* row = g_.rowWords(int32_t(y), int32_t(z));
          const uint64_t next = w + 1 < wpr ? row[w + 1] : 0;
          for (uint64_t t = row[w] ^ (row[w] >> 1 | next << 63); t; t &= t - 1) {
            const int bit = std::countr_zero(t);  // plane x = 64w + bit: voxels x - 1 (this bit) and x (the next)
            auto& img = (row[w] >> bit & 1) ? xpos[size_t(bit)] : xneg[size_t(bit)];
            if (img.empty()) img.assign(size_t(nz * wy), 0);
            img[size_t(z * wy + (y >> 6))] |= uint64_t(1) << (y & 63);
          }
        }
      }
      auto& out = xrects[size_t(w)];
      for (int bit = 0; bit < 64; ++bit) {
        const auto c = int32_t(w * 64 + bit);
        if (!xpos[size_t(bit)].empty()) xfaces[size_t(w)] += addPlane(0, c, false, xpos[size_t(bit)], nz, wy, 0, out);
        if (!xneg[size_t(bit)].empty()) xfaces[size_t(w)] += addPlane(0, c, true, xneg[size_t(bit)], nz, wy, 0, out);
        // rectangles() leaves the images cleared, ready for the next 64 planes
      }
    }
  });
  for (int64_t w = 0; w < xwords; ++w) {
    rects_.insert(rects_.end(), xrects[size_t(w)].begin(), xrects[size_t(w)].end());
    stats.voxel_faces += xfaces[size_t(w)];
  }
  stats.rectangles = int64_t(rects_.size());
  return !progress || progress(0.6);
}

void Mesher::makeCorner(const P3& p) {
  const size_t i = corners_->rank(cornerIndex(p));
  if (corners_->base(i) != CornerIndex::kNone) return;
  // the first rectangle with a corner here makes the corner's vertices, one per fan
  const int cfg = corners_->cfg(i);
  corners_->base(i) = uint32_t(mesh_.vertices.size());
  const glm::dvec3 at{double(p[0]), double(p[1]), double(p[2])};
  const int fans = fans_.count[cfg];
  for (int f = 0; f < fans; ++f) add(fans > 1 ? at + kSplitMove * fans_.move[cfg][f] : at);
  if (fans > 1) stats.split_vertices += fans;
}

int64_t Mesher::findCorner(const Rect& r, const P3& p, int64_t uf, int64_t vf) const {
  const uint64_t key = cornerIndex(p);
  if (!corners_->has(key)) return -1;
  const size_t i = corners_->rank(key);
  const P3 q = point(r.a, r.c, uf, vf);  // the face's min corner
  std::array<int, 3> quadrant{};
  for (int k = 0; k < 3; ++k) quadrant[size_t(k)] = q[size_t(k)] == p[size_t(k)] ? 1 : 0;
  return corners_->base(i) + uint32_t(fans_.fan[corners_->cfg(i)][CornerFans::faceIndex(r.a, quadrant)]);
}

std::optional<uint64_t> Mesher::middleKey(const Rect& r, int64_t u, int64_t v, int e) const {
  const P3 p = point(r.a, r.c, u, v);
  const int o1 = (e + 1) % 3, o2 = (e + 2) % 3;
  auto voxel = [&](int k) {
    P3 q = p;
    q[size_t(o1)] += (k & 1) - 1;
    q[size_t(o2)] += (k >> 1) - 1;
    return g_.get(q[0], q[1], q[2]);
  };
  // A checkerboard: voxels 0 and 3 alike, 1 and 2 alike, the two pairs different (tested lazily: most edges fail
  // at the first pair, since one of r's own two voxels is in each)
  const bool f0 = voxel(0);
  if (voxel(3) != f0 || voxel(1) == f0 || voxel(2) == f0) return std::nullopt;
  // r's filled voxel along this edge: the voxel of r's face next to it, on r's filled side of the plane
  P3 vox = point(r.a, r.c - (r.neg ? 0 : 1), std::min<int64_t>(u, r.u1 - 1), std::min<int64_t>(v, r.v1 - 1));
  vox[size_t(e)] = p[size_t(e)];
  const int i = int(vox[size_t(o1)] - (p[size_t(o1)] - 1)), j = int(vox[size_t(o2)] - (p[size_t(o2)] - 1));
  return ((cornerIndex(p) * 3 + uint64_t(e)) << 2) | uint64_t(i + 2 * j);
}

uint32_t Mesher::middleVertex(uint64_t key) {
  if (auto it = middles_.find(key); it != middles_.end()) return it->second;
  const int e = int((key >> 2) % 3), i = int(key & 1), j = int((key >> 1) & 1);
  const uint64_t corner = (key >> 2) / 3;
  const int64_t nx1 = g_.nx() + 1, ny1 = g_.ny() + 1;
  glm::dvec3 at{double(int64_t(corner) % nx1), double((int64_t(corner) / nx1) % ny1),
                double(int64_t(corner) / (nx1 * ny1))};
  at[e] += 0.5;
  glm::dvec3 dir(0.0);
  dir[(e + 1) % 3] = i - 0.5;
  dir[(e + 2) % 3] = j - 0.5;
  at += kSplitMove * glm::normalize(dir);
  ++stats.split_vertices;
  const uint32_t id = add(at);
  middles_.emplace(key, id);
  return id;
}

void Mesher::ring(const Rect& r, std::vector<uint64_t>& out) const {
  const int eu = kU[r.a], ev = kV[r.a];
  // Counter-clockwise in (u, v): bottom, right, top, left. Each side: its first corner, then the vertices of r's
  // fan at the lattice points inside it and the middle vertices of checkerboard edges along it.
  auto side = [&](int64_t u, int64_t v, int64_t du, int64_t dv, int64_t n) {
    for (int64_t k = 0; k < n; ++k, u += du, v += dv) {
      const int64_t id =
          findCorner(r, point(r.a, r.c, u, v), std::min<int64_t>(u, r.u1 - 1), std::min<int64_t>(v, r.v1 - 1));
      if (id >= 0) out.push_back(uint64_t(id));
      // the voxel edge from (u, v) to (u + du, v + dv), named by its lower end
      if (auto mid = middleKey(r, std::min(u, u + du), std::min(v, v + dv), du != 0 ? eu : ev)) {
        out.push_back(kMiddle | *mid);
      }
    }
  };
  side(r.u0, r.v0, 1, 0, r.u1 - r.u0);
  side(r.u1, r.v0, 0, 1, r.v1 - r.v0);
  side(r.u1, r.v1, -1, 0, r.u1 - r.u0);
  side(r.u0, r.v1, 0, -1, r.v1 - r.v0);
}

void Mesher::emit(const Rect& r, const uint64_t* refs, size_t n, std::vector<uint32_t>& ids) {
  ids.clear();
  for (size_t k = 0; k < n; ++k)
    ids.push_back(refs[k] & kMiddle ? middleVertex(refs[k] & ~kMiddle) : uint32_t(refs[k]));
  const bool flip = (r.a == 1) != r.neg;
  auto tri = [&](uint32_t x, uint32_t y, uint32_t z) {
    mesh_.triangles.push_back(flip ? std::array<uint32_t, 3>{x, z, y} : std::array<uint32_t, 3>{x, y, z});
  };
  if (ids.size() == 4) {
    tri(ids[0], ids[1], ids[2]);
    tri(ids[0], ids[2], ids[3]);
    return;
  }
  glm::dvec3 centre(0.0);
  centre[r.a] = r.c;
  centre[kU[r.a]] = 0.5 * (r.u0 + r.u1);
  centre[kV[r.a]] = 0.5 * (r.v0 + r.v1);
  const uint32_t m = add(centre);
  for (size_t k = 0; k < ids.size(); ++k) tri(m, ids[k], ids[(k + 1) % ids.size()]);
}

Result<IndexedMesh> Mesher::build() {
  // Every rectangle corner first, so that each side finds the vertices of its neighbours.
  corners_.emplace(uint64_t(g_.nx() + 1) * uint64_t(g_.ny() + 1) * uint64_t(g_.nz() + 1));
  for (const Rect& r : rects_) {
    corners_->mark(cornerIndex(point(r.a, r.c, r.u0, r.v0)));
    corners_->mark(cornerIndex(point(r.a, r.c, r.u1, r.v0)));
    corners_->mark(cornerIndex(point(r.a, r.c, r.u1, r.v1)));
    corners_->mark(cornerIndex(point(r.a, r.c, r.u0, r.v1)));
  }
  corners_->freeze();
  // every corner's configuration, in parallel over the bit words
  const int64_t words = int64_t(corners_->words()), nx1 = g_.nx() + 1, ny1 = g_.ny() + 1;
  parallelChunks(0, words, 1 << 12, threadsFor(int64_t(rects_.size()) * 16), [&](int, int64_t w0, int64_t w1) {
    size_t i = corners_->wordRank(size_t(w0));
    for (int64_t w = w0; w < w1; ++w) {
      for (uint64_t t = corners_->word(size_t(w)); t; t &= t - 1) {
        const int64_t key = w * 64 + std::countr_zero(t);
        corners_->cfg(i++) = uint8_t(cfgAt(P3{key % nx1, (key / nx1) % ny1, key / (nx1 * ny1)}));
      }
    }
  });
  for (const Rect& r : rects_) {
    makeCorner(point(r.a, r.c, r.u0, r.v0));
    makeCorner(point(r.a, r.c, r.u1, r.v0));
    makeCorner(point(r.a, r.c, r.u1, r.v1));
    makeCorner(point(r.a, r.c, r.u0, r.v1));
  }
  // The rings of vertices around the rectangles, in parallel (the corner table is only read), in blocks of
  // rectangles; then the triangles in order (middle vertices are made at first use: the mesh does not depend on
  // the thread split).
  constexpr int64_t kBlock = 1 << 14;
  const int64_t n = int64_t(rects_.size()), blocks = (n + kBlock - 1) / kBlock;
  std::vector<std::vector<uint64_t>> refs(static_cast<size_t>(blocks));
  std::vector<std::vector<uint32_t>> ends(static_cast<size_t>(blocks));
  parallelChunks(0, blocks, 1, threadsFor(n * 8), [&](int, int64_t b0, int64_t b1) {
    for (int64_t b = b0; b < b1; ++b)
      for (int64_t k = b * kBlock; k < std::min(n, (b + 1) * kBlock); ++k) {
        ring(rects_[size_t(k)], refs[size_t(b)]);
        ends[size_t(b)].push_back(uint32_t(refs[size_t(b)].size()));
      }
  });
  std::vector<uint32_t> ids;
  for (int64_t b = 0; b < blocks; ++b) {
    uint32_t start = 0;
    for (int64_t k = b * kBlock; k < std::min(n, (b + 1) * kBlock); ++k) {
      const uint32_t end = ends[size_t(b)][size_t(k - b * kBlock)];
      emit(rects_[size_t(k)], refs[size_t(b)].data() + start, end - start, ids);
      start = end;
    }
    std::vector<uint64_t>().swap(refs[size_t(b)]);
  }
  if (mesh_.vertices.size() >= (uint64_t(1) << 32)) {
    return makeError(ErrorCode::kLimit, "surface mesh: more than 2^32 vertices");
  }
  return std::move(mesh_);
}

}  // namespace

// Smoothing (constrained surface nets, after Gibson 1998): every vertex moves towards the mean of its neighbours,
// alternately by lambda and back by mu (Taubin 1995, so that a convex part does not shrink as under plain
// averaging), `iterations` pairs of steps, but never more than kSmoothReach voxels from where it started on any
// axis, so the surface stays within half a voxel of the voxels' boundary and keeps its topology.
constexpr double kSmoothReach = 0.45;

void smooth(IndexedMesh& mesh, double h, int iterations) {
  const size_t n = mesh.vertices.size();
  std::vector<uint32_t> start(n + 1, 0), nb;  // neighbours by vertex, from the triangles' edges
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) start[t[size_t(k)] + 1] += 2;
  for (size_t i = 0; i < n; ++i) start[i + 1] += start[i];
  nb.resize(start[n]);
  std::vector<uint32_t> fill(start.begin(), start.end() - 1);
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      nb[fill[t[size_t(k)]]++] = t[size_t((k + 1) % 3)];
      nb[fill[t[size_t(k)]]++] = t[size_t((k + 2) % 3)];
    }
  const std::vector<glm::dvec3> home = mesh.vertices;
  std::vector<glm::dvec3> next(n);
  const double reach = kSmoothReach * h;
  for (int it = 0; it < 2 * iterations; ++it) {
    const double step = it % 2 == 0 ? 0.5 : -0.53;  // Taubin's lambda and mu
    parallelChunks(0, int64_t(n), 1 << 14, threadsFor(int64_t(nb.size())), [&](int, int64_t b, int64_t e) {
      for (int64_t i = b; i < e; ++i) {
        glm::dvec3 sum(0.0);
        for (uint32_t k = start[size_t(i)]; k < start[size_t(i) + 1]; ++k) sum += mesh.vertices[nb[k]];
        const uint32_t count = start[size_t(i) + 1] - start[size_t(i)];
        const glm::dvec3 v = mesh.vertices[size_t(i)], mean = count ? sum / double(count) : v;
        next[size_t(i)] = glm::clamp(v + step * (mean - v), home[size_t(i)] - reach, home[size_t(i)] + reach);
      }
    });
    mesh.vertices.swap(next);
  }
}

Result<IndexedMesh> extractSurfaceMesh(const VoxelGrid& grid, const SurfaceMeshParams& params,
                                       const ProgressFn& progress, SurfaceMeshStats* stats) {
  SurfaceMeshParams p = params;
  if (p.smooth_iterations > 0) p.merge_coplanar = false;  // smoothing moves every voxel corner
  Mesher m(grid, p);
  if (!grid.empty() && !m.collect(progress)) return makeError(ErrorCode::kCancelled, "surface mesh cancelled");
  auto mesh = m.build();
  if (!mesh) return mesh.error();
  if (p.smooth_iterations > 0) smooth(*mesh, grid.voxelSize(), p.smooth_iterations);
  if (stats) *stats = m.stats;
  if (progress && !progress(1.0)) return makeError(ErrorCode::kCancelled, "surface mesh cancelled");
  return mesh;
}

}  // namespace vox
