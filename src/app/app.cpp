#include "vox/app/app.h"

#include <cstdio>

namespace vox::app {

// The modeler window is not written yet (issue 7). Until then, say so plainly instead of pretending.
int runGui(int /*argc*/, char** /*argv*/) {
  std::fprintf(stderr,
               "voxmod: the modeler window is not part of this build yet; use a subcommand "
               "(voxmod --help), e.g. voxmod info FILE\n");
  return 1;
}

}  // namespace vox::app
