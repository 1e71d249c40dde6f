// voxmod render FILE -o OUT.png: the point renderer headless (EGL, no display; docs/conventions.md, "Command line"),
// plus camera, table, cut-away section and peel-depth options. Exit code 3 when no usable OpenGL is available.
#include <CLI/CLI.hpp>

#include "cli/cmd_list.h"
#include "cli/commands.h"
#include "cli/model_input.h"
#include "vox/analysis/analysis.h"
#include "vox/core/surface.h"
#include "vox/io/image_io.h"
#include "vox/render/render.h"

namespace vox::cli {
namespace {

struct RenderOptions {
  std::string file, out, lut = "classic", view, section_axis, section_side = "below";
  int32_t width = 800, height = 600, section_index = 0, peel_depth = 0;
  double yaw = 30.0, pitch = 20.0, zoom = 1.0, point_size = 0.0;
  bool ortho = false, round_points = false, json = false;
  MeshOptions mesh;
};

std::optional<render::StandardView> parseView(const std::string& s) {
  using render::StandardView;
  if (s == "+x") return StandardView::kPosX;
  if (s == "-x") return StandardView::kNegX;
  if (s == "+y") return StandardView::kPosY;
  if (s == "-y") return StandardView::kNegY;
  if (s == "+z") return StandardView::kPosZ;
  if (s == "-z") return StandardView::kNegZ;
  if (s == "iso") return StandardView::kIso;
  return std::nullopt;
}

int runRender(const RenderOptions& o) {
  Output out(o.json);
  if (const std::string why = pngOutputProblem(o.out); !why.empty()) return out.fail(kExitUsage, why);
  auto model = loadModel(o.file, o.mesh, out);
  if (!model) return out.fail(model.error());
  VoxelGrid grid = std::move(model->grid);
  if (o.peel_depth > 0) {
    PeelParams peel;
    peel.layers = o.peel_depth;
    auto depth = computeDepthMap(grid, peel, terminalProgress("peeling"));
    if (!depth) return out.fail(depth.error());
    grid = depth->remainingAfter(peel.layers);
  }

  render::RenderParams p;
  p.width = o.width;
  p.height = o.height;
  p.yaw_deg = o.yaw;
  p.pitch_deg = o.pitch;
  if (!o.view.empty()) {
    const glm::dvec2 angles = render::standardViewAngles(*parseView(o.view));
    p.yaw_deg = angles.x;
    p.pitch_deg = angles.y;
  }
  p.lut = o.lut == "lit" ? render::Lut::kLit : render::Lut::kClassic;
  p.projection = o.ortho ? render::Projection::kOrthographic : render::Projection::kPerspective;
  p.zoom = o.zoom;
  p.point_size_px = o.point_size;
  p.round_points = o.round_points;
  if (!o.section_axis.empty()) {
    p.section.axis = o.section_axis == "x"   ? render::SectionAxis::kX
                     : o.section_axis == "y" ? render::SectionAxis::kY
                                             : render::SectionAxis::kZ;
    p.section.index = o.section_index;
    p.section.side = o.section_side == "above" ? render::SectionSide::kAbove : render::SectionSide::kBelow;
  }
  const double t0 = nowSeconds();
  auto image = render::renderGridHeadless(grid, p);
  if (!image) return out.fail(image.error());
  const double t1 = nowSeconds();
  if (auto s = io::savePng(*image, o.out); !s) return out.fail(s.error());

  auto& d = out.data();
  d["output"] = o.out;
  d["width"] = o.width;
  d["height"] = o.height;
  d["yaw"] = p.yaw_deg;
  d["pitch"] = p.pitch_deg;
  d["lut"] = o.lut;
  d["surface_voxels"] = countSurfaceVoxels(grid);
  d["filled"] = grid.filledCount();
  d["render_s"] = t1 - t0;
  out.say("rendered " + o.file + " to " + o.out + " (" + std::to_string(o.width) + " x " + std::to_string(o.height) +
          ")");
  return out.finish();
}

}  // namespace

void addRenderCommand(CLI::App& sub, CommandContext& ctx) {
  auto o = std::make_shared<RenderOptions>();
  sub.add_option("FILE", o->file, kFileHelp)->required();
  sub.add_option("-o,--output", o->out, "Output PNG")->required();
  sub.add_option("--width", o->width, "Image width in pixels (default 800)")->check(CLI::Range(1, 16384));
  sub.add_option("--height", o->height, "Image height in pixels (default 600)")->check(CLI::Range(1, 16384));
  sub.add_option("--yaw", o->yaw, "Camera yaw about +Y in degrees (default 30)");
  sub.add_option("--pitch", o->pitch, "Camera pitch in degrees (default 20)")->check(CLI::Range(-90.0, 90.0));
  sub.add_option("--view", o->view, "Standard view instead of yaw/pitch: +x -x +y -y +z -z iso")
      ->check(CLI::IsMember({"+x", "-x", "+y", "-y", "+z", "-z", "iso"}));
  sub.add_option("--lut", o->lut, "Shading table: classic (thesis Table 5.2, green) or lit (light follows the view)")
      ->check(CLI::IsMember({"classic", "lit"}));
  sub.add_flag("--ortho", o->ortho, "Orthographic projection (default perspective)");
  sub.add_option("--zoom", o->zoom, "Magnification relative to fitting the model (default 1)")
      ->check(CLI::PositiveNumber);
  sub.add_option("--point-size", o->point_size, "Point size in pixels (default: from the projected voxel size)")
      ->check(CLI::Range(0.0, 255.0));
  sub.add_flag("--round", o->round_points, "Round (smoothed) points");
  sub.add_option("--section-axis", o->section_axis, "Cut-away: keep one side of a plane normal to x, y or z")
      ->check(CLI::IsMember({"x", "y", "z"}));
  sub.add_option("--section-index", o->section_index, "Cut-away plane index along the axis");
  sub.add_option("--section-side", o->section_side, "Side kept: below (default) or above")
      ->check(CLI::IsMember({"below", "above"}));
  sub.add_option("--peel-depth", o->peel_depth, "Remove this many skin layers before drawing")
      ->check(CLI::NonNegativeNumber);
  sub.add_flag("--json", o->json, "Print one JSON object on stdout");
  addMeshOptions(sub, o->mesh);
  sub.callback([o, &ctx] { ctx.exit_code = runRender(*o); });
}

}  // namespace vox::cli
