#pragma once
// The headless command line (docs/conventions.md, "Command line"). Never links ImGui or opens a window; the GUI entry
// point is passed in by main() so that cli does not depend on app.
namespace vox::cli {

// Signature of the GUI entry: receives the program's arguments (argv[1], if any, is a file to open).
using GuiEntry = int (*)(int argc, char** argv);

// Dispatches: a subcommand runs headless; no arguments or a file argument opens the GUI through `gui`.
// Exit codes: 0 ok, 1 usage, 2 input or output error, 3 no usable OpenGL (render).
int main(int argc, char** argv, GuiEntry gui);

}  // namespace vox::cli
