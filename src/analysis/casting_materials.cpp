// The alloys and moulds of the casting simulation, and its feeders (vox/analysis/casting.h). Each value's source is
// in docs/conventions.md ("Casting"): constant properties, as handbooks give them, reported in the JSON as used.
#include <algorithm>
#include <charconv>
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

double feederModulus(const Feeder& f) {
  if (f.diameter <= 0.0 || f.height <= 0.0) return 0.0;
  return f.diameter * f.height / (4.0 * f.height + f.diameter);
}

Result<Feeder> parseFeeder(std::string_view text) {
  const std::string_view prefix = "cylinder:";
  const auto bad = [&](const std::string& why) {
    return makeError(ErrorCode::kInvalidArgument,
                     "feeder '" + std::string(text) + "': " + why + " (expected cylinder:X,Y,Z,D,H in model units)");
  };
  if (text.substr(0, prefix.size()) != prefix) return bad("only cylinders are known");
  std::string_view rest = text.substr(prefix.size());
  double v[5];
  for (int i = 0; i < 5; ++i) {
    const size_t comma = i < 4 ? rest.find(',') : rest.size();
    if (comma == std::string_view::npos) return bad("five numbers are needed");
    const std::string_view item = rest.substr(0, comma);
    const auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), v[i]);
    if (ec != std::errc() || end != item.data() + item.size() || !std::isfinite(v[i])) {
      return bad("'" + std::string(item) + "' is not a number");
    }
    rest = i < 4 ? rest.substr(comma + 1) : std::string_view();
  }
  if (v[3] <= 0.0 || v[4] <= 0.0) return bad("the diameter and height must be positive");
  return Feeder{glm::dvec3(v[0], v[1], v[2]), v[3], v[4]};
}

bool feederBox(const Feeder& f, const GridFrame& frame, glm::ivec3& lo, glm::ivec3& hi) {
  const double h = frame.voxel_size, r = 0.5 * f.diameter;
  constexpr double kFar = double(1 << 28);  // voxel indices this far out hold no grid voxmod makes
  bool held = true;
  // voxel i's centre: origin + (i + 0.5) h
  const auto index = [&](double v, double o, bool first) {
    const double i = first ? std::ceil((v - o) / h - 0.5) : std::floor((v - o) / h - 0.5);
    if (!(std::abs(i) < kFar)) {
      held = false;
      return int32_t(0);
    }
    return int32_t(i);
  };
  lo = glm::ivec3(index(f.base.x - r, frame.origin.x, true), index(f.base.y - r, frame.origin.y, true),
                  index(f.base.z, frame.origin.z, true));
  hi = glm::ivec3(index(f.base.x + r, frame.origin.x, false), index(f.base.y + r, frame.origin.y, false),
                  index(f.base.z + f.height, frame.origin.z, false));
  return held;
}

bool inFeeder(const Feeder& f, const GridFrame& frame, glm::ivec3 v) {
  const glm::dvec3 c = frame.voxelCentre(v.x, v.y, v.z);
  const double dx = c.x - f.base.x, dy = c.y - f.base.y, r = 0.5 * f.diameter;
  return dx * dx + dy * dy <= r * r && c.z >= f.base.z && c.z <= f.base.z + f.height;
}

}  // namespace vox
