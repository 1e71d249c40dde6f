// voxmod batch: one input to one output, exactly as `voxmod voxelize` (voxel formats) or `voxmod convert` (volumes,
// surfaces) would write it, so a batch's outputs are byte for byte those of the one-file commands.
#include <new>

#include "cli/batch.h"
#include "cli/write_grid.h"
#include "vox/analysis/surface_mesh.h"
#include "vox/io/mesh_export.h"
#include "vox/io/volume_export.h"
#include "vox/io/voxel_file.h"

namespace vox::cli {

namespace fs = std::filesystem;

namespace {

// The input as a grid: a voxel file read, or a mesh or CAD file read and voxelized with `threads` threads. Warnings
// are collected (a batch prints nothing per file).
Result<VoxelGrid> readGrid(const BatchItem& item, const BatchSettings& settings, int threads,
                           std::vector<std::string>& warnings) {
  workflow::ModelFileOptions o;
  o.reading = meshFileOptions(settings.mesh);
  o.reading.progress = {};  // several files at once: no per-file progress lines
  auto params = voxelizeParams(settings.mesh);
  if (!params) return params.error();
  o.params = *params;
  o.params.threads = threads;
  o.units = settings.mesh.units;
  o.name = item.input;
  o.messages = [&warnings](workflow::InputMessage kind, const std::string& text) {
    if (kind == workflow::InputMessage::kWarning) warnings.push_back(text);
  };
  auto model = workflow::readModelFile(item.input, o);
  if (!model) return model.error();
  return std::move(model->grid);
}

// The grid in the format of the item's output (atomic; the directories below OUTDIR made first).
Status writeGrid(const BatchItem& item, const VoxelGrid& grid) {
  std::error_code ec;
  fs::create_directories(item.output.parent_path(), ec);
  if (ec) return makeError(ErrorCode::kIo, item.output.parent_path().string() + ": cannot create: " + ec.message());
  return writeGridAs(grid, item.output, item.input);
}

Json baseLine(const BatchItem& item, const char* status) {
  Json line;
  line["input"] = item.input;
  line["status"] = status;
  line["output"] = nullptr;
  line["dims"] = nullptr;
  line["filled"] = nullptr;
  line["warnings"] = Json::array();
  line["seconds"] = 0.0;
  line["error"] = nullptr;
  return line;
}

}  // namespace

Json errorLine(const BatchItem& item, const std::string& error, double seconds) {
  Json line = baseLine(item, "error");
  line["seconds"] = seconds;
  line["error"] = error;
  return line;
}

BatchOutcome convertItem(const BatchItem& item, const BatchSettings& settings, int threads) {
  const double t0 = nowSeconds();
  BatchOutcome outcome;
  outcome.index = item.index;
  auto fail = [&](const std::string& message) {
    outcome.line = errorLine(item, message, nowSeconds() - t0);
    outcome.stop_batch = isDiskFull(message);
    return outcome;
  };
  if (!item.problem.empty()) return fail(item.problem);
  const auto stamp = fileStamp(item.input);  // before reading: a file changed while read is not taken as current
  std::vector<std::string> warnings;
  try {
    auto grid = readGrid(item, settings, threads, warnings);
    if (!grid) return fail(grid.error().message);
    if (Status s = writeGrid(item, *grid); !s.ok()) return fail(s.error().message);
    outcome.line = baseLine(item, "ok");
    outcome.line["output"] = item.output.string();
    outcome.line["dims"] = {grid->nx(), grid->ny(), grid->nz()};
    outcome.line["filled"] = grid->filledCount();
  } catch (const std::bad_alloc&) {
    return fail(item.input + ": not enough memory");
  }
  outcome.line["warnings"] = warnings;
  if (stamp) {
    auto entry = journalEntry(item, settings, *stamp, outcome.line);
    if (!entry) return fail(entry.error().message);
    outcome.journal = std::move(entry).value();
  }
  outcome.line["seconds"] = nowSeconds() - t0;
  return outcome;
}

}  // namespace vox::cli
