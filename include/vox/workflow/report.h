#pragma once
// The report (`voxmod report`): one self-contained HTML page of what voxmod computes of a part, numbers with
// their units and pictures embedded as PNG data: the model (dims, voxel size, volume with its bound, box, centroid,
// mass for a material), the walls (local thickness, the thinnest wall, the walls under a minimum wall), the hot spots
// with their moduli, printability upright (overhang, support, trapped cavities), a section through the middle
// coloured by thickness and, for an assembly, its parts, the pairs that interfere or touch and a clearance the caller
// found. The caller adds pictures only it can make (a rendered 3D view). Written once here for the CLI and the
// window.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "vox/analysis/assembly.h"
#include "vox/core/assembly.h"
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
  // An assembly (two parts or more; the grid is their union): its parts listed and their interference found, each
  // overlap at most `contact` thick (model units; 0: none) listed as contact, not interference.
  const Assembly* parts = nullptr;
  double contact = 0.0;
  struct PartClearance {
    size_t a = 0, b = 0;  // part indices
    Clearance clearance;
  };
  std::optional<PartClearance> clearance;  // one the caller found (the window's selected pair), shown as it is
};

struct ReportPicture {
  std::string title;
  std::vector<uint8_t> png;
};

struct ReportFacts {  // the numbers the page shows, for the caller's summary (JSON)
  double volume = 0.0, wall_min = 0.0, thickness_max = 0.0, support_volume = 0.0;
  int64_t thin_regions = 0, hot_spots = 0, trapped_cavities = 0;
  int64_t parts = 0, interfering_pairs = 0, contact_pairs = 0;  // the assembly's (0 for one part)
};

// The page, and its facts. Progress covers the analyses; returning false cancels (kCancelled).
Result<std::string> buildReport(const VoxelGrid& grid, const ReportOptions& options,
                                const std::vector<ReportPicture>& pictures, ReportFacts* facts = nullptr,
                                const ProgressFn& progress = {});

}  // namespace vox::workflow
