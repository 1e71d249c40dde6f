#include "app/ui.h"

#include "app/glossary.h"
#include "vox/core/text.h"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>

namespace vox::app {

std::string groupDigits(int64_t n) {
  const std::string digits = std::to_string(n < 0 ? -n : n);
  std::string out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ' ';
    out += digits[i];
  }
  return n < 0 ? "-" + out : out;
}

std::string formatSeconds(double s) {
  char buf[32];
  if (s < 1.0) {
    std::snprintf(buf, sizeof buf, "%.0f ms", s * 1000.0);
  } else {
    std::snprintf(buf, sizeof buf, "%.2f s", s);
  }
  return buf;
}

std::string formatLength(double value, const std::string& units) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g %s", value, units == "model" ? "model units" : units.c_str());
  return buf;
}

std::string formatArea(double value, const std::string& units) { return formatLength(value, units) + "^2"; }
std::string formatVolume(double value, const std::string& units) { return formatLength(value, units) + "^3"; }

std::string columnHeader(const char* name, const std::string& units, int power) {
  if (units == "model" || units.empty()) return name;
  return std::string(name) + ", " + units + (power > 1 ? "^" + std::to_string(power) : "");
}

std::string columnNumber(double value) {
  if (std::abs(value) >= 1000.0) return (value < 0 ? "-" : "") + groupDigits(int64_t(std::llround(std::abs(value))));
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g", value);
  return buf;
}

namespace {
// A section's title, with a term's marker beside it when there is a term.
void headingWith(const char* title, AppState* state, const char* term) {
  ImGui::Spacing();
  ImGui::TextColored(ImVec4(0.55f, 0.75f, 1.0f, 1.0f), "%s", title);
  if (state) termMarker(*state, term);
  ImGui::Separator();
}
}  // namespace

void heading(const char* title) { headingWith(title, nullptr, nullptr); }
void heading(const char* title, AppState& state, const char* term) { headingWith(title, &state, term); }

void helpMarker(const char* text) {
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  if (ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    ImGui::TextUnformatted(text);
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
}

bool beginFactTable(const char* id, float label_width) {
  if (!ImGui::BeginTable(id, 2, ImGuiTableFlags_RowBg)) return false;
  ImGui::TableSetupColumn("label", ImGuiTableColumnFlags_WidthFixed, label_width);
  ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch);
  return true;
}

void tableRow(const char* label, const std::string& value) {
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(0);
  ImGui::TextDisabled("%s", label);
  ImGui::TableSetColumnIndex(1);
  ImGui::TextWrapped("%s", value.c_str());
}

void markCell(ImVec2 area_min, ImVec2 area_max, ImVec2 cell_min, ImVec2 cell_max) {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 c((cell_min.x + cell_max.x) * 0.5f, (cell_min.y + cell_max.y) * 0.5f);
  const float half = std::max(3.5f, (cell_max.x - cell_min.x) * 0.5f);
  const ImU32 line = IM_COL32(255, 255, 255, 110);
  dl->AddLine(ImVec2(area_min.x, c.y), ImVec2(c.x - half - 1.0f, c.y), line);
  dl->AddLine(ImVec2(c.x + half + 1.0f, c.y), ImVec2(area_max.x, c.y), line);
  dl->AddLine(ImVec2(c.x, area_min.y), ImVec2(c.x, c.y - half - 1.0f), line);
  dl->AddLine(ImVec2(c.x, c.y + half + 1.0f), ImVec2(c.x, area_max.y), line);
  dl->AddRect(ImVec2(c.x - half - 1.0f, c.y - half - 1.0f), ImVec2(c.x + half + 1.0f, c.y + half + 1.0f),
              IM_COL32(0, 0, 0, 255));
  dl->AddRect(ImVec2(c.x - half, c.y - half), ImVec2(c.x + half, c.y + half), IM_COL32(255, 255, 255, 255));
}

void wrappedColoured(const ImVec4& colour, const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, colour);
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::PopStyleColor();
}

void drawScaleBar(ImVec2 at, float pixels_per_unit, const std::string& units, float max_px) {
  if (!(pixels_per_unit > 0.0f) || !(max_px > 8.0f)) return;
  // The longest round length (1, 2 or 5 times a power of ten) that fits in max_px.
  const double most = double(max_px) / double(pixels_per_unit);
  const double mag = std::pow(10.0, std::floor(std::log10(most)));
  double length = mag;
  for (double m : {2.0, 5.0}) {
    if (m * mag <= most) length = m * mag;
  }
  const float px = float(length) * pixels_per_unit;
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImU32 ink = ImGui::GetColorU32(ImGuiCol_Text);
  const float y = at.y + ImGui::GetTextLineHeight() * 0.5f;
  dl->AddLine(ImVec2(at.x, y), ImVec2(at.x + px, y), ink, 2.0f);
  dl->AddLine(ImVec2(at.x, y - 4.0f), ImVec2(at.x, y + 4.0f), ink, 2.0f);
  dl->AddLine(ImVec2(at.x + px, y - 4.0f), ImVec2(at.x + px, y + 4.0f), ink, 2.0f);
  char label[64];
  std::snprintf(label, sizeof label, "%g %s", length, units == "model" ? "model units" : units.c_str());
  dl->AddText(ImVec2(at.x + px + 6.0f, at.y), ink, label);
}

void peeledNotice(const AppState& state) {
  if (state.doc.model && !state.doc.model->round_peels.empty()) {
    wrappedColoured(kWarningColour, "On the model peeled by distance (" + state.doc.model->round_peels +
                                        "; Edit > Undo brings the part back).");
  }
  if (!state.doc.model || state.doc.model->peeled <= 0) return;
  wrappedColoured(kWarningColour, "On the model peeled by " + countOf(state.doc.model->peeled, "skin layer") +
                                      " (Skin > Reset skin for the whole part).");
}

namespace {
WidgetRecorder& widgetRecorder() {
  static WidgetRecorder recorder;
  return recorder;
}
}  // namespace

void markWidget(const std::string& name, const char* kind) {
  if (const WidgetRecorder& r = widgetRecorder()) r(name, kind, ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
}

void recordAt(const std::string& name, const char* kind, ImVec2 min, ImVec2 max) {
  if (const WidgetRecorder& r = widgetRecorder()) r(name, kind, min, max);
}

void setWidgetRecorder(WidgetRecorder recorder) { widgetRecorder() = std::move(recorder); }

void actionCheckbox(AppState& state, ActionId id, const char* label) {
  const Action& a = action(id);
  bool on = a.checked && a.checked(state);
  if (widget::Checkbox(label, &on)) dispatch(state, id);
}

void setToggle(AppState& state, ActionId id, bool on) { dispatchValues(state, id, {on ? "on" : "off"}); }

void termMarker(AppState& state, const char* key) {
  const Term* t = findTerm(key);
  if (!t) return;
  ImGui::SameLine();
  const std::string label = std::string("(?)##") + t->key;
  ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.0f, 0.0f, 0.0f, 0.0f));
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  const bool pressed = widget::SmallButton(label.c_str());
  ImGui::PopStyleColor(2);
  if (ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    ImGui::TextUnformatted(t->name);
    ImGui::TextUnformatted(t->text);
    ImGui::TextDisabled("Click for Help > Terms.");
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
  if (pressed) dispatchValues(state, ActionId::kTerms, {t->key});
}

}  // namespace vox::app
