// Dialogs: voxelize (resolution, mode and the plan before starting), job progress with Cancel, errors, the
// unsaved-changes prompt and About.
#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "vox/render/gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/actions.h"
#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/ui.h"
#include "vox/core/units.h"

namespace vox::app {
namespace {

void centreNextWindow() {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + vp->Size.x * 0.5f, vp->Pos.y + vp->Size.y * 0.5f), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
}

const char* modeHelp(FillMode m) {
  switch (m) {
    case FillMode::kAuto:
      return "nonzero for closed meshes, vote for broken ones";
    case FillMode::kParity:
      return "odd number of crossings along +X (the thesis)";
    case FillMode::kNonzero:
      return "winding number: overlapping closed bodies become their union";
    case FillMode::kVote:
      return "parity along X, Y and Z, majority per voxel: for meshes with holes";
  }
  return "";
}

}  // namespace

void drawVoxelizeDialog(AppState& state) {
  VoxelizeDialog& d = state.voxelize;
  if (d.open_requested) {
    d.open_requested = false;
    if (state.doc.mesh) {
      proposeResolution(state);
      ImGui::OpenPopup("Voxelize");
    }
  }
  centreNextWindow();
  if (!ImGui::BeginPopupModal("Voxelize", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  if (!state.doc.mesh || state.close_dialogs) {  // the mesh went away (another file was opened), or a script closes
    ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return;
  }
  const MeshSource& mesh = *state.doc.mesh;
  ImGui::Text("%s: %s triangles", mesh.path.filename().string().c_str(),
              groupDigits(int64_t(mesh.mesh.triangles.size())).c_str());
  ImGui::Spacing();

  VoxelizeParams& p = d.params;
  int by_size = d.by_voxel_size ? 1 : 0;
  ImGui::RadioButton("Resolution", &by_size, 0);
  ImGui::SameLine();
  ImGui::RadioButton("Voxel size", &by_size, 1);
  d.by_voxel_size = by_size == 1;
  if (!d.by_voxel_size) {
    p.voxel_size = 0.0;
    for (int64_t preset : {100, 200, 400, 1000}) {
      char label[16];
      std::snprintf(label, sizeof label, "%" PRId64, preset);
      if (ImGui::RadioButton(label, p.resolution == preset)) p.resolution = preset;
      ImGui::SameLine();
    }
    ImGui::SetNextItemWidth(110.0f);
    int res = int(p.resolution);
    if (ImGui::InputInt("voxels on the longest axis", &res, 10, 100)) p.resolution = std::clamp(res, 1, kMaxResolution);
  } else {
    if (p.voxel_size <= 0.0) {
      const glm::dvec3 e = mesh.mesh.bounds().extent();
      p.voxel_size = std::max({e.x, e.y, e.z}) / double(std::max<int64_t>(p.resolution, 1));
    }
    ImGui::SetNextItemWidth(160.0f);
    ImGui::InputDouble("model units per voxel", &p.voxel_size, 0.0, 0.0, "%.6g");
  }

  ImGui::SetNextItemWidth(160.0f);
  if (ImGui::BeginCombo("Fill mode", fillModeName(p.mode))) {
    for (FillMode m : kFillModes) {
      if (ImGui::Selectable(fillModeName(m), m == p.mode)) p.mode = m;
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", modeHelp(m));
    }
    ImGui::EndCombo();
  }
  ImGui::TextDisabled("%s", modeHelp(p.mode));
  ImGui::SetNextItemWidth(160.0f);
  if (ImGui::BeginCombo("Units", unitsLabel(p.units).c_str())) {
    for (std::string_view u : kLengthUnits) {
      if (ImGui::Selectable(unitsLabel(u).c_str(), u == p.units)) p.units = std::string(u);
    }
    ImGui::EndCombo();
  }
  helpMarker("What the mesh's coordinates are in (STL files do not say): for masses in kg and lengths in mm.");

  // The plan, before anything is allocated.
  ImGui::Separator();
  const auto plan = planFor(state, p);
  bool can_start = plan.ok();
  if (plan) {
    const GridPlacement& g = plan->placement;
    ImGui::Text("Grid: %d x %d x %d = %s voxels", g.dims.nx, g.dims.ny, g.dims.nz, groupDigits(g.dims.count()).c_str());
    ImGui::Text("Voxel size: %.6g model units", g.frame.voxel_size);
    ImGui::Text("Memory: up to %s (limit %s)", formatBytes(plan->bytes).c_str(),
                formatBytes(plan->limit_bytes).c_str());
    if (!d.proposal_note.empty()) ImGui::TextColored(kWarningColour, "%s", d.proposal_note.c_str());
    if (plan->bytes > comfortableVoxelizeBytes() && plan->bytes <= plan->limit_bytes) {
      ImGui::TextColored(kWarningColour, "This takes %s of memory, and peeling it several times that.",
                         formatBytes(plan->bytes).c_str());
    }
    if (plan->limit_bytes > 0 && plan->bytes > plan->limit_bytes) {
      ImGui::TextColored(kErrorColour, "Too large for this machine's memory limit: choose a lower resolution.");
      can_start = false;
    }
  } else {
    ImGui::TextColored(kErrorColour, "%s", plan.error().message.c_str());
  }
  if (!mesh.topology.watertight() && !mesh.topology.closes_when_noise_welded) {
    ImGui::TextColored(kWarningColour, "The mesh is not watertight (%s boundary, %s non-manifold edges).",
                       groupDigits(mesh.topology.boundary_edges).c_str(),
                       groupDigits(mesh.topology.nonmanifold_edges).c_str());
  }
  if (p.mode == FillMode::kAuto) {
    // The same words the Model panel shows after voxelizing (mode_reason), before it starts.
    const ModeChoice choice = resolveAutoMode(mesh.topology);
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 520.0f);
    ImGui::TextDisabled("auto will use %s: %s", fillModeName(choice.mode), choice.reason.c_str());
    ImGui::PopTextWrapPos();
  }
  if (mesh.topology.degenerate_triangles > 0) {
    ImGui::TextColored(kWarningColour, "%s degenerate triangles (they cross no ray and are ignored).",
                       groupDigits(mesh.topology.degenerate_triangles).c_str());
  }

  ImGui::Spacing();
  if (!can_start) ImGui::BeginDisabled();
  if (ImGui::Button("Voxelize", ImVec2(120.0f, 0.0f)) ||
      (can_start && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false))) {
    startVoxelize(state, p);
    ImGui::CloseCurrentPopup();
  }
  if (!can_start) ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Cancel", ImVec2(120.0f, 0.0f)) ||
      ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

void drawJobWindow(AppState& state) {
  const bool loading = state.load_job.active();
  if (!loading && !state.voxelize_job.active()) return;
  const std::string label = loading ? state.load_job.label() : state.voxelize_job.label();
  const double progress = loading ? state.load_job.progress() : state.voxelize_job.progress();
  const bool cancelling = loading ? state.load_job.cancelRequested() : state.voxelize_job.cancelRequested();

  // Not modal: the window keeps drawing the current model and its panels while the worker runs.
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + vp->Size.x * 0.5f + 180.0f, vp->Pos.y + vp->Size.y - 120.0f),
                          ImGuiCond_Always, ImVec2(0.5f, 1.0f));
  ImGui::SetNextWindowSize(ImVec2(420.0f, 0.0f));
  ImGui::Begin("Working", nullptr,
               ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::TextUnformatted(label.c_str());
  char overlay[48];
  std::snprintf(overlay, sizeof overlay, "%.0f%%   %.1f s", progress * 100.0, nowSeconds() - state.job_started);
  ImGui::ProgressBar(float(progress), ImVec2(-1.0f, 0.0f), overlay);
  if (cancelling) {
    ImGui::TextDisabled("Cancelling...");
  } else if (ImGui::Button("Cancel")) {
    dispatch(state, ActionId::kCancelJob);
  }
  ImGui::End();
}

