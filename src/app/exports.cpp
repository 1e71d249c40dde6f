#include "app/exports.h"

#include <algorithm>

#include "app/messages.h"
#include "app/section_plane.h"
#include "app/thickness.h"
#include "app/update.h"
#include "vox/analysis/cut.h"
#include "vox/analysis/surface_mesh.h"
#include "vox/io/figure.h"
#include "vox/io/file_util.h"
#include "vox/io/image_io.h"
#include "vox/io/mesh_export.h"
#include "vox/io/voxel_file.h"
#include "vox/workflow/thickness_figure.h"

namespace vox::app {

bool exportBinvox(AppState& state, const std::filesystem::path& path) {
  if (state.model.empty()) {
    reportError(state, "there is no model to export", path);
    return false;
  }
  if (Status s = io::saveBinvox(state.model, path); !s) {
    reportError(state, describe(s.error(), path), path);
    return false;
  }
  return true;
}

bool exportsCutAway(const AppState& state) { return state.panel == Panel::kSection && state.view.cut_away; }

VoxelGrid cutAwayModel(const AppState& state) {
  if (!exportsCutAway(state)) return state.model;
  if (state.section.oblique) {
    const render::CutAway cut = obliqueCutAway(state.model.frame(), state.model.dims(), state.section);
    return cutAway(state.model, sectionPlaneOf(cut.normal, cut.offset), state.view.keep_above);
  }
  return cutAway(state.model, state.section.axis, state.section.index, state.view.keep_above);
}

bool exportSurface(AppState& state, const std::filesystem::path& path, bool smooth) {
  if (state.model.empty() || state.model.filledCount() == 0) {
    reportError(state, "there is no model to export", path);
    return false;
  }
  if (!io::isMeshExportFile(path)) {
    reportError(state, path.string() + ": not a mesh format (" + io::meshExportExtensions() + ")", path);
    return false;
  }
  // What the view shows: with the Section panel's cut-away on, the half it keeps (the cut face included).
  const bool cut = exportsCutAway(state);
  const VoxelGrid half = cut ? cutAwayModel(state) : VoxelGrid();
  if (cut && half.filledCount() == 0) {
    reportError(state, "the cut-away keeps no voxels: nothing to export", path);
    return false;
  }
  auto mesh = extractSurfaceMesh(cut ? half : state.model, SurfaceMeshParams{true, smooth ? 10 : 0});
  if (!mesh) {
    reportError(state, describe(mesh.error(), path), path);
    return false;
  }
  mesh->name = state.doc.path.empty() ? std::string("model") : state.doc.path.stem().string();
  if (Status s = io::saveMesh(*mesh, path, state.model.frame().units); !s) {
    reportError(state, describe(s.error(), path), path);
    return false;
  }
  return true;
}

// On the Thickness panel the section exported is the one it shows: coloured by the thickness shown, with its colour
// bar and legend, about 512 pixels across.
bool exportThicknessSectionPng(AppState& state, const ThicknessResult& r, const std::filesystem::path& path) {
  currentSection(state);  // clamps the index to the model
  const Dims d = state.model.dims();
  const int32_t across = std::max({d.nx, d.ny, d.nz, 1});
  const int32_t scale = std::clamp((512 + across - 1) / across, 1, 8);
  auto figure = workflow::thicknessSectionFigure(r.thickness, shownRay(state, r),
                                                 SectionParams{state.section.axis, state.section.index},
                                                 state.model.frame().units, scale);
  Status s = figure ? io::savePng(*figure, path) : Status(figure.error());
  if (!s) {
    reportError(state, describe(s.error(), path), path);
    return false;
  }
  return true;
}

bool exportSectionPng(AppState& state, const std::filesystem::path& path) {
  if (const ThicknessResult* r = state.panel == Panel::kThickness ? currentThickness(state) : nullptr) {
    return exportThicknessSectionPng(state, *r, path);
  }
  const Section* section = state.section.oblique ? nullptr : currentSection(state);
  const ObliqueSection* oblique = state.section.oblique ? currentObliqueSection(state) : nullptr;
  if (!section && !oblique) {
    reportError(state, "there is no section to export", path);
    return false;
  }
  if (Status s = io::savePng(io::sectionPicture(section ? section->mask : oblique->mask, 1), path); !s) {
    reportError(state, describe(s.error(), path), path);
    return false;
  }
  return true;
}

bool exportXrayPng(AppState& state, const std::filesystem::path& path) {
  const XrayResult* x = currentXray(state);
  if (!x) {
    reportError(state, "there is no X-ray image to export (open the X-ray panel first)", path);
    return false;
  }
  // Independent of the window: about 512 pixels across the longer side of the map.
  const int32_t longest = std::max({x->thickness.width, x->thickness.height, 1});
  const int32_t scale = std::clamp((512 + longest - 1) / longest, 1, 8);
  if (Status s = io::savePng(io::drawScalarMapFigure(x->thickness, x->max, xrayLegend(*x), scale).image, path); !s) {
    reportError(state, describe(s.error(), path), path);
    return false;
  }
  return true;
}

bool exportXrayCsv(AppState& state, const std::filesystem::path& path) {
  const XrayResult* x = currentXray(state);
  if (!x) {
    reportError(state, "there is no X-ray to export (open the X-ray panel first)", path);
    return false;
  }
  if (Status s = io::writeFileAtomic(path, xrayCsv(*x)); !s) {
    reportError(state, describe(s.error(), path), path);
    return false;
  }
  return true;
}

}  // namespace vox::app
