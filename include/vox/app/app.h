#pragma once
// The modeler window (GLFW + Dear ImGui). The only module that includes ImGui.
namespace vox::app {

// Opens the window; argv[1], when given, is a mesh or voxel file to open. Returns the process exit code.
int runGui(int argc, char** argv);

}  // namespace vox::app
