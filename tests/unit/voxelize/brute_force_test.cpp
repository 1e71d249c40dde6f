// The voxelizer against a brute-force evaluation of the rule in docs/conventions.md, "Grid placement", on random
// triangle soups full of ties and near-ties. The brute force tests every triangle against every ray with the exact
// predicates alone (no pruning, no estimates, no fast paths), so it checks the voxelizer's shortcuts: ray-range
// pruning, rays certainly inside a triangle's section, the bounded estimate of the crossing position and
// planes u = const.
#include <gtest/gtest.h>

#include <array>
#include <random>
#include <string>
#include <vector>

#include "support/test_meshes.h"
#include "vox/voxelize/voxelize.h"
#include "voxelize/exact_predicates.h"

namespace vox {
namespace {

using voxelize_detail::orient2d;
using voxelize_detail::orient3dExact;

// The rule of docs/conventions.md, "Grid placement", for rays along axis `u` (the other two, v and w, as in the
// voxelizer's frames), the centre displaced by (eps, eps^3, eps^2) in (u, v, w). Returns the per-voxel crossing count
// parity and winding number.
struct BruteRay {
  int parity = 0;
  int winding = 0;
};

// Side of (v + eps^3, w + eps^2) relative to the directed edge p -> q, written from the SoS expansion
// det[p - r; q - r] = D0 + (q.v - p.v) eps^2 + (p.w - q.w) eps^3.
int sosSide(double pv, double pw, double qv, double qw, double v, double w) {
  const int d0 = orient2d(pv, pw, qv, qw, v, w);
  if (d0 != 0) return d0;
  if (qv - pv != 0) return qv - pv > 0 ? 1 : -1;
  if (pw - qw != 0) return pw - qw > 0 ? 1 : -1;
  return 0;
}

VoxelGrid bruteForce(const TriangleMesh& mesh, const VoxelGrid& like, int u, int v, int w, bool nonzero) {
  VoxelGrid out(like.dims(), like.frame());
  const int n[3] = {like.nx(), like.ny(), like.nz()};
  for (int32_t kw = 0; kw < n[w]; ++kw) {
    for (int32_t kv = 0; kv < n[v]; ++kv) {
      std::vector<BruteRay> along(size_t(n[u]));
      glm::ivec3 idx(0);
      idx[v] = kv;
      idx[w] = kw;
      const glm::dvec3 c0 = like.frame().voxelCentre(idx.x, idx.y, idx.z);
      for (const Triangle& t : mesh.triangles) {
        double p[3][3];
        for (int k = 0; k < 3; ++k) {
          p[k][0] = t.v[k][u];
          p[k][1] = t.v[k][v];
          p[k][2] = t.v[k][w];
        }
        const int s = orient2d(p[0][1], p[0][2], p[1][1], p[1][2], p[2][1], p[2][2]);
        if (s == 0) continue;
        bool crossed = true;
        for (int k = 0; k < 3 && crossed; ++k) {
          crossed = sosSide(p[k][1], p[k][2], p[(k + 1) % 3][1], p[(k + 1) % 3][2], c0[v], c0[w]) == s;
        }
        if (!crossed) continue;
        for (int32_t i = 0; i < n[u]; ++i) {
          glm::ivec3 at = idx;
          at[u] = i;
          const glm::dvec3 c = like.frame().voxelCentre(at.x, at.y, at.z);
          const double q[3] = {c[u], c[v], c[w]};
          const int o = orient3dExact(p[0], p[1], p[2], q);
          if (o == 0 || o == -s) {  // the centre is past the crossing
            along[size_t(i)].parity ^= 1;
            along[size_t(i)].winding -= s;
          }
        }
      }
      for (int32_t i = 0; i < n[u]; ++i) {
        glm::ivec3 at = idx;
        at[u] = i;
        const BruteRay& r = along[size_t(i)];
        if (nonzero ? r.winding != 0 : r.parity != 0) out.set(at.x, at.y, at.z);
      }
    }
  }
  return out;
}

// Coordinates on the voxel-centre lattice (k + 0.5 with h = 1), a float ulp or a few away from it, or anywhere.
class SoupMaker {
 public:
  explicit SoupMaker(uint32_t seed) : rng_(seed) {}
  float coordinate() {
    const int kind = pick(4);
    const float lattice = float(pick(15)) + 0.5f;
    if (kind == 0) return lattice;
    if (kind == 1) return std::nextafter(lattice, pick(2) ? 100.0f : -100.0f);
    if (kind == 2) return lattice + float(pick(9) - 4) * 1e-5f;
    return 1.0f + float(std::uniform_real_distribution<double>(0.0, 14.0)(rng_));
  }
  TriangleMesh soup(int triangles) {
    TriangleMesh m = test::combined(test::tetrahedron({0, 0, 0}, 0.25), test::tetrahedron({15.75, 15.75, 15.75}, 0.25));
    for (int i = 0; i < triangles; ++i) {
      Triangle t;
      for (auto& p : t.v) p = glm::vec3(coordinate(), coordinate(), coordinate());
      // Some triangles in a plane x, y or z = const, some sharing coordinates between vertices.
      const int shape = pick(6);
      if (shape < 3) t.v[1][shape] = t.v[2][shape] = t.v[0][shape];
      if (shape == 3) t.v[1].y = t.v[0].y;
      m.triangles.push_back(t);
    }
    return m;
  }

