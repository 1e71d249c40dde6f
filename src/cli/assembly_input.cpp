#include "cli/assembly_input.h"

#include <cmath>
#include <filesystem>
#include <optional>

#include <CLI/CLI.hpp>
#include <glm/common.hpp>

#include "vox/analysis/assembly.h"
#include "vox/core/mesh_bodies.h"
#include "vox/core/text.h"
#include "vox/io/mesh_file.h"
#include "vox/io/voxel_file.h"
#include "vox/voxelize/bodies.h"
#include "vox/workflow/model_input.h"

namespace vox::cli {
namespace {

struct Input {
  std::string path, name;
  std::optional<VoxelGrid> grid;  // a voxel file
  std::optional<io::MeshFileLoad> mesh;
};

Result<std::vector<Input>> readInputs(const std::vector<std::string>& files, const MeshOptions& options, Output& out,
                                      double& load_s) {
  const double t0 = nowSeconds();
  std::vector<Input> inputs;
  for (const std::string& f : files) {
    Input in;
    in.path = f;
    in.name = std::filesystem::path(f).filename().string();
    if (io::isVoxelFile(f)) {
      auto g = io::loadVoxelFile(f);
      if (!g) return g.error();
      in.grid = std::move(g).value();
    } else {
      auto m = loadMesh(f, options, out);
      if (!m) return m.error();
      m->mesh.name = in.name;
      in.mesh = std::move(m).value();
    }
    inputs.push_back(std::move(in));
  }
  load_s = nowSeconds() - t0;
  return inputs;
}

// The placement every mesh is voxelized on: the first voxel file's lattice, or the standard grid (docs/conventions.md,
// "Grid placement") fitted to the union of the meshes' bounding boxes. `lattice_frame` gets the lattice as a frame with
// first = 0.
Result<GridPlacement> wholePlacement(const std::vector<Input>& inputs, const VoxelizeParams& params) {
  for (const Input& in : inputs) {
    if (in.grid) return placeGridOnLattice(in.grid->frame(), glm::ivec3(0), in.grid->dims());
  }
  Box3d all;
  for (const Input& in : inputs) {
    const Box3d b = in.mesh->mesh.bounds();
    if (!b.empty()) {
      all.expand(b.min);
      all.expand(b.max);
    }
  }
  auto plan = planVoxelization(all, params);
  if (!plan) return plan.error();
  return plan->placement;
}

// A voxel file's grid as a part (or its components as parts), on the lattice of `whole`.
Status addVoxelInput(Input& in, const GridPlacement& whole, const Lattice& lattice, bool bodies, bool several,
                     Connectivity connectivity, PartsOnLattice& out) {
  glm::ivec3 first(0);
  if (Status s = checkSharedLattice(whole.frame, in.grid->frame(), &first); !s) {
    // An input error (exit 2): the files cannot be combined word by word.
    return makeError(ErrorCode::kUnsupported, in.name + " is not on the lattice of " + whole.frame.source + ": " +
                                                  s.error().message + " (voxel files must share one lattice)");
  }
  LatticeGrid part{std::move(*in.grid), first};
  part.grid.frame() = lattice.frameAt(first, in.name);
  out.frame = unite(out.frame, part.box());
  if (!bodies) {
    out.parts.push_back(std::move(part));
    out.names.push_back(in.name);
    out.body_names.emplace_back();
    out.triangles.push_back(-1);
    return Ok{};
  }
  const Components comps = findComponents(part.grid, connectivity);
  for (size_t i = 0; i < comps.components.size(); ++i) {
    const Component& c = comps.components[i];
    LatticeGrid body{componentGrid(part.grid, comps, i), part.first};
    out.parts.push_back(reframe(body, Box3i{part.first + c.box_min, part.first + c.box_max + glm::ivec3(1)}, lattice));
    out.names.push_back((several ? in.name + " " : std::string()) + "body " + std::to_string(i));
    out.body_names.emplace_back();
    out.triangles.push_back(-1);
  }
  return Ok{};
}

// A mesh as one part over its own box of `whole`, or its bodies as parts: the file's own (a CAD file's solids, the
// objects of a file with several), else its shells.
Status addMeshInput(const Input& in, const GridPlacement& whole, const VoxelizeParams& params, bool bodies,
                    bool several, bool clamp, PartsOnLattice& out, Output& log) {
  VoxelizeParams p = params;
  const TriangleMesh& mesh = in.mesh->mesh;
  out.input_triangles += int64_t(mesh.triangles.size());
  if (clamp) {  // the meshes' own grid: each over its box of it
    glm::ivec3 begin, end;
    latticeRange(whole, mesh.bounds(), begin, end);
    const glm::ivec3 size = glm::max(end - begin, glm::ivec3(1));
    p.placement = placeGridOnLattice(whole.frame, begin, Dims{size.x, size.y, size.z});
  } else {  // a voxel file's lattice: wherever the mesh lies on it
    auto placed = placeBoundsOnLattice(whole.frame, mesh.bounds());
    if (!placed) return makeError(placed.error().code, in.name + ": " + placed.error().message);
    p.placement = std::move(placed).value();
  }
  out.frame = unite(
      out.frame, Box3i{p.placement->first, p.placement->first + glm::ivec3(p.placement->dims.nx, p.placement->dims.ny,
                                                                           p.placement->dims.nz)});
  if (bodies) {
    const auto given = io::fileBodies(in.mesh->bodies, mesh.triangles.size(), io::isCadFormat(in.mesh->format));
    auto r = voxelizeBodies(mesh, p, terminalProgress("voxelizing bodies"), given ? &given->bodies : nullptr);
    if (!r) return makeError(r.error().code, in.name + ": " + r.error().message);
    for (const std::string& w : r->warnings) log.warn(in.name + ": " + w);
    for (size_t i = 0; i < r->bodies.size(); ++i) {
      out.parts.push_back(std::move(r->bodies[i].voxels));
      out.names.push_back((several ? in.name + " " : std::string()) + "body " + std::to_string(i));
      out.body_names.push_back(given ? given->names[i] : std::string());
      out.triangles.push_back(r->bodies[i].triangles);
    }
    return Ok{};
  }
  auto r = workflow::voxelizeMesh(mesh, in.mesh->topology, p, terminalProgress("voxelizing " + in.name), in.name);
  if (!r) return r.error();
  for (const std::string& w : r->warnings) log.warn(in.name + ": " + w);
  out.parts.push_back(LatticeGrid{std::move(r->grid), p.placement->first});
  out.names.push_back(in.name);
  out.body_names.emplace_back();
  out.triangles.push_back(int64_t(mesh.triangles.size()));
  return Ok{};
}

}  // namespace

Result<PartsOnLattice> placeInputs(const std::vector<std::string>& files, const MeshOptions& options, bool bodies,
                                   Output& out, int connectivity) {
  PartsOnLattice parts;
  auto inputs = readInputs(files, options, out, parts.load_s);
  if (!inputs) return inputs.error();
  auto params = voxelizeParams(options);
  if (!params) return params.error();
  auto whole_or = wholePlacement(*inputs, *params);
  if (!whole_or) return whole_or.error();
  GridPlacement whole = std::move(whole_or).value();
  bool any_voxels = false;
  for (const Input& in : *inputs) any_voxels = any_voxels || in.grid.has_value();
  if (any_voxels) {
    for (const Input& in : *inputs) {
      if (in.grid) {
        whole.frame.source = in.name;  // the file that set the lattice, for messages
        break;
      }
    }
  }
  // Units: the voxel files', else --units, else what the first mesh file says (CAD files: mm).
  std::string units = params->units;
  if (any_voxels) {
    units = whole.frame.units;
  } else if (options.units.empty()) {
    units = inputs->front().mesh->units;
  }
  parts.lattice = Lattice{whole.frame.origin, whole.frame.voxel_size, units};
  params->units = units;
  whole.frame.units = parts.lattice.units;
  if (!any_voxels) parts.frame = Box3i{glm::ivec3(0), glm::ivec3(whole.dims.nx, whole.dims.ny, whole.dims.nz)};
  const bool several = files.size() > 1;
  const double t0 = nowSeconds();
  for (Input& in : *inputs) {
    Status s = in.grid ? addVoxelInput(in, whole, parts.lattice, bodies, several,
                                       connectivity == 26 ? Connectivity::kAll : Connectivity::kFace, parts)
                       : addMeshInput(in, whole, *params, bodies, several, !any_voxels, parts, out);
    if (!s) return s.error();
  }
  parts.voxelize_s = nowSeconds() - t0;
  return parts;
}

CLI::Validator contactValue() {
  return CLI::NonNegativeNumber & CLI::Validator(
                                      [](std::string& v) {
                                        double x = 0.0;
                                        return parseNumber(v, x) && std::isfinite(x) ? std::string()
                                                                                     : "not a finite number";
                                      },
                                      "FINITE");
}

nlohmann::ordered_json boxJson(const Box3i& box, const Lattice& lattice) {
  if (box.empty()) return nullptr;
  return {{"min", jsonVec3(lattice.corner(box.min))}, {"max", jsonVec3(lattice.corner(box.max))}};
}

}  // namespace vox::cli
