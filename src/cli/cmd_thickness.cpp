// voxmod thickness (docs/conventions.md, "Distance and thickness"): the exact distance field, local thickness with
// its statistics, thin walls under --min-wall and hot spots; the fields as volumes (NRRD, VTK image data or OpenVDB,
// by extension) and a thickness section as PNG. The files asked for are written together or not at all.
#include <algorithm>
#include <optional>

#include <CLI/CLI.hpp>

#include "cli/cmd_list.h"
#include "cli/commands.h"
#include "cli/model_input.h"
#include "vox/analysis/distance.h"
#include "vox/analysis/thickness.h"
#include "vox/analysis/thickness_map.h"
#include "vox/analysis/ray_thickness.h"
#include "vox/analysis/walls.h"
#include "vox/io/figure.h"
#include "vox/io/file_util.h"
#include "vox/io/image_io.h"
#include "vox/io/volume_export.h"
#include "vox/io/voxel_file.h"
#include "vox/workflow/thickness_figure.h"
#include "vox/workflow/thickness_run.h"

namespace vox::cli {
namespace {

struct ThicknessOptions {
  CommonOptions c;
  double min_wall = 0.0;  // model units; 0: no thin-wall report
  bool edges = false;     // thin regions by local thickness alone, convex edges included
  double ray_angle = 30.0;
  double min_area = -1.0;         // model units^2; < 0: min_wall^2
  std::string method = "sphere";  // the field -o and --png show: sphere (local thickness) or ray
  std::string out, distance_out, png;
  bool signed_distance = false;
  std::string section_axis;
  int32_t section_index = -1;
  int32_t scale = 1;
  int32_t hot_spots_shown = 10;
};

nlohmann::ordered_json bboxJson(const Box3d& b) { return {{"min", jsonVec3(b.min)}, {"max", jsonVec3(b.max)}}; }

// The thin regions: walls (or, with --edges, every voxel under the minimum), each with its thickness.
void reportThinRegions(double min_wall, int64_t voxels, const std::vector<ThinWallRegion>& list, bool edges,
                       const std::string& units, Output& out) {
  auto& d = out.data();
  d["thin_voxels"] = voxels;
  nlohmann::ordered_json regions = nlohmann::ordered_json::array();
  for (const ThinWallRegion& r : list) {
    regions.push_back({{"voxels", r.voxels},
                       {"bbox", bboxJson(r.bbox)},
                       {"min", r.min},
                       {"area", r.area},
                       {"bbox_min_ijk", jsonVec3(r.bbox_min_ijk)},
                       {"bbox_max_ijk", jsonVec3(r.bbox_max_ijk)}});
  }
  d["thin_regions"] = regions;
  const std::string what = edges ? "voxels thinner than " : "walls thinner than ";
  out.say(what + significant(min_wall) + " " + units + ": " + countOf(voxels, "voxel") + " in " +
          countOf(int64_t(list.size()), "region"));
  for (size_t i = 0; i < std::min<size_t>(list.size(), 5); ++i) {
    const ThinWallRegion& r = list[i];
    out.say("  " + std::to_string(r.voxels) + " voxels, " + (edges ? "thinnest " : "wall ") + significant(r.min, 4) +
            ", from (" + significant(r.bbox.min.x, 4) + ", " + significant(r.bbox.min.y, 4) + ", " +
            significant(r.bbox.min.z, 4) + ") to (" + significant(r.bbox.max.x, 4) + ", " +
            significant(r.bbox.max.y, 4) + ", " + significant(r.bbox.max.z, 4) + ")");
  }
}

void reportHotSpots(const std::vector<HotSpot>& spots, int32_t shown, Output& out) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const HotSpot& h : spots) {
    list.push_back({{"centre", jsonVec3(h.centre)},
                    {"radius", h.radius},
                    {"modulus", h.modulus},
                    {"isolated", h.isolated},
                    {"voxel", jsonVec3(h.voxel)},
                    {"dynamic", h.dynamic}});
  }
  out.data()["hot_spots"] = list;
  out.say(std::to_string(spots.size()) + " hot spots (regional maxima of the distance, largest first):");
  for (size_t i = 0; i < std::min<size_t>(spots.size(), size_t(shown)); ++i) {
    const HotSpot& h = spots[i];
    out.say("  at (" + significant(h.centre.x, 5) + ", " + significant(h.centre.y, 5) + ", " +
            significant(h.centre.z, 5) + "): radius " + significant(h.radius, 4) + ", modulus " +
            significant(h.modulus, 4) + (h.isolated ? ", isolated (fed through a thinner neck)" : ""));
  }
}

