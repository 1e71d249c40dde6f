#include "vox/core/feeder.h"

#include <charconv>
#include <cmath>
#include <string>

#include "vox/core/text.h"

namespace vox {

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

Result<LatticeGrid> feederVoxels(const Feeder& f, const Lattice& lattice) {
  const GridFrame frame = lattice.frameAt(glm::ivec3(0));
  glm::ivec3 lo(0), hi(0);
  if (!feederBox(f, frame, lo, hi)) {
    return makeError(ErrorCode::kLimit, "the feeder lies further from the part than a grid holds");
  }
  const glm::ivec3 n = hi - lo + 1;
  if (n.x <= 0 || n.y <= 0 || n.z <= 0) {
    return makeError(ErrorCode::kInvalidArgument, "the feeder is thinner or shorter than a voxel: it holds no voxel");
  }
  if (n.x > VoxelGrid::kMaxDim || n.y > VoxelGrid::kMaxDim || n.z > VoxelGrid::kMaxDim) {
    return makeError(ErrorCode::kLimit, "the feeder spans " + std::to_string(n.x) + " x " + std::to_string(n.y) +
                                            " x " + std::to_string(n.z) + " voxels, more than a grid holds");
  }
  const Dims dims{n.x, n.y, n.z};
  if (estimateGridBytes(dims) > defaultMemoryLimitBytes() / 2) {
    return makeError(ErrorCode::kLimit, "the feeder spans " + std::to_string(n.x) + " x " + std::to_string(n.y) +
                                            " x " + std::to_string(n.z) + " voxels, more than memory holds");
  }
  VoxelGrid g(dims, lattice.frameAt(lo));
  for (int32_t z = 0; z < n.z; ++z)
    for (int32_t y = 0; y < n.y; ++y)
      for (int32_t x = 0; x < n.x; ++x)
        if (inFeeder(f, frame, lo + glm::ivec3(x, y, z))) g.set(x, y, z, true);
  if (g.filledCount() == 0) {
    return makeError(ErrorCode::kInvalidArgument, "the feeder is thinner or shorter than a voxel: it holds no voxel");
  }
  return LatticeGrid{std::move(g), lo};
}

}  // namespace vox
