#include "app/measure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/thickness.h"
#include "vox/core/units.h"

namespace vox::app {

void addMeasurePick(AppState& state, const glm::ivec3& voxel) {
  MeasureUi& m = state.measure;
  if (!(m.dims == state.model.dims())) clearMeasure(m);
  if (m.picks.size() >= 2) m.picks.clear();
  m.dims = state.model.dims();
  m.picks.push_back(voxel);
  m.recent.push_back(voxel);
  if (m.recent.size() > 3) m.recent.erase(m.recent.begin());
}

void clearMeasure(MeasureUi& m) {
  m.picks.clear();
  m.recent.clear();
}

namespace {
// The picks when they were made on the current model's lattice, else none.
const std::vector<glm::ivec3>& onModel(const AppState& state, const std::vector<glm::ivec3>& picks) {
  static const std::vector<glm::ivec3> none;
  return state.measure.dims == state.model.dims() ? picks : none;
}
}  // namespace

const std::vector<glm::ivec3>& recentPicks(const AppState& state) { return onModel(state, state.measure.recent); }
const std::vector<glm::ivec3>& measurePicks(const AppState& state) { return onModel(state, state.measure.picks); }

namespace {

// "  wall 2 mm (spheres)": the thickness the Thickness panel shows at voxel v; empty without one there.
std::string wallAt(const AppState& state, const glm::ivec3& v, const std::string& units) {
  const ThicknessResult* r = currentThickness(state);
  if (!r) return {};
  const double t = shownThickness(state, *r, v);
  if (!(t > 0.0)) return {};
  char buf[80];
  std::snprintf(buf, sizeof buf, "  wall %.4g %s (%s)", t, units.c_str(), shownRay(state, *r) ? "rays" : "spheres");
  return buf;
}

bool filledAt(const Image2D<uint8_t>& mask, int32_t u, int32_t row) {
  return u >= 0 && row >= 0 && u < mask.width && row < mask.height && mask.at(u, row) != 0;
}

}  // namespace

glm::ivec2 snapToEdge(const Image2D<uint8_t>& mask, int32_t u, int32_t row, double reach) {
  const int32_t r = int32_t(std::floor(reach));
  glm::ivec2 best(u, row);
  double best_d = reach * reach + 1e-9;
  bool found = false;
  for (int32_t dv = -r; dv <= r; ++dv) {
    for (int32_t du = -r; du <= r; ++du) {
      const int32_t cu = u + du, cr = row + dv;
      const double d = double(du) * du + double(dv) * dv;
      if (d > best_d || (found && d == best_d) || !filledAt(mask, cu, cr)) continue;
      if (filledAt(mask, cu - 1, cr) && filledAt(mask, cu + 1, cr) && filledAt(mask, cu, cr - 1) &&
          filledAt(mask, cu, cr + 1)) {
        continue;  // inside the material
      }
      best = glm::ivec2(cu, cr);
      best_d = d;
      found = true;
    }
  }
  return best;
}

std::vector<std::string> measureLines(const AppState& state) {
  const std::vector<glm::ivec3>& picks = measurePicks(state);
  std::vector<std::string> lines;
  const GridFrame& f = state.model.frame();
  const std::string u = unitsLabel(f.units);
  char buf[200];
  for (size_t i = 0; i < picks.size(); ++i) {
    const glm::ivec3& v = picks[i];
    const glm::dvec3 c = f.voxelCentre(v.x, v.y, v.z);
    std::snprintf(buf, sizeof buf, "%c  voxel (%d, %d, %d)  at (%.5g, %.5g, %.5g) %s", char('A' + i), v.x, v.y, v.z,
                  c.x, c.y, c.z, u.c_str());
    lines.emplace_back(std::string(buf) + wallAt(state, v, u));
  }
  if (picks.size() == 2) {
    const glm::dvec3 d = glm::dvec3(picks[1] - picks[0]) * f.voxel_size;
    std::snprintf(buf, sizeof buf, "distance %.5g %s  (dx %.4g, dy %.4g, dz %.4g; centre to centre)",
                  std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z), u.c_str(), d.x, d.y, d.z);
    lines.emplace_back(buf);
  }
  return lines;
}

}  // namespace vox::app
