#include "app/settings_sync.h"

namespace vox::app {

void rememberSettings(AppState& state) {
  Settings& s = state.settings;
  s.resolution = state.voxelize.params.resolution;
  s.fill_mode = fillModeName(state.voxelize.params.mode);
  s.lit = state.view.lit;
  s.round_points = state.view.round_points;
  s.point_size_px = state.view.point_size_px;
  s.lod = state.view.lod;
}

void applySettings(AppState& state) {
  const Settings& s = state.settings;
  state.voxelize.params.resolution = s.resolution;
  if (auto mode = parseFillMode(s.fill_mode)) state.voxelize.params.mode = *mode;
  state.view.lit = s.lit;
  state.view.round_points = s.round_points;
  state.view.point_size_px = s.point_size_px;
  state.view.lod = s.lod;
}

}  // namespace vox::app
