// The alloys and moulds of the casting simulation, and its feeders (vox/analysis/casting.h). Each value's source is
// in docs/conventions.md ("Casting"): constant properties, as handbooks give them, reported in the JSON as used.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "vox/analysis/casting.h"
#include "vox/core/text.h"

namespace vox {

const std::vector<Alloy>& castingAlloys() {
  static const std::vector<Alloy> alloys = {
      // name, liquidus, solidus (C), density (kg/m3), latent heat (J/kg), conductivity (W/m K), specific heat (J/kg K)
      {"aluminium", 660.3, 660.3, 2702.0, 397000.0, 237.0, 903.0},
      {"a356", 615.0, 555.0, 2685.0, 389000.0, 151.0, 963.0},
      {"grey-iron", 1210.0, 1150.0, 7150.0, 230000.0, 46.0, 490.0},
      {"carbon-steel", 1510.0, 1460.0, 7854.0, 272000.0, 60.5, 434.0},
  };
  return alloys;
}

const std::vector<MouldMaterial>& castingMoulds() {
  static const std::vector<MouldMaterial> moulds = {
      // name, conductivity (W/m K), density (kg/m3), specific heat (J/kg K), starting temperature (C)
      {"silica-sand", 0.52, 1600.0, 1170.0, 20.0},
      {"steel", 24.3, 7800.0, 460.0, 200.0},
  };
  return moulds;
}

const Alloy* findAlloy(std::string_view name) {
  for (const Alloy& a : castingAlloys())
    if (a.name == name) return &a;
  return nullptr;
}

const MouldMaterial* findMould(std::string_view name) {
  for (const MouldMaterial& m : castingMoulds())
    if (m.name == name) return &m;
  return nullptr;
}

namespace {
template <class T>
std::string namesOf(const std::vector<T>& items) {
  std::string out;
  for (const T& t : items) out += (out.empty() ? "" : ", ") + t.name;
  return out;
}
}  // namespace

std::string alloyNames() { return namesOf(castingAlloys()); }
std::string mouldNames() { return namesOf(castingMoulds()); }

}  // namespace vox
