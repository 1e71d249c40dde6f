// The assembly subcommands (docs/conventions.md, "Assemblies"): boolean, bodies, interfere,
// clearance. Inputs go through placeInputs (assembly_input.h), which puts every file on one lattice.
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/assembly_input.h"
#include "cli/cmd_list.h"
#include "cli/commands.h"
#include "cli/write_grid.h"
#include "vox/analysis/assembly.h"
#include "vox/core/text.h"
#include "vox/io/file_util.h"
#include "vox/io/voxel_file.h"

namespace vox::cli {
namespace {

double volumeOf(int64_t voxels, const Lattice& lattice) {
  const double h = lattice.voxel_size;
  return double(voxels) * h * h * h;
}

void frameJson(nlohmann::ordered_json& d, const Dims& dims, const Lattice& lattice, const glm::ivec3& first) {
  d["dims"] = {dims.nx, dims.ny, dims.nz};
  d["origin"] = jsonVec3(lattice.corner(first));
  d["voxel_size"] = lattice.voxel_size;
  d["units"] = lattice.units;
}

// ---- boolean ----
struct BooleanOptions {
  std::vector<std::string> files;
  std::string op_text, out;
  bool json = false;
  MeshOptions mesh;
};

int runBoolean(const BooleanOptions& o) {
  Output out(o.json);
  const double t0 = nowSeconds();
  const auto op = parsePartOp(o.op_text);
  if (!op) return out.fail(kExitUsage, "unknown --op '" + o.op_text + "' (union, intersection, difference, xor)");
  if (!isGridOutput(o.out)) return out.fail(kExitUsage, gridOutputFormats(o.out));  // before any work
  auto placed = placeInputs(o.files, o.mesh, false, out);
  if (!placed) return out.fail(placed.error());
  const PartsOnLattice& p = *placed;
  const double t1 = nowSeconds();
  LatticeGrid result = booleanParts(p.parts[0], p.parts[1], *op, p.lattice);
  if (result.box() != p.frame) result = reframe(result, p.frame, p.lattice);
  result.grid.frame() = p.lattice.frameAt(result.first, std::filesystem::path(o.out).filename().string());
  const double boolean_s = nowSeconds() - t1;
  auto& d = out.data();
  d["op"] = partOpName(*op);
  d["filled"] = result.grid.filledCount();
  d["filled_a"] = p.parts[0].grid.filledCount();
  d["filled_b"] = p.parts[1].grid.filledCount();
  frameJson(d, result.grid.dims(), p.lattice, result.first);
  d["volume"] = volumeOf(d["filled"].get<int64_t>(), p.lattice);
  const double t2 = nowSeconds();
  // Any failure here is the output's (exit 2), an empty result written as a surface too.
  if (Status s = writeGridAs(result.grid, o.out, o.out); !s) return out.fail(kExitIo, s.error().message);
  d["output"] = o.out;
  d["load_s"] = p.load_s;
  d["voxelize_s"] = p.voxelize_s;
  d["boolean_s"] = boolean_s;
  d["write_s"] = nowSeconds() - t2;
  d["total_s"] = nowSeconds() - t0;
  out.say(std::string(partOpName(*op)) + ": " + std::to_string(d["filled"].get<int64_t>()) + " voxels (A " +
          std::to_string(d["filled_a"].get<int64_t>()) + ", B " + std::to_string(d["filled_b"].get<int64_t>()) +
          ") written to " + o.out);
  return out.finish();
}

// ---- bodies ----
struct BodiesOptions {
  CommonOptions c;
  std::string dir, format = "vxm";
  int connectivity = 6;
};

// Every body as a voxel file DIR/body_NNN.EXT, all written or none.
Status writeBodies(const PartsOnLattice& p, const std::string& dir, const std::string& format,
                   nlohmann::ordered_json& files) {
  std::vector<io::VoxelFileToWrite> out;
  for (size_t i = 0; i < p.parts.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "body_%03zu.%s", i, format.c_str());
    io::VoxelFileToWrite f{std::filesystem::path(dir) / name, p.parts[i].grid};
    f.grid.frame() = p.lattice.frameAt(p.parts[i].first, p.names[i]);
    files.push_back(f.path.string());
    out.push_back(std::move(f));
  }
  return io::saveVoxelFiles(out);
}

int runBodies(const BodiesOptions& o) {
  Output out(o.c.json);
  const double t0 = nowSeconds();
  auto placed = placeInputs({o.c.file}, o.c.mesh, true, out, o.connectivity);
  if (!placed) return out.fail(placed.error());
  const PartsOnLattice& p = *placed;
  auto& d = out.data();
  nlohmann::ordered_json bodies = nlohmann::ordered_json::array();
  for (size_t i = 0; i < p.parts.size(); ++i) {
    const int64_t filled = p.parts[i].grid.filledCount();
    nlohmann::ordered_json b;
    b["index"] = i;
    if (!p.body_names[i].empty()) b["name"] = p.body_names[i];
    b["triangles"] = p.triangles[i] >= 0 ? nlohmann::ordered_json(p.triangles[i]) : nlohmann::ordered_json(nullptr);
    b["filled"] = filled;
    b["volume"] = volumeOf(filled, p.lattice);
    b["bbox"] = boxJson(filledBox(p.parts[i]), p.lattice);
    bodies.push_back(std::move(b));
  }
  d["bodies"] = std::move(bodies);
  frameJson(d, Dims{p.frame.size().x, p.frame.size().y, p.frame.size().z}, p.lattice, p.frame.min);
  d["load_s"] = p.load_s;
  d["voxelize_s"] = p.voxelize_s;
  out.say(std::to_string(p.parts.size()) + " bodies in " + o.c.file);
  if (!o.dir.empty()) {
    nlohmann::ordered_json files = nlohmann::ordered_json::array();
    if (Status s = writeBodies(p, o.dir, o.format, files); !s) return out.fail(s.error());
    d["files"] = std::move(files);
    out.say("wrote " + std::to_string(p.parts.size()) + " voxel files to " + o.dir);
  }
  d["total_s"] = nowSeconds() - t0;
  return out.finish();
}

// ---- interfere ----
struct InterfereOptions {
  std::vector<std::string> files;
  bool bodies = false, json = false;
  int connectivity = 6;
  double contact = 0.0;  // --contact: overlaps at most this thick are contact, not interference (model units)
  MeshOptions mesh;
};

nlohmann::ordered_json pairJson(const InterferencePair& pair, const Lattice& lattice, double contact) {
  nlohmann::ordered_json j;
  j["a"] = pair.a;
  j["b"] = pair.b;
  j["voxels"] = pair.voxels;
  j["volume"] = volumeOf(pair.voxels, lattice);
  j["bbox"] = boxJson(pair.box, lattice);
  j["centre"] = jsonVec3(pair.centre);
  j["thickness"] = pair.thickness;
  j["contact"] = isContact(pair, contact);
  return j;
}

int runInterfere(const InterfereOptions& o) {
  Output out(o.json);
  const double t0 = nowSeconds();
  auto placed = placeInputs(o.files, o.mesh, o.bodies, out, o.connectivity);
  if (!placed) return out.fail(placed.error());
  const PartsOnLattice& p = *placed;
  const double t1 = nowSeconds();
  const Interference r = findInterference(p.parts, p.lattice);
  const double interfere_s = nowSeconds() - t1;
  auto& d = out.data();
  d["parts"] = p.names;
  nlohmann::ordered_json pairs = nlohmann::ordered_json::array();
  int64_t interfering = 0;
  for (const InterferencePair& pair : r.pairs) {
    pairs.push_back(pairJson(pair, p.lattice, o.contact));
    interfering += !isContact(pair, o.contact);
  }
  d["pairs"] = std::move(pairs);
  d["contact"] = o.contact;
  d["interfering_pairs"] = interfering;
  d["overlap_voxels"] = r.overlap_voxels;
  d["overlap_volume"] = volumeOf(r.overlap_voxels, p.lattice);
  d["multiple_overlap_voxels"] = r.multiple_overlap_voxels;
  d["multiple_overlap_bbox"] = boxJson(r.multiple_overlap_box, p.lattice);
  d["candidate_pairs"] = r.candidate_pairs;
  frameJson(d, Dims{p.frame.size().x, p.frame.size().y, p.frame.size().z}, p.lattice, p.frame.min);
  d["load_s"] = p.load_s;
  d["voxelize_s"] = p.voxelize_s;
  d["interfere_s"] = interfere_s;
  d["total_s"] = nowSeconds() - t0;
  const std::string contacts = o.contact > 0.0 ? " (and " + std::to_string(int64_t(r.pairs.size()) - interfering) +
                                                     " in contact, overlapping " + significant(o.contact) + " or less)"
                                               : std::string();
  out.say(std::to_string(p.parts.size()) + " parts, " + std::to_string(interfering) + " interfering pairs" + contacts +
          ", " + std::to_string(r.overlap_voxels) + " voxels in two or more parts (" +
          std::to_string(r.multiple_overlap_voxels) + " in three or more)");
  for (size_t i = 0; i < r.pairs.size() && i < 10; ++i) {
    const InterferencePair& q = r.pairs[i];
    out.say("  " + p.names[size_t(q.a)] + " / " + p.names[size_t(q.b)] + ": " + std::to_string(q.voxels) +
            " voxels, volume " + significant(volumeOf(q.voxels, p.lattice)) + ", " + significant(q.thickness) +
            " thick" + (isContact(q, o.contact) ? " (contact)" : ""));
  }
  return out.finish();
}

// ---- clearance ----
struct ClearanceOptions {
  std::vector<std::string> files;
  double max_distance = 0.0;
  bool json = false;
  MeshOptions mesh;
};

int runClearance(const ClearanceOptions& o) {
  Output out(o.json);
  auto placed = placeInputs(o.files, o.mesh, false, out);
  if (!placed) return out.fail(placed.error());
  const PartsOnLattice& p = *placed;
  const double t1 = nowSeconds();
  auto c = findClearance(p.parts[0], p.parts[1], p.lattice, ClearanceParams{o.max_distance});
  if (!c) return out.fail(c.error());
  auto& d = out.data();
  d["found"] = c->found;
  d["touching"] = c->found ? nlohmann::ordered_json(c->touching) : nlohmann::ordered_json(nullptr);
  d["gap"] = c->found ? nlohmann::ordered_json(c->gap) : nlohmann::ordered_json(nullptr);
  d["distance"] = c->found ? nlohmann::ordered_json(c->centre_distance) : nlohmann::ordered_json(nullptr);
  d["point_a"] = c->found ? jsonVec3(c->centre_a) : nlohmann::ordered_json(nullptr);
  d["point_b"] = c->found ? jsonVec3(c->centre_b) : nlohmann::ordered_json(nullptr);
  d["voxel_a"] = c->found ? jsonVec3(c->voxel_a - p.frame.min) : nlohmann::ordered_json(nullptr);
  d["voxel_b"] = c->found ? jsonVec3(c->voxel_b - p.frame.min) : nlohmann::ordered_json(nullptr);
  frameJson(d, Dims{p.frame.size().x, p.frame.size().y, p.frame.size().z}, p.lattice, p.frame.min);
  d["clearance_s"] = nowSeconds() - t1;
  if (!c->found) {
    out.say(o.max_distance > 0 ? "no voxels of the two parts lie within " + significant(o.max_distance)
                               : std::string("a part is empty: no clearance"));
  } else if (c->touching) {
    out.say("the parts touch (gap 0)");
  } else {
    out.say("gap " + significant(c->gap) + " (voxel centres " + significant(c->centre_distance) + " apart)");
  }
  return out.finish();
}

void addFilesAndMeshOptions(CLI::App& sub, std::vector<std::string>& files, bool& json, MeshOptions& mesh, int count) {
  sub.add_option("FILES", files, "Meshes or voxel files (voxel files must share one lattice)")
      ->required()
      ->expected(count < 0 ? -1 : count);
  sub.add_flag("--json", json, "Print one JSON object on stdout");
  addMeshOptions(sub, mesh);
}

}  // namespace

