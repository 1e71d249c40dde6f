// voxmod: with a subcommand it works headless (src/cli); with no arguments or a mesh/voxel file it opens the
// modeler window (src/app). The one catch-all for unexpected exceptions lives here and nowhere else.
#include <cstdio>
#include <exception>

#include "vox/app/app.h"
#include "vox/cli/cli.h"

int main(int argc, char** argv) {
  try {
    return vox::cli::main(argc, argv, &vox::app::runGui);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "voxmod: internal error: %s\n", e.what());
  } catch (...) {
    std::fprintf(stderr, "voxmod: internal error\n");
  }
  return 70;
}
