#include "app/viewport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include <glm/mat4x4.hpp>
#include <imgui.h>

#include "app/actions.h"
#include "app/measure.h"
#include "app/operations.h"
#include "app/parts.h"
#include "app/parts_view.h"
#include "app/casting_view.h"
#include "app/print.h"
#include "app/print_view.h"
#include "app/section_plane.h"
#include "app/ui.h"
#include "app/thickness_view.h"
#include "app/view_cube.h"
#include "app/view_export.h"
#include "app/view_overlays.h"
#include "app/viewport_input.h"
#include "vox/io/image_io.h"
#include "vox/render/gl.h"

namespace vox::app {
namespace {

constexpr Rgba8 kBackground{46, 50, 58, 255};
constexpr glm::vec3 kCoreColour{1.0f, 0.2f, 0.85f};
constexpr float kGhostOpacity = 0.14f;  // the whole part around a peeled one: visible, never in the way
constexpr glm::vec3 kDisputedColour{1.0f, 0.85f, 0.1f};
constexpr glm::vec3 kOverlapColour{1.0f, 0.12f, 0.1f};
// Points a frame may draw: while the camera moves (llvmpipe draws about 8 million a second on 2 cores), and once it
// rests, when the view refines to full detail if the model's surface has no more points than this (R = 1000 parts
// have 1 to 5 million), else to the finest level that does.
constexpr int64_t kMovingPointBudget = 1'000'000;
constexpr int64_t kRestingPointBudget = 6'000'000;

render::SectionAxis toRenderAxis(Axis a) {
  switch (a) {
    case Axis::kX:
      return render::SectionAxis::kX;
    case Axis::kY:
      return render::SectionAxis::kY;
    case Axis::kZ:
      return render::SectionAxis::kZ;
  }
  return render::SectionAxis::kNone;
}

// What the overlay renderer should hold: the core while the Skin panel is open, else the disputed voxels when asked
// for (both expanded into `scratch` when the key changes). Returns 0 for nothing; otherwise a key that changes with
// the content.
uint64_t overlayKey(const AppState& state, const VoxelGrid** grid_out, VoxelGrid& scratch) {
  *grid_out = nullptr;
  if (!state.doc.model) return 0;
  const ModelSnapshot& m = *state.doc.model;
  // The shared voxels of the interference pair the Parts panel shows (already a grid on the model's frame).
  if (state.parts_ui.pair >= 0 && state.parts_ui.pair_overlap.dims() == state.model.dims()) {
    *grid_out = &state.parts_ui.pair_overlap;
    return state.parts_ui.pair_key * 4 + 3;
  }
  if (state.panel == Panel::kSkin && state.view.show_core) {
    if (const DepthMap* d = currentDepthMap(state); d && d->layers() > 0) {
      const uint64_t key = m.base_id * 4 + 1;
      if (key != state.viewport.overlay_key) scratch = d->removedBy(d->layers());
      *grid_out = &scratch;
      return key;
    }
  }
  if (state.view.show_disputed && m.origin && m.origin->disputed && m.origin->disputed_count > 0) {
    const uint64_t key = m.base_id * 4 + 2;
    if (key != state.viewport.overlay_key) scratch = m.origin->disputed->toGrid();
    *grid_out = &scratch;
    return key;
  }
  return 0;
}

render::DrawParams drawParams(const AppState& state, bool coarse) {
  render::DrawParams p;
  p.lut = state.view.lit ? render::Lut::kLit : render::Lut::kClassic;
  p.round_points = state.view.round_points;
  p.point_size_px = state.view.point_size_px;
  p.coarse = coarse;
  p.lod_point_budget = state.viewport.interacting ? kMovingPointBudget : kRestingPointBudget;
  if (state.panel == Panel::kSection && state.view.cut_away && !state.model.empty()) {
    p.section = state.section.oblique ? obliqueCutAway(state.model.frame(), state.model.dims(), state.section)
                                      : render::CutAway{toRenderAxis(state.section.axis), state.section.index};
    p.section.side = state.view.keep_above ? render::SectionSide::kAbove : render::SectionSide::kBelow;
  }
  thicknessDrawParams(state, p);
  printDrawParams(state, p);
  castingDrawParams(state, p);
  return p;
}

// The model fitted to the view of w x h pixels; while the Thickness panel's colour scale takes the view's top, to the
// part below it (fitted to that part's shape, moved down by half the scale's height).
void fitIfPending(AppState& state, int w, int h) {
  if (!state.view.fit_pending || !state.model_bounds) return;
  render::Camera& camera = state.view.camera;
  const double band = std::min(double(thicknessLegendHeight(state)), 0.5 * double(h));
  const double below = double(h) - band;
  camera.fitToBox(*state.model_bounds, double(w) / below);
  if (band > 0.0) {
    camera.distance *= double(h) / below;
    camera.pan(0.0, 0.5 * band, double(h));
  }
  state.view.fit_pending = false;
}

// Everything the image depends on; the view is redrawn only when this changes.
std::vector<double> signature(const AppState& state, int w, int h, bool coarse) {
  const render::Camera& c = state.view.camera;
  const render::DrawParams p = drawParams(state, coarse);
  return {double(state.model_version),
          double(state.viewport.overlay_key),
          double(w),
          double(h),
          c.target.x,
          c.target.y,
          c.target.z,
          c.distance,
          c.yaw_deg,
          c.pitch_deg,
          c.fov_y_deg,
          double(int(c.projection)),
          double(int(p.lut)),
          double(p.round_points),
          p.point_size_px,
          double(coarse),
          double(int(p.section.axis)),
          double(p.section.index),
          double(p.section.normal.x),
          double(p.section.normal.y),
          double(p.section.normal.z),
          double(p.section.offset),
          double(int(p.section.side)),
          double(state.thickness_ui.volume_key),
          double(state.print_ui.volume_key),
          double(state.print_ui.support_key),
          double(state.casting_ui.volume_key),
          state.casting_ui.volume_sig.empty() ? 0.0 : state.casting_ui.volume_sig[0],
          state.casting_ui.volume_sig.empty() ? 0.0 : state.casting_ui.volume_sig[1],
          double(p.scalar_colour),
          double(p.scalar_threshold)};
}

// The model's image, with its parts in their colours when it is a scene.
std::vector<double> viewSignature(const AppState& state, int w, int h, bool coarse) {
  std::vector<double> sig = signature(state, w, h, coarse);
  appendPartsSignature(state, sig);
  return sig;
}

void renderView(AppState& state, int w, int h, bool coarse) {
  Viewport& vp = state.viewport;
  const double t0 = nowSeconds();
  if (Status s = vp.framebuffer.resize(w, h); !s) {
    reportError(state, "the 3D view could not be drawn: " + s.error().message);
    return;
  }
  vp.framebuffer.clear(kBackground);
  vp.stats = {};
  if (!state.model.empty()) {
    const render::DrawParams params = drawParams(state, coarse);
    vp.stats = drawsParts(state) ? drawParts(state, w, h, params) : vp.renderer->draw(state.view.camera, w, h, params);
    if (vp.ghost_key != 0) {
      render::DrawParams faint = params;
      faint.opacity = kGhostOpacity;
      vp.ghost->draw(state.view.camera, w, h, faint);
    }
    drawPrintSupport(state, w, h, params);
    if (vp.overlay_key != 0) {
      // Drawn over the model regardless of depth, so the core (deep inside) or a disputed voxel shows through.
      glClear(GL_DEPTH_BUFFER_BIT);
      render::DrawParams over = params;
      over.lut = render::Lut::kLit;
      // A core of a few voxels would be a few pixels: draw it at least 8 pixels wide so it can be found.
      const bool core = vp.overlay_key % 4 == 1;
      const bool overlap = vp.overlay_key % 4 == 3;
      if ((core || overlap) && over.point_size_px <= 0.0) {
        const render::Camera& cam = state.view.camera;
        const double ppv = render::pixelsPerVoxel(cam, double(h), cam.distance);
        over.point_size_px = std::max(
            6.0,
            render::closedPointSize(ppv, render::pointCoverageFactor(cam, over.round_points, double(w) / double(h))));
      }
      over.colour = core ? kCoreColour : overlap ? kOverlapColour : kDisputedColour;
      over.cull_back_groups = true;
      vp.overlay->draw(state.view.camera, w, h, over);
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  vp.was_coarse = coarse && vp.stats.lod_level > 0;
  vp.draw_ms = (nowSeconds() - t0) * 1000.0;
}

}  // namespace

void syncRenderers(AppState& state) {
  Viewport& vp = state.viewport;
  syncPartRenderers(state);
  if (drawsParts(state)) {
    // The parts are drawn, not the model (their union): it is uploaded only when it is drawn again (undo to before the
    // split), so a move of one part costs that part's points alone.
    if (vp.parts_bounds_version != vp.parts_version || vp.parts_bounds_model != state.model_version) {
      state.model_bounds = partsBounds(state);
      vp.parts_bounds_version = vp.parts_version;
      vp.parts_bounds_model = state.model_version;
      vp.dirty = true;
    }
  } else if (vp.uploaded_version != state.model_version || vp.parts_bounds_version != 0) {
    if (!state.model.empty()) {
      vp.renderer->setGrid(state.model);
      state.model_bounds = vp.renderer->bounds();
    } else {
      state.model_bounds.reset();
    }
    vp.uploaded_version = state.model_version;
    vp.parts_bounds_version = 0;
    vp.dirty = true;
  }
  // A peeled model is drawn inside a faint ghost of the whole part, so the core never floats alone.
  const uint64_t ghost = state.doc.model && state.doc.model->peeled > 0 ? state.doc.model->base_id : 0;
  if (ghost != vp.ghost_key) {
    if (ghost) vp.ghost->setGrid(state.doc.model->base);
    vp.ghost_key = ghost;
    vp.dirty = true;
  }
  VoxelGrid scratch;
  const VoxelGrid* overlay = nullptr;
  const uint64_t key = overlayKey(state, &overlay, scratch);
  if (key != vp.overlay_key) {
    if (overlay) vp.overlay->setGrid(*overlay);
    vp.overlay_key = key;
    vp.dirty = true;
  }
  syncThicknessVolume(state);
  syncPrintView(state);
  syncCastingView(state);
}

Status initViewport(AppState& state) {
  auto main_renderer = render::PointRenderer::create();
  if (!main_renderer) return main_renderer.error();
  auto overlay = render::PointRenderer::create();
  if (!overlay) return overlay.error();
  auto ghost = render::PointRenderer::create();
  if (!ghost) return ghost.error();
  auto support = render::PointRenderer::create();
  if (!support) return support.error();
  state.viewport.support = std::move(support).value();
  state.viewport.ghost = std::move(ghost).value();
  state.viewport.renderer = std::move(main_renderer).value();
  state.viewport.overlay = std::move(overlay).value();
  return Ok{};
}

void shutdownViewport(AppState& state) {
  state.viewport.renderer.reset();
  state.viewport.overlay.reset();
  state.viewport.ghost.reset();
  state.viewport.support.reset();
  state.viewport.framebuffer = render::Framebuffer();
}

void drawViewport(AppState& state) {
  Viewport& vp = state.viewport;
  const ImVec2 pos = ImGui::GetCursorScreenPos();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const int w = std::max(1, int(avail.x));
  const int h = std::max(1, int(avail.y));
  vp.x = pos.x;
  vp.y = pos.y;
  vp.width = float(w);
  vp.height = float(h);

  syncRenderers(state);
  const double aspect = double(w) / double(h);
  if (vp.aspect > 0.0 && aspect != vp.aspect && state.model_bounds) {
    // The view changed shape (a panel with an image opened or closed, or the window was resized): keep the zoom
    // relative to "fit", so the model stays as completely in view as it was.
    render::Camera before = state.view.camera, after = state.view.camera;
    before.fitToBox(*state.model_bounds, vp.aspect);
    after.fitToBox(*state.model_bounds, aspect);
    state.view.camera.distance *= after.distance / before.distance;
  }
  vp.aspect = aspect;
  fitIfPending(state, w, h);

  const bool dragging = handleViewMouse(state, pos, w, h, aspect);
  fitIfPending(state, w, h);
  vp.interacting = vp.interacting || dragging;
  // Coarser points while something moves; at rest the view refines (drawParams: the point budget of each case).
  const bool coarse = state.view.lod;
  const std::vector<double> sig = viewSignature(state, w, h, coarse && vp.interacting);
  if (vp.dirty || sig != vp.drawn_signature) {
    renderView(state, w, h, coarse);
    vp.drawn_signature = sig;
    vp.dirty = false;
  }

  // The framebuffer's rows run bottom-up (GL), ImGui's top-down: flip the texture coordinates.
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddImage(textureId(vp.framebuffer.colourTexture()), pos, ImVec2(pos.x + float(w), pos.y + float(h)), ImVec2(0, 1),
               ImVec2(1, 0));

  // Read-outs and the view buttons drawn over the image.
  const ImVec2 after = ImGui::GetCursorScreenPos();
  if (state.model.empty()) {
    const char* msg = modelBusy(state) ? "Working..."
                      : state.doc.mesh ? "Not voxelized yet: Model > Voxelize... (Ctrl+R)"
                                       : "Open a mesh or voxel file (File > Open, or drop it here)";
    const ImVec2 ts = ImGui::CalcTextSize(msg);
    dl->AddText(ImVec2(pos.x + (float(w) - ts.x) * 0.5f, pos.y + (float(h) - ts.y) * 0.5f),
                IM_COL32(220, 220, 220, 255), msg);
  } else {
    char info[256];
    std::snprintf(info, sizeof info, "%s points%s  |  %.0f ms", groupDigits(vp.stats.points_drawn).c_str(),
                  vp.stats.lod_level > 0 ? ("  |  coarse x" + std::to_string(1 << vp.stats.lod_level) +
                                            (vp.interacting ? " while moving" : " (over 6 M surface points)"))
                                               .c_str()
                                         : "",
                  vp.draw_ms);
    dl->AddText(ImVec2(pos.x + 8.0f, pos.y + float(h) - ImGui::GetFontSize() - 6.0f), IM_COL32(200, 200, 200, 255),
                info);
    const float legend_bottom =
        std::max({drawThicknessOverlay(state, dl, pos, w, h, aspect), drawPrintOverlay(state, dl, pos, w, h, aspect),
                  drawCastingOverlay(state, dl, pos, w, h, aspect)});
    drawMeasureOverlay(state, dl, pos, w, h, aspect, legend_bottom + 4.0f);
    drawClearanceOverlay(state, dl, pos, w, h, aspect);
    drawAxisTriad(state.view.camera, ImVec2(pos.x + 40.0f, pos.y + float(h) - 60.0f), 28.0f);
    if (vp.overlay_key % 4 == 3) {  // under the view buttons, wrapped within the view
      const ImVec2 at(pos.x + 8.0f, pos.y + 12.0f + ImGui::GetFrameHeight());
      dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), at, IM_COL32(255, 70, 60, 255),
                  interferencePairText(state).c_str(), nullptr, std::max(80.0f, float(w) - 16.0f));
    } else if (vp.overlay_key != 0) {
      const bool core = vp.overlay_key % 4 == 1;
      dl->AddText(ImVec2(pos.x + 8.0f, pos.y + 8.0f), core ? IM_COL32(255, 60, 220, 255) : IM_COL32(255, 215, 30, 255),
                  core ? "Core (thickest region) shown through the model" : "Disputed voxels (vote mode)");
    }
  }
  drawViewToolbar(state, ImVec2(pos.x + float(w) - 310.0f, pos.y + 6.0f));
  if (!state.model.empty()) drawViewCube(state, ImVec2(pos.x + float(w) - 52.0f, pos.y + 80.0f), 22.0f);
  ImGui::SetCursorScreenPos(after);
}

Result<ImageRgba> renderViewImage(AppState& state) {
  Viewport& vp = state.viewport;
  if (state.model.empty() || vp.width < 1 || vp.height < 1) {
    return makeError(ErrorCode::kInvalidArgument, "there is no 3D view to export");
  }
  syncRenderers(state);
  // At the size asked for (the same view: the camera keeps its framing, the aspect follows the picture), or as shown.
  const int w = state.export_width > 0 && state.export_height > 0 ? state.export_width : int(vp.width);
  const int h = state.export_width > 0 && state.export_height > 0 ? state.export_height : int(vp.height);
  renderView(state, w, h, false);
  vp.drawn_signature.clear();  // the panel redraws its own (possibly coarse) image next frame
  ImageRgba image = vp.framebuffer.readPixels();
  drawThicknessLegendOnImage(state, image);  // what the window draws over the view, on the picture too
  return image;
}

bool exportViewPng(AppState& state, const std::filesystem::path& path) {
  auto image = renderViewImage(state);
  if (!image) {
    reportError(state, image.error().message, path);
    return false;
  }
  if (Status s = io::savePng(*image, path); !s) {
    reportError(state, s.error().message, path);
    return false;
  }
  return true;
}

}  // namespace vox::app
