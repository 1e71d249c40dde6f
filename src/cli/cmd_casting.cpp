// voxmod casting (docs/conventions.md, "Casting"): the part poured in an alloy into a mould, with its
// feeders: when each voxel freezes, the hot spots that freeze last and whether a feeder reaches them, the verdict.
// The solidification time, modulus and Niyama fields as volumes and a section as a PNG; the files asked for are
// written together or not at all.
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/cmd_list.h"
#include "cli/commands.h"
#include "cli/model_input.h"
#include "vox/io/file_util.h"
#include "vox/io/image_io.h"
#include "vox/io/volume_export.h"
#include "vox/workflow/casting_run.h"

namespace vox::cli {
namespace {

struct CastingOptions {
  CommonOptions c;
  std::string alloy = "a356", mould = "silica-sand";
  double superheat = 50.0;
  double mould_temperature = 0.0;
  bool mould_temperature_given = false;
  std::vector<std::string> feeders;
  std::string time_out, modulus_out, niyama_out, png_out;
};

nlohmann::ordered_json alloyJson(const Alloy& a) {
  return {{"name", a.name},
          {"liquidus_c", a.liquidus_c},
          {"solidus_c", a.solidus_c},
          {"density_kg_m3", a.density_kg_m3},
          {"latent_heat_j_kg", a.latent_heat_j_kg},
          {"conductivity_w_mk", a.conductivity_w_mk},
          {"specific_heat_j_kgk", a.specific_heat_j_kgk}};
}

nlohmann::ordered_json mouldJson(const MouldMaterial& m) {
  return {{"name", m.name},
          {"conductivity_w_mk", m.conductivity_w_mk},
          {"density_kg_m3", m.density_kg_m3},
          {"specific_heat_j_kgk", m.specific_heat_j_kgk},
          {"temperature_c", m.temperature_c}};
}

void reportResult(const workflow::CastingRun& run, const std::string& units, Output& out) {
  const CastingResult& r = run.result;
  auto& d = out.data();
  d["solidification_s"] = r.solidification_s;
  d["last_metal_s"] = r.last_metal_s;
  d["modulus_max"] = run.modulus_max;
  auto spots = nlohmann::ordered_json::array();
  for (const CastingHotSpot& s : r.hot_spots) {
    nlohmann::ordered_json j = {{"centre", jsonVec3(s.centre)}, {"solidification_s", s.solidification_s},
                                {"modulus", s.modulus},         {"isolated", s.isolated},
                                {"in_feeder", s.in_feeder},     {"voxels", s.voxels}};
    if (s.fed_by >= 0) {
      j["fed_by"] = s.fed_by;
      j["saddle"] = jsonVec3(s.saddle);
    }
    spots.push_back(j);
  }
  d["hot_spots"] = spots;
  d["sound"] = r.sound;
  d["verdict"] = r.verdict;
  auto feeders = nlohmann::ordered_json::array();
  for (const FeederResult& f : r.feeders) {
    feeders.push_back({{"centre", jsonVec3(f.feeder.base)},
                       {"diameter", f.feeder.diameter},
                       {"height", f.feeder.height},
                       {"modulus", f.modulus},
                       {"volume", f.volume}});
  }
  d["feeders"] = feeders;
  d["casting_volume"] = r.casting_volume;
  d["yield"] = r.yield;
  d["time_step_s"] = r.time_step_s;
  d["steps"] = r.steps;
  d["box"] = {r.box.nx, r.box.ny, r.box.nz};
  d["envelope_voxels"] = r.envelope_voxels;
  d["modulus_s"] = run.modulus_s;
  d["simulate_s"] = r.simulate_s;
  out.say("solid after " + significant(r.solidification_s, 4) + " s (" + significant(r.solidification_s / 60.0, 3) +
          " min); largest modulus " + significant(run.modulus_max, 4) + " " + units);
  for (size_t k = 0; k < r.hot_spots.size() && k < 10; ++k) {
    const CastingHotSpot& s = r.hot_spots[k];
    out.say("  hot spot at (" + significant(s.centre.x, 5) + ", " + significant(s.centre.y, 5) + ", " +
            significant(s.centre.z, 5) + ") freezes at " + significant(s.solidification_s, 4) + " s, modulus " +
            significant(s.modulus, 3) + (s.in_feeder ? ", in a feeder" : (s.isolated ? ", isolated" : ", fed")));
  }
  for (const FeederResult& f : r.feeders) {
    out.say("  feeder: modulus " + significant(f.modulus, 4) + " " + units + ", volume " + significant(f.volume, 4) +
            " " + units + "^3");
  }
  if (!r.feeders.empty()) out.say("yield " + significant(100.0 * r.yield, 3) + "%");
  out.say(r.verdict);
}

Status encodeOutputs(const CastingOptions& o, const workflow::CastingRun& run, std::vector<io::PendingFile>& files) {
  const std::pair<const std::string*, std::pair<const char*, const ScalarField*>> fields[] = {
      {&o.time_out, {"solidification_time", &run.result.time}},
      {&o.modulus_out, {"modulus", &run.modulus}},
      {&o.niyama_out, {"niyama", &run.result.niyama}}};
  for (const auto& [path, field] : fields) {
    if (path->empty()) continue;
    auto bytes = io::encodeVolume(io::oneField(field.first, *field.second), *io::volumeFormatOf(*path), *path);
    if (!bytes) return bytes.error();
    files.push_back({*path, std::move(bytes).value()});
  }
  if (!o.png_out.empty()) {
    auto figure = workflow::castingSectionFigure(run.result, workflow::latestHotSpotSection(run.result), 4);
    if (!figure) return figure.error();
    auto png = io::encodePng(*figure, o.png_out);
    if (!png) return png.error();
    files.push_back({o.png_out, std::move(png).value()});
  }
  return Ok{};
}

int runCasting(const CastingOptions& o) {
  Output out(o.c.json);
  for (const std::string* field : {&o.time_out, &o.modulus_out, &o.niyama_out}) {
    if (!field->empty() && (!io::volumeFormatOf(*field) || !io::holdsFields(*io::volumeFormatOf(*field)))) {
      return out.fail(kExitUsage,
                      *field + ": a volume file that holds fields is needed (" + io::volumeExtensionList(true) + ")");
    }
  }
  if (!o.png_out.empty() && io::lowerExtension(o.png_out) != ".png") {
    return out.fail(kExitUsage, o.png_out + ": --png writes a .png file");
  }
  CastingParams params;
  const Alloy* alloy = findAlloy(o.alloy);
  if (!alloy) return out.fail(kExitUsage, "unknown alloy '" + o.alloy + "'; known: " + alloyNames());
  const MouldMaterial* mould = findMould(o.mould);
  if (!mould) return out.fail(kExitUsage, "unknown mould '" + o.mould + "'; known: " + mouldNames());
  params.alloy = *alloy;
  params.mould = *mould;
  if (o.mould_temperature_given) params.mould.temperature_c = o.mould_temperature;
  params.superheat_k = o.superheat;
  for (const std::string& text : o.feeders) {
    auto feeder = parseFeeder(text);
    if (!feeder) return out.fail(kExitUsage, feeder.error().message);
    params.feeders.push_back(*feeder);
  }
  auto model = loadModel(o.c.file, o.c.mesh, out);
  if (!model) return out.fail(model.error());
  const VoxelGrid& grid = model->grid;
  if (metresPerUnit(grid.frame().units) <= 0.0) {
    return out.fail(kExitIo, o.c.file +
                                 " has no length units, and a casting's times depend on its size: say what "
                                 "its numbers are in with --units mm|cm|m|in");
  }
  auto& d = out.data();
  d["units"] = grid.frame().units;
  d["voxel_size"] = grid.voxelSize();
  d["alloy"] = alloyJson(params.alloy);
  d["mould"] = mouldJson(params.mould);
  d["superheat_k"] = params.superheat_k;
  const ProgressFn modulus_line = terminalProgress("modulus"), simulate_line = terminalProgress("solidifying");
  const workflow::CastingProgress progress = [&](workflow::CastingStage stage, double f) {
    const ProgressFn& line = stage == workflow::CastingStage::kModulus ? modulus_line : simulate_line;
    return !line || line(f);
  };
  auto run = workflow::runCasting(grid, params, progress, o.c.mesh.memory_limit_bytes);
  if (!run) return out.fail(run.error());
  reportResult(*run, grid.frame().units, out);
  std::vector<io::PendingFile> files;
  if (Status st = encodeOutputs(o, *run, files); !st) return out.fail(st.error());
  if (Status st = writeOutputs(files, out); !st) return out.fail(st.error());
  return out.finish();
}

}  // namespace

void addCastingCommand(CLI::App& sub, CommandContext& ctx) {
  auto o = std::make_shared<CastingOptions>();
  addCommonOptions(sub, o->c);
  sub.add_option("--alloy", o->alloy, "The metal poured: " + alloyNames() + " (default a356)");
  sub.add_option("--mould", o->mould, "The mould: " + mouldNames() + " (default silica-sand)");
  sub.add_option("--superheat", o->superheat, "Kelvin above the liquidus the metal is poured at (default 50)")
      ->check(CLI::Range(0.0, 1000.0));
  sub.add_option("--mould-temperature", o->mould_temperature,
                 "The mould's starting temperature, C (default: sand 20, a steel die 200)")
      ->each([o](const std::string&) { o->mould_temperature_given = true; });
  sub.add_option("--feeder", o->feeders,
                 "A feeder: cylinder:X,Y,Z,D,H, diameter D and height H standing on the point (X, Y, Z) of the part "
                 "along +Z (model units); repeatable");
  sub.add_option("-o,--output", o->time_out, "Write each voxel's solidification time, s (.nrrd, .vti, .vdb)");
  sub.add_option("--modulus", o->modulus_out, "Write the geometric modulus V/A, model units (.nrrd, .vti, .vdb)");
  sub.add_option("--niyama", o->niyama_out,
                 "Write Niyama's criterion where the metal froze, (K s)^0.5 / mm (.nrrd, .vti, .vdb)");
  sub.add_option("--png", o->png_out, "Write the Z section through the latest hot spot, coloured by time (.png)");
  sub.callback([o, &ctx] { ctx.exit_code = runCasting(*o); });
}

}  // namespace vox::cli
