// voxmod report FILE -o OUT.html (vox/workflow/report.h): one self-contained HTML page of what voxmod
// computes of the part (or, with --bodies, of the assembly of its bodies), with a rendered view (headless; left out,
// with a note, where no OpenGL can be had).
#include <filesystem>
#include <memory>
#include <optional>

#include <CLI/CLI.hpp>

#include "cli/assembly_input.h"
#include "cli/cmd_list.h"
#include "cli/commands.h"
#include "cli/model_input.h"
#include "vox/analysis/analysis.h"
#include "vox/core/units.h"
#include "vox/io/file_util.h"
#include "vox/io/image_io.h"
#include "vox/render/render.h"
#include "vox/workflow/report.h"

namespace vox::cli {
namespace {

struct ReportCliOptions {
  CommonOptions c;
  std::string out;
  double min_wall = 0.0;
  std::string material;
  bool bodies = false;   // the file's bodies as the parts of an assembly (interference listed)
  double contact = 0.0;  // with bodies: overlaps at most this thick only touch
};

// With --bodies: the file's bodies (a CAD file's solids by their names, a mesh's shells, a voxel file's components)
// as the parts of an assembly.
Result<Assembly> bodiesOf(const ReportCliOptions& o, Output& out) {
  auto placed = placeInputs({o.c.file}, o.c.mesh, true, out);
  if (!placed) return placed.error();
  Assembly parts(placed->lattice);
  for (size_t i = 0; i < placed->parts.size(); ++i) {
    const std::string& own = placed->body_names[i];
    parts.addPart(std::move(placed->parts[i]), own.empty() ? placed->names[i] : own);
  }
  return parts;
}

// The part lit, from above at an angle: the report's first picture; none (and a note) without OpenGL.
std::vector<workflow::ReportPicture> viewPictures(const VoxelGrid& grid, Output& out) {
  render::RenderParams p;
  p.width = 900;
  p.height = 600;
  p.lut = render::Lut::kLit;
  p.background = Rgba8{255, 255, 255, 255};
  auto image = render::renderGridHeadless(grid, p);
  if (!image) {
    out.note("the report has no 3D view: " + image.error().message);
    return {};
  }
  auto png = io::encodePng(*image, "view.png");
  if (!png) {
    out.note("the report has no 3D view: " + png.error().message);
    return {};
  }
  return {workflow::ReportPicture{"The part, lit", std::move(png).value()}};
}

int runReport(const ReportCliOptions& o) {
  Output out(o.c.json);
  if (std::filesystem::path(o.out).extension() != ".html") {
    return out.fail(kExitUsage, o.out + ": the report is an HTML page: give a name ending in .html");
  }
  workflow::ReportOptions options;
  options.min_wall = o.min_wall;
  if (!o.material.empty()) {
    const auto density = materialDensity(o.material);
    if (!density) return out.fail(kExitUsage, "unknown material '" + o.material + "' (known: " + materialNames() + ")");
    options.density_kg_m3 = *density;
    options.material = o.material;
  }
  auto model = loadModel(o.c.file, o.c.mesh, out, true);
  if (!model) return out.fail(model.error());
  const VoxelGrid& grid = model->grid;
  if (options.density_kg_m3 > 0.0 && metresPerUnit(grid.frame().units) == 0.0) {
    return out.fail(kExitUsage, o.c.file +
                                    ": a mass in kg needs the model's length units, which this file does not "
                                    "give: say them with --units mm|cm|m|in");
  }
  options.name = std::filesystem::path(o.c.file).filename().string();
  options.mesh = model->mesh ? &*model->mesh : nullptr;
  std::optional<Assembly> parts;
  if (o.bodies) {
    auto split = bodiesOf(o, out);
    if (!split) return out.fail(split.error());
    parts = std::move(split).value();
    options.parts = &*parts;
    options.contact = o.contact;
  }
  const double t0 = nowSeconds();
  const std::vector<workflow::ReportPicture> pictures = viewPictures(grid, out);
  workflow::ReportFacts facts;
  auto html = workflow::buildReport(grid, options, pictures, &facts, terminalProgress("report"));
  if (!html) return out.fail(html.error());
  if (Status st = writeOutputs({{o.out, std::vector<uint8_t>(html->begin(), html->end())}}, out); !st) {
    return out.fail(st.error());
  }
  auto& d = out.data();
  d["output"] = o.out;
  d["units"] = grid.frame().units;
  d["pictures"] = int64_t(pictures.size()) + 1;  // and the section
  d["volume"] = facts.volume;
  d["wall_min"] = facts.wall_min;
  d["thickness_max"] = facts.thickness_max;
  d["thin_regions"] = facts.thin_regions;
  d["hot_spots"] = facts.hot_spots;
  d["support_volume"] = facts.support_volume;
  d["trapped_cavities"] = facts.trapped_cavities;
  if (o.bodies) {
    d["parts"] = facts.parts;
    d["interfering_pairs"] = facts.interfering_pairs;
    d["contact_pairs"] = facts.contact_pairs;
  }
  d["report_s"] = nowSeconds() - t0;
  return out.finish();
}

}  // namespace

void addReportCommand(CLI::App& sub, CommandContext& ctx) {
  auto o = std::make_shared<ReportCliOptions>();
  addCommonOptions(sub, o->c);
  sub.add_option("-o,--output", o->out, "The report: one HTML file with its pictures in it")->required();
  sub.add_option("--min-wall", o->min_wall, "List the walls thinner than this (model units)")
      ->check(CLI::PositiveNumber);
  sub.add_option("--material", o->material,
                 "Give the mass for a common material's density (needs units): " + materialNames());
  sub.add_flag("--bodies", o->bodies,
               "Report the file's bodies as an assembly: its parts and the pairs that interfere (a CAD file's solids, "
               "a mesh's shells, a voxel file's components)");
  auto* contact = sub.add_option("--contact", o->contact,
                                 "With --bodies: overlaps at most this thick (model units) only touch: listed as "
                                 "contact, not interference")
                      ->check(contactValue());
  sub.callback([o, contact, &ctx] {
    if (contact->count() > 0 && !o->bodies) {
      Output out(o->c.json);
      ctx.exit_code = out.fail(kExitUsage, "--contact applies to an assembly's overlaps: give --bodies too");
      return;
    }
    ctx.exit_code = runReport(*o);
  });
}

}  // namespace vox::cli
