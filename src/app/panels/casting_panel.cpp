// Casting panel (docs/conventions.md, "Casting"): the part poured in an alloy into a mould, with feeders placed by
// clicking the part or typed; the run in the background with its progress and cancel; the verdict, the hot spots (a
// click takes the section there), the time slider and Play for the freezing front, and which field the views colour by.
#include <algorithm>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "app/actions.h"
#include "app/casting.h"
#include "app/parts.h"
#include "app/panels/panels.h"
#include "app/ui.h"
#include "vox/core/units.h"

namespace vox::app {
namespace {

void materials(AppState& state) {
  heading("Metal and mould");
  CastingKey& k = state.casting_ui.chosen;
  ImGui::SetNextItemWidth(160.0f);
  if (widget::BeginCombo("Alloy", k.alloy.c_str())) {
    for (const Alloy& a : castingAlloys()) {
      if (widget::Selectable(a.name.c_str(), a.name == k.alloy))
        dispatchValues(state, ActionId::kCastingAlloy, {a.name});
    }
    ImGui::EndCombo();
  }
  ImGui::SetNextItemWidth(160.0f);
  if (widget::BeginCombo("Mould", k.mould.c_str())) {
    for (const MouldMaterial& m : castingMoulds()) {
      if (widget::Selectable(m.name.c_str(), m.name == k.mould))
        dispatchValues(state, ActionId::kCastingMould, {m.name});
    }
    ImGui::EndCombo();
  }
  double superheat = k.superheat_k;
  ImGui::SetNextItemWidth(100.0f);
  if (widget::InputDouble("Superheat, K", &superheat, 0.0, 0.0, "%.4g", ImGuiInputTextFlags_EnterReturnsTrue)) {
    dispatchValues(state, ActionId::kCastingSuperheat, {std::to_string(superheat)});
  }
  const MouldMaterial* mould = findMould(k.mould);
  double temperature = k.mould_temperature_c > -273.0 ? k.mould_temperature_c : (mould ? mould->temperature_c : 20.0);
  ImGui::SetNextItemWidth(100.0f);
  if (widget::InputDouble("Mould at, C", &temperature, 0.0, 0.0, "%.4g", ImGuiInputTextFlags_EnterReturnsTrue)) {
    dispatchValues(state, ActionId::kCastingMouldTemperature, {std::to_string(temperature)});
  }
  helpMarker("Poured at the liquidus plus the superheat, all at once; the mould starts at its temperature.");
}

void feeders(AppState& state, const std::string& units) {
  heading("Feeders");
  CastingUi& ui = state.casting_ui;
  const bool placing = ui.placing_feeder;
  if (widget::Button(placing ? "Click the part in the 3D view... (cancel)" : "Place a feeder")) {
    dispatch(state, ActionId::kCastingPlaceFeeder);
  }
  markWidget("casting_place_feeder");
  helpMarker(
      "Click where the feeder should stand: it stands on the part's top there, sized to 1.2 times the modulus "
      "of the nearest isolated hot spot of the last run (simulate first).");
  const std::vector<size_t> rows = feederParts(state);
  if (rows.empty()) {
    ImGui::TextDisabled("None.");
    return;
  }
  const Assembly& parts = *currentParts(state);
  for (size_t i = 0; i < rows.size(); ++i) {
    const Feeder f = *parts.placedFeeder(rows[i]);
    ImGui::PushID(int(i));
    ImGui::Text("%s: D %s, H %s at (%.4g, %.4g, %.4g)", parts.part(rows[i]).name.c_str(),
                formatLength(f.diameter, units).c_str(), formatLength(f.height, units).c_str(), f.base.x, f.base.y,
                f.base.z);
    ImGui::SameLine();
    if (widget::SmallButton("Delete")) dispatchValues(state, ActionId::kCastingDeleteFeeder, {std::to_string(i + 1)});
    ImGui::PopID();
  }
  ImGui::TextDisabled("Feeders are parts: the Parts panel moves them; Undo takes a change back.");
}

// The run: its progress, or the button that starts it; returns the result to show, if any.
const CastingOutcome* runOrStatus(AppState& state) {
  heading("Simulation");
  if (castingComputing(state)) {
    ImGui::TextUnformatted("Simulating the casting...");
    ImGui::ProgressBar(float(state.casting.progress()), ImVec2(-1.0f, 0.0f));
    if (widget::Button("Cancel")) dispatch(state, ActionId::kCancelCasting);
    markWidget("casting_cancel");
  } else {
    if (widget::Button("Simulate")) dispatch(state, ActionId::kSimulateCasting);
    markWidget("casting_simulate");
  }
  if (const Error* e = castingError(state))
    wrappedColoured(kErrorColour, "The casting could not be simulated: " + e->message);
  const CastingOutcome* r = currentCasting(state);
  if (r && castingStale(state)) {
    wrappedColoured(kWarningColour, "Shown: the last run, with other settings. Simulate to run these.");
  }
  return r;
}

void facts(AppState& state, const CastingOutcome& r, const std::string& units) {
  const CastingResult& c = r.run.result;
  wrappedColoured(c.sound ? ImVec4(0.5f, 0.9f, 0.5f, 1.0f) : kErrorColour, c.verdict);
  if (!beginFactTable("casting_facts")) return;
  char text[96];
  std::snprintf(text, sizeof text, "%.4g s (%.3g min)", c.solidification_s, c.solidification_s / 60.0);
  tableRow("Solid after", text);
  if (!c.feeders.empty()) {
    std::snprintf(text, sizeof text, "%.4g s", c.last_metal_s);
    tableRow("Feeders solid", text);
    std::snprintf(text, sizeof text, "%.1f%%", 100.0 * c.yield);
    tableRow("Yield", text);
  }
  tableRow("Largest modulus", formatLength(r.run.modulus_max, units));
  termMarker(state, "modulus");
  std::snprintf(text, sizeof text, "%d x %d x %d, %lld steps", c.box.nx, c.box.ny, c.box.nz, (long long)c.steps);
  tableRow("Simulated", text);
  tableRow("Took", formatSeconds(r.seconds));
  ImGui::EndTable();
}

void hotSpots(AppState& state, const CastingOutcome& r, const std::string& units) {
  heading("Hot spots (latest first)");
  const auto& spots = r.run.result.hot_spots;
  ImGui::TextWrapped("Red: isolated, nothing later to feed it. White: fed. Blue: in a feeder. Click one to see it.");
  termMarker(state, "isolated");
  const int rows = std::min(int(spots.size()), 100);
  if (!beginScrollList("casting_hot_spots", 3, rows, 6)) return;
  ImGui::TableSetupColumn("Freezes at", ImGuiTableColumnFlags_WidthFixed, 95.0f);
  ImGui::TableSetupColumn(columnHeader("Modulus", units).c_str(), ImGuiTableColumnFlags_WidthFixed, 95.0f);
  ImGui::TableSetupColumn("Where", ImGuiTableColumnFlags_WidthStretch);
  ImGui::TableHeadersRow();
  for (int i = 0; i < rows; ++i) {
    const CastingHotSpot& s = spots[size_t(i)];
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::PushID(i);
    char label[48];
    std::snprintf(label, sizeof label, "%d. %.4g s", i + 1, s.solidification_s);
    const ImVec4 colour = s.in_feeder
                              ? ImVec4(0.45f, 0.67f, 1.0f, 1.0f)
                              : (s.isolated ? ImVec4(1.0f, 0.35f, 0.3f, 1.0f) : ImVec4(0.95f, 0.95f, 0.95f, 1.0f));
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    if (widget::Selectable(label, selectedCastingSpot(state) == &s, ImGuiSelectableFlags_SpanAllColumns)) {
      dispatchValues(state, ActionId::kCastingHotSpot, {std::to_string(i + 1)});
    }
    ImGui::PopStyleColor();
    ImGui::PopID();
    ImGui::TableSetColumnIndex(1);
    ImGui::TextUnformatted(columnNumber(s.modulus).c_str());
    ImGui::TableSetColumnIndex(2);
    ImGui::Text("%.4g, %.4g, %.4g", s.centre.x, s.centre.y, s.centre.z);
  }
  ImGui::EndTable();
}

void viewChoice(AppState& state, const CastingOutcome& r) {
  heading("Show");
  CastingUi& ui = state.casting_ui;
  static const char* const names[] = {"time", "niyama", "modulus"};
  static const char* const labels[] = {"Freezing time", "Niyama", "Modulus"};
  for (int i = 0; i < 3; ++i) {
    if (i > 0) ImGui::SameLine();
    if (widget::RadioButton(labels[i], int(ui.field) == i)) dispatchValues(state, ActionId::kCastingField, {names[i]});
  }
  termMarker(state, "niyama");
  const double end = r.run.result.last_metal_s;
  float t = float(castingTimeShown(state, r));
  ImGui::SetNextItemWidth(-70.0f);
  if (widget::SliderFloat("##casting_time", &t, float(r.first_solid_s), float(end), "front at %.4g s")) {
    dispatchValues(state, ActionId::kCastingTime, {t >= float(end) ? std::string("end") : std::to_string(t)});
  }
  markWidget("casting_time_slider");
  ImGui::SameLine();
  if (widget::Button(ui.playing ? "Pause" : "Play")) dispatch(state, ActionId::kCastingPlay);
  markWidget("casting_play");
  helpMarker(
      "The freezing front: metal still liquid at that time is red in the views. Play runs the whole freezing "
      "in 8 seconds.");
}

}  // namespace

void drawCastingPanel(AppState& state) {
  if (state.model.empty()) {
    ImGui::TextWrapped("Open a voxel file or voxelize a mesh to see where it freezes last as a casting.");
    return;
  }
  const std::string units = state.model.frame().units;
  drawUnitsPrompt(state, "A casting's times depend on its size: say what they are.");
  materials(state);
  feeders(state, units);
  const CastingOutcome* r = runOrStatus(state);
  if (!r) return;
  facts(state, *r, units);
  viewChoice(state, *r);
  hotSpots(state, *r, units);
}

}  // namespace vox::app