void drawErrorDialog(AppState& state) {
  if (state.errors.messages.empty()) return;
  if (!ImGui::IsPopupOpen("Error")) {
    ImGui::OpenPopup("Error");
    state.errors.shown_frame = ImGui::GetFrameCount();
  }
  centreNextWindow();
  ImGui::SetNextWindowSizeConstraints(ImVec2(360.0f, 0.0f), ImVec2(720.0f, 600.0f));
  if (ImGui::BeginPopupModal("Error", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::PushTextWrapPos(680.0f);
    ImGui::TextUnformatted(state.errors.messages.front().c_str());
    ImGui::PopTextWrapPos();
    if (state.errors.messages.size() > 1) ImGui::TextDisabled("(%zu more)", state.errors.messages.size() - 1);
    ImGui::Spacing();
    // Enter or Escape close it, but not the very press that raised the error (Enter in a file name field).
    const bool keys = ImGui::GetFrameCount() > state.errors.shown_frame &&
                      (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false) ||
                       ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false));
    if (ImGui::Button("OK", ImVec2(120.0f, 0.0f)) || keys) {
      state.errors.messages.erase(state.errors.messages.begin());
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
}

void drawUnsavedPrompt(AppState& state) {
  if (state.unsaved_prompt_requested) {
    state.unsaved_prompt_requested = false;
    ImGui::OpenPopup("Unsaved changes");
  }
  centreNextWindow();
  if (!ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  if (state.close_dialogs) state.after_unsaved_prompt = nullptr;  // as Cancel
  ImGui::Text("The model of %s has changes that are not saved.", state.doc.path.filename().string().c_str());
  if (state.doc.model) ImGui::TextDisabled("Last change: %s", state.doc.model->label.c_str());
  ImGui::Spacing();
  auto then = [&state] {
    auto f = std::move(state.after_unsaved_prompt);
    state.after_unsaved_prompt = nullptr;
    return f;
  };
  const bool save = ImGui::Button("Save", ImVec2(110.0f, 0.0f));
  markWidget("prompt_save");
  if (save) {
    ImGui::CloseCurrentPopup();
    saveThen(state, then());
  }
  ImGui::SameLine();
  const bool discard = ImGui::Button("Discard", ImVec2(110.0f, 0.0f));
  markWidget("prompt_discard");
  if (discard) {
    ImGui::CloseCurrentPopup();
    if (auto f = then()) f(state);
  }
  ImGui::SameLine();
  const bool cancel = ImGui::Button("Cancel", ImVec2(110.0f, 0.0f));
  markWidget("prompt_cancel");
  if (cancel || state.close_dialogs || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
    ImGui::CloseCurrentPopup();
    then();
  }
  ImGui::EndPopup();
}

void drawControlsDialog(AppState& state) {
  if (state.show_controls) {
    state.show_controls = false;
    ImGui::OpenPopup("Mouse and keyboard");
  }
  centreNextWindow();
  if (!ImGui::BeginPopupModal("Mouse and keyboard", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  static constexpr const char* kMouse[][2] = {
      {"Left drag", "orbit the 3D view"},
      {"Right or middle drag, Shift+left drag", "pan"},
      {"Wheel", "zoom"},
      {"Double-click", "fit the model in the view"},
      {"Ctrl+click in the 3D view", "pick a voxel to measure (two: their distance)"},
      {"Click in the section image", "pick a voxel to measure"},
      {"Hover the section or X-ray image", "read the voxel or ray under the cursor"},
  };
  const auto row = [](const char* what, const std::string& does) {  // unwrapped: the window sizes itself to fit
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::TextDisabled("%s", what);
    ImGui::TableSetColumnIndex(1);
    ImGui::TextUnformatted(does.c_str());
  };
  if (ImGui::BeginTable("controls", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
    for (const auto& r : kMouse) row(r[0], r[1]);
    // Every shortcut from the action table, so the list is never out of date.
    for (const Action& a : actionTable()) {
      const std::string sc = shortcutText(a.shortcut);
      if (!sc.empty()) row(sc.c_str(), std::string(a.menu) + " > " + a.label);
    }
    ImGui::EndTable();
  }
  if (ImGui::Button("Close", ImVec2(120.0f, 0.0f)) || state.close_dialogs ||
      ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

void drawAboutDialog(AppState& state) {
  if (state.show_about) {
    state.show_about = false;
    ImGui::OpenPopup("About voxmod");
  }
  centreNextWindow();
  if (!ImGui::BeginPopupModal("About voxmod", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::TextUnformatted("voxmod: a voxel solid modeler");
  ImGui::TextDisabled("After the thesis 'Voxel based solid models' (2005): scan-line voxelization into Z bit-plane");
  ImGui::TextDisabled("layers, points shaded by their face-neighbour code, sections, skin removal and X-ray scans.");
  ImGui::Spacing();
  ImGui::Text("Dear ImGui %s, GLFW %s", ImGui::GetVersion(), glfwGetVersionString());
  ImGui::Text("OpenGL: %s", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  if (ImGui::Button("Close", ImVec2(120.0f, 0.0f)) || state.close_dialogs ||
      ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

}  // namespace vox::app