 private:
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }
  std::mt19937 rng_;
};

TEST(VoxelizeBruteForce, randomSoupsWithTiesMatchTheSpecEvaluatedNaively) {
  SoupMaker maker(99);
  for (int round = 0; round < 100; ++round) {
    const TriangleMesh mesh = maker.soup(30);
    for (FillMode mode : {FillMode::kParity, FillMode::kNonzero, FillMode::kVote}) {
      VoxelizeParams p;
      p.resolution = 16;
      p.mode = mode;
      p.threads = 1 + round % 3;
      auto r = voxelizeSolid(mesh, p);
      ASSERT_TRUE(r.ok()) << r.error().message;
      ASSERT_EQ(r->grid.voxelSize(), 1.0);
      if (mode != FillMode::kVote) {
        const VoxelGrid expected = bruteForce(mesh, r->grid, 0, 1, 2, mode == FillMode::kNonzero);
        ASSERT_EQ(test::mismatches(r->grid, expected), 0) << "round " << round << " " << fillModeName(mode);
        continue;
      }
      // Vote: parity along X (u, v, w = x, y, z), Y (y, x, z) and Z (z, x, y), majority of three.
      const VoxelGrid gx = bruteForce(mesh, r->grid, 0, 1, 2, false);
      const VoxelGrid gy = bruteForce(mesh, r->grid, 1, 0, 2, false);
      const VoxelGrid gz = bruteForce(mesh, r->grid, 2, 0, 1, false);
      VoxelGrid expected(r->grid.dims(), r->grid.frame()), expected_disputed(r->grid.dims(), r->grid.frame());
      int64_t disputed = 0;
      for (int32_t z = 0; z < expected.nz(); ++z)
        for (int32_t y = 0; y < expected.ny(); ++y)
          for (int32_t x = 0; x < expected.nx(); ++x) {
            const int votes = gx.get(x, y, z) + gy.get(x, y, z) + gz.get(x, y, z);
            if (votes >= 2) expected.set(x, y, z);
            if (votes == 1 || votes == 2) {
              expected_disputed.set(x, y, z);
              ++disputed;
            }
          }
      ASSERT_EQ(test::mismatches(r->grid, expected), 0) << "round " << round << " vote";
      ASSERT_EQ(r->disputed_count, disputed) << "round " << round;
      ASSERT_TRUE(r->disputed.has_value());
      ASSERT_EQ(r->disputed->count(), disputed) << "round " << round;
      ASSERT_EQ(test::mismatches(r->disputed->toGrid(), expected_disputed), 0) << "round " << round;
    }
  }
}

}  // namespace
}  // namespace vox