// With --min-wall: the thinnest wall, and the walls (or, with --edges, the voxels) thinner than it.
Status reportWalls(const workflow::ThicknessRun& run, const ThicknessOptions& o, const std::string& units,
                   Output& out) {
  auto& d = out.data();
  auto walls = findWalls(*run.ridge, run.thickness.radius, WallParams{o.min_wall, o.min_area});
  if (!walls) return walls.error();
  d["wall_min"] = walls->wall_min;
  d["ray_angle"] = o.ray_angle;
  d["min_area"] = walls->min_area;
  out.say("thinnest wall " + significant(walls->wall_min, 4) + " " + units + " (convex edges and corners aside)");
  if (o.edges) {
    auto thin = findThinWalls(run.thickness, o.min_wall);
    if (!thin) return thin.error();
    reportThinRegions(o.min_wall, thin->voxels, thin->regions, true, units, out);
  } else {
    reportThinRegions(o.min_wall, walls->voxels, walls->regions, false, units, out);
    d["specks"] = walls->specks;
    if (walls->specks > 0) {
      out.say("  and " + countOf(walls->specks, "speck") + " under " + significant(walls->min_area, 3) + " " + units +
              "^2 of surface, not listed (--min-area)");
    }
  }
  return Ok{};
}

int runThickness(const ThicknessOptions& o) {
  Output out(o.c.json);
  for (const std::string* field : {&o.out, &o.distance_out}) {
    if (field->empty()) continue;
    if (const std::string why = fieldOutputProblem(*field); !why.empty()) return out.fail(kExitUsage, why);
  }
  if (!o.png.empty()) {
    if (const std::string why = pngOutputProblem(o.png); !why.empty()) return out.fail(kExitUsage, why);
    if (o.section_axis.empty()) return out.fail(kExitUsage, "--png needs --section-axis and --section-index");
  }
  const bool ray = o.method == "ray";
  if (ray && io::isVoxelFile(o.c.file)) {
    return out.fail(kExitUsage, "--method ray follows a mesh's own surface: " +
                                    std::filesystem::path(o.c.file).filename().string() +
                                    " is a voxel file (give the mesh, or use --method sphere)");
  }
  auto model = loadModel(o.c.file, o.c.mesh, out, ray);
  if (!model) return out.fail(model.error());
  const VoxelGrid& grid = model->grid;
  const std::string units = grid.frame().units;
  // Terminal lines for the distance and the thickness; the hot spots, quick, say nothing.
  const ProgressFn distance_line = terminalProgress("distance"), thickness_line = terminalProgress("thickness");
  const ProgressFn walls_line = o.min_wall > 0.0 ? terminalProgress("walls") : ProgressFn();
  const ProgressFn rays_line = ray ? terminalProgress("rays") : ProgressFn();
  const workflow::StageProgress progress = [&](workflow::ThicknessStage stage, double f) {
    if (stage == workflow::ThicknessStage::kDistance) return !distance_line || distance_line(f);
    if (stage == workflow::ThicknessStage::kThickness) return !thickness_line || thickness_line(f);
    if (stage == workflow::ThicknessStage::kWalls) return !walls_line || walls_line(f);
    if (stage == workflow::ThicknessStage::kRays) return !rays_line || rays_line(f);
    return true;
  };
  // local thickness paints into the field itself unless --distance still needs it
  workflow::ThicknessRunOptions run_options;
  run_options.keep_distance = !o.distance_out.empty();
  if (o.min_wall > 0.0) run_options.walls = WallRidgeParams{o.ray_angle};
  if (ray) {
    run_options.ray_mesh = &*model->mesh;
    run_options.ray.angle_deg = o.ray_angle;
  }
  auto run = workflow::runThickness(
      grid, run_options,
      distance_line || thickness_line || walls_line || rays_line ? progress : workflow::StageProgress());
  if (!run) return out.fail(run.error());
  const Thickness* thickness = &run->thickness;
  const std::vector<HotSpot>* spots = &run->hot_spots;
  const std::optional<DistanceField>& distance = run->distance;
  const double distance_max = run->distance_max;

  const ThicknessStats& s = thickness->stats;
  auto& d = out.data();
  d["units"] = units;
  d["voxel_size"] = grid.voxelSize();
  d["filled"] = s.voxels;
  d["min"] = s.min;
  d["max"] = s.max;
  d["mean"] = s.mean;
  d["histogram"] = {{"edges", s.edges}, {"counts", s.counts}};
  d["distance_max"] = distance_max;
  out.say("local thickness over " + std::to_string(s.voxels) + " voxels: min " + significant(s.min, 4) + ", max " +
          significant(s.max, 4) + ", mean " + significant(s.mean, 4) + " " + units + "; deepest voxel " +
          significant(distance_max, 4) + " from the surface");
  d["method"] = o.method;
  if (run->ray) {
    const RayThicknessResult& r = *run->ray;
    d["ray"] = {{"min", r.min},       {"max", r.max},   {"mean", r.mean},
                {"voxels", r.voxels}, {"rays", r.rays}, {"accepted", r.accepted}};
    out.say("ray thickness over " + std::to_string(r.voxels) + " voxels: min " + significant(r.min, 4) + ", max " +
            significant(r.max, 4) + ", mean " + significant(r.mean, 4) + " " + units + " (" +
            std::to_string(r.accepted) + " of " + std::to_string(r.rays) + " rays met a wall facing back)");
  }
  if (o.min_wall > 0.0) {
    if (Status st = reportWalls(*run, o, units, out); !st) return out.fail(st.error());
  }
  reportHotSpots(*spots, o.hot_spots_shown, out);

  std::vector<io::PendingFile> files;
  if (!o.out.empty()) {
    auto bytes = encodeFieldFile("thickness", run->ray ? run->ray->field : thicknessField(*thickness), o.out,
                                 terminalProgress("writing"));
    if (!bytes) return out.fail(bytes.error());
    files.push_back({o.out, std::move(bytes).value()});
  }
  if (!o.distance_out.empty()) {
    std::optional<DistanceField> clearance;
    if (o.signed_distance) {
      auto c = computeClearance(grid, terminalProgress("clearance"));
      if (!c) return out.fail(c.error());
      clearance = std::move(c).value();
    }
    auto bytes = encodeFieldFile("distance", distanceField(*distance, clearance ? &*clearance : nullptr),
                                 o.distance_out, terminalProgress("writing"));
    if (!bytes) return out.fail(bytes.error());
    files.push_back({o.distance_out, std::move(bytes).value()});
  }
  if (!o.png.empty()) {
    SectionParams p;
    p.axis = parseAxis(o.section_axis).value();
    p.index = o.section_index;
    auto figure = workflow::thicknessSectionFigure(*thickness, run->ray ? &*run->ray : nullptr, p, units, o.scale);
    if (!figure) return out.fail(figure.error());
    auto png = io::encodePng(*figure, o.png);
    if (!png) return out.fail(png.error());
    files.push_back({o.png, std::move(png).value()});
  }
  if (Status st = writeOutputs(files, out); !st) return out.fail(st.error());
  d["distance_s"] = run->distance_s;
  d["thickness_s"] = run->thickness_s;
  d["hot_spots_s"] = run->hot_spots_s;
  if (run->ridge) d["walls_s"] = run->walls_s;
  if (run->ray) d["ray_s"] = run->ray_s;
  return out.finish();
}

}  // namespace

