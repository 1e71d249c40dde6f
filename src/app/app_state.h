#pragma once
// Everything the window knows, in one struct passed by reference to the panels (no globals): the document (mesh,
// model, undo stack), the params structs the widgets edit, the background jobs, the caches of derived results and
// the UI flags. Panels read it and edit the params; changes to the model go through the operations in
// operations.h, which the action table, the panels and the script share.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "app/autosave_state.h"
#include "app/job.h"
#include "app/parts_state.h"
#include "app/casting_state.h"
#include "app/file_browser_state.h"
#include "app/glossary.h"
#include "app/print_state.h"
#include "app/viewport_state.h"
#include "app/settings.h"
#include "app/texture.h"
#include "vox/analysis/analysis.h"
#include "vox/analysis/oblique_section.h"
#include "vox/analysis/assembly.h"
#include "vox/analysis/thickness.h"
#include "vox/analysis/ray_thickness.h"
#include "vox/analysis/walls.h"
#include "vox/core/assembly.h"
#include "vox/core/mesh.h"
#include "vox/core/voxel_grid.h"
#include "vox/io/mesh_file.h"
#include "vox/io/project_file.h"
#include "vox/render/camera.h"
#include "vox/render/framebuffer.h"
#include "vox/render/point_renderer.h"
#include "vox/voxelize/voxelize.h"
#include "vox/core/text.h"

struct GLFWwindow;

