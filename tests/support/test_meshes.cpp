#include "support/test_meshes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

namespace vox::test {

TriangleMesh boxMesh(glm::dvec3 lo, glm::dvec3 hi) {
  const glm::vec3 p[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                          {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
  const int f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                        {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  TriangleMesh m;
  m.name = "box";
  for (auto& t : f) m.triangles.push_back({{p[t[0]], p[t[1]], p[t[2]]}});
  return m;
}

TriangleMesh icosphere(glm::dvec3 centre, double radius, int subdivisions) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<glm::dvec3> v = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                               {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (auto& p : v) p = glm::normalize(p);
  std::vector<std::array<int, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back(glm::normalize(v[size_t(a)] + v[size_t(b)]));
      return mid[key] = int(v.size()) - 1;
    };
    std::vector<std::array<int, 3>> g;
    for (auto& tri : f) {
      const int a = midpoint(tri[0], tri[1]), b = midpoint(tri[1], tri[2]), c = midpoint(tri[2], tri[0]);
      g.push_back({tri[0], a, c});
      g.push_back({tri[1], b, a});
      g.push_back({tri[2], c, b});
      g.push_back({a, b, c});
    }
    f = std::move(g);
  }
  TriangleMesh m;
  m.name = "icosphere";
  for (auto& tri : f) {
    Triangle out;
    for (int k = 0; k < 3; ++k) out.v[k] = glm::vec3(centre + radius * v[size_t(tri[size_t(k)])]);
    m.triangles.push_back(out);
  }
  return m;
}

TriangleMesh torus(glm::dvec3 centre, double ring_radius, double tube_radius, int n, int m) {
  auto point = [&](int i, int j) {
    const double a = 2.0 * std::numbers::pi * (i % n) / n, b = 2.0 * std::numbers::pi * (j % m) / m;
    const double r = ring_radius + tube_radius * std::cos(b);
    return glm::vec3(centre + glm::dvec3(r * std::cos(a), r * std::sin(a), tube_radius * std::sin(b)));
  };
  TriangleMesh mesh;
  mesh.name = "torus";
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      const glm::vec3 p00 = point(i, j), p10 = point(i + 1, j), p11 = point(i + 1, j + 1), p01 = point(i, j + 1);
      // Outward: (d/da) x (d/db) points away from the tube's axis.
      mesh.triangles.push_back({{p00, p10, p11}});
      mesh.triangles.push_back({{p00, p11, p01}});
    }
  }
  return mesh;
}

TriangleMesh prismAlongX(const std::vector<glm::dvec2>& yz, double x0, double x1) {
  TriangleMesh m;
  m.name = "prism";
  auto at = [&](double x, size_t i) {
    return glm::vec3(float(x), float(yz[i % yz.size()].x), float(yz[i % yz.size()].y));
  };
  for (size_t i = 1; i + 1 < yz.size(); ++i) {
    m.triangles.push_back({{at(x0, 0), at(x0, i + 1), at(x0, i)}});  // clockwise seen from +x: normal -x
    m.triangles.push_back({{at(x1, 0), at(x1, i), at(x1, i + 1)}});
  }
  for (size_t i = 0; i < yz.size(); ++i) {
    m.triangles.push_back({{at(x0, i), at(x0, i + 1), at(x1, i + 1)}});
    m.triangles.push_back({{at(x0, i), at(x1, i + 1), at(x1, i)}});
  }
  return m;
}

TriangleMesh octahedron(glm::dvec3 c, double r) {
  TriangleMesh m;
  m.name = "octahedron";
  for (int sx : {-1, 1})
    for (int sy : {-1, 1})
      for (int sz : {-1, 1}) {
        glm::vec3 a(c + glm::dvec3(sx * r, 0, 0)), b(c + glm::dvec3(0, sy * r, 0)), d(c + glm::dvec3(0, 0, sz * r));
        // (b - a) x (d - a) points along (sx, sy, sz) when sx * sy * sz > 0; otherwise swap to keep it outward.
        if (sx * sy * sz > 0) {
          m.triangles.push_back({{a, b, d}});
        } else {
          m.triangles.push_back({{a, d, b}});
        }
      }
  return m;
}

