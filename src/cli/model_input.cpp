#include "cli/model_input.h"

#include <unistd.h>

#include <cstdio>
#include <exception>
#include <memory>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "vox/core/units.h"
#include "vox/io/voxel_file.h"

namespace vox::cli {

const char* const kFileHelp =
    "Voxel file (.vxm, .binvox), or a mesh or CAD file voxelized with --res: .stl .obj .ply .3mf .gltf .glb .off "
    ".step .stp .iges .igs";

void addCommonOptions(CLI::App& sub, CommonOptions& c, const std::string& mode_names) {
  sub.add_option("FILE", c.file, kFileHelp)->required();
  sub.add_flag("--json", c.json, "Print one JSON object on stdout");
  addMeshOptions(sub, c.mesh, mode_names);
}

namespace {

// "512" (MiB), "64K", "512M", "2G" (binary units); nullopt for anything else, zero or past 2^60 bytes.
std::optional<uint64_t> parseMemorySize(const std::string& text) {
  size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  const std::string unit = text.substr(used);
  double scale = 0;
  if (unit.empty() || unit == "M" || unit == "m" || unit == "MiB") scale = double(1 << 20);
  if (unit == "K" || unit == "k" || unit == "KiB") scale = double(1 << 10);
  if (unit == "G" || unit == "g" || unit == "GiB") scale = double(1 << 30);
  const double bytes = v * scale;
  if (!(bytes >= 1.0) || bytes > double(uint64_t(1) << 60)) return std::nullopt;
  return uint64_t(bytes);
}

}  // namespace

void addMeshOptions(CLI::App& sub, MeshOptions& options, const std::string& mode_names) {
  auto* res = sub.add_option("--res", options.params.resolution,
                             "For a mesh FILE: voxels along the longest axis (1-16384, default 200)");
  auto* size = sub.add_option("--voxel-size", options.params.voxel_size,
                              "For a mesh FILE: voxel size in model units (instead of --res)");
  res->excludes(size);
  auto* mode =
      sub.add_option(mode_names, options.mode_text, "For a mesh FILE: " + fillModeNames("|") + " (default auto)")
          ->check(CLI::IsMember(fillModeNameList()));
  options.mesh_only = {res, size, mode};
  sub.add_option("--units", options.units,
                 "Length units of the file's coordinates: mm, cm, m, in (STL, OBJ, PLY and OFF carry none; "
                 "default: the file's own, or 'model'). CAD files are converted from it to millimetres")
      ->check(CLI::IsMember(std::vector<std::string>(kLengthUnits.begin(), kLengthUnits.end())));
  sub.add_option("--threads", options.params.threads, "Worker threads (default: all cores)")
      ->check(CLI::Range(0, 1024));
  sub.add_option_function<std::string>(
         "--memory-limit",
         [&options](const std::string& text) {
           const std::optional<uint64_t> bytes = parseMemorySize(text);
           if (!bytes) throw CLI::ValidationError("--memory-limit", "'" + text + "' is not a size: 512, 512M, 2G");
           options.memory_limit_bytes = *bytes;
         },
         "Memory for the grid (SIZE: MiB, or with K, M, G; default 80% of physical memory): voxelize streams a larger "
         "grid to a .vxm file in Z slabs, info/section/xray/mass/convert read a larger .vxm file in windows, the "
         "rest refuse it")
      ->type_name("SIZE");
}

ProgressFn terminalProgress(const std::string& label) {
  if (!isatty(STDERR_FILENO)) return {};
  auto last = std::make_shared<int>(-1);
  return [label, last](double f) {
    const int pct = int(f * 100.0);
    if (pct != *last) {
      *last = pct;
      std::fprintf(stderr, "\r%s %3d%%%s", label.c_str(), pct, pct >= 100 ? "\n" : "");
      std::fflush(stderr);
    }
    return true;
  };
}

Result<VoxelizeParams> voxelizeParams(const MeshOptions& options) {
  VoxelizeParams params = options.params;
  if (!options.units.empty()) params.units = options.units;
  auto mode = parseFillMode(options.mode_text);
  if (!mode) return makeError(ErrorCode::kInvalidArgument, "unknown --mode '" + options.mode_text + "'");
  params.mode = *mode;
  if (options.memory_limit_bytes > 0) params.memory_limit_bytes = options.memory_limit_bytes;
  return params;
}

io::MeshFileOptions meshFileOptions(const MeshOptions& options) {
  io::MeshFileOptions o;
  o.resolution = options.params.resolution;
  o.voxel_size = options.params.voxel_size;
  o.units = options.units;
  if (options.memory_limit_bytes > 0) o.memory_limit_bytes = options.memory_limit_bytes;
  o.progress = terminalProgress("reading");  // only CAD files report progress: reading, healing, tessellating
  return o;
}

namespace {

// The reader's and the voxelizer's warnings and notes, through `out` as they arise.
workflow::InputMessages messagesTo(Output& out) {
  return [&out](workflow::InputMessage kind, const std::string& text) {
    if (kind == workflow::InputMessage::kWarning) {
      out.warn(text);
    } else {
      out.note(text);
    }
  };
}

}  // namespace

Result<io::MeshFileLoad> loadMesh(const std::filesystem::path& file, const MeshOptions& options, Output& out) {
  return workflow::readMeshFile(file, meshFileOptions(options), messagesTo(out));
}

void warnMeshOnlyOptions(const std::filesystem::path& file, const MeshOptions& options, Output& out) {
  for (const CLI::Option* o : options.mesh_only) {
    if (o->count() > 0) {
      out.warn(o->get_name() + " is ignored: " + file.filename().string() +
               " is a voxel file, already voxelized (the option applies to a mesh FILE)");
    }
  }
}

Result<LoadedModel> loadModel(const std::filesystem::path& file, const MeshOptions& options, Output& out,
                              bool keep_mesh) {
  if (io::isVoxelFile(file)) warnMeshOnlyOptions(file, options, out);
  workflow::ModelFileOptions o;
  o.reading = meshFileOptions(options);
  auto params = voxelizeParams(options);
  if (!params) return params.error();
  o.params = *params;
  o.units = options.units;
  o.voxelizing = terminalProgress("voxelizing");
  o.keep_mesh = keep_mesh;
  o.messages = messagesTo(out);
  auto m = workflow::readModelFile(file, o);
  if (!m) return m.error();
  if (m->from_mesh) {
    out.say("voxelized " + file.filename().string() + " with mode " + m->mode_used + " (" + m->mode_reason + ")");
  }
  return m;
}

}  // namespace vox::cli