namespace vox::app {

struct AppState;

// ---- The document ----

// The mesh or CAD file a document was opened from (kept so it can be voxelized again at another resolution).
struct MeshSource {
  std::filesystem::path path;
  TriangleMesh mesh;
  MeshTopology topology;
  std::string format;                 // "binary STL", "3MF", "STEP (AUTOMOTIVE_DESIGN)", ...
  std::vector<io::MeshBody> bodies;   // the file's solids / objects, ranges of mesh.triangles
  std::string units = "model";        // what the coordinates are in (CAD files: mm)
  std::string file_units;             // as the file names its unit; empty when it names none
  std::vector<std::string> warnings;  // from the reader: degenerate triangles, not watertight
  std::vector<std::string> notes;     // from the reader: information (closed once exporter noise is welded)
  double load_s = 0.0;
  double volume = 0.0;  // signed volume of the mesh (model units cubed), for comparison with the voxel volume
  // CAD files: the exact geometry and the deflection the mesh was made with; a finer grid tessellates it again.
  std::shared_ptr<const io::CadModel> cad;
  double deflection = 0.0;
};

// A MeshSource from what io::loadMeshFile (or a CAD tessellation) gave.
std::shared_ptr<MeshSource> makeMeshSource(const std::filesystem::path& path, io::MeshFileLoad&& load);

// How a model grid came about (shown in the Model panel).
struct ModelOrigin {
  std::string what;       // "voxelized at R=200 (nonzero)", "loaded part.vxm"
  std::string mode_used;  // voxelized: the fill mode, and why
  std::string mode_reason;
  int64_t resolution = 0;
  double voxelize_s = 0.0;
  double load_s = 0.0;
  std::vector<std::string> warnings;
  // Vote mode: voxels on which the three axes disagreed (sparse; expanded into a grid only while shown).
  std::shared_ptr<const SparseVoxels> disputed;
  int64_t disputed_count = 0;
};

// One state of the model: what the undo stack stores. Copies are cheap (grid layers are shared copy-on-write).
struct ModelSnapshot {
  uint64_t base_id = 0;  // unique per distinct base grid: keys the depth map
  uint64_t version = 0;  // unique per state: keys the caches of derived results
  VoxelGrid base;        // as voxelized or loaded
  int32_t peeled = 0;    // skin layers removed from base
  VoxelGrid grid;        // the model: base minus its outer `peeled` layers (kept, so undo needs no depth map)
  std::shared_ptr<const ModelOrigin> origin;
  std::string label;  // the change that produced this state, for "Undo <label>"
  // The round peels (peel by distance) that made `base` from the part, e.g. "0.5 mm + 0.2 mm"; empty: none. Each
  // makes a new base, so layer peels continue from what it left.
  std::string round_peels;
  // A scene of parts on one lattice (split into bodies, added from files, Booleans: app/parts.h); null for one model.
  // `base` and `grid` then hold the union of the parts on the frame of the assembly's extent.
  std::shared_ptr<const Assembly> parts;
};

struct Document {
  std::filesystem::path path;              // the file opened (mesh or voxel file); empty when nothing is open
  std::shared_ptr<const MeshSource> mesh;  // when opened from a mesh or CAD file
  std::optional<ModelSnapshot> model;      // none until the mesh is voxelized
  std::vector<ModelSnapshot> undo_stack, redo_stack;
  std::filesystem::path save_path;  // where Save writes; empty until saved once (or loaded from a voxel file)
  // The model version that matches a file on disk; the model is "unsaved" when it differs.
  uint64_t saved_version = 0;
  // > 1: the model is a coarse view of `path` at this level (each level^3 block of the file's voxels is one voxel,
  // filled when any of its voxels is), because the file's grid does not fit in memory; Save does not overwrite it.
  int32_t coarse_level = 1;
  Dims full_dims;  // the file's own dims, when coarse_level > 1
};

// ---- Params the widgets edit ----

enum class Panel { kModel, kSection, kSkin, kXray, kMass, kThickness, kParts, kPrint, kCasting };
inline constexpr int kPanelCount = 9;
const char* panelName(Panel p);  // "model", "section", ...

struct ViewParams {
  // Looking down on the XY plane from the +Z side, turned a little so that three faces of a box show.
  render::Camera camera{.yaw_deg = 30.0, .pitch_deg = 25.0};
  bool fit_pending = true;  // refit the camera to the model on the next draw
  bool lit = true;          // lit table, or the thesis's classic table
  bool round_points = false;
  float point_size_px = 0.0f;  // fixed point diameter in pixels; 0: automatic (closes the surface)
  bool lod = true;             // coarser points while the mouse drags the view or a slider
  bool cut_away = true;        // show the section as a 3D cut-away while the Section panel is open
  bool keep_above = false;     // cut-away keeps the half above the plane instead of below
  bool show_disputed = false;
  bool show_core = true;  // draw the thickest core over the model while the Skin panel is open
};

struct SectionUi {
  Axis axis = Axis::kZ;
  int32_t index = -1;  // -1: the middle, set when a model arrives
  // At any angle (section-plane): the plane with this normal, `offset` model units along it (the unit normal) from
  // the centre of the model's box. The 3D view's cut-away follows it.
  bool oblique = false;
  glm::dvec3 normal{1.0, 1.0, 0.0};
  double offset = 0.0;
  // The axis section's picture zoomed (section-zoom): 1 shows it whole; `centre` is the point shown in its middle, as
  // fractions of the picture's width (right) and height (up).
  double zoom = 1.0;
  glm::dvec2 centre{0.5, 0.5};
  bool playing = false;
  int32_t step = 1;
  float play_speed = 15.0f;  // sections per second while playing
  double play_accumulator = 0.0;
};

struct SkinUi {
  int32_t peel_count = 5;               // "Peel N"
  std::optional<int32_t> pending_peel;  // a peel asked for before the depth map was ready
  float peel_distance = 0.0f;           // "Peel by distance": model units (0: not chosen yet, one voxel is offered)
  uint64_t cancelled_base = 0;          // the base whose skin layers the user cancelled (not asked again until retried)
};

struct XrayUi {
  XrayParams params;
};

// Voxels picked for measuring (app/measure.h), on the lattice of `dims`.
struct MeasureUi {
  std::vector<glm::ivec3> picks;   // the pair being measured
  std::vector<glm::ivec3> recent;  // the last three picks, oldest first (a section's plane can go through them)
  Dims dims{0, 0, 0};
};

// The Mass panel's material: a density in kg/m^3 (0: unit density) and the name it came from.
struct MassUi {
  std::string material = "unit density";
  double density = 0.0;
};

struct VoxelizeDialog {
  bool open_requested = false;
  VoxelizeParams params;
  bool by_voxel_size = false;
  std::string proposal_note;  // why the dialog proposes another resolution than the last one used
};

// The actions of the window's table (app/actions.h): the file browser gives its path to one of them.
// ---- Caches of results derived from the model (recomputed when their key changes) ----

struct SectionKey {
  uint64_t model_version = 0;
  Axis axis = Axis::kZ;
  int32_t index = -1;
  bool operator==(const SectionKey&) const = default;
};
struct XrayKey {
  uint64_t model_version = 0;
  Axis axis = Axis::kZ;
  XrayMode mode = XrayMode::kTotal;
  bool operator==(const XrayKey&) const = default;
};

// Distance, local thickness and hot spots of one model version (the Thickness panel's background result).
struct ThicknessResult {
  uint64_t id = 0;  // this computation's (takeId): what the views and thin walls derived from it are keyed by
  VoxelGrid grid;   // the voxels it was computed from (sharing their layers)
  Thickness thickness;
  std::vector<HotSpot> hot_spots;
  WallRidge ridge;            // the wall stops, from which the walls under any minimum wall are found
  double distance_max = 0.0;  // the deepest voxel's distance from the surface, model units (the rays' paint limit)
  double seconds = 0.0;
};

// The Thickness panel: the minimum wall (model units; < 0: not chosen, a quarter of the maximum is used) and the
// thin walls under it, found in the background when the value or the model changes (AppState::thin_walls).
struct WallsKey {
  uint64_t result = 0;  // ThicknessResult::id
  double min_wall = -1.0, min_area = -1.0;
  bool operator==(const WallsKey&) const = default;
};
struct ThicknessUi {
  double min_wall = -1.0;
  double min_area = -1.0;       // walls with less exposed area are specks, counted not listed (model units^2; < 0: W^2)
  float wall_drag = -1.0f;      // the slider's value while it is dragged (< 0: not dragged); applied when let go
  bool ray = false;             // the views show the ray thickness (vox/analysis/ray_thickness.h), not local thickness
  uint64_t rays_cancelled = 0;  // the result (ThicknessResult::id) whose rays were cancelled: not cast until asked
  uint64_t cancelled_version = 0;  // the model version whose computation the user cancelled (not asked again)
  WallsKey walls_shown;            // the walls the selected region is a region of
  SectionKey image_key;            // what the section texture shows, with the minimum wall it paints red
  double image_min_wall = -1.0;
  bool image_ray = false;
  Texture image_texture;
  // The thin-wall region and the hot spot last clicked in the lists (indices; -1: none), in the result
  // selected_result (ThicknessResult::id; a region, in the thin walls walls_shown).
  int32_t selected_region = -1;
  int32_t selected_spot = -1;
  uint64_t selected_result = 0;
  uint64_t volume_key = 0;        // the result (ThicknessResult::id) the 3D view's volume holds (0: none)
  double volume_min_wall = -1.0;  // ... and the minimum wall whose walls it marks
  bool volume_ray = false;        // ... and whether it holds the ray thickness
  std::string volume_problem;     // why the 3D view cannot colour by thickness (empty: it can)
};

// A voxelization, and the CAD file's new tessellation when the open one was too coarse for its grid.
struct VoxelizeOutcome {
  VoxelizeResult result;
  std::shared_ptr<const MeshSource> mesh;  // null when the open mesh was used
};

struct LoadedFile {
  std::filesystem::path path;
  std::shared_ptr<const MeshSource> mesh;  // a mesh or CAD file
  std::optional<VoxelGrid> grid;           // a voxel file
  std::optional<io::ProjectFile> project;  // a voxmod project (.vxp)
  bool recovered = false;                  // the project is an autosave being recovered (autosave.h)
  double load_s = 0.0;
  // > 1: `grid` is a coarse view of a .vxm file too large for memory (io::readVxmCoarse at this level), whose own
  // dims are full_dims.
  int32_t coarse_level = 1;
  Dims full_dims;
};

// Shown one at a time in a modal dialog; each names the file and the problem.
struct ErrorQueue {
  std::vector<std::string> messages;
  int shown_frame = -1;  // the ImGui frame the dialog opened on: the key press that raised the error must not close it
  int64_t reported = 0;  // errors raised since the window opened
  std::string last_reported;  // the last of them
};

struct AppState {
  GLFWwindow* window = nullptr;
  Settings settings;
  std::filesystem::path settings_path;  // empty: do not remember anything

