#pragma once
// FILE arguments: a voxel file (.vxm, .binvox) is read; anything else is read as a mesh or CAD file
// (io::loadMeshFile: STL, OBJ, PLY, 3MF, glTF, OFF, STEP, IGES) and voxelized with the --res / --voxel-size / --mode /
// --threads options (docs/conventions.md, "Command line": default resolution 200).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cli/output.h"
#include "vox/core/mesh.h"
#include "vox/core/text.h"
#include "vox/core/voxel_grid.h"
#include "vox/io/mesh_file.h"
#include "vox/voxelize/voxelize.h"
#include "vox/workflow/model_input.h"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace vox::cli {

struct MeshOptions {
  VoxelizeParams params;
  std::string mode_text = "auto";
  // --memory-limit SIZE; 0: the default (80% of physical memory).
  uint64_t memory_limit_bytes = 0;
  std::string units;  // --units: what the model's numbers are in (mm, cm, m, in); empty: the file's own
  // The options above that only a mesh FILE uses, to say so when they are given with a voxel file.
  std::vector<const CLI::Option*> mesh_only;
};

// Adds --res, --voxel-size, --mode (alias --fill-mode), --threads, --memory-limit to a subcommand. Subcommands
// whose own --mode means something else (xray) pass mode_names = "--fill-mode". --memory-limit takes a SIZE: a
// number of MiB, or a number with K, M or G (KiB, MiB, GiB).
void addMeshOptions(CLI::App& sub, MeshOptions& options, const std::string& mode_names = "--mode,--fill-mode");

// A model read from FILE (vox/workflow/model_input.h).
using LoadedModel = workflow::ModelFile;

// The voxelizer's params from the options (--mode, --memory-limit, --units on top of --res / --voxel-size /
// --threads), for every subcommand that voxelizes a mesh.
Result<VoxelizeParams> voxelizeParams(const MeshOptions& options);

// What reading a mesh file needs from the options: the grid (CAD files are tessellated for its voxel size), --units,
// --memory-limit; progress on stderr when it is a terminal.
io::MeshFileOptions meshFileOptions(const MeshOptions& options);
// Reads a mesh or CAD file; its warnings and notes go through `out`.
Result<io::MeshFileLoad> loadMesh(const std::filesystem::path& file, const MeshOptions& options, Output& out);

// Warns about each mesh-only option (--res, --voxel-size, --mode) given with the voxel file FILE.
void warnMeshOnlyOptions(const std::filesystem::path& file, const MeshOptions& options, Output& out);

// Reads FILE; messages and warnings go through `out`. Progress goes to stderr when it is a terminal.
// With keep_mesh, a mesh FILE's triangles stay in LoadedModel::mesh (the ray thickness casts rays against them).
Result<LoadedModel> loadModel(const std::filesystem::path& file, const MeshOptions& options, Output& out,
                              bool keep_mesh = false);

// The FILE argument's help: which files a subcommand reads.
extern const char* const kFileHelp;

// What every analysis subcommand takes: FILE (a voxel file, or a mesh voxelized with the mesh options) and --json.
struct CommonOptions {
  std::string file;
  bool json = false;
  MeshOptions mesh;
};
void addCommonOptions(CLI::App& sub, CommonOptions& c, const std::string& mode_names = "--mode,--fill-mode");

// The common materials' names, for --material's help and errors ("aluminium, steel, ...").
std::string materialNames();

// Progress printer for a terminal: "voxelizing  42%" on stderr, rewritten in place; silent otherwise.
ProgressFn terminalProgress(const std::string& label);

}  // namespace vox::cli
