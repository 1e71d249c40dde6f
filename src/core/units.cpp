#include "vox/core/units.h"

namespace vox {

double metresPerUnit(std::string_view u) {
  if (u == "mm") return 0.001;
  if (u == "cm") return 0.01;
  if (u == "m") return 1.0;
  if (u == "in" || u == "inch") return 0.0254;
  return 0.0;
}

std::string unitsLabel(std::string_view u) { return u.empty() || u == "model" ? "model units" : std::string(u); }

}  // namespace vox
