// The Voxelize dialog's plan, shown before anything is allocated: the grid, the voxel size, the memory it takes and
// what is wrong with the mesh.
#include <imgui.h>

#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/ui.h"
#include "vox/core/units.h"

namespace vox::app {

bool drawVoxelizePlan(const AppState& state, const VoxelizeDialog& d, const MeshSource& mesh) {
  const VoxelizeParams& p = d.params;
  ImGui::Separator();
  const auto plan = planFor(state, p);
  bool can_start = plan.ok();
  if (plan) {
    const GridPlacement& g = plan->placement;
    ImGui::Text("Grid: %d x %d x %d = %s voxels", g.dims.nx, g.dims.ny, g.dims.nz, groupDigits(g.dims.count()).c_str());
    ImGui::Text("Voxel size: %.6g %s", g.frame.voxel_size, unitsLabel(p.units).c_str());
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
  return can_start;
}

}  // namespace vox::app
