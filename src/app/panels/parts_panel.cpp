// The Parts panel: the document as a scene of parts on one lattice (app/parts.h). The list (colour, visibility, name,
// volume), selection (click; Ctrl+click adds), splitting into bodies, adding a part from a file, a Boolean of two
// selected parts, removing one, what Section, X-ray and mass work on, a part's placement (move, quarter turns) and
// colour, the clearance of two parts, and the interference list: clicking a pair shows its overlap in red in the 3D
// view and in the section beside the panel. Widgets dispatch actions.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <imgui.h>

#include "app/actions.h"
#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/parts.h"
#include "app/ui.h"
#include "vox/core/units.h"

namespace vox::app {
namespace {

constexpr int kMostPairs = 500;  // more would not be read; the count above the list says how many there are

bool beginList(const char* id, int columns, int rows, int most_rows) {
  const float row_h = ImGui::GetTextLineHeightWithSpacing() + 2.0f;
  const float height = float(std::min(rows, most_rows) + 1) * row_h + 6.0f;
  if (!ImGui::BeginTable(id, columns, ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_BordersOuter,
                         ImVec2(0.0f, height)))
    return false;
  ImGui::TableSetupScrollFreeze(0, 1);
  return true;
}

void drawSplit(AppState& state) {
  const bool voxel_model = state.doc.mesh == nullptr;
  if (voxel_model) {
    int c = state.parts_ui.connectivity == Connectivity::kFace ? 6 : 26;
    widget::RadioButton("6-connected", &c, 6);
    ImGui::SameLine();
    widget::RadioButton("26-connected", &c, 26);
    state.parts_ui.connectivity = c == 6 ? Connectivity::kFace : Connectivity::kAll;
  }
  ImGui::BeginDisabled(!actionEnabled(state, action(ActionId::kSplitBodies)));
  if (widget::Button(voxel_model ? "Split into connected components" : "Split into bodies")) {
    dispatchValues(state, ActionId::kSplitBodies,
                   {voxel_model && state.parts_ui.connectivity == Connectivity::kAll ? "26" : "6"});
  }
  markWidget("split_bodies");
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!actionEnabled(state, action(ActionId::kAddPart)));
  if (widget::Button("Add part from file...")) dispatch(state, ActionId::kAddPart);
  ImGui::EndDisabled();
}

void drawPartRow(AppState& state, const Assembly& parts, size_t i, int64_t voxels) {
  const Part& p = parts.part(i);
  PartsUi& ui = state.parts_ui;
  const bool selected = std::find(ui.selected.begin(), ui.selected.end(), i) != ui.selected.end();
  ImGui::TableNextRow();
  ImGui::PushID(int(i));
  ImGui::TableSetColumnIndex(0);
  // The swatch opens a colour picker; the part's points are drawn in the colour as it is picked. A change while the
  // picker was already active in the last frame continues its drag ("drag"): the whole drag is one undo step.
  float colour[3] = {p.colour.x, p.colour.y, p.colour.z};
  const bool changed = widget::ColorEdit3(
      "##colour", colour, ImGuiColorEditFlags_NoInputs | ImGuiColorEditFlags_NoLabel | ImGuiColorEditFlags_NoTooltip);
  const bool dragging = ui.colour_drag_part == i;
  if (ImGui::IsItemActive()) {
    ui.colour_drag_part = i;
  } else if (dragging) {
    ui.colour_drag_part = SIZE_MAX;
  }
  if (changed) {
    std::vector<std::string> values = {std::to_string(i + 1), std::to_string(colour[0]), std::to_string(colour[1]),
                                       std::to_string(colour[2])};
    if (dragging) values.emplace_back("drag");
    dispatchValues(state, ActionId::kPartColour, values);
  }
  if (i == 0) markWidget("part_colour_first");
  ImGui::SameLine();
  bool visible = p.visible;
  if (widget::Checkbox("##visible", &visible)) {
    dispatchValues(state, ActionId::kPartVisible, {std::to_string(i + 1), visible ? "on" : "off"});
  }
  ImGui::TableSetColumnIndex(1);
  const std::string label = std::to_string(i + 1) + "  " + p.name;
  if (widget::Selectable(label.c_str(), selected, ImGuiSelectableFlags_SpanAllColumns)) {
    if (ImGui::GetIO().KeyCtrl) {
      dispatchValues(state, ActionId::kSelectPart, {"add", std::to_string(i + 1)});
    } else {
      dispatchValues(state, ActionId::kSelectPart, {std::to_string(i + 1)});
    }
  }
  ImGui::TableSetColumnIndex(2);
  ImGui::TextUnformatted(columnNumber(double(voxels) * std::pow(parts.lattice().voxel_size, 3)).c_str());
  ImGui::PopID();
}

void drawPartList(AppState& state, const Assembly& parts) {
  const std::vector<int64_t>& counts = partVoxelCounts(state);
  ImGui::TextWrapped("%s on one lattice (voxel %s). Click to select; Ctrl+click adds.",
                     countOf(int64_t(parts.size()), "part").c_str(),
                     formatLength(parts.lattice().voxel_size, parts.lattice().units).c_str());
  if (!beginList("parts", 3, int(parts.size()), 10)) return;
  ImGui::TableSetupColumn("Show", ImGuiTableColumnFlags_WidthFixed, 58.0f);
  ImGui::TableSetupColumn("Part");
  ImGui::TableSetupColumn(columnHeader("Volume", parts.lattice().units, 3).c_str(), ImGuiTableColumnFlags_WidthFixed,
                          110.0f);
  ImGui::TableHeadersRow();
  ImGuiListClipper clipper;
  clipper.Begin(int(parts.size()));
  while (clipper.Step()) {
    for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
      drawPartRow(state, parts, size_t(i), size_t(i) < counts.size() ? counts[size_t(i)] : 0);
    }
  }
  ImGui::EndTable();
  markWidget("part_list");
}

