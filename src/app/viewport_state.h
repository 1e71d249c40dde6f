#pragma once
// The 3D view's state: the renderers (the model, overlays, one per part), the framebuffer and what they hold
// (viewport.cpp, parts_view.cpp). GL objects of the window's context.
#include <cstdint>
#include <memory>
#include <vector>

#include "vox/core/assembly.h"
#include "vox/core/lattice.h"
#include "vox/render/framebuffer.h"
#include "vox/render/point_renderer.h"

namespace vox::app {

// The 3D view: GL objects of the window's context.
struct Viewport {
  std::unique_ptr<render::PointRenderer> renderer;  // the model
  std::unique_ptr<render::PointRenderer> overlay;   // disputed voxels or the core, drawn over the model
  std::unique_ptr<render::PointRenderer> ghost;     // the whole part, faint, around a peeled model
  std::unique_ptr<render::PointRenderer> support;   // the Print panel's support, translucent (print_view.h)

  // One renderer per part of a scene (parts_view.h), each on its placed part's own box; the model version they were
  // last brought up to date with, and how many times a part renderer was filled (setGrid) so far: a move refills only
  // the part that moved.
  struct PartView {
    std::unique_ptr<render::PointRenderer> renderer;
    LatticeGrid voxels;  // what it was filled from: the part's voxels as added (sharing the part's layers)
    PartPlacement placement;
    Box3i box;  // the placed part's box of lattice voxels: the renderer's voxel (0, 0, 0) is box.min
  };
  std::vector<PartView> parts;
  uint64_t parts_version = 0;
  int64_t part_fills = 0;

  render::Framebuffer framebuffer;
  uint64_t uploaded_version = 0;  // model_version the renderer holds
  // While the parts are drawn, model_bounds come from their renderers: the parts_version and model_version they were
  // taken for (parts_bounds_version 0: from the model's renderer).
  uint64_t parts_bounds_version = 0;
  uint64_t parts_bounds_model = 0;
  uint64_t overlay_key = 0;             // what the overlay holds (see viewport.cpp)
  uint64_t ghost_key = 0;               // base_id of the model the ghost holds while peeled, else 0
  bool dirty = true;                    // draw again on the next frame
  std::vector<double> drawn_signature;  // what the framebuffer shows (see viewport.cpp)
  bool interacting = false;             // the mouse is dragging the view or a slider: coarse points
  bool was_coarse = false;
  double aspect = 0.0;  // width / height the camera was last used with              // the last image used coarse
                        // points (redraw sharp when the drag ends)
  render::DrawStats stats;
  double draw_ms = 0.0;
  float x = 0, y = 0, width = 0, height = 0;  // where the view sits in the window, pixels
};

}  // namespace vox::app
