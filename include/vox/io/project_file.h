#pragma once
// A voxmod project (.vxp): what the window had open, so that it reopens as it was: the model (as voxelized or loaded,
// and as shown after skin layers were peeled), or a scene of parts with their names, colours, visibility and
// placements on one lattice, the length units, and the view worth keeping (panel, section, selection). A zip of a
// JSON manifest and one .vxm file per grid; docs/file-format.md describes it. The window saves it (File > Save, Save
// As with .vxp) and autosaves it for recovery.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "vox/core/assembly.h"
#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"

namespace vox::io {

struct ProjectFile {
  std::string source;      // the file the document was opened from (may be empty)
  std::string origin;      // how the model came about, e.g. "voxelized at R=200 (nonzero)"
  int64_t resolution = 0;  // the resolution it was voxelized at (0: loaded)
  std::string units = "model";
  // The model as voxelized or loaded (the round peels named in `round_peels` made it), and as shown: `base` less its
  // outer `peeled` skin layers. With parts, `base` is the union of the parts.
  VoxelGrid base;
  VoxelGrid shown;
  int32_t peeled = 0;
  std::string round_peels;
  std::optional<Assembly> parts;  // a scene of parts; none for one model
  // The view worth keeping.
  std::string panel;             // "model", "section", ... (empty: the window's choice)
  std::string section_axis;      // "x", "y", "z" (empty: the window's choice)
  int32_t section_index = -1;    // -1: the middle
  std::vector<size_t> selected;  // selected parts (indices from 0)
};

// The project as the bytes of a .vxp file. Grids are stored once: `shown` only when something was peeled, `base` only
// when there are no parts or something was peeled (else it is the union of the parts, made again on reading).
// Fails (kLimit) past the zip's 4 GiB.
Result<std::vector<uint8_t>> encodeProject(const ProjectFile& project, const std::string& name);
// Reads a .vxp file's bytes; `name` names it in messages. Fails (kParse, kCorrupt, kUnsupported) naming the file and
// the problem for anything that is not a whole project of a version this build reads (a key missing or of the wrong
// kind, a number out of range, grids that do not fit together), and (kLimit) when its grids, with the union of its
// parts, would need more than `memory_limit_bytes` all together (0: the default limit), before any is allocated.
// With parts and no stored `base`, `base` and `shown` are left empty for the caller to make (the union of the parts).
Result<ProjectFile> decodeProject(std::span<const uint8_t> bytes, const std::string& name,
                                  uint64_t memory_limit_bytes = 0);
// Written atomically: the old file stays whole until the new one is complete.
Status saveProject(const ProjectFile& project, const std::filesystem::path& path);
Result<ProjectFile> loadProject(const std::filesystem::path& path, uint64_t memory_limit_bytes = 0);
bool isProjectFile(const std::filesystem::path& path);  // by extension: .vxp
// The file a project was opened from (its manifest's `source`), read without decoding its grids; empty when the
// file is no readable project.
std::string projectSource(const std::filesystem::path& path);

}  // namespace vox::io