void drawPartOperations(AppState& state, const Assembly& parts) {
  PartsUi& ui = state.parts_ui;
  int scope = ui.scope_selected ? 1 : 0;
  ImGui::TextUnformatted("Section, X-ray, mass on:");
  ImGui::SameLine();
  if (widget::RadioButton("all parts", &scope, 0)) dispatchValues(state, ActionId::kPartsScope, {"union"});
  ImGui::SameLine();
  if (widget::RadioButton("selected part", &scope, 1)) dispatchValues(state, ActionId::kPartsScope, {"selected"});

  const char* ops[] = {"union", "intersection", "difference", "xor"};
  int op = int(ui.op);
  ImGui::SetNextItemWidth(120.0f);
  if (widget::Combo("##op", &op, ops, 4)) ui.op = PartOp(op);
  ImGui::SameLine();
  ImGui::BeginDisabled(ui.selected.size() < 2);
  if (widget::Button("Boolean of the two selected")) dispatchValues(state, ActionId::kPartBoolean, {ops[op]});
  markWidget("part_boolean");
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled) && ui.selected.size() >= 2) {
    ImGui::SetTooltip("%s %s %s, as a new part", parts.part(ui.selected[0]).name.c_str(), ops[op],
                      parts.part(ui.selected[1]).name.c_str());
  }
  ImGui::BeginDisabled(ui.selected.empty() || parts.size() < 2);
  if (widget::Button("Remove the selected part")) dispatch(state, ActionId::kRemovePart);
  ImGui::EndDisabled();
}

// Placement of the first selected part: a translation in model units (snapped to whole voxels when an edit ends) and
// quarter turns about X, Y and Z, each a new model state (undoable).
void drawPlacement(AppState& state, const Assembly& parts) {
  PartsUi& ui = state.parts_ui;
  if (ui.selected.empty()) {
    ImGui::TextDisabled("Select a part to move or turn it.");
    return;
  }
  const size_t i = ui.selected.front();
  const Part& p = parts.part(i);
  const double h = parts.lattice().voxel_size;
  if (ui.translation_edit_part != i || ui.translation_edit_version != state.doc.model->version) {
    ui.translation_edit = glm::dvec3(p.placement.translation) * h;
    ui.translation_edit_part = i;
    ui.translation_edit_version = state.doc.model->version;
  }
  ImGui::TextWrapped("Placement of %s (moves snap to whole voxels):", p.name.c_str());
  const char* axes[3] = {"X##move", "Y##move", "Z##move"};
  bool edited = false;
  for (int k = 0; k < 3; ++k) {
    if (k > 0) ImGui::SameLine();
    ImGui::SetNextItemWidth(90.0f);
    widget::InputDouble(axes[k], &ui.translation_edit[k], 0.0, 0.0, "%.4g");
    if (k == 0) markWidget("part_move_x");
    edited = edited || ImGui::IsItemDeactivatedAfterEdit();
  }
  if (edited) {
    const glm::dvec3 t = ui.translation_edit;
    dispatchValues(state, ActionId::kPlacePart,
                   {std::to_string(i + 1), std::to_string(t.x), std::to_string(t.y), std::to_string(t.z),
                    std::to_string(p.placement.quarter_turns.x), std::to_string(p.placement.quarter_turns.y),
                    std::to_string(p.placement.quarter_turns.z)});
    ui.translation_edit_part = SIZE_MAX;  // shows the snapped value next frame
  }
  const char* turn_labels[3] = {"Turn X +90", "Turn Y +90", "Turn Z +90"};
  const char* axis_words[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    if (k > 0) ImGui::SameLine();
    if (widget::Button(turn_labels[k]))
      dispatchValues(state, ActionId::kTurnPart, {std::to_string(i + 1), axis_words[k]});
  }
  ImGui::SameLine();
  ImGui::BeginDisabled(p.placement.identity());
  if (widget::Button("Reset")) {
    dispatchValues(state, ActionId::kPlacePart, {std::to_string(i + 1), "0", "0", "0", "0", "0", "0"});
  }
  ImGui::EndDisabled();
  const glm::ivec3 q = p.placement.quarter_turns;
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped("Turned %d, %d, %d degrees about X, Y, Z; moved %d, %d, %d voxels.", 90 * q.x, 90 * q.y, 90 * q.z,
                     p.placement.translation.x, p.placement.translation.y, p.placement.translation.z);
  ImGui::PopStyleColor();
}

