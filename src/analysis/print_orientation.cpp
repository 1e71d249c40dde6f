// The build directions searched for the least support, and their names. See vox/analysis/printability.h.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include <glm/geometric.hpp>

#include "vox/analysis/printability.h"
#include "vox/core/text.h"

namespace vox {

std::vector<glm::dvec3> printDirections(int sphere) {
  std::vector<glm::dvec3> out = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < sphere; ++i) {
    const double z = 1.0 - 2.0 * (double(i) + 0.5) / double(sphere);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden * double(i);
    out.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
  }
  return out;
}

Result<std::vector<PrintSupport>> searchPrintOrientations(const PrintSurface& surface, const VoxelGrid& grid,
                                                          const std::vector<glm::dvec3>& directions,
                                                          const PrintParams& params, const ProgressFn& progress) {
  std::vector<PrintSupport> out;
  out.reserve(directions.size());
  for (size_t i = 0; i < directions.size(); ++i) {
    PrintParams p = params;
    p.up = directions[i];
    p.fields = false;
    const ProgressFn each = [&](double f) {
      return !progress || progress((double(i) + f) / double(directions.size()));
    };
    auto support = computePrintSupport(surface, grid, p, each);
    if (!support) return support.error();
    out.push_back(std::move(support).value());
  }
  std::stable_sort(out.begin(), out.end(), [](const PrintSupport& a, const PrintSupport& b) {
    if (a.support_volume != b.support_volume) return a.support_volume < b.support_volume;
    if (a.overhang_area != b.overhang_area) return a.overhang_area < b.overhang_area;
    return a.height < b.height;
  });
  return out;
}

std::string printDirectionName(glm::dvec3 d) {
  static const char* const names[] = {"+x", "-x", "+y", "-y", "+z", "-z"};
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign = 0; sign < 2; ++sign) {
      glm::dvec3 e(0.0);
      e[axis] = sign == 0 ? 1.0 : -1.0;
      if (glm::length(d - e) < 1e-12) return names[2 * axis + sign];
    }
  }
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(4);
  s << d.x << ", " << d.y << ", " << d.z;
  return s.str();
}

Result<glm::dvec3> parsePrintDirection(const std::string& text) {
  static const std::pair<const char*, glm::dvec3> axes[] = {{"+x", {1, 0, 0}},  {"-x", {-1, 0, 0}}, {"+y", {0, 1, 0}},
                                                            {"-y", {0, -1, 0}}, {"+z", {0, 0, 1}},  {"-z", {0, 0, -1}}};
  for (const auto& [name, d] : axes)
    if (text == name) return d;
  // X,Y,Z: three numbers separated by commas (spaces around them allowed)
  std::string spaced = text;
  std::replace(spaced.begin(), spaced.end(), ',', ' ');
  const std::vector<std::string_view> parts = splitWords(spaced);
  glm::dvec3 d(0.0);
  bool ok = parts.size() == 3 && std::count(text.begin(), text.end(), ',') == 2;
  for (size_t k = 0; ok && k < 3; ++k) ok = parseFileNumber(parts[k], d[int(k)]);
  if (!ok) {
    return makeError(ErrorCode::kInvalidArgument,
                     "build direction '" + text + "': give +z, -z, +x, -x, +y, -y or X,Y,Z");
  }
  const double n = glm::length(d);
  if (!(n > 0.0)) return makeError(ErrorCode::kInvalidArgument, "build direction '" + text + "' is zero");
  return d / n;
}

}  // namespace vox
