// Names of the analysis enums as the CLI and the JSON output spell them (docs/conventions.md, "Command line").
#include <algorithm>
#include <cctype>

#include "vox/analysis/analysis.h"

namespace vox {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

}  // namespace

const char* axisName(Axis a) {
  switch (a) {
    case Axis::kX:
      return "x";
    case Axis::kY:
      return "y";
    case Axis::kZ:
      return "z";
  }
  return "?";
}

std::optional<Axis> parseAxis(const std::string& s) {
  const std::string l = lower(s);
  if (l == "x") return Axis::kX;
  if (l == "y") return Axis::kY;
  if (l == "z") return Axis::kZ;
  return std::nullopt;
}

const char* xrayModeName(XrayMode m) {
  switch (m) {
    case XrayMode::kMin:
      return "min";
    case XrayMode::kMax:
      return "max";
    case XrayMode::kTotal:
      return "total";
  }
  return "?";
}

std::optional<XrayMode> parseXrayMode(const std::string& s) {
  const std::string l = lower(s);
  if (l == "min" || l == "minimum") return XrayMode::kMin;
  if (l == "max" || l == "maximum") return XrayMode::kMax;
  if (l == "total") return XrayMode::kTotal;
  return std::nullopt;
}

Axis imageRightAxis(Axis normal) { return normal == Axis::kX ? Axis::kY : Axis::kX; }
Axis imageUpAxis(Axis normal) { return normal == Axis::kZ ? Axis::kY : Axis::kZ; }

}  // namespace vox