// Clearance of the two selected parts: the smallest gap and where (the two voxels are marked in the 3D view).
void drawClearance(AppState& state) {
  const PartsUi& ui = state.parts_ui;
  ImGui::BeginDisabled(ui.selected.size() < 2 || state.clearance_job.active());
  if (widget::Button("Clearance of the two selected")) dispatch(state, ActionId::kClearance);
  markWidget("part_clearance");
  ImGui::EndDisabled();
  termMarker(state, "clearance");
  if (state.clearance_job.active()) {
    ImGui::SameLine();
    ImGui::Text("Finding the clearance... %.1f s", nowSeconds() - state.job_started);
    ImGui::SameLine();
    if (widget::Button("Cancel##clearance")) dispatch(state, ActionId::kCancelJob);
  }
  const std::string text = clearanceText(state);
  if (!text.empty()) ImGui::TextWrapped("%s", text.c_str());
}

void drawPairList(AppState& state, const Assembly& parts, const Interference& inter) {
  const std::string units = parts.lattice().units;
  const double h = parts.lattice().voxel_size;
  if (inter.pairs.empty()) {
    ImGui::TextWrapped("No two parts share a voxel (%s compared voxel by voxel).",
                       countOf(inter.candidate_pairs, "pair").c_str());
    return;
  }
  const double contact = state.parts_ui.contact;
  const auto contacts = std::count_if(inter.pairs.begin(), inter.pairs.end(),
                                      [&](const InterferencePair& p) { return isContact(p, contact); });
  const std::string touching = contacts > 0 ? " (" + std::to_string(contacts) + " only touch: overlaps " +
                                                  formatLength(contact, units) + " thick or less, greyed)"
                                            : std::string();
  ImGui::TextWrapped(
      "%s interfere%s; %s voxels in two or more parts, %s in three or more; found in %s. Click one to see its "
      "overlap.",
      countOf(int64_t(inter.pairs.size()) - contacts, "pair").c_str(), touching.c_str(),
      groupDigits(inter.overlap_voxels).c_str(), groupDigits(inter.multiple_overlap_voxels).c_str(),
      formatSeconds(state.parts_ui.interference_s).c_str());
  const int rows = std::min(int(inter.pairs.size()), kMostPairs);
  if (!beginList("pairs", 5, rows, 12)) return;
  ImGui::TableSetupColumn("A");
  ImGui::TableSetupColumn("B");
  ImGui::TableSetupColumn("Voxels", ImGuiTableColumnFlags_WidthFixed, 48.0f);
  ImGui::TableSetupColumn(columnHeader("Volume", units, 3).c_str(), ImGuiTableColumnFlags_WidthFixed, 92.0f);
  ImGui::TableSetupColumn("Thick", ImGuiTableColumnFlags_WidthFixed, 56.0f);
  ImGui::TableHeadersRow();
  for (int i = 0; i < rows; ++i) {
    const InterferencePair& p = inter.pairs[size_t(i)];
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::PushID(i);
    const bool shown = state.parts_ui.pair == i;
    const bool touches = isContact(p, contact);  // the row greyed
    if (touches) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    if (widget::Selectable(parts.part(size_t(p.a)).name.c_str(), shown, ImGuiSelectableFlags_SpanAllColumns)) {
      dispatchValues(state, ActionId::kInterferencePair, {std::to_string(shown ? 0 : i + 1)});
    }
    if (i == 0) markWidget("interference_first_pair");
    ImGui::TableSetColumnIndex(1);
    ImGui::TextUnformatted(parts.part(size_t(p.b)).name.c_str());
    ImGui::TableSetColumnIndex(2);
    ImGui::TextUnformatted(groupDigits(p.voxels).c_str());
    ImGui::TableSetColumnIndex(3);
    ImGui::TextUnformatted(columnNumber(double(p.voxels) * h * h * h).c_str());
    ImGui::TableSetColumnIndex(4);
    ImGui::TextUnformatted(formatLength(p.thickness, units).c_str());
    if (touches) ImGui::PopStyleColor();
    ImGui::PopID();
  }
  ImGui::EndTable();
}