TriangleMesh tetrahedron(glm::dvec3 corner, double size) {
  const glm::vec3 o(corner), x(corner + glm::dvec3(size, 0, 0)), y(corner + glm::dvec3(0, size, 0)),
      z(corner + glm::dvec3(0, 0, size));
  TriangleMesh m;
  m.name = "tetrahedron";
  m.triangles = {{{o, y, x}}, {{o, x, z}}, {{o, z, y}}, {{x, y, z}}};
  return m;
}

TriangleMesh cantileverMesh() { return combined(boxMesh({0, 0, 0}, {10, 10, 20}), boxMesh({10, 0, 15}, {40, 10, 20})); }

double windingNumber(const TriangleMesh& mesh, const glm::dvec3& p) {
  double sum = 0.0;
  for (const Triangle& t : mesh.triangles) {
    const glm::dvec3 a = glm::dvec3(t.v[0]) - p, b = glm::dvec3(t.v[1]) - p, c = glm::dvec3(t.v[2]) - p;
    const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    const double num = glm::dot(a, glm::cross(b, c));
    const double den = la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
    sum += 2.0 * std::atan2(num, den);
  }
  return sum / (4.0 * std::numbers::pi);
}

glm::dmat3 rotation(glm::dvec3 axis, double degrees) {
  axis = glm::normalize(axis);
  const double a = degrees * std::numbers::pi / 180.0, c = std::cos(a), s = std::sin(a);
  const double x = axis.x, y = axis.y, z = axis.z;
  // Column-major (glm): columns are the images of the basis vectors.
  return glm::dmat3(glm::dvec3(c + x * x * (1 - c), y * x * (1 - c) + z * s, z * x * (1 - c) - y * s),
                    glm::dvec3(x * y * (1 - c) - z * s, c + y * y * (1 - c), z * y * (1 - c) + x * s),
                    glm::dvec3(x * z * (1 - c) + y * s, y * z * (1 - c) - x * s, c + z * z * (1 - c)));
}

TriangleMesh transformed(const TriangleMesh& mesh, const glm::dmat3& rot, glm::dvec3 centre) {
  TriangleMesh out = mesh;
  for (auto& t : out.triangles)
    for (auto& v : t.v) v = glm::vec3(centre + rot * (glm::dvec3(v) - centre));
  return out;
}

TriangleMesh combined(const TriangleMesh& a, const TriangleMesh& b) {
  TriangleMesh out = a;
  out.triangles.insert(out.triangles.end(), b.triangles.begin(), b.triangles.end());
  return out;
}

int64_t mismatches(const VoxelGrid& a, const VoxelGrid& b) {
  const int32_t nx = std::max(a.nx(), b.nx()), ny = std::max(a.ny(), b.ny()), nz = std::max(a.nz(), b.nz());
  int64_t n = 0;
  for (int32_t z = 0; z < nz; ++z)
    for (int32_t y = 0; y < ny; ++y)
      for (int32_t x = 0; x < nx; ++x) {
        const bool va = a.inBounds(x, y, z) && a.get(x, y, z);
        const bool vb = b.inBounds(x, y, z) && b.get(x, y, z);
        n += va != vb ? 1 : 0;
      }
  return n;
}

VoxelGrid gridFromPredicate(const VoxelGrid& like, const std::function<bool(const glm::dvec3&)>& inside) {
  VoxelGrid g(like.dims(), like.frame());
  for (int32_t z = 0; z < g.nz(); ++z)
    for (int32_t y = 0; y < g.ny(); ++y)
      for (int32_t x = 0; x < g.nx(); ++x)
        if (inside(g.frame().voxelCentre(x, y, z))) g.set(x, y, z);
  return g;
}

}  // namespace vox::test
