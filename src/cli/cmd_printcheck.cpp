// voxmod printcheck (docs/conventions.md, "Printability"): overhangs and support along a build direction,
// trapped cavities with their drains and, with --orient, the build directions ranked by support. The overhang and
// support voxels as volumes; the files asked for are written together or not at all.
#include <algorithm>
#include <memory>

#include <CLI/CLI.hpp>

#include "cli/cmd_list.h"
#include "cli/commands.h"
#include "cli/model_input.h"
#include "vox/io/file_util.h"
#include "vox/io/volume_export.h"
#include "vox/io/voxel_file.h"
#include "vox/workflow/print_check.h"

namespace vox::cli {
namespace {

struct PrintOptions {
  CommonOptions c;
  std::string direction = "+z";
  double overhang_angle = 45.0;
  bool orient = false;
  int32_t directions = 100;
  std::string overhang_out, support_out;
};

nlohmann::ordered_json supportJson(const PrintSupport& s) {
  return {{"direction", jsonVec3(s.direction)},
          {"name", printDirectionName(s.direction)},
          {"support_volume", s.support_volume},
          {"overhang_area", s.overhang_area},
          {"height", s.height}};
}

void reportCavities(const workflow::PrintCheck& check, const std::string& units, Output& out) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const TrappedCavity& c : check.cavities) {
    nlohmann::ordered_json item = {{"volume", c.volume},
                                   {"centre", jsonVec3(c.centre)},
                                   {"bbox", {{"min", jsonVec3(c.bbox.min)}, {"max", jsonVec3(c.bbox.max)}}},
                                   {"voxels", c.voxels}};
    if (c.drain) {
      item["drain"] = {{"from", jsonVec3(c.drain->from)},
                       {"to", jsonVec3(c.drain->to)},
                       {"direction", jsonVec3(c.drain->step)},
                       {"length", c.drain->length}};
    }
    list.push_back(item);
  }
  out.data()["trapped_cavities"] = list;
  out.data()["trapped_volume"] = check.trapped_volume;
  const size_t n = check.cavities.size();
  out.say(std::to_string(n) + (n == 1 ? " trapped cavity" : " trapped cavities") +
          (n == 0 ? "" : ", " + significant(check.trapped_volume, 4) + " " + units + "^3 in all"));
  for (size_t i = 0; i < std::min<size_t>(check.cavities.size(), 5); ++i) {
    const TrappedCavity& c = check.cavities[i];
    std::string line = "  " + significant(c.volume, 4) + " " + units + "^3 at (" + significant(c.centre.x, 5) + ", " +
                       significant(c.centre.y, 5) + ", " + significant(c.centre.z, 5) + ")";
    if (c.drain) {
      line += "; shortest drain " + significant(c.drain->length, 4) + " " + units + " from (" +
              significant(c.drain->to.x, 5) + ", " + significant(c.drain->to.y, 5) + ", " +
              significant(c.drain->to.z, 5) + ")";
    }
    out.say(line);
  }
}

void reportOrientations(const workflow::PrintCheck& check, const std::string& units, Output& out) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const PrintSupport& s : check.orientations) list.push_back(supportJson(s));
  auto& d = out.data();
  d["orientations"] = list;
  if (check.orientations.empty()) return;
  const PrintSupport& best = check.orientations.front();
  d["best_direction"] = jsonVec3(best.direction);
  out.say("best of " + std::to_string(check.orientations.size()) +
          " build directions: " + printDirectionName(best.direction) + ", support " +
          significant(best.support_volume, 4) + " " + units + "^3, overhang " + significant(best.overhang_area, 4) +
          " " + units + "^2, height " + significant(best.height, 4) + " " + units);
  d["orient_s"] = check.orient_s;
}

