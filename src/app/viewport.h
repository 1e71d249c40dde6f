#pragma once
// The 3D view: the render module's point renderer drawing into an offscreen framebuffer that ImGui shows as an
// image, with orbit (left drag), pan (right or middle drag, or Shift + left drag) and zoom (wheel). The image is
// redrawn only when something it shows changed, so an idle window costs nothing and moving a slider costs one
// point render per frame.
#include "app/app_state.h"
#include "vox/core/result.h"

namespace vox::app {

// Creates the renderers in the window's GL context (kNoOpenGL with the driver's words when that fails).
Status initViewport(AppState& state);
// Destroys the GL objects; call while the context is still current.
void shutdownViewport(AppState& state);

// Brings the renderers up to date with the model, the parts and the overlay choice (uploads what changed); each frame
// of drawViewport starts with it. Needs the renderers' GL context current.
void syncRenderers(AppState& state);

// Panel function: draws the view into the current ImGui window's remaining area.
void drawViewport(AppState& state);

}  // namespace vox::app
