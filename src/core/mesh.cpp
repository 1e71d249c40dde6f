#include "vox/core/mesh.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "vox/core/prefetch.h"

namespace vox {

void Box3d::expand(const glm::dvec3& p) {
  min = glm::min(min, p);
  max = glm::max(max, p);
}

Box3d TriangleMesh::bounds() const {
  Box3d b;
  for (const Triangle& t : triangles) {
    for (const glm::vec3& v : t.v) b.expand(glm::dvec3(v));
  }
  return b;
}

bool isDegenerate(const Triangle& t) {
  if (t.v[0] == t.v[1] || t.v[1] == t.v[2] || t.v[0] == t.v[2]) return true;
  const glm::dvec3 a(t.v[0]), b(t.v[1]), c(t.v[2]);
  const glm::dvec3 n = glm::cross(b - a, c - a);
  return n.x == 0.0 && n.y == 0.0 && n.z == 0.0;
}

namespace {

// Welding keys. Exact (tolerance 0): the float bits, with -0 folded onto +0. With a tolerance: each coordinate
// rounded to a multiple of it, so positions closer than the tolerance usually (not when they straddle a rounding
// boundary) share a key: enough to see through exporter noise such as 0 vs 1e-35.
using ExactKey = std::array<uint32_t, 3>;
using RoundedKey = std::array<int64_t, 3>;

ExactKey exactKey(const glm::vec3& v) {
  ExactKey k{};
  for (int i = 0; i < 3; ++i) k[size_t(i)] = std::bit_cast<uint32_t>(v[i] == 0.0f ? 0.0f : v[i]);
  return k;
}

RoundedKey roundedKey(const glm::vec3& v, double tolerance) {
  RoundedKey k{};
  for (int i = 0; i < 3; ++i) k[size_t(i)] = std::llround(double(v[i]) / tolerance);
  return k;
}

template <class Key>
uint64_t hashKey(const Key& k) {
  // Each coordinate folded in with a multiply and a rotation, then a final avalanche (splitmix64's finalizer).
  uint64_t h = 0x9E3779B97F4A7C15ull;
  for (const auto c : k) h = std::rotl((h ^ uint64_t(c)) * 0xBF58476D1CE4E5B9ull, 29);
  h ^= h >> 31;
  h *= 0x94D049BB133111EBull;
  return h ^ (h >> 29);
}

// Vertex ids for the 3 * T corners: equal keys get one id, numbered in order of first appearance. An open-addressing
// hash table of distinct positions (kept at most half full) rather than a sort of all corners: about 16 bytes per
// vertex (a closed mesh has about T / 2 vertices) instead of 32 per corner, and one pass instead of a sort.
template <class Key, class KeyFn>
std::vector<uint32_t> weldCorners(const TriangleMesh& mesh, KeyFn&& key_of, int64_t& vertices) {
  struct Slot {
    Key key;
    uint32_t id;
  };
  constexpr uint32_t kEmpty = UINT32_MAX;
  const size_t corners = mesh.triangles.size() * 3;
  std::vector<uint32_t> vid(corners);
  size_t capacity = std::bit_ceil(std::max<size_t>(16, mesh.triangles.size()));
  std::vector<Slot> table(capacity, Slot{Key{}, kEmpty});
  uint32_t next = 0;
  auto insert = [&](std::vector<Slot>& t, const Key& key, uint64_t hash, uint32_t id) -> uint32_t {
    const size_t mask = t.size() - 1;
    for (size_t i = size_t(hash) & mask;; i = (i + 1) & mask) {
      if (t[i].id == kEmpty) {
        t[i] = Slot{key, id};
        return id;
      }
      const Key& k = t[i].key;  // compared element by element: std::array's == becomes a memcmp call here
      if (k[0] == key[0] && k[1] == key[1] && k[2] == key[2]) return t[i].id;
    }
  };
  // A large table misses the cache on nearly every lookup, so the keys and hashes of the next kAhead corners are
  // computed ahead and their slots prefetched.
  constexpr size_t kAhead = prefetch_distance::kWeldCorners;
  std::array<Key, kAhead> ahead_key{};
  std::array<uint64_t, kAhead> ahead_hash{};
  auto prepare = [&](size_t c) {
    const Key k = key_of(mesh.triangles[c / 3].v[c % 3]);
    const uint64_t h = hashKey(k);
    ahead_key[c % kAhead] = k;
    ahead_hash[c % kAhead] = h;
    prefetchBytes(&table[size_t(h) & (table.size() - 1)], 1);  // the slot's line
  };
  for (size_t c = 0; c < std::min(corners, kAhead); ++c) prepare(c);
  for (size_t c = 0; c < corners; ++c) {
    const Key key = ahead_key[c % kAhead];
    const uint64_t hash = ahead_hash[c % kAhead];
    if (c + kAhead < corners) prepare(c + kAhead);
    const uint32_t id = insert(table, key, hash, next);
    vid[c] = id;
    if (id != next) continue;
    if (++next > capacity / 2) {  // grow: rehash into twice the slots
      capacity *= 2;
      std::vector<Slot> bigger(capacity, Slot{Key{}, kEmpty});
      for (const Slot& s : table) {
        if (s.id != kEmpty) insert(bigger, s.key, hashKey(s.key), s.id);
      }
      table.swap(bigger);
    }
  }
  vertices = next;
  return vid;
}

// Counts edge uses from the corners' vertex ids. Directed edges are bucketed by their lower vertex (a counting
// sort); each bucket is small (a vertex's higher neighbours), sorted on its own, and equal upper vertices are one
// undirected edge. An entry holds the upper vertex and the direction: (hi << 1) | forward, in 32 bits while the ids
// allow it.
template <class Packed>
void countEdges(const std::vector<uint32_t>& vid, int64_t vertices, MeshTopology& topo) {
  const size_t corners = vid.size();
  std::vector<size_t> start(size_t(vertices) + 1, 0);
  for (size_t c = 0; c < corners; ++c) {
    const uint32_t a = vid[c], b = vid[c - c % 3 + (c + 1) % 3];
    if (a != b) ++start[size_t(std::min(a, b)) + 1];
  }
  for (size_t v = 0; v < size_t(vertices); ++v) start[v + 1] += start[v];
  std::vector<Packed> entries(start[size_t(vertices)]);
  {
    std::vector<size_t> fill(start.begin(), start.end() - 1);
    for (size_t c = 0; c < corners; ++c) {
      const uint32_t a = vid[c], b = vid[c - c % 3 + (c + 1) % 3];
      if (a == b) continue;
      const Packed forward = a < b ? 1 : 0;
      entries[fill[std::min(a, b)]++] = Packed(std::max(a, b)) << 1 | forward;
    }
  }
  for (size_t v = 0; v < size_t(vertices); ++v) {
    const auto b = entries.begin() + ptrdiff_t(start[v]), e = entries.begin() + ptrdiff_t(start[v + 1]);
    std::sort(b, e);
    for (auto i = b; i != e;) {
      auto j = i;
      size_t forward = 0;
      while (j != e && (*j >> 1) == (*i >> 1)) forward += size_t(*j++ & 1);
      const size_t uses = size_t(j - i);
      ++topo.edges;
      if (uses == 1) ++topo.boundary_edges;
      if (uses >= 3) ++topo.nonmanifold_edges;
      if (uses == 2 && forward != 1) ++topo.inconsistent_edges;
      if (2 * forward != uses) ++topo.unbalanced_edges;
      i = j;
    }
  }
}

}  // namespace

MeshTopology analyzeTopology(const TriangleMesh& mesh) {
  MeshTopology topo = analyzeTopologyWelded(mesh, 0.0);
  if (topo.boundary_edges > 0) {
    topo.closes_when_noise_welded = analyzeTopologyWelded(mesh, noiseWeldTolerance(mesh)).closedOriented();
  }
  return topo;
}

std::vector<uint32_t> weldExactVertices(const TriangleMesh& mesh, int64_t& vertices) {
  return weldCorners<ExactKey>(mesh, exactKey, vertices);
}

MeshTopology analyzeTopologyWelded(const TriangleMesh& mesh, double weld_tolerance) {
  MeshTopology topo;
  // Corners are numbered in 32 bits.
  if (mesh.triangles.size() > UINT32_MAX / 3) {
    throw std::length_error("analyzeTopology: more than 1431655765 triangles");
  }
  std::vector<uint32_t> vid =
      weld_tolerance > 0.0 ? weldCorners<RoundedKey>(
                                 mesh, [&](const glm::vec3& v) { return roundedKey(v, weld_tolerance); }, topo.vertices)
                           : weldCorners<ExactKey>(mesh, exactKey, topo.vertices);
  for (const Triangle& t : mesh.triangles) topo.degenerate_triangles += isDegenerate(t) ? 1 : 0;
  if (topo.vertices < (int64_t(1) << 31)) {
    countEdges<uint32_t>(vid, topo.vertices, topo);
  } else {
    countEdges<uint64_t>(vid, topo.vertices, topo);
  }
  return topo;
}

double noiseWeldTolerance(const TriangleMesh& mesh) {
  const Box3d b = mesh.bounds();
  return b.empty() ? 0.0 : 1e-9 * glm::length(b.extent());
}

double signedVolume(const TriangleMesh& mesh) {
  const Box3d b = mesh.bounds();
  if (b.empty()) return 0.0;
  const glm::dvec3 c = (b.min + b.max) * 0.5;
  double sum = 0.0;
  for (const Triangle& t : mesh.triangles) {
    const glm::dvec3 p0 = glm::dvec3(t.v[0]) - c, p1 = glm::dvec3(t.v[1]) - c, p2 = glm::dvec3(t.v[2]) - c;
    sum += glm::dot(p0, glm::cross(p1, p2));
  }
  return sum / 6.0;
}

}  // namespace vox
