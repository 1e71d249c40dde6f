#include "vox/cli/cli.h"

#include <cstdio>
#include <string>

#include "cli/commands.h"

namespace vox::cli {

int main(int argc, char** argv, GuiEntry gui) {
  // No arguments, or a first argument that is neither an option nor a subcommand: open the GUI.
  if (argc < 2 || (argv[1][0] != '-' && findCommand(argv[1]) == nullptr)) return gui(argc, argv);
  return runCommandLine(argc, argv);
}

}  // namespace vox::cli
