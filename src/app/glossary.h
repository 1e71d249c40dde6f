#pragma once
// The terms the panels use, explained (Help > Terms, and a "(?)" beside each term where a panel shows it). No ImGui
// here: the panels draw them (panels/help_dialogs.cpp, ui.h's helpMarker).
#include <span>
#include <string>
#include <string_view>

namespace vox::app {

struct Term {
  const char* key;   // the script's word for it: "modulus", "suspect-voxels"
  const char* name;  // as the panels write it: "Modulus", "Suspect voxels"
  const char* text;  // what it means and what to do about it, in plain words
};

// Every term, in the order Help > Terms lists them.
std::span<const Term> glossary();
// The term `key` names (its key or its name, any case); null when none does.
const Term* findTerm(std::string_view key);
// "core, modulus, ...": every key, for an error that says which words are known.
std::string termKeys();

// What Help > Terms shows: whether to open it on the next frame, and the term to show first.
struct HelpUi {
  bool show_about = false;
  bool show_controls = false;   // Help > Mouse and keyboard
  bool show_terms = false;      // Help > Terms
  std::string term;             // the key of the term Help > Terms opens at (empty: the top)
  bool scroll_to_term = false;  // the dialog has just opened at `term`: scroll it into view
};

}  // namespace vox::app
