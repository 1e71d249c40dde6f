#include "app/export_report.h"
#include "app/browser_purposes.h"

#include <system_error>

#include "app/document.h"
#include "app/export_volume.h"
#include "app/exports.h"
#include "app/messages.h"
#include "app/parts.h"
#include "app/view_export.h"
#include "vox/io/mesh_file.h"

namespace vox::app {

std::vector<std::string> browserExtensions(BrowserPurpose purpose) {
  switch (purpose) {
    case BrowserPurpose::kOpen: {
      std::vector<std::string> all = io::meshFileExtensions();
      all.insert(all.end(), {".vxp", ".vxm", ".binvox"});
      return all;
    }
    case BrowserPurpose::kAddPart: {
      std::vector<std::string> all = io::meshFileExtensions();
      all.insert(all.end(), {".vxm", ".binvox"});
      return all;
    }
    case BrowserPurpose::kSaveModel:
      return {".vxp", ".vxm", ".binvox"};
    case BrowserPurpose::kExportBinvox:
      return {".binvox"};
    case BrowserPurpose::kExportSurface:
    case BrowserPurpose::kExportSmoothSurface:
      return {".stl", ".ply", ".obj", ".3mf"};
    case BrowserPurpose::kExportViewPng:
    case BrowserPurpose::kExportSectionPng:
    case BrowserPurpose::kExportXrayPng:
      return {".png"};
    case BrowserPurpose::kExportXrayCsv:
      return {".csv"};
    case BrowserPurpose::kExportVolume:
      return {".vti", ".vdb", ".nrrd", ".vox"};
    case BrowserPurpose::kExportThickness:
    case BrowserPurpose::kExportDepth:
    case BrowserPurpose::kExportXrayVolume:
      return {".vti", ".vdb", ".nrrd"};
    case BrowserPurpose::kExportReport:
      return {".html"};
    case BrowserPurpose::kSaveParts:
      return {};  // a folder: the browser lists folders only
  }
  return {};
}

const char* browserTitle(BrowserPurpose purpose) {
  switch (purpose) {
    case BrowserPurpose::kOpen:
      return "Open a mesh or voxel file";
    case BrowserPurpose::kSaveModel:
      return "Save the model as";
    case BrowserPurpose::kExportBinvox:
      return "Export binvox";
    case BrowserPurpose::kExportSurface:
      return "Export the surface as a mesh (.stl, .ply, .obj, .3mf)";
    case BrowserPurpose::kExportSmoothSurface:
      return "Export a smooth surface, within half a voxel (.stl, .ply, .obj, .3mf)";
    case BrowserPurpose::kExportViewPng:
      return "Export the 3D view as PNG";
    case BrowserPurpose::kExportSectionPng:
      return "Export the section image as PNG";
    case BrowserPurpose::kExportXrayPng:
      return "Export the X-ray image as PNG";
    case BrowserPurpose::kExportXrayCsv:
      return "Export the X-ray thickness as CSV";
    case BrowserPurpose::kExportVolume:
      return "Export the model as a volume: .vti (ParaView), .vdb (Blender, Houdini), .nrrd (3D Slicer), .vox "
             "(MagicaVoxel)";
    case BrowserPurpose::kExportThickness:
      return "Export the thickness as a volume: .vti or .vdb (voxels, thickness, distance), .nrrd (thickness)";
    case BrowserPurpose::kExportDepth:
      return "Export the skin depth as a volume (.vti, .vdb, .nrrd): each voxel's skin layer, 1 the outer skin, the "
             "core last";
    case BrowserPurpose::kExportXrayVolume:
      return "Export the X-ray as a volume (.vti, .vdb, .nrrd): each ray's thickness in model units, one voxel thick";
    case BrowserPurpose::kExportReport:
      return "Export a report: one HTML page with the model, its walls, hot spots and printing, pictures included";
    case BrowserPurpose::kAddPart:
      return "Add a part from a mesh or voxel file (on the scene's lattice)";
    case BrowserPurpose::kSaveParts:
      return "Save each part as a .vxm file into a folder (type its name; all files are written or none)";
  }
  return "";
}

void openBrowser(AppState& state, BrowserPurpose purpose) {
  FileBrowser& b = state.browser;
  b.open_requested = true;
  b.accepted = false;
  b.then = nullptr;  // a continuation belongs to the browsing that set it (saveThen), never to a later one
  b.purpose = purpose;
  b.error.clear();
  std::error_code ec;
  std::filesystem::path dir = state.settings.last_directory;
  if (dir.empty() || !std::filesystem::is_directory(dir, ec)) dir = std::filesystem::current_path(ec);
  b.directory = dir;
  const std::string stem = state.doc.path.empty() ? std::string("model") : state.doc.path.stem().string();
  switch (purpose) {
    case BrowserPurpose::kOpen:
    case BrowserPurpose::kAddPart:
      b.file_name.clear();
      break;
    case BrowserPurpose::kSaveModel:  // a scene of parts keeps its parts only in a project
      b.file_name = stem + (state.doc.model && state.doc.model->parts ? ".vxp" : ".vxm");
      break;
    case BrowserPurpose::kExportBinvox:
      b.file_name = stem + ".binvox";
      break;
    case BrowserPurpose::kExportSurface:
      b.file_name = stem + "_surface.stl";
      break;
    case BrowserPurpose::kExportSmoothSurface:
      b.file_name = stem + "_smooth.stl";
      break;
    case BrowserPurpose::kExportViewPng:
      b.file_name = stem + "_view.png";
      break;
    case BrowserPurpose::kExportSectionPng:
      b.file_name = stem + "_section_" + axisName(state.section.axis) + std::to_string(state.section.index) + ".png";
      break;
    case BrowserPurpose::kExportXrayPng:
      b.file_name =
          stem + "_xray_" + axisName(state.xray.params.axis) + "_" + xrayModeName(state.xray.params.mode) + ".png";
      break;
    case BrowserPurpose::kExportXrayCsv:
      b.file_name =
          stem + "_xray_" + axisName(state.xray.params.axis) + "_" + xrayModeName(state.xray.params.mode) + ".csv";
      break;
    case BrowserPurpose::kExportVolume:
      b.file_name = stem + ".vti";
      break;
    case BrowserPurpose::kExportReport:
      b.file_name = stem + "_report.html";
      break;
    case BrowserPurpose::kExportThickness:
      b.file_name = stem + "_thickness.vti";
      break;
    case BrowserPurpose::kExportDepth:
      b.file_name = stem + "_depth.vti";
      break;
    case BrowserPurpose::kExportXrayVolume:
      b.file_name =
          stem + "_xray_" + axisName(state.xray.params.axis) + "_" + xrayModeName(state.xray.params.mode) + ".vti";
      break;
    case BrowserPurpose::kSaveParts:
      b.file_name = stem + "_parts";
      break;
  }
}

bool acceptBrowserPath(AppState& state, BrowserPurpose purpose, const std::filesystem::path& path) {
  if (path.filename().empty()) {
    reportError(state, "no file name given", path);
    return false;
  }
  bool ok = false;
  switch (purpose) {
    case BrowserPurpose::kOpen:
      // Refuse a missing file here, where the browser can stay open, rather than after the unsaved prompt.
      if (std::error_code ec; !std::filesystem::is_regular_file(path, ec)) {
        reportError(state, path.string() + ": no such file");
        return false;
      }
      requestOpen(state, path);
      ok = true;
      break;
    case BrowserPurpose::kAddPart:
      if (std::error_code ec; !std::filesystem::is_regular_file(path, ec)) {
        reportError(state, path.string() + ": no such file");
        return false;
      }
      startAddPart(state, path);
      ok = true;
      break;
    case BrowserPurpose::kSaveModel:
      ok = saveModel(state, path);
      break;
    case BrowserPurpose::kExportBinvox:
      ok = exportBinvox(state, path);
      break;
    case BrowserPurpose::kExportSurface:
      ok = exportSurface(state, path, false);
      break;
    case BrowserPurpose::kExportSmoothSurface:
      ok = exportSurface(state, path, true);
      break;
    case BrowserPurpose::kExportViewPng:
      ok = exportViewPng(state, path);
      break;
    case BrowserPurpose::kExportSectionPng:
      ok = exportSectionPng(state, path);
      break;
    case BrowserPurpose::kExportXrayPng:
      ok = exportXrayPng(state, path);
      break;
    case BrowserPurpose::kExportXrayCsv:
      ok = exportXrayCsv(state, path);
      break;
    case BrowserPurpose::kExportVolume:  // written in the background: it says where it wrote when done
      ok = startVolumeExport(state, path);
      break;
    case BrowserPurpose::kExportThickness:
      ok = startThicknessExport(state, path);
      break;
    case BrowserPurpose::kExportDepth:
      ok = startDepthExport(state, path);
      break;
    case BrowserPurpose::kExportXrayVolume:
      ok = startXrayVolumeExport(state, path);
      break;
    case BrowserPurpose::kExportReport:
      ok = startReportExport(state, path);
      break;
    case BrowserPurpose::kSaveParts:
      if (Status s = saveParts(state, path); !s) {
        reportError(state, s.error().message, path);
      } else {
        ok = true;
      }
      break;
  }
  if (ok) {
    state.settings.last_directory = std::filesystem::absolute(path).parent_path().string();
    // Say where a file went (the name typed may have been relative, or the directory not the one in mind).
    const bool in_background = purpose == BrowserPurpose::kExportVolume ||
                               purpose == BrowserPurpose::kExportThickness || purpose == BrowserPurpose::kExportDepth ||
                               purpose == BrowserPurpose::kExportXrayVolume || purpose == BrowserPurpose::kExportReport;
    if (purpose != BrowserPurpose::kOpen && purpose != BrowserPurpose::kAddPart && !in_background &&
        purpose != BrowserPurpose::kSaveParts) {  // saveParts says how many files it wrote
      state.status_message = "Wrote " + std::filesystem::absolute(path).lexically_normal().string();
      const bool surface = purpose == BrowserPurpose::kExportSurface || purpose == BrowserPurpose::kExportSmoothSurface;
      if (surface && exportsCutAway(state)) state.status_message += kCutAwayNote;
      state.status_since = nowSeconds();
    }
    if (auto then = std::move(state.browser.then)) {
      state.browser.then = nullptr;
      then(state);
    }
  }
  return ok;
}

}  // namespace vox::app
