#pragma once
// A file turned into a model, for both front ends: a mesh or CAD file read (io::loadMeshFile) and voxelized
// (voxelizeSolid), or a voxel file (.vxm, .binvox) read. The front ends choose the options and show the messages.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "vox/core/mesh.h"
#include "vox/core/progress.h"
#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"
#include "vox/io/mesh_file.h"
#include "vox/voxelize/voxelize.h"

namespace vox::workflow {

// A reader's or the voxelizer's warning (the part is suspect) or note (what was assumed), as it arises.
enum class InputMessage { kWarning, kNote };
using InputMessages = std::function<void(InputMessage, const std::string&)>;

// Reads a mesh or CAD file; its warnings and notes go to `messages` as well as staying in the load.
Result<io::MeshFileLoad> readMeshFile(const std::filesystem::path& file, const io::MeshFileOptions& options,
                                      const InputMessages& messages = {});

// Voxelizes `mesh` (its topology from the reader: the fill mode `auto` picks by it). With a `name`, a failure is
// "name: why"; the result's warnings are left to the caller.
Result<VoxelizeResult> voxelizeMesh(const TriangleMesh& mesh, const MeshTopology& topology,
                                    const VoxelizeParams& params, const ProgressFn& progress,
                                    const std::string& name = {});

struct ModelFileOptions {
  io::MeshFileOptions reading;  // a mesh or CAD file: how it is read (its grid tessellates a CAD file)
  VoxelizeParams params;        // and voxelized; the units are the mesh's own
  std::string units;            // a voxel file: its units when given (empty: the file's own)
  ProgressFn voxelizing;
  bool keep_mesh = false;  // a mesh file's triangles stay in ModelFile::mesh (rays are cast against them)
  std::string name;        // how a failure to voxelize names the file (empty: by its file name)
  InputMessages messages;  // warnings and notes, as they arise
};

struct ModelFile {
  VoxelGrid grid;  // its source: the file's name
  bool from_mesh = false;
  // A mesh file's: the format ("binary STL", "STEP (AUTOMOTIVE_DESIGN)"), bodies, triangles, topology, the unit the
  // file declares and, for CAD files, the tessellation's deflection (model units).
  std::string format;
  int64_t bodies = 0, triangles = 0;
  MeshTopology topology;
  std::string file_units;
  double deflection = 0.0;
  std::optional<TriangleMesh> mesh;    // with keep_mesh
  std::string mode_used, mode_reason;  // the fill mode the voxelizer used, and why
  double load_s = 0.0, voxelize_s = 0.0;
};

// The model in `file`: a voxel file read, or a mesh or CAD file read and voxelized. Failures name the file.
Result<ModelFile> readModelFile(const std::filesystem::path& file, const ModelFileOptions& options);

}  // namespace vox::workflow
