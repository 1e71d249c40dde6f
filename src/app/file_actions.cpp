// The File entries of the action table (actions.cpp): each opens the file browser for itself (without values) or uses
// the path it is given, the browser's or a script's (file_browsing.h).
#include <algorithm>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "app/action_functions.h"
#include "app/export_report.h"
#include "app/file_browsing.h"
#include "app/operations.h"
#include "app/view_export.h"
#include "vox/core/text.h"

namespace vox::app::actions {

void open(AppState& s) {
  openBrowser(s, {ActionId::kOpen, "Open a mesh or voxel file", openableExtensions(true), "", false});
}
Status openPath(AppState& s, const ActionArgs& a) {
  usePath(s, a.rest, PathSays::kNothing, [](AppState& st, const std::filesystem::path& path) {
    if (!isExistingFile(st, path)) return false;  // here, not after the unsaved-changes prompt
    requestOpen(st, path);
    return true;
  });
  return Ok{};
}
void save(AppState& s) { saveOrAsk(s); }
void saveAs(AppState& s) { openBrowser(s, saveModelBrowsing(s)); }
Status savePath(AppState& s, const ActionArgs& a) {
  usePath(s, a.rest, PathSays::kWrote, saveModel);
  return Ok{};
}
void exportBinvox(AppState& s) {
  openBrowser(s, {ActionId::kExportBinvox, "Export binvox", {".binvox"}, documentStem(s) + ".binvox"});
}
Status exportBinvoxPath(AppState& s, const ActionArgs& a) {
  usePath(s, a.rest, PathSays::kWrote, app::exportBinvox);
  return Ok{};
}

namespace {

const std::vector<std::string> kMeshExtensions = {".stl", ".ply", ".obj", ".3mf"};
const std::vector<std::string> kFieldExtensions = {".vti", ".vdb", ".nrrd"};

// The surface, blocky or smooth: "Wrote ..." says too when the cut-away's half was left out.
void useSurfacePath(AppState& s, const ActionArgs& a, bool smooth) {
  usePath(s, a.rest, PathSays::kWrote,
          [smooth](AppState& st, const std::filesystem::path& path) { return app::exportSurface(st, path, smooth); });
  if (s.browser.went_through && exportsCutAway(s)) s.status_message += kCutAwayNote;
}

// "_xray_z_max": the X-ray's axis and mode, for the names proposed.
std::string xraySuffix(const AppState& s) {
  return "_xray_" + std::string(axisName(s.xray.params.axis)) + "_" + xrayModeName(s.xray.params.mode);
}

}  // namespace

void exportSurface(AppState& s) {
  openBrowser(s, {ActionId::kExportSurface, "Export the surface as a mesh (.stl, .ply, .obj, .3mf)", kMeshExtensions,
                  documentStem(s) + "_surface.stl"});
}
Status exportSurfacePath(AppState& s, const ActionArgs& a) {
  useSurfacePath(s, a, false);
  return Ok{};
}
void exportSmoothSurface(AppState& s) {
  openBrowser(s,
              {ActionId::kExportSmoothSurface, "Export a smooth surface, within half a voxel (.stl, .ply, .obj, .3mf)",
               kMeshExtensions, documentStem(s) + "_smooth.stl"});
}
Status exportSmoothSurfacePath(AppState& s, const ActionArgs& a) {
  useSurfacePath(s, a, true);
  return Ok{};
}
void exportView(AppState& s) {
  openBrowser(s, {ActionId::kExportViewPng, "Export the 3D view as PNG", {".png"}, documentStem(s) + "_view.png"});
}
Status exportViewPath(AppState& s, const ActionArgs& a) {
  usePath(s, a.rest, PathSays::kWrote, exportViewPng);
  return Ok{};
}
void exportSection(AppState& s) {
  openBrowser(s, {ActionId::kExportSectionPng,
                  "Export the section image as PNG",
                  {".png"},
                  documentStem(s) + "_section_" + axisName(s.section.axis) + std::to_string(s.section.index) + ".png"});
}
Status exportSectionPath(AppState& s, const ActionArgs& a) {
  usePath(s, a.rest, PathSays::kWrote, exportSectionPng);
  return Ok{};
}
void exportXray(AppState& s) {
  openBrowser(
      s,
      {ActionId::kExportXrayPng, "Export the X-ray image as PNG", {".png"}, documentStem(s) + xraySuffix(s) + ".png"});
}
Status exportXrayPath(AppState& s, const ActionArgs& a) {
  usePath(s, a.rest, PathSays::kWrote, exportXrayPng);
  return Ok{};
}
void exportCsv(AppState& s) {
  openBrowser(s, {ActionId::kExportXrayCsv,
                  "Export the X-ray thickness as CSV",
                  {".csv"},
                  documentStem(s) + xraySuffix(s) + ".csv"});
}
Status exportCsvPath(AppState& s, const ActionArgs& a) {
  usePath(s, a.rest, PathSays::kWrote, exportXrayCsv);
  return Ok{};
}
// The exports below are written in the background: each says where it wrote when done.
void exportReport(AppState& s) {
  openBrowser(s, {ActionId::kExportReport,
                  "Export a report: one HTML page with the model, its walls, hot spots and printing, pictures included",
                  {".html"},
                  documentStem(s) + "_report.html"});
}
Status exportReportPath(AppState& s, const ActionArgs& a) {
  usePath(s, a.rest, PathSays::kNothing, startReportExport);
  return Ok{};
}
void exportVolume(AppState& s) {
  openBrowser(s, {ActionId::kExportVolume,
                  "Export the model as a volume: .vti (ParaView), .vdb (Blender, Houdini), .nrrd (3D Slicer), .vox "
                  "(MagicaVoxel)",
                  {".vti", ".vdb", ".nrrd", ".vox"},
                  documentStem(s) + ".vti"});
}
Status exportVolumePath(AppState& s, const ActionArgs& a) {
  usePath(s, a.rest, PathSays::kNothing, startVolumeExport);
  return Ok{};
}
void exportThickness(AppState& s) {
  openBrowser(s, {ActionId::kExportThickness,
                  "Export the thickness as a volume: .vti or .vdb (voxels, thickness, distance), .nrrd (thickness)",
                  kFieldExtensions, documentStem(s) + "_thickness.vti"});
}
Status exportThicknessPath(AppState& s, const ActionArgs& a) {
  usePath(s, a.rest, PathSays::kNothing, startThicknessExport);
  return Ok{};
}
void exportDepth(AppState& s) {
  openBrowser(s, {ActionId::kExportDepth,
                  "Export the skin depth as a volume (.vti, .vdb, .nrrd): each voxel's skin layer, 1 the outer skin, "
                  "the core last",
                  kFieldExtensions, documentStem(s) + "_depth.vti"});
}
Status exportDepthPath(AppState& s, const ActionArgs& a) {
  usePath(s, a.rest, PathSays::kNothing, startDepthExport);
  return Ok{};
}
void exportXrayVolume(AppState& s) {
  openBrowser(s, {ActionId::kExportXrayVolume,
                  "Export the X-ray as a volume (.vti, .vdb, .nrrd): each ray's thickness in model units, one voxel "
                  "thick",
                  kFieldExtensions, documentStem(s) + xraySuffix(s) + ".vti"});
}
Status exportXrayVolumePath(AppState& s, const ActionArgs& a) {
  usePath(s, a.rest, PathSays::kNothing, startXrayVolumeExport);
  return Ok{};
}

Status exportSize(AppState& s, const ActionArgs& a) {  // W H: the 3D view's export size (0 0: as shown)
  int32_t w = 0, h = 0;
  if (!parseNumber(a.words[0], w) || !parseNumber(a.words[1], h) || w < 0 || h < 0 || w > 8192 || h > 8192) {
    return badValues("export-size takes a width and a height in pixels, 0 to 8192");
  }
  s.export_width = w;
  s.export_height = h;
  return Ok{};
}

}  // namespace vox::app::actions
