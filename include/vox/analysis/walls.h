#pragma once
// Walls, not edges (docs/accuracy.md, "Walls"): a wall is material between two surfaces that face each other. The
// sphere thickness (vox/analysis/thickness.h) reads every convex edge thin, because no ball inside the material
// reaches into the edge; a wall is found instead on the distance field's ridge:
//  - climbing the distance field from any voxel, the distance rises at slope 1 across a wall and keeps rising along
//    an edge's bisector (at sin(a/2) for an edge of opening a) until the edge meets a wall or the part's core;
//  - it stops on a wall's mid-surface, where the two sides face each other and the distance is flat along it;
//  - so the wall stops are the voxels from which no voxel within `reach` voxels rises at the edge slope
//    sin(angle/2) or more, `angle` being the largest opening of two sides still read as a wall (the ray method's
//    --ray-angle), and a wall's thickness is twice the distance at its stops;
//  - the thin wall itself is the union of the inscribed balls of its stops (every voxel of a plate, a tube or a fin;
//    none of a convex edge).
#include <cstdint>
#include <vector>

#include "vox/analysis/distance.h"
#include "vox/analysis/thickness.h"
#include "vox/core/progress.h"
#include "vox/core/result.h"

namespace vox {

struct WallRidgeParams {
  double angle_deg = 30.0;  // two sides opening by at most this angle are a wall; sharper openings are edges
  int32_t reach = 3;        // voxels: how far a stop looks for a steeper way up (discretisation noise is ~0.5 voxel)
};

// The wall stops of a part: independent of any minimum wall, found once per distance field.
struct WallRidge {
  struct Stop {
    int64_t index = 0;     // into the distance field's box (x fastest, then y, then z)
    uint32_t squared = 0;  // its squared distance (voxel units^2): the wall's half-thickness squared
  };
  Dims box_dims{};
  glm::ivec3 box_min{0};
  GridFrame frame{};
  std::vector<Stop> stops;  // thinnest first
};

// The wall stops of a dense or packed distance field (vox/analysis/distance.h). Cost: a look at the 26 neighbours
// of every filled voxel, and at the (2 reach + 1)^3 box of the few on a ridge; memory: 12 bytes per stop.
Result<WallRidge> findWallRidge(const DistanceField& distance, const WallRidgeParams& params = {},
                                const ProgressFn& progress = {});

struct WallParams {
  double min_wall = 0.0;  // model units: walls thinner than this are listed
  // Regions whose exposed area (model units^2) is below this are specks, counted but not listed; < 0: min_wall^2.
  double min_area = -1.0;
  // How the union of the thin stops' balls is painted: kAuto ball by ball while their volume is under a few passes
  // over the box, else as the lower envelope of the stops' paraboloids (a distance transform, linear in the box). The
  // voxels are the same (the tests check both against a brute force).
  enum class Paint { kAuto, kBalls, kEnvelope };
  Paint paint = Paint::kAuto;
};

struct Walls {
  double min_wall = 0.0;                // model units
  double min_area = 0.0;                // the speck limit used, model units^2
  double wall_min = 0.0;                // the part's thinnest wall: twice its thinnest stop, model units (0: empty)
  int64_t voxels = 0;                   // voxels in the listed thin walls
  int64_t specks = 0;                   // thin regions under min_area, not listed
  std::vector<ThinWallRegion> regions;  // 26-connected, largest first; `min` is the wall's thickness
  // One bit per voxel of the box (x fastest, then y, then z): set in the listed thin walls.
  std::vector<uint64_t> mask;
  Dims box_dims{};
  glm::ivec3 box_min{0};
  bool inWall(int64_t x, int64_t y, int64_t z) const;  // grid coordinates
};

// The walls thinner than params.min_wall, from the ridge and a field over the same box whose nonzero values are the
// filled voxels (the distance field, or the local thickness's radius).
Result<Walls> findWalls(const WallRidge& ridge, const DistanceField& filled, const WallParams& params,
                        const ProgressFn& progress = {});

}  // namespace vox
