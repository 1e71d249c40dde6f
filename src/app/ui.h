#pragma once
// Small ImGui helpers shared by the panels: number formatting, images from GL textures, tooltips.
#include <cstdint>
#include <functional>
#include <string>
#include <utility>

#include <imgui.h>
#include <imgui_stdlib.h>  // InputText on a std::string, which widget::InputText forwards to

#include "app/actions.h"
#include "app/app_state.h"
#include "vox/core/text.h"

namespace vox::app {

inline const ImVec4 kErrorColour{1.0f, 0.45f, 0.4f, 1.0f};
inline const ImVec4 kWarningColour{1.0f, 0.78f, 0.3f, 1.0f};

// ImGui identifies textures by an opaque pointer-sized value; the OpenGL3 backend reads it as a GL texture name.
inline ImTextureID textureId(uint32_t gl_name) { return reinterpret_cast<ImTextureID>(uintptr_t(gl_name)); }

// 1234567 -> "1 234 567" (thin groups are easier to read in a table of voxel counts).
std::string groupDigits(int64_t n);
// Seconds as "0.42 s" or "85 ms".
std::string formatSeconds(double s);
// A number in model units with the units name: "12.5 mm", "0.031 model units".
std::string formatLength(double value, const std::string& units);
// An area: '0.25 mm^2', '3 model units^2'.
std::string formatArea(double value, const std::string& units);
// A volume: '4500 mm^3'.
std::string formatVolume(double value, const std::string& units);
// A table column's header with the unit of its numbers ("Height, mm", "Volume, mm^3"; power 1 to 3); the bare name
// in model units (the status bar says so). Its cells then hold columnNumber(value): the column stays narrow.
std::string columnHeader(const char* name, const std::string& units, int power = 1);
// Four significant digits, never an exponent: "15 790", "2.77".
std::string columnNumber(double value);

// A section heading: a gap, the title in the accent colour and a rule (ImGui 1.86 has no SeparatorText).
void heading(const char* title);
// A "(?)" marker whose tooltip explains a control.
void helpMarker(const char* text);
// A two-column table of facts: a fixed label column and a value column that wraps. Call EndTable() when it
// returns true.
bool beginFactTable(const char* id, float label_width = 125.0f);
// Label on the left, value on the right in a two-column table row.
void tableRow(const char* label, const std::string& value);
// Marks the cell [cell_min, cell_max] (a voxel or ray under the mouse) in an image spanning [area_min, area_max]:
// thin cross-hair lines across the image and a box around the cell (at least 7 pixels, so it shows at any scale).
// Screenshots carry no mouse pointer, so this also shows where a read-out was taken.
void markCell(ImVec2 area_min, ImVec2 area_max, ImVec2 cell_min, ImVec2 cell_max);
// Wrapped text in a colour (warnings, errors).
void wrappedColoured(const ImVec4& colour, const std::string& text);

// A scale bar at `at` (top left of a text line): the longest round length (1, 2 or 5 x 10^k) that fits in max_px,
// labelled with its length and units.
void drawScaleBar(ImVec2 at, float pixels_per_unit, const std::string& units, float max_px);

// Where the last widget was drawn, for a test driver that clicks it ("section_slider"): given to the recorder set
// with setWidgetRecorder (the script harness), nothing without one. `kind` says how a driver uses it: "mark" (a
// name given here), "button", "toggle" (checkbox, radio button), "row" (a selectable), "field" (typed into),
// "slider", "combo", "colour".
void markWidget(const std::string& name, const char* kind = "mark");
using WidgetRecorder = std::function<void(const std::string& name, const char* kind, ImVec2 min, ImVec2 max)>;
void setWidgetRecorder(WidgetRecorder recorder);
// As markWidget, for a widget whose rectangle is given.
void recordAt(const std::string& name, const char* kind, ImVec2 min, ImVec2 max);

// The panels' and dialogs' widgets: ImGui's, under the same names and arguments, each recorded (markWidget) under its
// label, so that a test presses the real buttons and types into the real fields (script.h: press, type, press-all).
namespace widget {
inline bool recorded(const char* kind, const char* label, bool result) {
  markWidget(label, kind);
  return result;
}
template <class... A>
bool Button(const char* label, A&&... a) {
  return recorded("button", label, ImGui::Button(label, std::forward<A>(a)...));
}
template <class... A>
bool SmallButton(const char* label, A&&... a) {
  return recorded("button", label, ImGui::SmallButton(label, std::forward<A>(a)...));
}
template <class... A>
bool Checkbox(const char* label, A&&... a) {
  return recorded("toggle", label, ImGui::Checkbox(label, std::forward<A>(a)...));
}
template <class... A>
bool RadioButton(const char* label, A&&... a) {
  return recorded("toggle", label, ImGui::RadioButton(label, std::forward<A>(a)...));
}
template <class... A>
bool Selectable(const char* label, A&&... a) {
  return recorded("row", label, ImGui::Selectable(label, std::forward<A>(a)...));
}
template <class... A>
bool InputDouble(const char* label, A&&... a) {
  return recorded("field", label, ImGui::InputDouble(label, std::forward<A>(a)...));
}
template <class... A>
bool InputFloat(const char* label, A&&... a) {
  return recorded("field", label, ImGui::InputFloat(label, std::forward<A>(a)...));
}
template <class... A>
bool InputInt(const char* label, A&&... a) {
  return recorded("field", label, ImGui::InputInt(label, std::forward<A>(a)...));
}
template <class... A>
bool InputInt2(const char* label, A&&... a) {
  return recorded("field", label, ImGui::InputInt2(label, std::forward<A>(a)...));
}
template <class... A>
bool InputText(const char* label, A&&... a) {
  return recorded("field", label, ImGui::InputText(label, std::forward<A>(a)...));
}
template <class... A>
bool SliderFloat(const char* label, A&&... a) {
  return recorded("slider", label, ImGui::SliderFloat(label, std::forward<A>(a)...));
}
template <class... A>
bool SliderInt(const char* label, A&&... a) {
  return recorded("slider", label, ImGui::SliderInt(label, std::forward<A>(a)...));
}
template <class... A>
bool Combo(const char* label, A&&... a) {
  return recorded("combo", label, ImGui::Combo(label, std::forward<A>(a)...));
}
// The combo's box is recorded whether or not its list is open (a press opens it; its rows are Selectables).
template <class... A>
bool BeginCombo(const char* label, A&&... a) {
  // Its box is where the cursor stands, as wide as the next item: once open, the last item is the list's window.
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const ImVec2 size(ImGui::CalcItemWidth(), ImGui::GetFrameHeight());
  const bool open = ImGui::BeginCombo(label, std::forward<A>(a)...);
  recordAt(label, "combo", at, ImVec2(at.x + size.x, at.y + size.y));
  return open;
}
template <class... A>
bool ColorEdit3(const char* label, A&&... a) {
  return recorded("colour", label, ImGui::ColorEdit3(label, std::forward<A>(a)...));
}
}  // namespace widget

// A checkbox for a toggle of the action table: shows whether it is on, and a click dispatches it.
void actionCheckbox(AppState& state, ActionId id, const char* label);
// Sets a toggle of the action table on or off through dispatch (as a script's "lit off").
void setToggle(AppState& state, ActionId id, bool on);

// A "(?)" after the last item for the term `key` (glossary.h): hovered, it says what the term means; pressed, it
// opens Help > Terms at it (the terms action). Recorded as "(?)@KEY" (script.h).
void termMarker(AppState& state, const char* key);
// A section heading whose title is a term: its "(?)" beside the title.
void heading(const char* title, AppState& state, const char* term);

// Under the Section and X-ray panels' controls: a line saying the model is peeled, when it is.
void peeledNotice(const AppState& state);

}  // namespace vox::app
