#pragma once
// The Section panel of a coarse view (Document::coarse_level > 1: a .vxm file too large for memory, opened at a
// coarse level): the section through the middle of the coarse section's blocks, at the file's full resolution,
// read from the file in windows of Z layers in the background (io::readVxmInWindows, SectionAccumulator).
#include <cstdint>

#include "app/app_state.h"

namespace vox::app {

// The file's index along `axis` of the middle of coarse section `index`: index x level + level / 2, within the
// file's grid.
int32_t fullResolutionIndex(const AppState& state, Axis axis, int32_t index);
// Starts reading the section of state.section (axis, index) at full resolution; a running one is cancelled.
void startFullSection(AppState& state);
// Takes a finished section (or its error) into state.full_section; called every frame.
void pollFullSection(AppState& state);
// Forgets the full-resolution section (another document).
void clearFullSection(AppState& state);

}  // namespace vox::app
