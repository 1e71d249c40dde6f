#pragma once
// The report (`voxmod report`): one self-contained HTML page of what voxmod computes of a part, numbers with
// their units and pictures embedded as PNG data: the model (dims, voxel size, volume with its bound, box, centroid,
// mass for a material), the walls (local thickness, the thinnest wall, the walls under a minimum wall), the hot spots
// with their moduli, printability upright (overhang, support, trapped cavities) and a section through the middle
// coloured by thickness. The caller adds pictures only it can make (a rendered 3D view). Written once here for the
// CLI and the window.
#include <cstdint>
#include <string>
#include <vector>

#include "vox/core/mesh.h"
#include "vox/core/progress.h"
#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"

namespace vox::workflow {

struct ReportOptions {
  std::string name;                    // the part's name (its file's), in the title
  double min_wall = 0.0;               // > 0: the walls thinner than this (model units) listed
  double density_kg_m3 = 0.0;          // > 0 (and known units): the mass
  std::string material;                // the density's name, if from a material
  const TriangleMesh* mesh = nullptr;  // the mesh the grid was voxelized from (printability's normals), or null
};

struct ReportPicture {
  std::string title;
  std::vector<uint8_t> png;
};

struct ReportFacts {  // the numbers the page shows, for the caller's summary (JSON)
  double volume = 0.0, wall_min = 0.0, thickness_max = 0.0, support_volume = 0.0;
  int64_t thin_regions = 0, hot_spots = 0, trapped_cavities = 0;
};

// The page, and its facts. Progress covers the analyses; returning false cancels (kCancelled).
Result<std::string> buildReport(const VoxelGrid& grid, const ReportOptions& options,
                                const std::vector<ReportPicture>& pictures, ReportFacts* facts = nullptr,
                                const ProgressFn& progress = {});

}  // namespace vox::workflow
