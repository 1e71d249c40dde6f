#include "app/export_volume.h"

#include <memory>
#include <utility>

#include "app/exports.h"
#include "app/messages.h"
#include "app/skin.h"
#include "app/thickness.h"
#include "app/update.h"
#include "vox/analysis/distance.h"
#include "vox/analysis/scalar_fields.h"
#include "vox/analysis/thickness_map.h"
#include "vox/core/text.h"
#include "vox/io/volume_export.h"

namespace vox::app {
namespace {

using ExportResult = Result<std::filesystem::path>;

// The extension's format when it holds what is asked for (a field, e.g. "the thickness", or the voxels when
// `field` is null); an error dialog otherwise.
std::optional<io::VolumeFormat> formatFor(AppState& state, const std::filesystem::path& path, const char* field) {
  const auto format = io::volumeFormatOf(path);
  if (!format || (field && !io::holdsFields(*format))) {
    reportError(state,
                std::string(field ? field : "volumes") + (field ? " is exported as " : " are exported as ") +
                    io::volumeExtensionList(field != nullptr) + "; choose one of those extensions",
                path);
    return std::nullopt;
  }
  return format;
}

// `note` follows "Wrote FILE" in the status line when it is done.
void start(AppState& state, const std::filesystem::path& path, Job<std::filesystem::path>::Work work,
           std::string note = {}) {
  state.volume_export_note = std::move(note);
  // A file written before a late Cancel is said to be written.
  state.volume_export_job.start("Writing " + path.filename().string(), std::move(work), true);
}

// One scalar field under `name`, as voxmod peel --depth and voxmod xray --volume write it (cli/output.h,
// encodeFieldFile): the field alone, in every format.
ExportResult writeField(const std::string& name, const ScalarField& field, const std::filesystem::path& path,
                        const ProgressFn& progress) {
  if (Status s = io::saveVolume(io::oneField(name, field), path, progress); !s) return s.error();
  return path;
}

}  // namespace

bool startVolumeExport(AppState& state, const std::filesystem::path& path) {
  if (state.model.empty()) {
    reportError(state, "there is no model to export", path);
    return false;
  }
  if (!formatFor(state, path, nullptr)) return false;
  // What the view shows: with the Section panel's cut-away on, the half it keeps (as the surface export).
  const bool cut = exportsCutAway(state);
  VoxelGrid grid = cutAwayModel(state);
  if (cut && grid.filledCount() == 0) {
    reportError(state, "the cut-away keeps no voxels: nothing to export", path);
    return false;
  }
  start(
      state, path,
      [grid = std::move(grid), path](const ProgressFn& progress) -> ExportResult {
        if (Status s = io::saveVolume(io::voxelsOnly(grid), path, progress); !s) return s.error();
        return path;
      },
      cut ? kCutAwayNote : "");
  return true;
}

bool startThicknessExport(AppState& state, const std::filesystem::path& path) {
  const ThicknessResult* current = currentThickness(state);
  if (!current || state.model.empty()) {
    reportError(state, "there is no thickness to export (open the Thickness panel and let it finish)", path);
    return false;
  }
  const auto format = formatFor(state, path, "the thickness");
  if (!format) return false;
  // The result is shared with the panel, not copied: it is immutable once computed.
  const auto& shared = *state.thickness.get(state.model_version);
  start(state, path, [grid = state.model, result = shared, path, format](const ProgressFn& progress) -> ExportResult {
    const ScalarField thickness = thicknessField(result->thickness);
    io::VolumeContent content = io::oneField("thickness", thickness);
    ScalarField distance;
    if (io::holdsSeveralVolumes(*format)) {  // the voxels and the distance beside the thickness
      auto d = computeDistance(grid);
      if (!d) return d.error();
      distance = distanceField(*d);
      content = io::VolumeContent{&grid, {{"thickness", &thickness}, {"distance", &distance}}};
    }
    if (Status s = io::saveVolume(content, path, progress); !s) return s.error();
    return path;
  });
  return true;
}

bool startDepthExport(AppState& state, const std::filesystem::path& path) {
  const DepthMap* current = currentDepthMap(state);
  if (!current || !state.doc.model) {
    reportError(state, "there is no skin depth to export (open the Skin panel and let it compute the skin layers)",
                path);
    return false;
  }
  if (!formatFor(state, path, "the skin depth")) return false;
  const ModelSnapshot& m = *state.doc.model;
  // The layers of the base, which the Skin panel counts (peeled ones included); the base carries the units now set.
  std::string note;
  if (m.peeled > 0) {
    note = " (all " + std::to_string(current->layers()) + " skin layers, the " + std::to_string(m.peeled) +
           (m.peeled == 1 ? " peeled one included)" : " peeled ones included)");
  }
  const auto& shared = *state.depth.get(m.base_id);  // immutable once computed: shared, not copied
  start(
      state, path,
      [depth = shared, base = m.base, path](const ProgressFn& progress) -> ExportResult {
        return writeField("depth", depthField(*depth, base), path, progress);
      },
      std::move(note));
  return true;
}

bool startXrayVolumeExport(AppState& state, const std::filesystem::path& path) {
  const XrayResult* x = currentXray(state);
  if (!x || state.model.empty()) {
    reportError(state, "there is no X-ray to export (open the X-ray panel and let it finish)", path);
    return false;
  }
  if (!formatFor(state, path, "the X-ray")) return false;
  const XrayKey key{state.model_version, state.xray.params.axis, state.xray.params.mode};
  const auto& shared = *state.xray_result.get(key);
  start(state, path, [xray = shared, grid = state.model, path](const ProgressFn& progress) -> ExportResult {
    return writeField("xray", xrayField(*xray, grid), path, progress);
  });
  return true;
}

void pollVolumeExport(AppState& state) {
  auto done = state.volume_export_job.take();
  if (!done) return;
  if (done->ok()) {
    state.status_message =
        "Wrote " + std::filesystem::absolute(done->value()).lexically_normal().string() + state.volume_export_note;
    state.status_since = nowSeconds();
  } else if (done->error().code != ErrorCode::kCancelled) {
    reportError(state, done->error().message);
  }
}

bool volumeExportRunning(const AppState& state) { return state.volume_export_job.active(); }

void cancelVolumeExport(AppState& state) { state.volume_export_job.cancel(); }

}  // namespace vox::app