  Document doc;
  // The model as shown (doc.model->grid, or empty). model_version changes whenever it does.
  VoxelGrid model;
  uint64_t model_version = 0;
  uint64_t next_id = 1;  // for base ids and model versions

  // Params edited by the widgets.
  Panel panel = Panel::kModel;
  bool panel_change_requested = true;  // select `panel` in the tab bar on the next frame
  ViewParams view;
  SectionUi section;
  SkinUi skin;
  XrayUi xray;
  MassUi mass_ui;
  ThicknessUi thickness_ui;
  MeasureUi measure;
  PartsUi parts_ui;
  PrintUi print_ui;
  CastingUi casting_ui;
  VoxelizeDialog voxelize;
  FileBrowser browser;

  // Background work.
  Job<LoadedFile> load_job;
  Job<VoxelizeOutcome> voxelize_job;

  // The parts (parts.h): splitting into bodies or adding a part (with the undo label of what it makes), and the
  // interference of the model version it runs for.
  Job<std::shared_ptr<const Assembly>> parts_job;
  std::string parts_job_label;
  Job<Interference> interference_job;
  uint64_t interference_job_version = 0;
  Job<Clearance> clearance_job;  // the clearance of parts clearance_job_a and _b in model version _version
  size_t clearance_job_a = 0, clearance_job_b = 0;
  uint64_t clearance_job_version = 0;