void addBooleanCommand(CLI::App& sub, CommandContext& ctx) {
  auto o = std::make_shared<BooleanOptions>();
  addFilesAndMeshOptions(sub, o->files, o->json, o->mesh, 2);
  sub.add_option("--op", o->op_text, "union, intersection, difference (A minus B) or xor")
      ->required()
      ->check(CLI::IsMember({"union", "intersection", "difference", "xor"}));
  sub.add_option("-o,--output", o->out,
                 "Output file, any format convert writes: voxels (.vxm, .binvox), a volume (.vti, .vdb, .nrrd, .vox) "
                 "or the surface as a mesh (.stl, .ply, .obj, .3mf)")
      ->required();
  sub.callback([o, &ctx] { ctx.exit_code = runBoolean(*o); });
}

void addBodiesCommand(CLI::App& sub, CommandContext& ctx) {
  auto o = std::make_shared<BodiesOptions>();
  addCommonOptions(sub, o->c);
  sub.add_option("-o,--output", o->dir, "Write each body as a voxel file body_NNN.vxm into this directory");
  sub.add_option("--format", o->format, "Voxel file format of the bodies: vxm or binvox")
      ->check(CLI::IsMember({"vxm", "binvox"}));
  sub.add_option("--connectivity", o->connectivity,
                 "For a voxel FILE: its bodies are components joined through faces (6, default) or also edges and "
                 "corners (26)")
      ->check(CLI::IsMember({6, 26}));
  sub.callback([o, &ctx] { ctx.exit_code = runBodies(*o); });
}