int runPrintCheck(const PrintOptions& o) {
  Output out(o.c.json);
  for (const std::string* field : {&o.overhang_out, &o.support_out}) {
    if (!field->empty() && !io::isVolumeFile(*field)) {
      return out.fail(kExitUsage, *field + ": a volume file is needed (" + io::volumeExtensionList() + ")");
    }
  }
  auto up = parsePrintDirection(o.direction);
  if (!up) return out.fail(up.error());
  auto model = loadModel(o.c.file, o.c.mesh, out, true);
  if (!model) return out.fail(model.error());
  const VoxelGrid& grid = model->grid;
  const std::string units = grid.frame().units;
  workflow::PrintCheckOptions options;
  options.params.up = *up;
  options.params.overhang_angle_deg = o.overhang_angle;
  options.params.fields = !o.overhang_out.empty() || !o.support_out.empty();
  options.orient_directions = o.orient ? o.directions : 0;
  options.mesh = model->mesh ? &*model->mesh : nullptr;
  const ProgressFn support_line = terminalProgress("support"), orient_line = terminalProgress("orientations");
  const workflow::PrintProgress progress = [&](workflow::PrintStage stage, double f) {
    if (stage == workflow::PrintStage::kSupport) return !support_line || support_line(f);
    if (stage == workflow::PrintStage::kOrient) return !orient_line || orient_line(f);
    return true;
  };
  auto check = workflow::runPrintCheck(grid, options, progress);
  if (!check) return out.fail(check.error());
  const PrintSupport& s = check->support;
  auto& d = out.data();
  d["units"] = units;
  d["voxel_size"] = grid.voxelSize();
  d["build_direction"] = jsonVec3(s.direction);
  d["overhang_angle"] = o.overhang_angle;
  d["normals"] = check->from_mesh ? "mesh" : "voxel surface";
  d["overhang_area"] = s.overhang_area;
  d["support_volume"] = s.support_volume;
  d["height"] = s.height;
  d["rays"] = s.rays;
  out.say("build direction " + printDirectionName(s.direction) + ": overhang " + significant(s.overhang_area, 4) + " " +
          units + "^2 steeper than " + significant(o.overhang_angle, 3) + " degrees, support " +
          significant(s.support_volume, 4) + " " + units + "^3, height " + significant(s.height, 4) + " " + units);
  reportCavities(*check, units, out);
  if (o.orient) reportOrientations(*check, units, out);

  std::vector<io::PendingFile> files;
  const std::pair<const std::string*, const std::optional<VoxelGrid>*> fields[] = {{&o.overhang_out, &s.overhang},
                                                                                   {&o.support_out, &s.support}};
  for (const auto& [path, grid_field] : fields) {
    if (path->empty() || !*grid_field) continue;
    auto bytes = io::encodeVolume(io::voxelsOnly(**grid_field), *io::volumeFormatOf(*path), *path);
    if (!bytes) return out.fail(bytes.error());
    files.push_back({*path, std::move(bytes).value()});
  }
  if (Status st = writeOutputs(files, out); !st) return out.fail(st.error());
  d["surface_s"] = check->surface_s;
  d["support_s"] = check->support_s;
  d["cavities_s"] = check->cavities_s;
  return out.finish();
}

}  // namespace

void addPrintCheckCommand(CLI::App& sub, CommandContext& ctx) {
  auto o = std::make_shared<PrintOptions>();
  addCommonOptions(sub, o->c);
  sub.add_option("--build-direction", o->direction,
                 "Up, away from the build plate: +z (the default), -z, +x, -x, +y, -y or X,Y,Z");
  sub.add_option("--overhang-angle", o->overhang_angle,
                 "Downward surfaces tilted more than this from the vertical need support (degrees; a vertical wall "
                 "is 0, a ceiling 90; default 45)")
      ->check(CLI::Range(0.0, 89.9));
  sub.add_flag("--orient", o->orient, "Also rank the six axes and --directions more build directions by support");
  sub.add_option("--directions", o->directions, "With --orient: directions spread over the sphere (default 100)")
      ->check(CLI::Range(1, 100000));
  sub.add_option("--overhang", o->overhang_out,
                 "Write the voxels just above the overhangs as a volume (.nrrd, .vti, .vdb, .vox)");
  sub.add_option("--support", o->support_out, "Write the support's voxels as a volume (.nrrd, .vti, .vdb, .vox)");
  sub.callback([o, &ctx] { ctx.exit_code = runPrintCheck(*o); });
}

}  // namespace vox::cli
