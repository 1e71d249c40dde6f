// The status bar along the window's bottom: the running job's progress, the last message, or what is open; and
// the frame rate.
#include <cstdio>
#include <string>

#include <imgui.h>

#include "app/panels/panels.h"
#include "app/ui.h"

namespace vox::app {

void drawStatusBar(AppState& state) {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const float h = ImGui::GetFrameHeight() + 6.0f;
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x, vp->Pos.y + vp->Size.y - h));
  ImGui::SetNextWindowSize(ImVec2(vp->Size.x, h));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(8.0f, 3.0f));
  ImGui::Begin("##status", nullptr, kFixedWindow);
  if (state.load_job.active() || state.voxelize_job.active()) {
    const std::string label = state.load_job.active() ? state.load_job.label() : state.voxelize_job.label();
    const double p = state.load_job.active() ? state.load_job.progress() : state.voxelize_job.progress();
    ImGui::TextUnformatted(label.c_str());
    ImGui::SameLine();
    ImGui::ProgressBar(float(p), ImVec2(200.0f, 0.0f));
  } else if (state.volume_export_job.active()) {  // File > Export volume; Esc cancels
    ImGui::TextUnformatted(state.volume_export_job.label().c_str());
    ImGui::SameLine();
    ImGui::ProgressBar(float(state.volume_export_job.progress()), ImVec2(200.0f, 0.0f));
  } else if (state.thickness.busy() || state.rays.busy()) {  // the Thickness panel's; its Cancel is in the panel
    const bool rays = !state.thickness.busy();
    ImGui::TextUnformatted(rays ? "Casting rays" : "Computing thickness");
    ImGui::SameLine();
    ImGui::ProgressBar(float(rays ? state.rays.progress() : state.thickness.progress()), ImVec2(200.0f, 0.0f));
  } else if (state.parts_job.active() || state.interference_job.active()) {  // the Parts panel's; Esc cancels
    const bool parts = state.parts_job.active();
    ImGui::TextUnformatted(parts ? state.parts_job.label().c_str() : state.interference_job.label().c_str());
    ImGui::SameLine();
    ImGui::ProgressBar(float(parts ? state.parts_job.progress() : state.interference_job.progress()),
                       ImVec2(200.0f, 0.0f));
  } else if (!state.status_message.empty() && nowSeconds() - state.status_since < 8.0) {
    ImGui::TextUnformatted(state.status_message.c_str());
  } else if (!state.model.empty()) {
    const VoxelGrid& g = state.model;
    const SurfaceStats* stats = state.surface_stats.get(state.model_version);
    std::string name = state.doc.path.filename().string();
    if (state.doc.coarse_level > 1) name += " (coarse view, level " + std::to_string(state.doc.coarse_level) + ")";
    ImGui::Text("%s   %d x %d x %d voxels   voxel %s   %s filled", name.c_str(), g.nx(), g.ny(), g.nz(),
                formatLength(g.voxelSize(), g.frame().units).c_str(),
                stats ? groupDigits(stats->filled).c_str() : "...");
  } else if (state.doc.mesh) {
    ImGui::Text("%s   %s triangles, not voxelized yet (Model > Voxelize...)",
                state.doc.path.filename().string().c_str(),
                groupDigits(int64_t(state.doc.mesh->mesh.triangles.size())).c_str());
  } else {
    ImGui::TextUnformatted("No file open");
  }
  char fps[48];
  std::snprintf(fps, sizeof fps, "%.1f fps", state.fps);
  ImGui::SameLine(ImGui::GetWindowWidth() - ImGui::CalcTextSize(fps).x - 12.0f);
  ImGui::TextDisabled("%s", fps);
  ImGui::End();
  ImGui::PopStyleVar();
}

}  // namespace vox::app
