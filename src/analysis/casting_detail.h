#pragma once
// What the casting simulation (solidification.cpp) hands to the search for its hot spots (casting_hot_spots.cpp).
#include <cstdint>
#include <vector>

#include "vox/analysis/casting.h"

namespace vox::casting_detail {

// Cell kinds of the simulated box.
constexpr uint8_t kMould = 0;
constexpr uint8_t kMetal = 1;   // bit 0: metal
constexpr uint8_t kFeeder = 2;  // bit 1: a feeder's (with kMetal)

// The regions freezing last, over the metal cells of a box (dims, x fastest) whose solidification times are `time`
// (s): each maximum of the time (6-connected through metal) whose region dips on every path to later metal by at
// least max(abs_tolerance seconds, rel_tolerance x its own latest time) is isolated; one dipping less but holding at
// least `min_voxels` voxels is listed as fed (by the spot it merges into). Latest first. Centres are in `frame`;
// `cell` gives each spot's cell.
struct TimeSpot {
  CastingHotSpot spot;
  int64_t cell = 0;
  int64_t fed_by_root = -1;  // while searching: the root cell of the set a fed spot merged into
};
std::vector<TimeSpot> findTimeSpots(const Dims& dims, const std::vector<uint8_t>& kind, const std::vector<float>& time,
                                    const GridFrame& frame, double abs_tolerance, double rel_tolerance,
                                    int64_t min_voxels);

}  // namespace vox::casting_detail
