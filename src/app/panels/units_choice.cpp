// The model's length units chosen in the window (the model-units action): one combo, and the prompt a panel shows
// while the model's units are not known: "model units", as a file that names none opens until units are chosen (a
// choice is remembered for the file).
#include <string>

#include <imgui.h>

#include "app/actions.h"
#include "app/panels/panels.h"
#include "app/ui.h"
#include "vox/core/units.h"

namespace vox::app {

void drawUnitsCombo(AppState& state, const char* label) {
  const std::string units = state.model.frame().units;
  ImGui::SetNextItemWidth(120.0f);
  if (widget::BeginCombo(label, unitsLabel(units).c_str())) {
    for (std::string_view u : kLengthUnits) {
      if (widget::Selectable(unitsLabel(u).c_str(), u == units)) {
        dispatchValues(state, ActionId::kModelUnits, {std::string(u)});
      }
    }
    ImGui::EndCombo();
  }
}

bool drawUnitsPrompt(AppState& state, const char* why) {
  if (state.model.empty() || metresPerUnit(state.model.frame().units) > 0.0) return false;
  wrappedColoured(kWarningColour, std::string("This file does not say what its numbers are in. ") + why);
  drawUnitsCombo(state, "Model units##prompt");
  helpMarker("Remembered for this file: the next time it opens, its lengths are in these units.");
  return true;
}

}  // namespace vox::app
