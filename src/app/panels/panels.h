#pragma once
// The window's panels and dialogs, each a function of the AppState (docs/architecture.md, "The window (app)"). Widgets
// edit params structs in the state and dispatch actions (actions.h) or call operations (operations.h); no panel loops
// over voxels.
#include <string>
#include <vector>

#include <imgui.h>

#include "app/app_state.h"

namespace vox::app {

// The whole frame: menu bar, side panel, 3D view, image view, status bar and dialogs.
void drawFrame(AppState& state);

// Menu bar generated from the action table, plus Open Recent.
void drawMainMenu(AppState& state);
// Runs the action of every shortcut key pressed since the last frame (not while a text field has the keyboard or
// a dialog is open).
void handleShortcuts(AppState& state);
void drawStatusBar(AppState& state);

// Side panel tabs.
void drawModelPanel(AppState& state);
void drawSectionPanel(AppState& state);
void drawSkinPanel(AppState& state);
void drawXrayPanel(AppState& state);
void drawMassPanel(AppState& state);
void drawThicknessPanel(AppState& state);
void drawPartsPanel(AppState& state);    // parts of a scene, Booleans, interference (parts_panel.cpp)
void drawPrintPanel(AppState& state);    // overhangs, support, trapped cavities, the best way up (print_panel.cpp)
void drawCastingPanel(AppState& state);  // alloy, mould, feeders, the run, hot spots, verdict (casting_panel.cpp)
// The model's length units (units_choice.cpp): a combo dispatching model-units, and while the units are not known
// ("model units") a prompt saying why they matter here, with the combo (false when they are known: nothing drawn).
void drawUnitsCombo(AppState& state, const char* label);
bool drawUnitsPrompt(AppState& state, const char* why);

// The 2D images beside the 3D view (Section and X-ray panels).
void drawSectionImage(AppState& state);
void drawXrayImage(AppState& state);
void drawThicknessImage(AppState& state);  // the section coloured by thickness (Thickness panel)
void drawCastingImage(AppState& state);  // the section coloured by freezing time, Niyama or modulus (casting_image.cpp)
// Room the X-ray image needs besides its map (title, colour bar and labels, read-out), in screen pixels.
ImVec2 xrayLegendSize();

// Dialogs.
void drawVoxelizeDialog(AppState& state);
void drawFileBrowser(AppState& state);
bool fileBrowserOpen();  // the file browser's popup is open (it then draws the error dialog itself)
void drawErrorDialog(AppState& state);
void drawUnsavedPrompt(AppState& state);
void drawRecoveryOffer(AppState& state);
void drawAboutDialog(AppState& state);
void drawControlsDialog(AppState& state);  // Help > Mouse and keyboard
void drawTermsDialog(AppState& state);     // Help > Terms (glossary.h), at the term asked for
// Progress of the running load or voxelization, with Cancel.
void drawJobWindow(AppState& state);

// ---- Parts the panel files share (each defined in the file named) ----

// thickness_lists.cpp: a scrolling table of `columns` columns showing at most `shown` of its `rows` rows at once,
// its header row frozen. Call ImGui::EndTable() when it returns true.
bool beginScrollList(const char* id, int columns, int rows, int shown);

// frame.cpp, status_bar.cpp: the flags of the fixed windows of the layout.
inline constexpr ImGuiWindowFlags kFixedWindow = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                                 ImGuiWindowFlags_NoSavedSettings |
                                                 ImGuiWindowFlags_NoBringToFrontOnFocus;

// image_layout.cpp: how the main area is shared between the 3D view and the 2D image of the Section and X-ray
// panels: beside or below the view, whichever shows the image larger, with the image taking the room it can use
// (35-60%).
struct ImageLayout {
  ImVec2 view;
  ImVec2 image{0.0f, 0.0f};  // zero: no image
  ImVec2 image_offset{0.0f, 0.0f};
};
ImageLayout layoutImage(AppState& state, float w, float h);

// section_image.cpp: image axes of a section (vox/analysis/analysis.h): which grid axis runs right and which runs up.
struct ImageAxes {
  int right, up;
};
ImageAxes imageAxes(Axis a);

// xray_colour_bar.cpp: the colour bar beside the X-ray map drawn at map0 with the given size: 0 at the bottom, the
// maximum at the top. Returns its height.
float drawXrayColourBar(const XrayResult& x, const ScalarMapLegend& legend, ImVec2 map0, ImVec2 size);

// thickness_lists.cpp: the Thickness panel's thin-wall regions and hot spots; a click moves the section there.
void drawThinWallList(AppState& state, const Walls& thin, const std::string& units);
void drawHotSpotList(AppState& state, const ThicknessResult& r, const std::string& units);

// dialogs.cpp: the next window appears at the middle of the main viewport.
void centreNextWindow();
// voxelize_plan.cpp: the Voxelize dialog's plan and warnings for the mesh; returns whether Voxelize can start.
bool drawVoxelizePlan(const AppState& state, const VoxelizeDialog& d, const MeshSource& mesh);

// file_listing.cpp: the file browser's listing and the widgets that move through it.
// The name ends in one of the extensions (lower case, with the dot), whatever the name's case.
bool matchesExtension(const std::string& name, const std::vector<std::string>& extensions);
// Lists the browser's directory into its entries: folders first, then the files that match the purpose (all with
// "All files"), hidden ones left out; a directory that cannot be read sets its error.
void listDirectory(FileBrowser& b);
// Up, Home and the path field.
void drawBrowserNavigation(FileBrowser& b);
// The entries above a footer of the given height; returns whether a file was double-clicked (to open or
// save it).
bool drawBrowserEntries(FileBrowser& b, float footer);

}  // namespace vox::app
