#pragma once
// Autosave and recovery. While the document has unsaved changes it is written as a project (project.h) in the
// background, at most every `interval_s` seconds, to this window's file in the autosave folder
// ($VOXMOD_AUTOSAVE_DIR, else $XDG_STATE_HOME/voxmod/autosave or ~/.local/state/voxmod/autosave). Saving the
// document, closing it with nothing unsaved, or quitting the window removes the file. A window that starts and finds
// the file of a window that is gone (a crash, a kill) offers to recover it. A script run (--script) autosaves only
// when VOXMOD_AUTOSAVE_DIR says where. VOXMOD_AUTOSAVE_SECONDS sets the interval (default 30 s).
#include <filesystem>
#include <string>
#include <vector>

#include "app/app_state.h"

namespace vox::app {

// Where this window autosaves (`scripted`: a --script run), and the autosaves of windows that are gone, newest first.
void initAutosave(AppState& state, bool scripted);
// Each frame: a finished write taken in, a new one started when the document changed and the interval has passed,
// the file removed once nothing is unsaved.
void updateAutosave(AppState& state);
// The window closes normally: a write under way finishes and the file is removed (nothing needs recovering).
void finishAutosave(AppState& state);
// Whether a write is under way (the script harness waits for it as for other background work).
bool autosaveBusy(const AppState& state);

// The recovery offer's answers: open the newest orphan as an unsaved document (its file then becomes this
// window's autosave), or delete it. Each leaves the next orphan, if any, to be offered.
void recoverAutosave(AppState& state);
void discardAutosave(AppState& state);
// A recovered autosave has become the document: its file becomes this window's autosave.
void adoptRecovered(AppState& state, const std::filesystem::path& orphan);

}  // namespace vox::app