void addInterfereCommand(CLI::App& sub, CommandContext& ctx) {
  auto o = std::make_shared<InterfereOptions>();
  addFilesAndMeshOptions(sub, o->files, o->json, o->mesh, -1);
  sub.add_flag("--bodies", o->bodies, "Split each file into its bodies (mesh shells, voxel components)");
  sub.add_option("--connectivity", o->connectivity,
                 "With --bodies, for voxel files: components joined through faces (6, default) or also edges and "
                 "corners (26)")
      ->check(CLI::IsMember({6, 26}));
  sub.add_option("--contact", o->contact,
                 "Overlaps at most this thick (model units) are contact, not interference: parts that touch overlap "
                 "by a voxel or two (default 0: every shared voxel interferes)")
      ->check(contactValue());
  sub.callback([o, &ctx] { ctx.exit_code = runInterfere(*o); });
}

void addClearanceCommand(CLI::App& sub, CommandContext& ctx) {
  auto o = std::make_shared<ClearanceOptions>();
  addFilesAndMeshOptions(sub, o->files, o->json, o->mesh, 2);
  sub.add_option("--max-distance", o->max_distance, "Search only this far (model units; default: everywhere)")
      ->check(CLI::NonNegativeNumber);
  sub.callback([o, &ctx] { ctx.exit_code = runClearance(*o); });
}

}  // namespace vox::cli