void addThicknessCommand(CLI::App& sub, CommandContext& ctx) {
  auto o = std::make_shared<ThicknessOptions>();
  addCommonOptions(sub, o->c);
  auto* min_wall =
      sub.add_option("--min-wall", o->min_wall, "Report walls thinner than this (model units), grouped in regions")
          ->check(CLI::PositiveNumber);
  sub.add_flag("--edges", o->edges,
               "With --min-wall: list every voxel whose local thickness is under it, convex edges and corners included")
      ->needs(min_wall);
  sub.add_option("--method", o->method,
                 "The thickness -o and --png show: sphere (local thickness, exact; the default) or ray (along the "
                 "inward normal of a mesh FILE to the opposite wall)")
      ->check(CLI::IsMember({"sphere", "ray"}));
  auto* ray_angle = sub.add_option("--ray-angle", o->ray_angle,
                                   "With --min-wall or --method ray: two sides facing each other within this angle "
                                   "(degrees) make a wall; sharper edges do not (default 30)")
                        ->check(CLI::Range(1.0, 89.0));
  sub.add_option("--min-area", o->min_area,
                 "With --min-wall: walls with less surface than this (model units^2) are specks, counted but not "
                 "listed (default: the minimum wall squared)")
      ->check(CLI::NonNegativeNumber)
      ->needs(min_wall);
  sub.add_option("-o,--output", o->out, "Write the local thickness (model units): .nrrd, .vti or .vdb");
  sub.add_option("--distance", o->distance_out, "Write the distance to the surface (model units): .nrrd, .vti or .vdb");
  sub.add_flag("--signed", o->signed_distance, "With --distance: empty voxels hold minus their distance to the part");
  auto* axis = sub.add_option("--section-axis", o->section_axis, "Section for --png: x, y or z")
                   ->check(CLI::IsMember({"x", "y", "z"}));
  auto* index = sub.add_option("--section-index", o->section_index, "Voxel index of the section along its axis");
  axis->needs(index);
  index->needs(axis);
  sub.add_option("--png", o->png, "Write the section coloured by local thickness as PNG")->needs(axis);
  sub.add_option("--scale", o->scale, "Pixels per voxel in the PNG (default 1)")->check(CLI::Range(1, 64));
  sub.add_option("--hot-spots", o->hot_spots_shown, "Hot spots listed in the text summary (JSON lists all)")
      ->check(CLI::NonNegativeNumber);
  sub.callback([o, ray_angle, &ctx] {
    if (ray_angle->count() > 0 && o->min_wall <= 0.0 && o->method != "ray") {
      // nothing would use it: say so rather than ignore it
      Output out(o->c.json);
      ctx.exit_code =
          out.fail(kExitUsage, "--ray-angle applies to the walls of --min-wall and to --method ray; give one");
      return;
    }
    ctx.exit_code = runThickness(*o);
  });
}

}  // namespace vox::cli
