#pragma once
// The modeler window (GLFW + Dear ImGui). The only module that includes ImGui.
namespace vox::app {

// Opens the window: `voxmod [FILE] [--script SCRIPT] [--screenshot PNG] [--size WxH]`. FILE is a mesh (.stl) or a
// voxel file (.vxm, .binvox); without one the bundled models/featuretype.stl is opened and voxelized. --script runs
// line commands for tests and documentation (src/app/script.h); --screenshot saves the window once everything is
// computed and quits. Settings live in $XDG_CONFIG_HOME/voxmod (or ~/.config/voxmod).
// Returns the process exit code: 0, 1 (usage or a failed script), 2 (a --screenshot could not be written) or
// 3 (no display or no OpenGL 3.3 context).
int runGui(int argc, char** argv);

}  // namespace vox::app
