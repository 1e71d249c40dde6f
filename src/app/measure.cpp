#include "app/measure.h"

#include <cmath>
#include <cstdio>

#include "vox/core/units.h"

namespace vox::app {

void addMeasurePick(AppState& state, const glm::ivec3& voxel) {
  MeasureUi& m = state.measure;
  if (!(m.dims == state.model.dims()) || m.picks.size() >= 2) m.picks.clear();
  m.dims = state.model.dims();
  m.picks.push_back(voxel);
}

void clearMeasure(AppState& state) { state.measure.picks.clear(); }

const std::vector<glm::ivec3>& measurePicks(const AppState& state) {
  static const std::vector<glm::ivec3> none;
  return state.measure.dims == state.model.dims() ? state.measure.picks : none;
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
    lines.emplace_back(buf);
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