// Overlaps at most this thick only touch (parts that touch share a voxel or two of their surfaces).
void contactField(AppState& state, const Assembly& parts) {
  double contact = state.parts_ui.contact;
  ImGui::SetNextItemWidth(100.0f);
  const std::string label = "Contact up to, " + unitsLabel(parts.lattice().units);
  if (widget::InputDouble(label.c_str(), &contact, 0.0, 0.0, "%.4g", ImGuiInputTextFlags_EnterReturnsTrue)) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", contact);  // the value as typed, every digit
    dispatchValues(state, ActionId::kInterferenceContact, {text});
  }
  markWidget("interference_contact");
  helpMarker(
      "Parts that touch (a bolt in its hole) share a sheet of surface voxels a voxel or two thick. Overlaps no "
      "thicker than this are listed as contact, not interference. 0: every shared voxel interferes.");
}

void drawInterference(AppState& state, const Assembly& parts) {
  heading("Interference", state, "interference");
  contactField(state, parts);
  if (const Interference* inter = currentInterference(state)) {
    drawPairList(state, parts, *inter);
  } else if (state.interference_job.active()) {
    char overlay[48];
    std::snprintf(overlay, sizeof overlay, "%.0f%%   %.1f s", state.interference_job.progress() * 100.0,
                  nowSeconds() - state.job_started);
    ImGui::TextUnformatted("Finding interference...");
    ImGui::ProgressBar(float(state.interference_job.progress()), ImVec2(-1.0f, 0.0f), overlay);
    ImGui::BeginDisabled(state.interference_job.cancelRequested());
    if (widget::Button("Cancel##interference")) dispatch(state, ActionId::kCancelInterference);
    markWidget("interference_cancel");
    ImGui::EndDisabled();
  } else {
    if (state.parts_ui.interference_cancelled_version == state.doc.model->version) {
      ImGui::TextUnformatted("Cancelled.");
    }
    ImGui::TextWrapped("Which parts share voxels, how many, and where.");
    if (widget::Button("Find interference")) dispatch(state, ActionId::kInterference);
    markWidget("find_interference");
  }
}

void drawProgress(AppState& state) {
  ImGui::TextUnformatted(state.parts_job.label().c_str());
  char overlay[48];
  std::snprintf(overlay, sizeof overlay, "%.0f%%   %.1f s", state.parts_job.progress() * 100.0,
                nowSeconds() - state.job_started);
  ImGui::ProgressBar(float(state.parts_job.progress()), ImVec2(-1.0f, 0.0f), overlay);
  if (widget::Button("Cancel##parts")) state.parts_job.cancel();
}

}  // namespace

void drawPartsPanel(AppState& state) {
  if (!state.doc.model) {
    ImGui::TextWrapped("Open a mesh or voxel file, then split it into bodies or add parts from other files.");
    return;
  }
  if (partsBusy(state)) drawProgress(state);
  const Assembly* parts = currentParts(state);
  if (!parts) {
    ImGui::TextWrapped(state.doc.mesh ? "The model is one part. Split the mesh into its bodies (shells), each "
                                        "voxelized on this lattice, or add a part from another file."
                                      : "The model is one part. Split it into its connected components, or add a "
                                        "part from another file on the same lattice.");
    drawSplit(state);
    return;
  }
  drawSplit(state);
  drawPartList(state, *parts);
  drawPartOperations(state, *parts);
  drawPlacement(state, *parts);
  drawClearance(state);
  drawInterference(state, *parts);
}

}  // namespace vox::app
