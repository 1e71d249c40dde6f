// The Parts entries of the action table (actions.cpp): splitting into bodies, adding a part, Booleans, removing,
// selecting and showing parts, and the interference list. Part numbers in scripts count from 1, as the panel shows.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <system_error>
#include <utility>

#include "app/action_functions.h"
#include "app/file_browsing.h"
#include "app/messages.h"
#include "app/operations.h"
#include "app/parts.h"
#include "vox/core/text.h"

namespace vox::app::actions {
namespace {

// A part number from 1 (as the panel lists them) to an index.
Result<size_t> partIndex(const AppState& s, const std::string& word) {
  const Assembly* parts = currentParts(s);
  int64_t n = 0;
  if (!parts || !parseNumber(word, n) || n < 1 || n > int64_t(parts->size())) {
    return badValues("part numbers go from 1 to " + std::to_string(parts ? parts->size() : 0) + ", not '" + word + "'");
  }
  return size_t(n - 1);
}

void showParts(AppState& s) {
  s.panel = Panel::kParts;
  s.panel_change_requested = true;
}

}  // namespace

bool hasParts(const AppState& s) { return currentParts(s) != nullptr && !partsBusy(s) && !modelBusy(s); }
bool canSplit(const AppState& s) {
  return s.doc.model.has_value() && !currentParts(s) && !partsBusy(s) && !modelBusy(s);
}
bool canAddPart(const AppState& s) { return !partsBusy(s) && !modelBusy(s); }
bool hasInterference(const AppState& s) { return currentInterference(s) != nullptr; }

void panelParts(AppState& s) { showParts(s); }
bool onParts(const AppState& s) { return s.panel == Panel::kParts; }

void splitBodies(AppState& s) {
  startSplitBodies(s);
  showParts(s);
}

Status splitBodiesWith(AppState& s, const ActionArgs& a) {
  if (a.words[0] == "6") {
    s.parts_ui.connectivity = Connectivity::kFace;
  } else if (a.words[0] == "26") {
    s.parts_ui.connectivity = Connectivity::kAll;
  } else {
    return badValues("split-bodies takes 6 or 26 (face or full connectivity), not '" + a.words[0] + "'");
  }
  splitBodies(s);
  return Ok{};
}

void addPartDialog(AppState& s) {
  openBrowser(s, {ActionId::kAddPart, "Add a part from a mesh or voxel file (on the scene's lattice)",
                  openableExtensions(false), "", false});
}
Status addPartPath(AppState& s, const ActionArgs& a) {
  usePath(s, a.rest, PathSays::kNothing, [](AppState& st, const std::filesystem::path& path) {
    if (!isExistingFile(st, path)) return false;
    startAddPart(st, path);
    return true;
  });
  showParts(s);
  return Ok{};
}

void booleanSelected(AppState& s) {
  if (s.parts_ui.selected.size() < 2) {
    reportError(s, "select two parts for a Boolean (Ctrl+click the second)");
    return;
  }
  if (Status r = partBoolean(s, s.parts_ui.op, s.parts_ui.selected[0], s.parts_ui.selected[1]); !r) {
    reportError(s, r.error().message);
  }
}

Status booleanWith(AppState& s, const ActionArgs& a) {
  const auto op = parsePartOp(a.words[0]);
  if (!op) return badValues("unknown Boolean '" + a.words[0] + "' (union, intersection, difference or xor)");
  s.parts_ui.op = *op;
  if (a.words.size() == 1) {
    booleanSelected(s);
    return Ok{};
  }
  if (a.words.size() != 3) return badValues("part-boolean takes OP, or OP A B");
  auto i = partIndex(s, a.words[1]);
  if (!i) return i.error();
  auto j = partIndex(s, a.words[2]);
  if (!j) return j.error();
  return partBoolean(s, *op, *i, *j);
}

void removeSelected(AppState& s) {
  if (s.parts_ui.selected.empty()) return;
  if (Status r = removePart(s, s.parts_ui.selected.front()); !r) reportError(s, r.error().message);
}

Status removeAt(AppState& s, const ActionArgs& a) {
  auto i = partIndex(s, a.words[0]);
  if (!i) return i.error();
  return removePart(s, *i);
}

void findInterferenceNow(AppState& s) {
  startInterference(s);
  showParts(s);
}

Status showPairAt(AppState& s, const ActionArgs& a) {
  const Interference* inter = currentInterference(s);
  int64_t n = 0;
  if (!parseNumber(a.words[0], n) || n < 0 || n > int64_t(inter->pairs.size())) {
    return badValues("interference pairs go from 1 to " + std::to_string(inter->pairs.size()) + " (0: none)");
  }
  showInterferencePair(s, int32_t(n) - 1);
  showParts(s);
  return Ok{};
}

Status contactAt(AppState& s, const ActionArgs& a) {
  double v = 0.0;
  if (!parseNumber(a.words[0], v) || !(v >= 0.0) || !std::isfinite(v)) {
    return badValues("contact takes a thickness >= 0 in model units (0: every shared voxel interferes)");
  }
  s.parts_ui.contact = v;
  showParts(s);
  return Ok{};
}

Status selectPartsAt(AppState& s, const ActionArgs& a) {
  // "add N": a Ctrl+click, N added to the selection or taken out of it; else the parts named are the selection.
  const bool add = a.words[0] == "add";
  if (add && a.words.size() != 2) return badValues("select-part add takes one part number");
  std::vector<size_t> chosen;
  for (size_t k = add ? 1 : 0; k < a.words.size(); ++k) {
    auto i = partIndex(s, a.words[k]);
    if (!i) return i.error();
    chosen.push_back(*i);
  }
  for (size_t k = 0; k < chosen.size(); ++k) selectPart(s, chosen[k], add || k > 0);
  return Ok{};
}

Status partVisibleAt(AppState& s, const ActionArgs& a) {
  auto i = partIndex(s, a.words[0]);
  if (!i) return i.error();
  if (a.words[1] != "on" && a.words[1] != "off") return badValues("part-visible takes N on|off");
  setPartVisible(s, *i, a.words[1] == "on");
  return Ok{};
}

Status partsScopeAt(AppState& s, const ActionArgs& a) {
  if (a.words[0] != "union" && a.words[0] != "selected") {
    return badValues("parts-scope takes union or selected, not '" + a.words[0] + "'");
  }
  setPartsScope(s, a.words[0] == "selected");
  return Ok{};
}

Status placePartAt(AppState& s, const ActionArgs& a) {
  auto i = partIndex(s, a.words[0]);
  if (!i) return i.error();
  if (a.words.size() != 4 && a.words.size() != 7) return badValues("place-part takes N TX TY TZ [QX QY QZ]");
  glm::dvec3 t(0.0);
  for (int k = 0; k < 3; ++k) {
    if (!parseNumber(a.words[size_t(1 + k)], t[k])) {
      return badValues("place-part: '" + a.words[size_t(1 + k)] + "' is not a translation in model units");
    }
    if (Status st = checkTranslation(s, t[k]); !st) return st;
  }
  PartPlacement p = placementWithTranslation(s, *i, t);
  if (a.words.size() == 7) {
    for (int k = 0; k < 3; ++k) {
      int q = 0;
      if (!parseNumber(a.words[size_t(4 + k)], q)) {
        return badValues("place-part: '" + a.words[size_t(4 + k)] + "' is not a number of quarter turns");
      }
      p.quarter_turns[k] = ((q % 4) + 4) % 4;
    }
  }
  return placePart(s, *i, p);
}

Status turnPartAt(AppState& s, const ActionArgs& a) {
  auto i = partIndex(s, a.words[0]);
  if (!i) return i.error();
  const std::string& w = a.words[1];
  const int axis = w == "x" ? 0 : w == "y" ? 1 : w == "z" ? 2 : -1;
  if (axis < 0) return badValues("turn-part takes N x|y|z, not '" + w + "'");
  return placePart(s, *i, placementTurned(s, *i, axis));
}

Status partColourAt(AppState& s, const ActionArgs& a) {
  auto i = partIndex(s, a.words[0]);
  if (!i) return i.error();
  // A last word "drag": the colour picker's drag goes on (one undo step for the whole drag).
  std::vector<std::string> words = a.words;
  const bool drag = words.back() == "drag";
  if (drag) words.pop_back();
  glm::vec3 c(0.0f);
  if (words.size() == 2) {
    const std::string& w = words[1];
    unsigned v = 0;
    if (w.size() != 7 || w[0] != '#' ||
        std::from_chars(w.data() + 1, w.data() + w.size(), v, 16).ptr != w.data() + w.size()) {
      return badValues("part-colour takes N #rrggbb or N R G B (0 to 1), not '" + w + "'");
    }
    c = glm::vec3(float((v >> 16) & 255u), float((v >> 8) & 255u), float(v & 255u)) / 255.0f;
  } else if (words.size() == 4) {
    for (int k = 0; k < 3; ++k) {
      if (!parseNumber(words[size_t(1 + k)], c[k]) || c[k] < 0.0f || c[k] > 1.0f) {
        return badValues("part-colour: '" + words[size_t(1 + k)] + "' is not a colour component from 0 to 1");
      }
    }
  } else {
    return badValues("part-colour takes N #rrggbb or N R G B (0 to 1), then drag while the picker is dragged");
  }
  setPartColour(s, *i, c, drag);
  return Ok{};
}

bool hasPartsNow(const AppState& s) { return currentParts(s) != nullptr; }
void savePartsDialog(AppState& s) {
  openBrowser(s, {ActionId::kSaveParts,
                  "Save each part as a .vxm file into a folder (type its name; all files are written or none)",
                  {},
                  documentStem(s) + "_parts"});
}
Status savePartsPath(AppState& s, const ActionArgs& a) {
  // saveParts says how many files it wrote where; its failure is this action's (the browser shows it)
  Status result = Ok{};
  usePath(s, a.rest, PathSays::kNothing, [&result](AppState& st, const std::filesystem::path& path) {
    result = saveParts(st, path);
    return result.ok();
  });
  return result;
}

void clearanceSelected(AppState& s) {
  if (s.parts_ui.selected.size() < 2) {
    reportError(s, "select two parts for their clearance (Ctrl+click the second)");
    return;
  }
  startClearance(s, s.parts_ui.selected[0], s.parts_ui.selected[1]);
  showParts(s);
}

Status clearanceAt(AppState& s, const ActionArgs& a) {
  auto i = partIndex(s, a.words[0]);
  if (!i) return i.error();
  auto j = partIndex(s, a.words[1]);
  if (!j) return j.error();
  if (*i == *j) return badValues("the clearance needs two different parts");
  s.parts_ui.selected = {*i, *j};
  s.viewport.dirty = true;
  if (s.parts_ui.scope_selected) applyPartsScope(s);
  startClearance(s, *i, *j);
  showParts(s);
  return Ok{};
}

bool interferenceRunning(const AppState& s) { return s.interference_job.active(); }
void cancelInterferenceNow(AppState& s) { cancelInterference(s); }

}  // namespace vox::app::actions
