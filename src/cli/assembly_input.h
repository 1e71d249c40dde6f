#pragma once
// FILE arguments of the assembly subcommands (boolean, bodies, interfere, clearance) put on one lattice
// (docs/conventions.md, "Assemblies"): voxel files must share one (the first sets it); meshes are voxelized on it over
// their own boxes, or, when no voxel file is given, on the standard grid (docs/conventions.md, "Grid placement") fitted
// to the union of the meshes' bounding boxes (--res / --voxel-size). With bodies, a mesh gives its shells and a voxel
// file its connected components (6-connected unless asked for 26).
#include <string>
#include <vector>

#include "cli/model_input.h"
#include "cli/output.h"
#include "vox/core/lattice.h"

namespace CLI {
class Validator;
}

namespace vox::cli {

struct PartsOnLattice {
  Lattice lattice;
  Box3i frame;  // the grid the inputs share: the meshes' fitted grid, or the union of the voxel files' boxes
  std::vector<LatticeGrid> parts;
  std::vector<std::string> names;  // file names, or "body N" ("FILE body N" with several files)
  // Per part: the name the file gives the body (a CAD solid's "solid 3", a 3MF object's name); empty when the file
  // names none (an STL's shells, a voxel file's components, a whole file).
  std::vector<std::string> body_names;
  std::vector<int64_t> triangles;  // per part; -1 for a part from a voxel file
  int64_t input_triangles = 0;     // over all mesh inputs
  double load_s = 0.0, voxelize_s = 0.0;
};

// Reads and places `files`. Errors name the file: unreadable input (exit 2), voxel files on different lattices
// ("B.vxm is not on the lattice of A.vxm: voxel sizes differ: 0.01 vs 0.02", exit 2).
// With `bodies`, a voxel file's bodies are its components, joined through faces (6) or also edges and corners (26).
Result<PartsOnLattice> placeInputs(const std::vector<std::string>& files, const MeshOptions& options, bool bodies,
                                   Output& out, int connectivity = 6);

// --contact T: a finite number of model units, 0 or more (overlaps at most T thick only touch).
CLI::Validator contactValue();

// {"min": [x, y, z], "max": [x, y, z]}: the outer faces of a box of lattice voxels, model units.
nlohmann::ordered_json boxJson(const Box3i& box, const Lattice& lattice);

}  // namespace vox::cli
