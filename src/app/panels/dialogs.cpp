// Dialogs: job progress with Cancel, errors and the unsaved-changes prompt. The Voxelize dialog is
// voxelize_dialog.cpp, Help's dialogs help_dialogs.cpp.
#include <cstdio>
#include <string>
#include <utility>

#include <imgui.h>

#include "app/actions.h"
#include "app/operations.h"
#include "app/panels/panels.h"
#include "app/ui.h"

namespace vox::app {

void centreNextWindow() {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + vp->Size.x * 0.5f, vp->Pos.y + vp->Size.y * 0.5f), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
}

void drawJobWindow(AppState& state) {
  const bool loading = state.load_job.active();
  if (!loading && !state.voxelize_job.active()) return;
  const std::string label = loading ? state.load_job.label() : state.voxelize_job.label();
  const double progress = loading ? state.load_job.progress() : state.voxelize_job.progress();
  const bool cancelling = loading ? state.load_job.cancelRequested() : state.voxelize_job.cancelRequested();

  // Not modal: the window keeps drawing the current model and its panels while the worker runs.
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + vp->Size.x * 0.5f + 180.0f, vp->Pos.y + vp->Size.y - 120.0f),
                          ImGuiCond_Always, ImVec2(0.5f, 1.0f));
  ImGui::SetNextWindowSize(ImVec2(420.0f, 0.0f));
  ImGui::Begin("Working", nullptr,
               ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::TextUnformatted(label.c_str());
  char overlay[48];
  std::snprintf(overlay, sizeof overlay, "%.0f%%   %.1f s", progress * 100.0, nowSeconds() - state.job_started);
  ImGui::ProgressBar(float(progress), ImVec2(-1.0f, 0.0f), overlay);
  if (cancelling) {
    ImGui::TextDisabled("Cancelling...");
  } else if (widget::Button("Cancel")) {
    dispatch(state, ActionId::kCancelJob);
  }
  ImGui::End();
}

void drawErrorDialog(AppState& state) {
  if (state.errors.messages.empty()) return;
  if (!ImGui::IsPopupOpen("Error")) {
    ImGui::OpenPopup("Error");
    state.errors.shown_frame = ImGui::GetFrameCount();
  }
  centreNextWindow();
  ImGui::SetNextWindowSizeConstraints(ImVec2(360.0f, 0.0f), ImVec2(720.0f, 600.0f));
  if (ImGui::BeginPopupModal("Error", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::PushTextWrapPos(680.0f);
    ImGui::TextUnformatted(state.errors.messages.front().c_str());
    ImGui::PopTextWrapPos();
    if (state.errors.messages.size() > 1) ImGui::TextDisabled("(%zu more)", state.errors.messages.size() - 1);
    ImGui::Spacing();
    // Enter or Escape close it, but not the very press that raised the error (Enter in a file name field).
    const bool keys = ImGui::GetFrameCount() > state.errors.shown_frame &&
                      (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false) ||
                       ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false));
    if (widget::Button("OK", ImVec2(120.0f, 0.0f)) || keys) {
      state.errors.messages.erase(state.errors.messages.begin());
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
}

void drawUnsavedPrompt(AppState& state) {
  if (state.unsaved_prompt_requested) {
    state.unsaved_prompt_requested = false;
    ImGui::OpenPopup("Unsaved changes");
  }
  centreNextWindow();
  if (!ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  if (state.close_dialogs) state.after_unsaved_prompt = nullptr;  // as Cancel
  ImGui::Text("The model of %s has changes that are not saved.", documentName(state).c_str());
  if (state.doc.model) ImGui::TextDisabled("Last change: %s", state.doc.model->label.c_str());
  ImGui::Spacing();
  auto then = [&state] {
    auto f = std::move(state.after_unsaved_prompt);
    state.after_unsaved_prompt = nullptr;
    return f;
  };
  const bool save = widget::Button("Save", ImVec2(110.0f, 0.0f));
  markWidget("prompt_save");
  if (save) {
    ImGui::CloseCurrentPopup();
    runBetweenFrames(state, "Save", [f = then()](AppState& s) { saveThen(s, f); });
  }
  ImGui::SameLine();
  const bool discard = widget::Button("Discard", ImVec2(110.0f, 0.0f));
  markWidget("prompt_discard");
  if (discard) {
    ImGui::CloseCurrentPopup();
    if (auto f = then()) runBetweenFrames(state, "Discard", std::move(f));
  }
  ImGui::SameLine();
  const bool cancel = widget::Button("Cancel", ImVec2(110.0f, 0.0f));
  markWidget("prompt_cancel");
  if (cancel || state.close_dialogs || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
    ImGui::CloseCurrentPopup();
    then();
  }
  ImGui::EndPopup();
}

}  // namespace vox::app

namespace vox::app {

// At start-up, when a window that is gone left unsaved work: recover it, discard it, or decide later (File > Recover
// unsaved work stays there).
void drawRecoveryOffer(AppState& state) {
  AutosaveState& a = state.autosave;
  if (a.orphans.empty() || a.offer_dismissed || !state.errors.messages.empty()) return;
  if (!ImGui::IsPopupOpen("Recover unsaved work")) {
    // Opened over nothing: another dialog (voxelize, unsaved changes) is answered first.
    if (ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel)) return;
    ImGui::OpenPopup("Recover unsaved work");
  }
  centreNextWindow();
  if (!ImGui::BeginPopupModal("Recover unsaved work", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  const OrphanAutosave& o = a.orphans.front();
  ImGui::Text("voxmod did not close properly. Unsaved work on %s was kept (%s).", o.document.c_str(), o.when.c_str());
  if (a.orphans.size() > 1) ImGui::TextDisabled("(%zu more)", a.orphans.size() - 1);
  ImGui::TextDisabled("Recover opens it as an unsaved document; Discard deletes it.");
  ImGui::Spacing();
  const bool busy = !actionEnabled(state, action(ActionId::kRecoverAutosave));  // a file still opening
  ImGui::BeginDisabled(busy);
  if (widget::Button("Recover", ImVec2(110.0f, 0.0f))) {
    ImGui::CloseCurrentPopup();
    dispatch(state, ActionId::kRecoverAutosave);
  }
  ImGui::SameLine();
  if (widget::Button("Discard", ImVec2(110.0f, 0.0f))) {
    ImGui::CloseCurrentPopup();
    dispatch(state, ActionId::kDiscardAutosave);
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (widget::Button("Later", ImVec2(110.0f, 0.0f)) || state.close_dialogs) {
    ImGui::CloseCurrentPopup();
    a.offer_dismissed = true;
  }
  ImGui::EndPopup();
}

}  // namespace vox::app
