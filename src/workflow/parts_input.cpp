// Parts from files and models (vox/workflow/parts_input.h).
#include "vox/workflow/parts_input.h"

#include <algorithm>
#include <string>
#include <utility>

#include "vox/analysis/assembly.h"
#include "vox/core/grid_placement.h"
#include "vox/io/mesh_file.h"
#include "vox/io/voxel_file.h"
#include "vox/voxelize/bodies.h"
#include "vox/voxelize/voxelize.h"

namespace vox::workflow {
namespace {

Error partsError(std::string message) { return makeError(ErrorCode::kInvalidArgument, std::move(message)); }

}  // namespace

// The bodies of a mesh, each voxelized on the lattice of `model` (the mesh's own grid, as shown): the file's own
// bodies, named as the file names them (a CAD file's solids, the objects of a file with several), else its shells.
Result<Assembly> splitMeshIntoBodies(const TriangleMesh& mesh, std::span<const io::MeshBody> file_bodies, bool cad,
                                     VoxelizeParams params, const VoxelGrid& model, const ProgressFn& progress) {
  params.placement = placeGridOnLattice(model.frame(), glm::ivec3(0), model.dims());
  params.units = model.frame().units;
  const auto given = io::fileBodies(file_bodies, mesh.triangles.size(), cad);
  auto bodies = voxelizeBodies(mesh, params, progress, given ? &given->bodies : nullptr);
  if (!bodies) return bodies.error();
  Assembly scene(bodies->lattice);
  for (size_t i = 0; i < bodies->bodies.size(); ++i) {
    BodyVoxels& b = bodies->bodies[i];
    if (b.filled == 0) continue;  // a body too thin for this lattice has no voxels to show
    const size_t k = scene.addPart(std::move(b.voxels), given ? given->names[i] : "body " + std::to_string(i));
    scene.part(k).colour = partColour(k);
  }
  if (scene.size() == 0) return partsError("no body of the mesh has a voxel at this resolution");
  return scene;
}

// The connected components of a voxel model, largest first.
Result<Assembly> splitIntoComponents(const VoxelGrid& model, Connectivity connectivity) {
  const Components comps = findComponents(model, connectivity);
  if (comps.components.empty()) return partsError("the model has no voxels to split");
  const Lattice lattice = latticeOf(model.frame());
  Assembly scene(lattice);
  const size_t kept = std::min(comps.components.size(), kMaxComponentParts);
  LatticeGrid taken{VoxelGrid(model.dims(), model.frame()), glm::ivec3(0)};
  for (size_t i = 0; i < kept; ++i) {
    const Component& c = comps.components[i];
    LatticeGrid whole{componentGrid(model, comps, i), glm::ivec3(0)};
    if (kept < comps.components.size()) taken = booleanParts(taken, whole, PartOp::kUnion, lattice);
    LatticeGrid part = reframe(whole, Box3i{c.box_min, c.box_max + 1}, lattice);
    const size_t k = scene.addPart(std::move(part), "component " + std::to_string(i + 1));
    scene.part(k).colour = partColour(k);
  }
  if (kept < comps.components.size()) {
    LatticeGrid rest = booleanParts(LatticeGrid{model, glm::ivec3(0)}, taken, PartOp::kDifference, lattice);
    const Box3i box = filledBox(rest);
    const size_t k = scene.addPart(reframe(rest, box, lattice),
                                   std::to_string(comps.components.size() - kept) + " smaller components");
    scene.part(k).colour = partColour(k);
  }
  return scene;
}

// A file added to `scene` as a part: a voxel file on the scene's lattice, a mesh voxelized on it.
Result<Assembly> addFileAsPart(Assembly scene, const std::filesystem::path& path, VoxelizeParams params,
                               const ProgressFn& progress) {
  const std::string name = path.filename().string();
  if (io::isVoxelFile(path)) {
    auto grid = io::loadVoxelFile(path);
    if (!grid) return grid.error();
    auto added = scene.addGrid(std::move(grid).value(), name);
    if (!added) return added.error();
    scene.part(*added).colour = partColour(*added);
    return scene;
  }
  // Any mesh or CAD file (io::loadMeshFile); a CAD file is tessellated for the scene's voxel size.
  io::MeshFileOptions options;
  options.resolution = params.resolution;
  options.voxel_size = scene.hasLattice() ? scene.lattice().voxel_size : params.voxel_size;
  options.progress = progress;
  auto stl = io::loadMeshFile(path, options);
  if (!stl) return stl.error();
  if (scene.hasLattice()) {
    auto placement = placeBoundsOnLattice(scene.lattice().frameAt(glm::ivec3(0)), stl->mesh.bounds());
    if (!placement) return makeError(placement.error().code, name + ": " + placement.error().message);
    params.placement = *placement;
    params.units = scene.lattice().units;
  }
  auto r = voxelizeSolid(stl->mesh, params, progress);
  if (!r) return makeError(r.error().code, name + ": " + r.error().message);
  if (!scene.hasLattice()) {
    auto added = scene.addGrid(std::move(r->grid), name);
    if (!added) return added.error();
  } else {
    scene.addPart(LatticeGrid{std::move(r->grid), params.placement->first}, name);
  }
  scene.part(scene.size() - 1).colour = partColour(scene.size() - 1);
  return scene;
}

}  // namespace vox::workflow
