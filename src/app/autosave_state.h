#pragma once
// What autosave and recovery keep between frames (autosave.h).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "app/job.h"

namespace vox::app {

// A window's autosave found at start-up whose window is gone (autosave.h).
struct OrphanAutosave {
  std::filesystem::path path;
  std::string document;  // the name of the document it holds ("part.stl")
  std::string when;      // when it was written, local time ("2026-12-06 18:30")
};

// Autosave and recovery (autosave.h).
struct AutosaveState {
  std::filesystem::path dir;   // empty: autosave is off
  std::filesystem::path file;  // this window's autosave
  double interval_s = 30.0;
  // What the file holds (the model version, its parts, the undo depth and the view it was written for) and when it
  // was written.
  struct Key {
    uint64_t version = 0;
    const void* parts = nullptr;
    size_t undo_depth = 0;
    // The view the project keeps.
    int panel = 0;
    int section_axis = 0;
    int32_t section_index = -1;
    std::vector<size_t> selected;
    bool operator==(const Key&) const = default;
  };
  Key written;
  bool file_written = false;
  double last_write = 0.0;
  Job<Key> job;
  std::string last_error;  // the last write that failed (shown in the status bar once)
  // Recovery: autosaves of windows that are gone, newest first; the offer is shown while there are some, until the
  // user answers "Later".
  std::vector<OrphanAutosave> orphans;
  bool offer_dismissed = false;
  bool keep_on_exit = false;  // the run ends as a kill would (a script's `exit`): the file stays
};

}  // namespace vox::app
