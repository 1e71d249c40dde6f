#include "vox/cli/cli.h"

#include <cstdio>
#include <string>

#include "cli/commands.h"

namespace vox::cli {

int main(int argc, char** argv, GuiEntry gui) {
  // A subcommand, --help or --version: headless. Anything else (no arguments, a file, the window's own options
  // such as --script) opens the GUI, which reports options it does not know.
  const std::string first = argc >= 2 ? argv[1] : "";
  const bool headless = findCommand(first) != nullptr || first == "--help" || first == "-h" || first == "--version";
  return headless ? runCommandLine(argc, argv) : gui(argc, argv);
}

}  // namespace vox::cli
