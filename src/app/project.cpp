#include "app/project.h"

#include <memory>
#include <string>
#include <utility>

#include "app/document.h"
#include "app/messages.h"
#include "app/parts.h"
#include "app/settings.h"
#include "app/update.h"
#include "vox/analysis/analysis.h"

namespace vox::app {

io::ProjectFile projectOf(const AppState& state) {
  io::ProjectFile p;
  if (!state.doc.model) return p;
  const ModelSnapshot& m = *state.doc.model;
  p.source = state.doc.path.string();
  if (m.origin) {
    p.origin = m.origin->what;
    p.resolution = m.origin->resolution;
  }
  p.units = m.grid.frame().units;
  p.base = m.base;
  p.shown = m.grid;
  p.peeled = m.peeled;
  p.round_peels = m.round_peels;
  if (m.parts) p.parts = *m.parts;
  p.panel = panelName(state.panel);
  p.section_axis = axisName(state.section.axis);
  p.section_index = state.section.index;
  p.selected = state.parts_ui.selected;
  return p;
}

namespace {

void setPanelNamed(AppState& state, const std::string& name) {
  for (int i = 0; i < kPanelCount; ++i) {
    if (name == panelName(Panel(i))) {
      state.panel = Panel(i);
      state.panel_change_requested = true;
    }
  }
}

}  // namespace

void applyProject(AppState& state, io::ProjectFile p, const std::filesystem::path& path, bool recovered) {
  auto origin = std::make_shared<ModelOrigin>();
  origin->what = (recovered ? "recovered " : "project ") + path.filename().string() +
                 (p.origin.empty() ? std::string() : ": " + p.origin);
  origin->resolution = p.resolution;
  std::shared_ptr<const Assembly> parts;
  if (p.parts) {
    parts = std::make_shared<const Assembly>(std::move(*p.parts));
    if (p.base.empty()) {
      p.base = partsUnion(*parts);
      p.shown = p.base;
    }
  }
  const std::string label = (recovered ? "recover " : "open ") + path.filename().string();
  ModelSnapshot snap = newBase(state, std::move(p.base), std::move(origin), label);
  snap.grid = std::move(p.shown);
  snap.peeled = p.peeled;
  snap.round_peels = p.round_peels;
  snap.parts = std::move(parts);
  state.parts_ui.selected = p.selected;
  setModel(state, std::move(snap), false);
  setModelUnits(state, p.units);
  if (auto axis = parseAxis(p.section_axis)) state.section.axis = *axis;
  if (p.section_index >= 0 && p.section_index < axisLength(state, state.section.axis)) {
    state.section.index = p.section_index;
  }
  setPanelNamed(state, p.panel);
  if (recovered) {
    state.doc.saved_version = 0;  // nothing on disk holds it: unsaved until the user saves it
  } else {
    state.doc.save_path = path;
    state.doc.saved_version = state.doc.model->version;
  }
}

}  // namespace vox::app
