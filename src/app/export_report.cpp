#include "app/export_report.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "app/messages.h"
#include "app/parts.h"      // currentClearance
#include "app/thickness.h"  // rayMesh
#include "app/view_export.h"
#include "vox/io/file_util.h"
#include "vox/io/image_io.h"
#include "vox/workflow/report.h"

namespace vox::app {

bool startReportExport(AppState& state, const std::filesystem::path& path) {
  if (state.model.empty()) {
    reportError(state, "there is no model to report on", path);
    return false;
  }
  if (state.volume_export_job.active()) {
    reportError(state, "an export is being written: wait for it, or cancel it (Esc), then export the report", path);
    return false;
  }
  if (path.extension() != ".html") {
    reportError(state, "the report is an HTML page: give a name ending in .html", path);
    return false;
  }
  std::vector<workflow::ReportPicture> pictures;
  if (auto view = renderViewImage(state)) {
    if (auto png = io::encodePng(*view, "view.png")) pictures.push_back({"The 3D view", std::move(png).value()});
  }
  workflow::ReportOptions options;
  options.name = state.doc.path.empty() ? std::string("model") : state.doc.path.filename().string();
  options.min_wall = state.thickness_ui.min_wall > 0.0 ? state.thickness_ui.min_wall : 0.0;
  if (state.mass_ui.density > 0.0) {
    options.density_kg_m3 = state.mass_ui.density;
    options.material = state.mass_ui.material;
  }
  // an assembly: its parts and interference, with the panel's contact tolerance and the clearance it found
  std::shared_ptr<const Assembly> parts = state.doc.model ? state.doc.model->parts : nullptr;
  options.contact = state.parts_ui.contact;
  if (const Clearance* c = currentClearance(state)) {
    options.clearance =
        workflow::ReportOptions::PartClearance{state.parts_ui.clearance_a, state.parts_ui.clearance_b, *c};
  }
  state.volume_export_note.clear();
  state.volume_export_job.start(
      "Writing " + path.filename().string(),
      [grid = state.model, mesh = rayMesh(state), parts, options, pictures = std::move(pictures),
       path](const ProgressFn& progress) -> Result<std::filesystem::path> {
        workflow::ReportOptions o = options;
        if (mesh) o.mesh = &mesh->mesh;
        o.parts = parts.get();
        auto html = workflow::buildReport(grid, o, pictures, nullptr, progress);
        if (!html) return html.error();
        if (Status s = io::writeFilesAtomic({{path, std::vector<uint8_t>(html->begin(), html->end())}}); !s) {
          return s.error();
        }
        return path;
      },
      true);
  return true;
}

}  // namespace vox::app