  VoxelizeParams voxelize_job_params;  // the params of the running voxelization
  double job_started = 0.0;
  AsyncValue<uint64_t, std::shared_ptr<const DepthMap>> depth;  // keyed by base_id
  AsyncValue<uint64_t, SurfaceStats> surface_stats;             // keyed by model_version
  AsyncValue<uint64_t, MassProperties> mass;                    // keyed by model_version
  AsyncValue<XrayKey, std::shared_ptr<const XrayResult>> xray_result;
  AsyncValue<uint64_t, std::shared_ptr<const ThicknessResult>> thickness;  // keyed by model_version
  // The ray thickness, cast once the thickness is known when the panel shows rays: keyed by ThicknessResult::id.
  AsyncValue<uint64_t, std::shared_ptr<const RayThicknessResult>> rays;
  AsyncValue<WallsKey, std::shared_ptr<const Walls>> thin_walls;          // walls, not edges (walls.h)
  AsyncValue<PrintKey, std::shared_ptr<const PrintResult>> print;         // the Print panel's (print.h)
  AsyncValue<CastingKey, std::shared_ptr<const CastingOutcome>> casting;  // the Casting panel's (casting.h)
  Job<std::filesystem::path> volume_export_job;  // File > Export volume: the file being written (export_volume.h)
  // What the status line adds to "Wrote FILE" when that export is done, e.g. " (the half the cut-away keeps)".
  std::string volume_export_note;
  // A coarse view's section at full resolution, read from the file in the background (full_section.h).
  Job<Section> full_section_job;
  std::optional<Section> full_section;
  std::string full_section_error;
  Texture full_section_texture;

  // Derived images (main thread: sections are cheap enough to compute while a slider moves).
  SectionKey section_key;
  std::optional<Section> section_result;
  std::string section_error;
  Texture section_texture;
  // The section at an angle (section-plane), for the model version, normal and offset it was computed for.
  std::optional<ObliqueSection> oblique_result;
  std::tuple<uint64_t, glm::dvec3, double> oblique_key{0, glm::dvec3(0.0), 0.0};
  std::string oblique_error;
  Texture oblique_texture;
  XrayKey xray_texture_key;
  Texture xray_texture;
  std::optional<render::Box3> model_bounds;

  Viewport viewport;

  AutosaveState autosave;

  // Dialogs.
  ErrorQueue errors;
  std::function<void(AppState&)> after_unsaved_prompt;  // what to do once the user saved or discarded
  std::vector<std::string> dropped_files;               // from GLFW's drop callback, handled next frame
  // Key presses (GLFW key, modifier bits) since the last frame, from GLFW's key callback. ImGui 1.86 only keeps
  // the keys' current state, so a tap shorter than a frame (llvmpipe frames can be slow) would be lost otherwise.
  std::vector<std::pair<int, int>> key_presses;
  bool unsaved_prompt_requested = false;
  bool quit_requested = false;
  bool release_memory = false;  // a document was closed: give freed memory back to the system after the next frame
  HelpUi help;                  // Help > About, Mouse and keyboard, Terms
  std::string status_message;   // e.g. "Wrote /home/me/part.png", in the status bar for a few seconds
  double status_since = 0.0;
  int32_t export_width = 0, export_height = 0;  // size of an exported 3D view in pixels; 0: the view's own
  bool close_dialogs = false;  // every open dialog closes itself on the next frame (the close-dialogs action)

  // Actions given while the frame's widgets are drawn (a button, a field, a list row): they run once the frame is
  // built (runDeferredActions), never against the state the frame is still drawing from (actions.h).
  bool building_frame = false;
  std::vector<std::function<void(AppState&)>> deferred_actions;

  // Frame bookkeeping.
  int64_t frame = 0;
  double frame_time_s = 0.0;  // duration of the last frame
  double fps = 0.0;           // smoothed
  int redraw_frames = 2;      // frames still to draw before sleeping until the next event

  // Opening.
  bool voxelize_after_load = false;     // the next mesh opened is voxelized at once instead of asking (start-up)
  bool voxelize_dialog_on_open = true;  // a mesh opened shows the voxelize dialog (off while a script drives)
};

}  // namespace vox::app
