// The analysis subcommands (docs/conventions.md, "Command line"): section, peel, xray, mass. Each binds its flags to
// the same params struct the GUI edits (vox/analysis/analysis.h) and FILE may be a mesh, voxelized on the fly.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>
#include <optional>

#include <CLI/CLI.hpp>

#include "cli/cmd_list.h"
#include "cli/commands.h"
#include "cli/model_input.h"
#include "cli/stream_readers.h"
#include "vox/analysis/oblique_section.h"
#include "vox/workflow/streamed_analyses.h"
#include "cli/write_grid.h"
#include "vox/analysis/analysis.h"
#include "vox/analysis/distance.h"
#include "vox/analysis/scalar_fields.h"
#include "vox/core/units.h"
#include "vox/io/figure.h"
#include "vox/io/file_util.h"
#include "vox/io/image_io.h"
#include "vox/io/volume_export.h"
#include "vox/io/voxel_file.h"

namespace vox::cli {

std::string materialNames() {
  std::string names;
  for (const Material& m : commonMaterials()) names += std::string(names.empty() ? "" : ", ") + m.name;
  return names;
}

namespace {

// Words to enum values, read by the parsers analysis gives them (parseAxis, parseXrayMode), so the flags bind
// straight to the params structs the window edits.
template <class E>
CLI::Validator enumWords(std::optional<E> (*parse)(const std::string&), const std::string& names) {
  return CLI::Validator(
      [parse, names](std::string& word) -> std::string {
        const std::optional<E> value = parse(word);
        if (!value) return "'" + word + "' is not one of " + names;
        word = std::to_string(int(*value));
        return {};
      },
      names);
}
CLI::Validator axisWords() { return enumWords<Axis>(parseAxis, "x|y|z"); }
CLI::Validator xrayModeWords() { return enumWords<XrayMode>(parseXrayMode, "min|max|total"); }

// ---- section ----
struct SectionOptions {
  CommonOptions c;
  SectionParams params;
  std::string out;
  int32_t scale = 1;
  // At any angle (--normal): the plane's normal and point ("X,Y,Z"), the pixel size (0: the voxel size).
  std::string normal, point;
  double pixel = 0.0;
};

// "X,Y,Z" as three finite numbers.
std::optional<glm::dvec3> parseTriple(const std::string& text) {
  glm::dvec3 v(0.0);
  size_t at = 0;
  for (int k = 0; k < 3; ++k) {
    const size_t comma = k < 2 ? text.find(',', at) : text.size();
    if (comma == std::string::npos) return std::nullopt;
    if (!parseFileNumber(std::string_view(text).substr(at, comma - at), v[k])) return std::nullopt;
    at = comma + 1;
  }
  return v;
}

// The section on the plane through a point with a normal (docs/conventions.md, "Sections at any angle").
int runObliqueSection(const SectionOptions& o, Output& out) {
  ObliqueSectionParams p;
  const auto normal = parseTriple(o.normal);
  if (!normal) return out.fail(kExitUsage, "--normal wants NX,NY,NZ (three numbers), found '" + o.normal + "'");
  p.normal = *normal;
  if (!o.point.empty()) {
    const auto point = parseTriple(o.point);
    if (!point) return out.fail(kExitUsage, "--point wants X,Y,Z (three numbers), found '" + o.point + "'");
    p.point = *point;
    p.point_given = true;
  }
  p.pixel = o.pixel;
  if (streamedVxm(o.c.file, o.c.mesh, out)) {
    return out.fail(kExitUsage, o.c.file +
                                    ": a section at an angle needs the grid in memory; this file's does not "
                                    "fit under the memory limit (--memory-limit)");
  }
  auto model = loadModel(o.c.file, o.c.mesh, out);
  if (!model) return out.fail(model.error());
  auto section = computeObliqueSection(model->grid, p);
  if (!section) return out.fail(kExitUsage, section.error().message);
  if (auto s = io::savePng(io::sectionPicture(section->mask, o.scale), o.out); !s) return out.fail(s.error());
  const std::string units = unitsLabel(model->grid.frame().units);
  auto& d = out.data();
  d["normal"] = jsonVec3(section->normal);
  d["point"] = jsonVec3(section->point);
  d["u"] = jsonVec3(section->u);
  d["v"] = jsonVec3(section->v);
  d["pixel_size"] = section->pixel;
  d["filled"] = section->filled;
  d["area"] = section->area;
  d["width"] = section->mask.width;
  d["height"] = section->mask.height;
  d["output"] = o.out;
  out.say("section through (" + significant(section->point.x) + ", " + significant(section->point.y) + ", " +
          significant(section->point.z) + ") normal to (" + significant(section->normal.x, 4) + ", " +
          significant(section->normal.y, 4) + ", " + significant(section->normal.z, 4) +
          "): " + std::to_string(section->filled) + " filled samples of " + significant(section->pixel) + " " + units +
          ", area " + significant(section->area) + " " + units + "^2; wrote " + o.out);
  return out.finish();
}

int runSection(const SectionOptions& o) {
  Output out(o.c.json);
  if (const std::string why = pngOutputProblem(o.out); !why.empty()) return out.fail(kExitUsage, why);
  if (!o.normal.empty()) return runObliqueSection(o, out);
  if (o.params.index < 0) return out.fail(kExitUsage, "section needs --axis and --index, or --normal");
  // The model's dims and frame (its voxels too, unless the file is read in windows).
  VoxelGrid grid;
  Result<Section> section = Error{};
  if (auto h = streamedVxm(o.c.file, o.c.mesh, out)) {
    grid = VoxelGrid(h->dims, h->frame);
    section = workflow::streamedSection(o.c.file, *h, windowLayers(h->dims, o.c.mesh), o.params);
  } else {
    auto model = loadModel(o.c.file, o.c.mesh, out);
    if (!model) return out.fail(model.error());
    grid = std::move(model->grid);
    section = computeSection(grid, o.params);
  }
  if (!section) return out.fail(section.error());
  if (auto s = io::savePng(io::sectionPicture(section->mask, o.scale), o.out); !s) return out.fail(s.error());
  auto& d = out.data();
  d["axis"] = axisName(o.params.axis);
  d["index"] = o.params.index;
  d["position"] = section->position;
  d["filled"] = section->filled;
  d["area"] = double(section->filled) * grid.voxelSize() * grid.voxelSize();
  d["width"] = section->mask.width;
  d["height"] = section->mask.height;
  d["output"] = o.out;
  out.say(std::string("section ") + axisName(o.params.axis) + " = " + std::to_string(o.params.index) + " (at " +
          significant(section->position) + " " + grid.frame().units + "): " + std::to_string(section->filled) +
          " filled voxels; wrote " + o.out);
  return out.finish();
}

// ---- peel ----
struct PeelOptions {
  CommonOptions c;
  int32_t layers = 1;
  bool all = false;
  double distance = -1.0;  // model units; >= 0: round skin removal instead of layers
  std::string out;
  std::string depth_out;  // --depth: every voxel's skin layer as a volume
};

// -o and --depth together: the remaining voxels and the depth volume, written as one (writeFilesAtomic: both files
// complete under temporary names before either replaces its target). An -o that is not a voxel file (a volume, a
// surface mesh) is first written by writeGridAs beside its target under a hidden temporary name and taken from there.
Status writePeelFiles(const PeelOptions& o, const DepthMap& depth, const VoxelGrid& grid, const VoxelGrid& remaining) {
  std::vector<io::PendingFile> files;
  if (!o.out.empty()) {
    const std::filesystem::path out(o.out);
    const std::string ext = io::lowerExtension(o.out);
    if (ext == ".vxm" || ext == ".binvox") {
      files.push_back({o.out, ext == ".vxm" ? io::encodeVxm(remaining) : io::encodeBinvox(remaining)});
    } else {
      const std::filesystem::path staged =
          out.parent_path() / ("." + out.stem().string() + ".voxmod-" + std::to_string(::getpid()) + ext);
      Status s = writeGridAs(remaining, staged, o.c.file);
      auto bytes = s.ok() ? io::readFileBytes(staged) : Result<std::vector<uint8_t>>(s.error());
      std::error_code ec;
      std::filesystem::remove(staged, ec);
      if (!s) {
        std::string message = s.error().message;  // it names the temporary file: name the output instead
        for (size_t at = message.find(staged.string()); at != std::string::npos;
             at = message.find(staged.string(), at + o.out.size())) {
          message.replace(at, staged.string().size(), o.out);
        }
        return makeError(s.error().code, message);
      }
      if (!bytes) return bytes.error();
      files.push_back({o.out, std::move(bytes).value()});
    }
  }
  auto bytes = encodeFieldFile("depth", depthField(depth, grid), o.depth_out);
  if (!bytes) return bytes.error();
  files.push_back({o.depth_out, std::move(bytes).value()});
  return io::writeFilesAtomic(files);
}

// --distance D: every filled voxel within D of the outside goes (the Euclidean peel, docs/accuracy.md).
int runPeelByDistance(const PeelOptions& o, const LoadedModel& model, Output& out) {
  const int64_t before = model.grid.filledCount();
  auto r = peelByDistance(model.grid, o.distance, terminalProgress("distance"));
  if (!r) return out.fail(r.error());
  if (!o.out.empty()) {
    if (auto s = writeGridAs(*r, o.out, o.c.file); !s) return out.fail(kExitIo, s.error().message);
  }
  const int64_t left = r->filledCount();
  auto& d = out.data();
  d["distance"] = o.distance;
  d["removed"] = before - left;
  d["remaining"] = left;
  if (!o.out.empty()) d["output"] = o.out;
  out.say("peeled everything within " + significant(o.distance) + " " + model.grid.frame().units +
          " of the outside: " + std::to_string(before - left) + " voxels removed, " + std::to_string(left) + " remain");
  return out.finish();
}

int runPeel(const PeelOptions& o) {
  Output out(o.c.json);
  if (!o.out.empty() && !isGridOutput(o.out)) return out.fail(kExitUsage, gridOutputFormats(o.out));  // before work
  if (!o.depth_out.empty()) {
    if (o.distance >= 0.0) return out.fail(kExitUsage, "--depth goes with --layers or --all, not --distance");
    if (const std::string why = fieldOutputProblem(o.depth_out); !why.empty()) return out.fail(kExitUsage, why);
  }
  auto model = loadModel(o.c.file, o.c.mesh, out);
  if (!model) return out.fail(model.error());
  if (o.distance >= 0.0) return runPeelByDistance(o, *model, out);
  PeelParams p;
  p.layers = o.layers;
  p.all = o.all;
  // The window's operation: the depth map, then what the layers asked for leave.
  auto depth = computeDepthMap(model->grid, p, terminalProgress("peeling"));
  if (!depth) return out.fail(depth.error());
  const PeelResult result = depth->peeled(p.all ? depth->layers() : p.layers);
  const PeelResult* r = &result;
  if (!o.depth_out.empty()) {
    if (auto s = writePeelFiles(o, *depth, model->grid, r->remaining); !s) {
      // An empty remainder has no surface to write: an output error (exit 2), as for boolean.
      if (s.error().code == ErrorCode::kInvalidArgument) return out.fail(kExitIo, s.error().message);
      return out.fail(s.error());
    }
  } else if (!o.out.empty()) {
    if (auto s = writeGridAs(r->remaining, o.out, o.c.file); !s) return out.fail(kExitIo, s.error().message);
  }
  auto& d = out.data();
  d["removed_per_layer"] = r->removed_per_layer;
  d["layers"] = r->removed_per_layer.size();
  d["remaining"] = r->remaining_count;
  d["core_voxels"] = r->core_voxels;
  if (!o.out.empty()) d["output"] = o.out;
  if (!o.depth_out.empty()) d["depth"] = o.depth_out;
  // The window's words: a model has L skin layers, the last (layer L) is the core.
  const size_t layers = r->removed_per_layer.size();
  std::string line =
      std::to_string(layers) + " layers peeled, " + std::to_string(r->remaining_count) + " voxels remain";
  if (r->remaining_count == 0 && layers > 0) {
    line += "; the model has " + std::to_string(layers) + " skin layers and the core (layer " + std::to_string(layers) +
            ", the thickest region) had " + std::to_string(r->core_voxels) + " voxels";
  }
  out.say(line);
  return out.finish();
}

// ---- xray ----
struct XrayOptions {
  CommonOptions c;
  XrayParams params;
  std::string out, csv;
  std::string volume;  // --volume: the X-ray as a one-voxel-thick volume
  int32_t scale = 1;
};

int runXray(const XrayOptions& o) {
  Output out(o.c.json);
  if (const std::string why = pngOutputProblem(o.out); !why.empty()) return out.fail(kExitUsage, why);
  if (!o.volume.empty()) {
    if (const std::string why = fieldOutputProblem(o.volume); !why.empty()) return out.fail(kExitUsage, why);
  }
  // The model's dims and frame (its voxels too, unless the file is read in windows).
  VoxelGrid grid;
  Result<XrayResult> x = Error{};
  if (auto h = streamedVxm(o.c.file, o.c.mesh, out)) {
    grid = VoxelGrid(h->dims, h->frame);
    x = workflow::streamedXray(o.c.file, *h, windowLayers(h->dims, o.c.mesh), o.params);
  } else {
    auto model = loadModel(o.c.file, o.c.mesh, out);
    if (!model) return out.fail(model.error());
    grid = std::move(model->grid);
    x = computeXray(grid, o.params);
  }
  if (!x) return out.fail(x.error());
  // The image, the CSV and the volume are written as one: all or, on any failure, none.
  auto png = io::encodePng(io::drawScalarMapFigure(x->thickness, x->max, xrayLegend(*x), o.scale).image, o.out);
  if (!png) return out.fail(png.error());
  std::vector<io::PendingFile> files{{o.out, std::move(png).value()}};
  if (!o.csv.empty()) {
    const std::string csv = xrayCsv(*x);
    files.push_back({o.csv, std::vector<uint8_t>(csv.begin(), csv.end())});
  }
  if (!o.volume.empty()) {
    auto bytes = encodeFieldFile("xray", xrayField(*x, grid), o.volume);
    if (!bytes) return out.fail(bytes.error());
    files.push_back({o.volume, std::move(bytes).value()});
  }
  if (auto s = io::writeFilesAtomic(files); !s) return out.fail(s.error());
  const double h = grid.voxelSize();
  // *_mm keys are millimetres when the model's units are known, model units otherwise ("units" says which).
  const double metres = metresPerUnit(grid.frame().units);
  const double to_mm = metres > 0 ? metres * 1000.0 : 1.0;
  auto& d = out.data();
  d["axis"] = axisName(o.params.axis);
  d["mode"] = xrayModeName(o.params.mode);
  d["units"] = metres > 0 ? std::string("mm") : grid.frame().units;
  d["rays_hit"] = x->rays_hit;
  d["min"] = x->min;
  d["max"] = x->max;
  d["mean"] = x->mean;
  d["min_mm"] = double(x->min) * h * to_mm;
  d["max_mm"] = double(x->max) * h * to_mm;
  d["mean_mm"] = x->mean * h * to_mm;
  d["output"] = o.out;
  if (!o.csv.empty()) d["csv"] = o.csv;
  if (!o.volume.empty()) d["volume"] = o.volume;
  out.say(std::string("x-ray ") + xrayModeName(o.params.mode) + " along " + axisName(o.params.axis) + ": " +
          std::to_string(x->rays_hit) + " rays hit; min " + std::to_string(x->min) + ", max " + std::to_string(x->max) +
          ", mean " + significant(x->mean) + " voxels (voxel size " + significant(h) + " " + grid.frame().units +
          "); wrote " + o.out);
  return out.finish();
}

// ---- mass ----
struct MassOptions {
  CommonOptions c;
  double density = 0.0;  // kg/m^3; 0: unit density only
  std::string material;
};

int massNeedsUnits(const std::string& file, Output& out) {
  return out.fail(kExitUsage, file +
                                  ": a mass in kg needs the model's length units, which this file does not give: say "
                                  "them with --units mm|cm|m|in");
}

int runMass(const MassOptions& o) {
  Output out(o.c.json);
  double density = o.density;
  if (!o.material.empty()) {
    const auto d = materialDensity(o.material);
    if (!d) return out.fail(kExitUsage, "unknown material '" + o.material + "' (known: " + materialNames() + ")");
    density = *d;
  }
  GridFrame frame;
  MassProperties m;
  if (auto h = streamedVxm(o.c.file, o.c.mesh, out)) {
    frame = h->frame;
    if (density > 0 && metresPerUnit(frame.units) == 0) return massNeedsUnits(o.c.file, out);
    auto r = workflow::streamedMass(o.c.file, *h, windowLayers(h->dims, o.c.mesh));
    if (!r) return out.fail(r.error());
    m = *r;
  } else {
    auto model = loadModel(o.c.file, o.c.mesh, out);
    if (!model) return out.fail(model.error());
    frame = model->grid.frame();
    if (density > 0 && metresPerUnit(frame.units) == 0) return massNeedsUnits(o.c.file, out);
    m = computeMassProperties(model->grid);
  }
  const std::string& units = frame.units;
  const double metres = metresPerUnit(units);
  auto& d = out.data();
  d["filled"] = m.filled;
  d["volume"] = m.volume;
  d["volume_error_bound"] = m.volume_error_bound;
  d["units"] = units;
  out.say("volume   " + significant(m.volume) + " (+/- " + significant(m.volume_error_bound, 3) + ") " +
          unitsLabel(units) + "^3");
  if (density > 0) {
    const double kg = m.volume * metres * metres * metres * density;
    d["density_kg_m3"] = density;
    d["mass_kg"] = kg;
    out.say("mass     " + significant(kg) + " kg (density " + significant(density) + " kg/m^3)");
  }
  if (m.filled == 0) {
    // An empty model has no centroid, inertia or bounding box: null, never a made-up number.
    for (const char* key :
         {"centroid", "inertia", "principal_moments", "principal_axes", "bbox", "bbox_min_ijk", "bbox_max_ijk"}) {
      d[key] = nullptr;
    }
    out.say("the model is empty: it has no centroid, inertia or bounding box");
    return out.finish();
  }
  const PrincipalAxes principal = principalAxes(m.inertia);
  const auto matrix = [](const glm::dmat3& t, double f) {
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (int r = 0; r < 3; ++r) rows.push_back({t[0][r] * f, t[1][r] * f, t[2][r] * f});
    return rows;
  };
  d["centroid"] = jsonVec3(m.centroid);
  d["inertia"] = matrix(m.inertia, 1.0);
  d["principal_moments"] = jsonVec3(principal.moments);
  d["principal_axes"] = {jsonVec3(principal.axes[0]), jsonVec3(principal.axes[1]), jsonVec3(principal.axes[2])};
  // Unit density in model units^5 -> kg m^2: times density and metres^5.
  const double to_kg_m2 = density * std::pow(metres, 5.0);
  if (density > 0) {
    d["inertia_kg_m2"] = matrix(m.inertia, to_kg_m2);
    d["principal_moments_kg_m2"] = jsonVec3(principal.moments * to_kg_m2);
  }
  d["bbox"] = {{"min", jsonVec3(m.bbox.min)}, {"max", jsonVec3(m.bbox.max)}};
  d["bbox_min_ijk"] = jsonVec3(m.bbox_min_ijk);
  d["bbox_max_ijk"] = jsonVec3(m.bbox_max_ijk);
  const auto vec = [](const glm::dvec3& v) {
    return significant(v.x) + " " + significant(v.y) + " " + significant(v.z);
  };
  out.say("centroid " + vec(m.centroid));
  const double f = density > 0 ? to_kg_m2 : 1.0;
  const std::string inertia_units = density > 0 ? " (kg m^2)" : " (unit density, " + unitsLabel(units) + "^5)";
  for (int r = 0; r < 3; ++r) {
    out.say(std::string(r == 0 ? "inertia  " : "         ") +
            vec(glm::dvec3(m.inertia[0][r], m.inertia[1][r], m.inertia[2][r]) * f) + (r == 0 ? inertia_units : ""));
  }
  out.say("principal moments " + vec(principal.moments * f));
  for (int i = 0; i < 3; ++i) out.say("  axis " + std::to_string(i + 1) + "         " + vec(principal.axes[i]));
  out.say("bbox     " + vec(m.bbox.min) + "  to  " + vec(m.bbox.max));
  return out.finish();
}

}  // namespace

void addSectionCommand(CLI::App& sub, CommandContext& ctx) {
  auto o = std::make_shared<SectionOptions>();
  addCommonOptions(sub, o->c);
  o->params.index = -1;
  auto* axis = sub.add_option("--axis", o->params.axis, "Section normal: x, y or z")->transform(axisWords());
  auto* index = sub.add_option("--index", o->params.index, "Voxel index along the axis (0-based)");
  axis->needs(index);
  index->needs(axis);
  auto* normal =
      sub.add_option("--normal", o->normal, "A section at any angle: the plane's normal NX,NY,NZ (instead of --axis)");
  normal->excludes(axis)->excludes(index);
  sub.add_option("--point", o->point, "With --normal: a point X,Y,Z of the plane (default: the grid's centre)")
      ->needs(normal);
  sub.add_option("--pixel", o->pixel, "With --normal: the samples' spacing in model units (default: the voxel size)")
      ->needs(normal)
      ->check(CLI::PositiveNumber);
  sub.add_option("-o,--output", o->out, "Output PNG")->required();
  sub.add_option("--scale", o->scale, "Pixels per voxel or sample (default 1)")->check(CLI::Range(1, 64));
  sub.callback([o, &ctx] { ctx.exit_code = runSection(*o); });
}

void addPeelCommand(CLI::App& sub, CommandContext& ctx) {
  auto o = std::make_shared<PeelOptions>();
  addCommonOptions(sub, o->c);
  auto* layers =
      sub.add_option("--layers", o->layers, "Number of skin layers to remove")->check(CLI::NonNegativeNumber);
  auto* all = sub.add_flag("--all", o->all, "Peel until nothing is left (reports the core)");
  auto* distance = sub.add_option("--distance", o->distance,
                                  "Remove every voxel within this distance of the outside (model units; round, the "
                                  "same in every orientation)")
                       ->check(CLI::NonNegativeNumber);
  layers->excludes(all);
  distance->excludes(layers)->excludes(all);
  sub.add_option("-o,--output", o->out,
                 "Write the remaining voxels: any output convert writes (voxels .vxm .binvox, a volume .nrrd .vti .vdb "
                 ".vox, the surface .stl .ply .obj .3mf)");
  sub.add_option("--depth", o->depth_out,
                 "Write every voxel's skin layer (1 = the outer skin, the core last; 0 = empty or deeper than the "
                 "layers peeled) as a volume: .nrrd, .vti or .vdb");
  sub.callback([o, layers, all, distance, &ctx] {
    if (layers->count() == 0 && all->count() == 0 && distance->count() == 0) {
      std::fprintf(stderr, "voxmod peel: give --layers N, --all or --distance D\n");
      ctx.exit_code = kExitUsage;
      return;
    }
    ctx.exit_code = runPeel(*o);
  });
}

void addXrayCommand(CLI::App& sub, CommandContext& ctx) {
  auto o = std::make_shared<XrayOptions>();
  addCommonOptions(sub, o->c, "--fill-mode");  // --mode is the X-ray mode here (docs/conventions.md, "Command line")
  sub.add_option("--axis", o->params.axis, "Ray direction: x, y or z")->required()->transform(axisWords());
  sub.add_option("--mode", o->params.mode, "Per ray: min, max or total thickness")
      ->required()
      ->transform(xrayModeWords());
  sub.add_option("-o,--output", o->out, "Output PNG (colour scale and legend)")->required();
  sub.add_option("--csv", o->csv, "Also write the per-ray thickness as CSV");
  sub.add_option("--volume", o->volume,
                 "Also write the per-ray thickness (model units) as a one-voxel-thick volume in the model's place: "
                 ".nrrd, .vti or .vdb");
  sub.add_option("--scale", o->scale, "Pixels per ray (default 1)")->check(CLI::Range(1, 64));
  sub.callback([o, &ctx] { ctx.exit_code = runXray(*o); });
}

void addMassCommand(CLI::App& sub, CommandContext& ctx) {
  auto o = std::make_shared<MassOptions>();
  addCommonOptions(sub, o->c);
  auto* density = sub.add_option("--density", o->density, "Density in kg/m^3, for the mass in kg (needs --units)")
                      ->check(CLI::PositiveNumber);
  sub.add_option("--material", o->material, "A common material's density instead: " + materialNames())
      ->excludes(density);
  sub.callback([o, &ctx] { ctx.exit_code = runMass(*o); });
}

}  // namespace vox::cli
