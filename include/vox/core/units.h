#pragma once
// Length units of a model. STL files carry none, so a mesh's units are "model" until the user says what they are
// (the voxelize dialog, `--units`); a .vxm file stores them. Known units convert to metres for masses in kg.
#include <array>
#include <string>
#include <string_view>

namespace vox {

// The units voxmod offers, in the order menus show them.
inline constexpr std::array<std::string_view, 5> kLengthUnits = {"model", "mm", "cm", "m", "in"};
// Metres per unit: 0.001 for "mm", 0.0254 for "in" ("inch" too); 0 for "model" and anything unknown.
double metresPerUnit(std::string_view units);
// "model units" for "model" (and an empty string), the unit itself otherwise: for messages and labels.
std::string unitsLabel(std::string_view units);

}  // namespace vox
