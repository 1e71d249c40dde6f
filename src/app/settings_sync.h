#pragma once
// The choices the window remembers between runs (settings.h), taken from and given back to the params the widgets
// edit. No ImGui and no GL here.
#include "app/app_state.h"

namespace vox::app {

void rememberSettings(AppState& state);  // params -> settings
void applySettings(AppState& state);     // settings -> params

}  // namespace vox::app
