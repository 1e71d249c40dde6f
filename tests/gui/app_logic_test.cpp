// The window's logic without a window: script parsing, settings, background jobs, the action table, and the
// document operations (open, peel, undo / redo, unsaved state) that the panels and the script share. No GL and no
// display are needed; the GUI itself is tested under Xvfb by gui_test.sh and files_test.sh.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iterator>
#include <set>
#include <thread>

#include "app/actions.h"
#include "app/app_state.h"
#include "app/full_section.h"
#include "app/glossary.h"
#include "app/job.h"
#include "app/measure.h"
#include "app/operations.h"
#include "app/casting.h"
#include "app/parts.h"
#include "app/print.h"
#include "app/script.h"
#include "app/script_runner.h"
#include "app/settings.h"
#include "app/update.h"
#include "gui/app_test_support.h"
#include "support/cad_parts.h"
#include "support/test_support.h"
#include "vox/io/cad.h"
#include "vox/io/image_io.h"
#include "vox/io/stl.h"
#include "vox/io/voxel_file.h"
#include "vox/io/vxm_stream.h"

namespace vox::app {
namespace {

// ---- Script ----

TEST(AppScript, parsesCommandsWithLineNumbersAndRest) {
  auto s = parseScript("# comment\n\nopen my part.stl\nvoxelize 200 vote  # trailing comment\nwait frames 3\nquit\n",
                       "t.script");
  ASSERT_TRUE(s.ok()) << s.error().message;
  ASSERT_EQ(s->size(), 4u);
  EXPECT_EQ((*s)[0].line, 3);
  EXPECT_EQ((*s)[0].name, "open");
  EXPECT_EQ((*s)[0].rest, "my part.stl");  // paths with spaces survive
  EXPECT_EQ((*s)[1].args, (std::vector<std::string>{"200", "vote"}));
  EXPECT_EQ((*s)[2].args, (std::vector<std::string>{"frames", "3"}));
}

TEST(AppScript, rejectsUnknownCommandsNamingFileAndLine) {
  auto s = parseScript("open a.stl\nvoxelise 200\n", "t.script");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().message, "t.script:2: unknown command 'voxelise'");
}

TEST(AppScript, rejectsWrongArgumentCounts) {
  auto s = parseScript("xray z\n", "t.script");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().message.find("t.script:1: 'xray' takes 2 arguments, found 1"), std::string::npos)
      << s.error().message;
  EXPECT_FALSE(parseScript("quit now\n", "t").ok());
}

// Every script command is an action of the table or one of the harness's own commands, never both, and every
// action can be named in a script.
TEST(AppScript, everyCommandIsAnActionOrAHarnessCommand) {
  for (const char* h : {"echo", "sweep", "screenshot", "state", "wait", "wait-file", "hover", "expect-error", "exit"}) {
    EXPECT_TRUE(isHarnessCommand(h)) << h;
    EXPECT_EQ(findAction(h), nullptr) << h << " is both an action and a harness command";
  }
  for (const Action& a : actionTable()) {
    EXPECT_FALSE(isHarnessCommand(a.name)) << a.name;
    std::string line = a.name;
    if (!a.run) {
      for (int i = 0; i < a.min_values; ++i) line += " 1";
    }
    EXPECT_TRUE(parseScript(line + "\n", "t").ok()) << line;
  }
  EXPECT_FALSE(parseScript("dialog open\n", "t").ok());  // the old spelling is no command now
}

// ---- Settings ----

TEST(AppSettings, roundTripsThroughTheIniText) {
  test::TempDir dir;
  Settings s;
  s.window_width = 1000;
  s.window_height = 700;
  s.recent_files = {"/a/b c.stl", "/d/e.vxm"};
  s.last_directory = "/a";
  s.resolution = 400;
  s.fill_mode = "vote";
  s.lit = false;
  s.round_points = true;
  s.point_size_px = 3.0f;
  s.lod = false;
  ASSERT_TRUE(saveSettings(s, dir / "sub" / "voxmod.ini").ok());  // creates the directory
  const Settings r = loadSettings(dir / "sub" / "voxmod.ini");
  EXPECT_EQ(r.window_width, 1000);
  EXPECT_EQ(r.window_height, 700);
  EXPECT_EQ(r.recent_files, s.recent_files);
  EXPECT_EQ(r.last_directory, "/a");
  EXPECT_EQ(r.resolution, 400);
  EXPECT_EQ(r.fill_mode, "vote");
  EXPECT_FALSE(r.lit);
  EXPECT_TRUE(r.round_points);
  EXPECT_EQ(r.point_size_px, 3.0f);
  EXPECT_FALSE(r.lod);
}

TEST(AppSettings, handEditedNonsenseIsIgnoredOrClamped) {
  test::TempDir dir;
  test::writeFile(dir / "voxmod.ini",
                  "garbage line\nwindow_width = 12\nresolution = 99999\nlit = maybe\n"
                  "unknown_key = 1\nwindow_height = tall\n");
  const Settings r = loadSettings(dir / "voxmod.ini");
  EXPECT_EQ(r.window_width, 640);   // clamped up to a usable window
  EXPECT_EQ(r.window_height, 800);  // unparsable: default
  EXPECT_EQ(r.resolution, 4096);
  EXPECT_TRUE(r.lit);
  const Settings missing = loadSettings(dir / "nope.ini");
  EXPECT_EQ(missing.window_width, 1280);
}

TEST(AppSettings, recentFilesAreDeduplicatedMostRecentFirstAndCapped) {
  Settings s;
  for (int i = 0; i < 12; ++i) addRecentFile(s, "/f" + std::to_string(i));
  addRecentFile(s, "/f5");
  ASSERT_EQ(s.recent_files.size(), kMaxRecentFiles);
  EXPECT_EQ(s.recent_files[0], "/f5");
  EXPECT_EQ(s.recent_files[1], "/f11");
  EXPECT_EQ(std::count(s.recent_files.begin(), s.recent_files.end(), "/f5"), 1);
}

// ---- Jobs ----

template <class T>
Result<T> waitFor(Job<T>& job) {
  for (int i = 0; i < 2000; ++i) {
    if (auto r = job.take()) return std::move(*r);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return makeError(ErrorCode::kLimit, "job did not finish");
}

TEST(AppJob, runsOnAWorkerAndHandsTheResultOverOnce) {
  Job<int> job;
  job.start("answer", [](const ProgressFn& progress) -> Result<int> {
    progress(0.5);
    return 42;
  });
  EXPECT_TRUE(job.active());
  auto r = waitFor(job);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(*r, 42);
  EXPECT_FALSE(job.active());
  EXPECT_FALSE(job.take().has_value());
}

TEST(AppJob, cancelReachesTheWorkThroughProgress) {
  Job<int> job;
  std::atomic<bool> started{false};
  job.start("forever", [&started](const ProgressFn& progress) -> Result<int> {
    started = true;
    while (progress(0.1)) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return makeError(ErrorCode::kCancelled, "cancelled");
  });
  while (!started) std::this_thread::yield();
  job.cancel();
  auto r = waitFor(job);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kCancelled);
}

// A cancel pressed after the work's last progress report (late in a voxelization at R = 3000) still holds: the
// result that comes anyway is not handed out.
TEST(AppJob, aCancelPressedAfterTheLastProgressReportStillHolds) {
  Job<int> job;
  std::atomic<bool> go{false};
  job.start("Voxelizing", [&go](const ProgressFn&) -> Result<int> {
    while (!go.load()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return 42;  // never asks progress again
  });
  job.cancel();
  go = true;
  std::optional<Result<int>> r;
  while (!(r = job.take())) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  ASSERT_FALSE(r->ok());
  EXPECT_EQ(r->error().code, ErrorCode::kCancelled);
}

TEST(AppJob, startingAgainRetiresTheRunningJobWithoutWaiting) {
  Job<int> job;
  job.start("slow", [](const ProgressFn& progress) -> Result<int> {
    while (progress(0.0)) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return 1;
  });
  job.start("fast", [](const ProgressFn&) -> Result<int> { return 2; });
  auto r = waitFor(job);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(*r, 2);  // the first job's result never arrives
}

TEST(AppAsyncValue, computesOncePerKeyAndDropsStaleKeys) {
  AsyncValue<int, int> v;
  std::atomic<int> runs{0};
  auto work = [&runs](int x) {
    return [&runs, x](const ProgressFn&) -> Result<int> {
      ++runs;
      return x * 10;
    };
  };
  v.request(1, "one", work(1));
  v.request(1, "one", work(1));  // already under way
  for (int i = 0; i < 2000 && !v.get(1); ++i) {
    v.poll();
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ASSERT_NE(v.get(1), nullptr);
  EXPECT_EQ(*v.get(1), 10);
  EXPECT_FALSE(v.wants(1));
  v.request(1, "one", work(1));  // present: nothing runs
  EXPECT_EQ(runs.load(), 1);
  EXPECT_TRUE(v.wants(2));
  EXPECT_EQ(v.get(2), nullptr);
}

// ---- Action table ----

TEST(AppActions, everyActionIsInTheTableOnceAndShortcutsAreUnique) {
  std::set<int> ids;
  std::set<std::pair<int, int>> shortcuts;
  for (const Action& a : actionTable()) {
    EXPECT_TRUE(ids.insert(int(a.id)).second) << a.label;
    EXPECT_TRUE(a.run || a.run_with) << a.label;
    if (a.menu) {
      EXPECT_NE(a.run, nullptr) << a.label << ": a menu item runs without values";
    }
    EXPECT_EQ(findAction(a.name), &a) << "script name '" << a.name << "' is not unique";
    if (a.shortcut.key != 0) {
      EXPECT_TRUE(shortcuts.insert({a.shortcut.key, a.shortcut.mods}).second) << "shortcut of " << a.label;
    }
  }
  for (int id = 0; id <= int(ActionId::kCloseDialogs); ++id) EXPECT_TRUE(ids.count(id)) << "ActionId " << id;
  EXPECT_EQ(shortcutText(action(ActionId::kSaveAs).shortcut), "Ctrl+Shift+S");
  EXPECT_EQ(shortcutText(action(ActionId::kSectionNext).shortcut), "PgUp");
  EXPECT_EQ(shortcutText(action(ActionId::kExportBinvox).shortcut), "");
}

// Help > Terms: each term once, explained; the terms action opens it at a term named by its key or as the panels
// write it, and refuses a word that is none, listing the known ones.
TEST(AppActions, theTermsActionOpensTheGlossaryAtATerm) {
  std::set<std::string> keys;
  for (const Term& t : glossary()) {
    EXPECT_TRUE(keys.insert(t.key).second) << t.key;
    EXPECT_GT(std::string(t.text).size(), 60u) << t.key;
    EXPECT_EQ(findTerm(t.name), &t) << t.name;
  }
  for (const char* used : {"suspect-voxels", "core", "modulus", "isolated", "niyama", "wall", "interference"}) {
    EXPECT_TRUE(keys.count(used)) << used;
  }
  AppState state;
  ASSERT_TRUE(test_app::run(state, "terms suspect voxels").ok());
  EXPECT_TRUE(state.help.show_terms);
  EXPECT_EQ(state.help.term, "suspect-voxels");
  ASSERT_TRUE(test_app::run(state, "terms Niyama").ok());
  EXPECT_EQ(state.help.term, "niyama");
  const Status bad = test_app::run(state, "terms flux capacitor");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("modulus"), std::string::npos) << bad.error().message;
  EXPECT_EQ(state.help.term, "niyama");
  ASSERT_TRUE(test_app::run(state, "terms").ok());  // Help > Terms from the menu: from the top
  EXPECT_TRUE(state.help.term.empty());
}

// section-zoom: the axis section's picture zoomed about a voxel, kept within the picture, refused out of range.
TEST(AppActions, theSectionZoomsAboutAVoxelWithinThePicture) {
  test::TempDir dir;
  VoxelGrid g(Dims{40, 20, 10});
  for (int32_t z = 0; z < 10; ++z)
    for (int32_t y = 0; y < 20; ++y) g.fillRun(y, z, 0, 40);
  ASSERT_TRUE(io::saveVxm(g, dir / "slab.vxm").ok());
  AppState state;
  ASSERT_TRUE(test_app::run(state, "open " + (dir / "slab.vxm").string()).ok());
  ASSERT_TRUE(test_app::pump(state, [&] { return state.doc.model.has_value(); }));
  ASSERT_TRUE(test_app::run(state, "section z 5").ok());  // the picture: x right (40), y up (20)
  ASSERT_TRUE(test_app::run(state, "section-zoom 4 9.5 9.5").ok());
  EXPECT_DOUBLE_EQ(state.section.zoom, 4.0);
  EXPECT_DOUBLE_EQ(state.section.centre.x, 10.0 / 40.0);
  EXPECT_DOUBLE_EQ(state.section.centre.y, 10.0 / 20.0);
  ASSERT_TRUE(test_app::run(state, "section-zoom 4 0 0").ok());  // the corner: as far as the picture goes
  EXPECT_DOUBLE_EQ(state.section.centre.x, 0.125);
  EXPECT_DOUBLE_EQ(state.section.centre.y, 0.125);
  EXPECT_FALSE(test_app::run(state, "section-zoom 0.5").ok());
  EXPECT_FALSE(test_app::run(state, "section-zoom 1000").ok());
  EXPECT_DOUBLE_EQ(state.section.zoom, 4.0);
  ASSERT_TRUE(test_app::run(state, "section-zoom").ok());  // Section > Whole section
  EXPECT_DOUBLE_EQ(state.section.zoom, 1.0);
}

// ---- Document operations ----

using test_app::pump;

// A solid 12 x 10 x 8 block: 4 skin layers, since the thinnest side (8) loses a voxel at both ends per layer.
VoxelGrid block() {
  VoxelGrid g(Dims{12, 10, 8});
  for (int32_t z = 0; z < 8; ++z) {
    for (int32_t y = 0; y < 10; ++y) g.fillRun(y, z, 0, 12);
  }
  return g;
}

// block.vxm written to `dir`, opened, and peeled by one layer: a document with an unsaved change.
void openBlockPeeledOnce(AppState& state, const test::TempDir& dir) {
  ASSERT_TRUE(io::saveVxm(block(), dir / "block.vxm").ok());
  startOpen(state, dir / "block.vxm");
  ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
  state.panel = Panel::kSkin;
  peelTo(state, 1);
  ASSERT_TRUE(pump(state, [&] { return state.doc.model->peeled == 1; }));
}

TEST(AppDocument, aVxmFileTooLargeForMemoryOpensAsACoarseViewThatSaysSo) {
  // 16384 x 16384 x 4096 voxels (138 GB as a grid; a few hundred bytes as a file): three voxels in it.
  test::TempDir dir;
  const Dims dims{16384, 16384, 4096};
  GridFrame frame;
  frame.voxel_size = 0.5;
  // The level it opens at (a quarter of the memory limit for the grid) and a voxel in the middle of block 100
  // along x, where the full-resolution section through coarse section x = 100 runs.
  const int32_t expected_level = io::coarseLevelFor(dims, defaultMemoryLimitBytes() / 4);
  const int32_t middle = 100 * expected_level + expected_level / 2;
  const std::vector<glm::ivec3> voxels = {{0, 0, 0}, {16383, 9, 5}, {77, 16383, 4095}, {middle, 50, 7}};
  auto saved = io::saveVxmInSlabs(dir / "huge.vxm", dims, frame, [&](io::VxmLayerWriter& w) {
    const VoxelGrid empty(Dims{dims.nx, dims.ny, 1}, frame);
    for (int32_t z = 0; z < dims.nz; ++z) {
      VoxelGrid layer = empty;
      for (const glm::ivec3& v : voxels) {
        if (v.z == z) layer.set(v.x, v.y, 0);
      }
      if (Status s = w.append(layer, 0, 1); !s) return s;
    }
    return Status(Ok{});
  });
  ASSERT_TRUE(saved.ok()) << saved.error().message;
  AppState state;
  startOpen(state, dir / "huge.vxm");
  // Reading the 4096 layers for the coarse view takes minutes under ThreadSanitizer (over 120 s in CI)
  ASSERT_TRUE(pump(
      state, [&] { return state.doc.model.has_value(); }, std::chrono::seconds(500)));
  const int32_t level = state.doc.coarse_level;
  ASSERT_GT(level, 1);
  ASSERT_EQ(level, expected_level);
  EXPECT_EQ(state.model.dims(), (Dims{16384 / level, 16384 / level, 4096 / level}));
  EXPECT_DOUBLE_EQ(state.model.voxelSize(), 0.5 * level);
  EXPECT_EQ(state.model.filledCount(), 4);
  for (const glm::ivec3& v : voxels) EXPECT_TRUE(state.model.get(v.x / level, v.y / level, v.z / level));
  EXPECT_NE(state.doc.model->origin->what.find("coarse view of huge.vxm"), std::string::npos);
  EXPECT_TRUE(state.doc.save_path.empty());  // Save never writes the coarse grid over the file
  EXPECT_FALSE(hasUnsavedChanges(state));

  // The Section panel reads the section through the middle of a coarse section's blocks from the file.
  state.section.axis = Axis::kX;
  state.section.index = 100;
  startFullSection(state);
  ASSERT_TRUE(pump(
      state, [&] { return state.full_section.has_value() || !state.full_section_error.empty(); },
      std::chrono::seconds(500)));
  ASSERT_TRUE(state.full_section_error.empty()) << state.full_section_error;
  const Section& full = *state.full_section;
  EXPECT_EQ(full.index, middle);
  EXPECT_EQ(full.mask.width, 16384);  // y, at the file's resolution
  EXPECT_EQ(full.mask.height, 4096);  // z
  EXPECT_EQ(full.filled, 1);
  EXPECT_EQ(full.mask.at(50, 4095 - 7), 1);
}

TEST(AppDocument, openPeelUndoRedoAndTheUnsavedState) {
  test::TempDir dir;
  ASSERT_TRUE(io::saveVxm(block(), dir / "block.vxm").ok());
  AppState state;
  startOpen(state, dir / "block.vxm");
  ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
  EXPECT_EQ(state.model.filledCount(), 12 * 10 * 8);
  EXPECT_FALSE(hasUnsavedChanges(state));  // as on disk
  EXPECT_FALSE(canUndo(state));

  // A peel asked for before the depth map exists is queued, then applied.
  state.panel = Panel::kSkin;
  peelTo(state, 1);
  ASSERT_TRUE(state.skin.pending_peel.has_value());
  ASSERT_TRUE(pump(state, [&] { return !state.skin.pending_peel && state.doc.model->peeled == 1; }));
  EXPECT_EQ(state.model.filledCount(), 10 * 8 * 6);
  EXPECT_TRUE(hasUnsavedChanges(state));
  EXPECT_EQ(peelLayersAvailable(state), 4);  // 8 voxels thick: layers 1..4

  peelTo(state, 100);  // clamped: the core (the last layer) stays
  EXPECT_EQ(state.doc.model->peeled, 3);
  EXPECT_EQ(state.model.filledCount(), 6 * 4 * 2);

  undo(state);
  EXPECT_EQ(state.doc.model->peeled, 1);
  undo(state);
  EXPECT_EQ(state.doc.model->peeled, 0);
  EXPECT_FALSE(hasUnsavedChanges(state));  // back to what the file holds
  EXPECT_FALSE(canUndo(state));
  redo(state);
  EXPECT_EQ(state.doc.model->peeled, 1);
  EXPECT_EQ(state.model.filledCount(), 10 * 8 * 6);

  // Save makes the current state the saved one; the saved file re-opens equal.
  ASSERT_TRUE(saveModel(state, dir / "peeled.vxm"));
  EXPECT_FALSE(hasUnsavedChanges(state));
  auto back = io::loadVxm(dir / "peeled.vxm");
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(back->filledCount(), 10 * 8 * 6);
}

// Computing the skin layers can be cancelled (they took 6-9 s on igea with no Cancel); they are not asked for again
// until the user asks (Compute the skin layers, or a peel).
TEST(AppDocument, theSkinLayersCanBeCancelledAndComputedAgain) {
  test::TempDir dir;
  ASSERT_TRUE(io::saveVxm(block(), dir / "block.vxm").ok());
  AppState state;
  startOpen(state, dir / "block.vxm");
  ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
  state.panel = Panel::kSkin;
  updateDocument(state);  // asks for the layers
  EXPECT_TRUE(actionEnabled(state, action(ActionId::kCancelSkinLayers)));
  EXPECT_TRUE(actionEnabled(state, action(ActionId::kCancelJob)));  // Esc cancels them too
  ASSERT_TRUE(dispatch(state, ActionId::kCancelSkinLayers));
  for (int i = 0; i < 20; ++i) updateDocument(state);
  EXPECT_FALSE(state.depth.busy()) << "asked for again after the cancel";
  EXPECT_EQ(currentDepthMap(state), nullptr);
  EXPECT_FALSE(actionEnabled(state, action(ActionId::kCancelSkinLayers)));
  ASSERT_TRUE(dispatch(state, ActionId::kSkinLayers));
  ASSERT_TRUE(pump(state, [&] { return currentDepthMap(state) != nullptr; }));
  EXPECT_EQ(peelLayersAvailable(state), 4);
}

// A thin region or hot spot clicked deep inside the part never puts the eye inside the surface (giant voxels,
// nothing red): the eye stays outside the model's box, looking at the target as before.
TEST(AppView, aRegionClickedDeepInsideKeepsTheEyeOutsideThePart) {
  AppState state;
  state.model = VoxelGrid(Dims{400, 300, 200});
  state.view.camera.distance = 2000.0;
  for (double yaw : {30.0, 135.0, -100.0}) {
    state.view.camera.yaw_deg = yaw;
    centreView(state, glm::dvec3(200.0, 150.0, 100.0), 3.0);  // a thin wall in the middle of the part
    const glm::dvec3 eye = state.view.camera.eyePosition();
    const bool outside = eye.x < 0.0 || eye.y < 0.0 || eye.z < 0.0 || eye.x > 400.0 || eye.y > 300.0 || eye.z > 200.0;
    EXPECT_TRUE(outside) << "yaw " << yaw << ": eye at " << eye.x << ", " << eye.y << ", " << eye.z;
    EXPECT_EQ(state.view.camera.target, glm::dvec3(200.0, 150.0, 100.0));
  }
  // Near the surface the close view stays close.
  state.view.camera.yaw_deg = 30.0;
  state.view.camera.pitch_deg = 25.0;
  centreView(state, glm::dvec3(398.0, 298.0, 198.0), 3.0);
  EXPECT_LE(state.view.camera.distance, 40.0);
}

// Peel, then Reset skin: the model is what the file holds again, so nothing is unsaved (the Skin panel asked to save).
TEST(AppDocument, aPeelThenResetSkinIsNotAnUnsavedChange) {
  test::TempDir dir;
  AppState state;
  openBlockPeeledOnce(state, dir);
  EXPECT_TRUE(hasUnsavedChanges(state));
  peelTo(state, 2);
  peelTo(state, 0);  // Reset skin
  EXPECT_EQ(state.doc.model->peeled, 0);
  EXPECT_EQ(state.doc.model->label, "reset skin");
  EXPECT_FALSE(hasUnsavedChanges(state));
  EXPECT_TRUE(canUndo(state));  // the reset is a step of its own
  peelTo(state, 1);
  EXPECT_TRUE(hasUnsavedChanges(state));
}

TEST(AppDocument, aBrokenFileIsAnErrorDialogAndTheDocumentStays) {
  test::TempDir dir;
  ASSERT_TRUE(io::saveVxm(block(), dir / "block.vxm").ok());
  test::writeFile(dir / "bad.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n");
  AppState state;
  startOpen(state, dir / "block.vxm");
  ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
  startOpen(state, dir / "bad.stl");
  ASSERT_TRUE(pump(state, [&] { return !state.errors.messages.empty(); }));
  EXPECT_NE(state.errors.messages[0].find("bad.stl"), std::string::npos) << state.errors.messages[0];
  EXPECT_EQ(state.doc.path, dir / "block.vxm");  // the open document is untouched
  EXPECT_TRUE(state.doc.model.has_value());
}

TEST(AppDocument, savingNeedsAVoxelExtension) {
  test::TempDir dir;
  ASSERT_TRUE(io::saveVxm(block(), dir / "block.vxm").ok());
  AppState state;
  startOpen(state, dir / "block.vxm");
  ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
  EXPECT_FALSE(saveModel(state, dir / "block.txt"));
  ASSERT_EQ(state.errors.messages.size(), 1u);
  EXPECT_NE(state.errors.messages[0].find("block.txt"), std::string::npos);
  EXPECT_TRUE(saveModel(state, dir / "copy.binvox"));
}

TEST(AppDocument, unsavedChangesAskBeforeQuitting) {
  test::TempDir dir;
  ASSERT_TRUE(io::saveVxm(block(), dir / "block.vxm").ok());
  AppState state;
  startOpen(state, dir / "block.vxm");
  ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
  requestQuit(state);
  EXPECT_TRUE(state.quit_requested);  // nothing to lose
  state.quit_requested = false;
  state.panel = Panel::kSkin;
  peelTo(state, 1);
  ASSERT_TRUE(pump(state, [&] { return state.doc.model->peeled == 1; }));
  requestQuit(state);
  EXPECT_FALSE(state.quit_requested);
  EXPECT_TRUE(state.unsaved_prompt_requested);
  ASSERT_TRUE(state.after_unsaved_prompt);
  state.after_unsaved_prompt(state);  // "Discard"
  EXPECT_TRUE(state.quit_requested);
}

// Quit -> Save -> the browser -> a save that fails -> the browser goes away; a later, ordinary Save As must save
// and nothing more: the quit belonged to the browsing that failed.
TEST(AppDocument, aQuitWhoseSaveFailedDoesNotComeBackWithALaterSave) {
  test::TempDir dir;
  AppState state;
  ASSERT_NO_FATAL_FAILURE(openBlockPeeledOnce(state, dir));
  state.doc.save_path.clear();  // as for a model voxelized from a mesh: no file to save to yet
  requestQuit(state);
  ASSERT_TRUE(state.after_unsaved_prompt);
  auto quit = std::move(state.after_unsaved_prompt);
  state.after_unsaved_prompt = nullptr;
  saveThen(state, std::move(quit));  // the prompt's "Save": no file yet, so the browser asks where
  ASSERT_TRUE(state.browser.open_requested);
  EXPECT_FALSE(givePath(state, ActionId::kSaveAs, dir / "block.vxm" / "sub.vxm"));
  EXPECT_FALSE(state.quit_requested);
  ASSERT_EQ(state.errors.messages.size(), 1u);

  dispatch(state, ActionId::kSaveAs);  // later, the user saves
  ASSERT_TRUE(givePath(state, ActionId::kSaveAs, dir / "good.vxm"));
  EXPECT_FALSE(hasUnsavedChanges(state));
  EXPECT_FALSE(state.quit_requested);  // the window stays open
}

// The prompt's Save that succeeds in its own browser does continue (here: quits).
TEST(AppDocument, aQuitWhoseSaveSucceedsQuits) {
  test::TempDir dir;
  AppState state;
  ASSERT_NO_FATAL_FAILURE(openBlockPeeledOnce(state, dir));
  state.doc.save_path.clear();
  requestQuit(state);
  auto quit = std::move(state.after_unsaved_prompt);
  saveThen(state, std::move(quit));
  EXPECT_FALSE(givePath(state, ActionId::kSaveAs, dir / "block.vxm" / "sub.vxm"));
  EXPECT_TRUE(givePath(state, ActionId::kSaveAs, dir / "good.vxm"));  // same browser, retried
  EXPECT_TRUE(state.quit_requested);
}

// Re-voxelizing at another resolution while zoomed in keeps showing the same part of the model: the camera (in
// voxel units) is carried to the new lattice, and back on undo. It was kept as it was, and the view went blank.
TEST(AppDocument, reVoxelizingKeepsTheViewOnTheSamePartOfTheModel) {
  test::TempDir dir;
  TriangleMesh cube = test::unitCubeMesh();
  for (Triangle& t : cube.triangles) {
    for (glm::vec3& v : t.v) v = v * glm::vec3(4, 2, 1) + glm::vec3(-1, 3, 5);  // a 4 x 2 x 1 box, off the origin
  }
  ASSERT_TRUE(io::saveStlBinary(cube, dir / "box.stl").ok());
  AppState state;
  startOpen(state, dir / "box.stl");
  ASSERT_TRUE(pump(state, [&] { return state.doc.mesh != nullptr; }));
  startVoxelize(state, VoxelizeParams{.resolution = 20});
  ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
  EXPECT_TRUE(state.view.fit_pending);  // the first model is fitted
  state.view.fit_pending = false;       // as the viewport does
  const GridFrame a = state.model.frame();
  state.view.camera.target = glm::dvec3(3.0, 2.0, 1.0);  // zoomed in on one corner region
  state.view.camera.distance = 6.0;
  const glm::dvec3 model_point = a.origin + state.view.camera.target * a.voxel_size;
  state.section.axis = Axis::kX;
  state.section.index = 3;  // the plane x = a.origin.x + 3.5 h
  const double plane = a.origin.x + 3.5 * a.voxel_size;

  const uint64_t before = state.model_version;
  startVoxelize(state, VoxelizeParams{.resolution = 100});
  ASSERT_TRUE(pump(state, [&] { return state.model_version != before; }));
  const GridFrame b = state.model.frame();
  // The section stays at the same place in the part: the new plane nearest the old one.
  EXPECT_LE(std::abs(b.origin.x + (state.section.index + 0.5) * b.voxel_size - plane), 0.5 * b.voxel_size + 1e-12);
  ASSERT_NE(a.voxel_size, b.voxel_size);
  EXPECT_FALSE(state.view.fit_pending);  // the user's zoom is kept, not thrown away
  const glm::dvec3 target = b.origin + state.view.camera.target * b.voxel_size;
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(target[i], model_point[i], 1e-9) << i;
  EXPECT_NEAR(state.view.camera.distance * b.voxel_size, 6.0 * a.voxel_size, 1e-9);

  undo(state);
  EXPECT_NEAR(state.view.camera.distance, 6.0, 1e-9);
  EXPECT_NEAR(state.view.camera.target.x, 3.0, 1e-9);
}

// A STEP part opens as a mesh in millimetres (the Voxelize dialog takes the unit), tessellated for the dialog's
// resolution; voxelizing at a finer one tessellates it again in the job, and the finer mesh becomes the document's.
TEST(AppDocument, aStepPartIsTessellatedForTheGridItIsVoxelizedOn) {
  test::TempDir dir;
  test::writeStep(dir / "c.step", {{test::CadShape::kCylinder, {0, 0, 0}, {10, 0, 20}}});
  AppState state;
  state.voxelize.params.resolution = 20;
  startOpen(state, dir / "c.step");
  ASSERT_TRUE(pump(state, [&] { return state.doc.mesh != nullptr; }));
  const auto opened = state.doc.mesh;
  EXPECT_EQ(opened->format, "STEP (AUTOMOTIVE_DESIGN)");
  EXPECT_EQ(opened->units, "mm");
  EXPECT_EQ(state.voxelize.params.units, "mm");
  ASSERT_NE(opened->cad, nullptr);
  EXPECT_NEAR(opened->deflection, io::kCadDeflectionVoxels * 1.0, 1e-9);  // h = 20 mm / 20

  startVoxelize(state, VoxelizeParams{.resolution = 20, .units = "mm"});
  ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
  EXPECT_EQ(state.doc.mesh, opened);  // fine enough already
  EXPECT_EQ(state.model.frame().units, "mm");

  const uint64_t before = state.model_version;
  startVoxelize(state, VoxelizeParams{.resolution = 200, .units = "mm"});
  ASSERT_TRUE(pump(state, [&] { return state.model_version != before; }));
  ASSERT_NE(state.doc.mesh, opened);
  EXPECT_NEAR(state.doc.mesh->deflection, io::kCadDeflectionVoxels * 0.1, 1e-9);
  EXPECT_GT(state.doc.mesh->mesh.triangles.size(), opened->mesh.triangles.size());
  EXPECT_TRUE(state.doc.mesh->topology.watertight());
}

TEST(AppDocument, theOpenBrowserListsEveryInputFormat) {
  const std::vector<std::string> e = openableExtensions(true);
  for (const char* ext :
       {".stl", ".obj", ".ply", ".3mf", ".gltf", ".glb", ".off", ".step", ".stp", ".iges", ".igs", ".vxm", ".binvox"})
    EXPECT_NE(std::find(e.begin(), e.end(), ext), e.end()) << ext;
}

// Voxelizing a mesh can be redone in a moment: it is not an unsaved change worth a prompt. A peel is.
TEST(AppDocument, voxelizingAloneIsNotAnUnsavedChangeButAPeelIs) {
  test::TempDir dir;
  ASSERT_TRUE(io::saveStlBinary(test::unitCubeMesh(), dir / "box.stl").ok());
  AppState state;
  startOpen(state, dir / "box.stl");
  ASSERT_TRUE(pump(state, [&] { return state.doc.mesh != nullptr; }));
  startVoxelize(state, VoxelizeParams{.resolution = 12});
  ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
  EXPECT_FALSE(hasUnsavedChanges(state));
  requestQuit(state);
  EXPECT_TRUE(state.quit_requested);  // no prompt
  state.quit_requested = false;
  state.panel = Panel::kSkin;
  peelTo(state, 1);
  ASSERT_TRUE(pump(state, [&] { return state.doc.model->peeled == 1; }));
  EXPECT_TRUE(hasUnsavedChanges(state));
  const uint64_t before = state.model_version;
  startVoxelize(state, VoxelizeParams{.resolution = 14});  // the peel is still on the undo stack: still unsaved
  ASSERT_TRUE(pump(state, [&] { return state.model_version != before; }));
  EXPECT_TRUE(hasUnsavedChanges(state));
}

// The dialog remembers the last resolution, but does not propose one that needs gigabytes for the next part.
TEST(AppDocument, theVoxelizeDialogProposesAResolutionThatFitsComfortably) {
  test::TempDir dir;
  ASSERT_TRUE(io::saveStlBinary(test::unitCubeMesh(), dir / "box.stl").ok());
  AppState state;
  startOpen(state, dir / "box.stl");
  ASSERT_TRUE(pump(state, [&] { return state.doc.mesh != nullptr; }));
  state.voxelize.params.resolution = 4096;  // a cube: 4096^3 bits = 8 GiB, more in auto mode (vote at worst)
  proposeResolution(state);
  EXPECT_EQ(state.voxelize.params.resolution, 1000);
  EXPECT_NE(state.voxelize.proposal_note.find("the last one used, 4096, would need "), std::string::npos)
      << state.voxelize.proposal_note;
  state.voxelize.params.resolution = 300;  // fits: kept, nothing said
  proposeResolution(state);
  EXPECT_EQ(state.voxelize.params.resolution, 300);
  EXPECT_TRUE(state.voxelize.proposal_note.empty());
}

// A file that names no unit never takes the previous file's (the bunny in metres opened labelled mm): it opens
// without units, or with the units the user gave that very file before.
TEST(AppDocument, unitsDoNotCarryOverToAFileThatNamesNone) {
  test::TempDir dir;
  ASSERT_TRUE(io::saveStlBinary(test::unitCubeMesh(), dir / "a.stl").ok());
  ASSERT_TRUE(io::saveStlBinary(test::unitCubeMesh(), dir / "b.stl").ok());
  AppState state;
  const auto open = [&](const char* name) {
    startOpen(state, dir / name);
    return pump(state, [&] { return state.doc.mesh != nullptr && state.doc.mesh->path == dir / name; });
  };
  ASSERT_TRUE(open("a.stl"));
  EXPECT_EQ(state.voxelize.params.units, "model");
  startVoxelize(state, VoxelizeParams{.resolution = 12, .units = "in"});
  ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
  EXPECT_EQ(state.model.frame().units, "in");
  ASSERT_TRUE(open("b.stl"));
  EXPECT_EQ(state.voxelize.params.units, "model") << "b.stl names no unit; a.stl's are not b's";
  startVoxelize(state, VoxelizeParams{.resolution = 12, .units = "model"});
  ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
  setModelUnits(state, "m");  // the Mass panel's units, for b.stl
  ASSERT_TRUE(open("a.stl"));
  EXPECT_EQ(state.voxelize.params.units, "in");
  ASSERT_TRUE(open("b.stl"));
  EXPECT_EQ(state.voxelize.params.units, "m");
  // Remembered across runs.
  ASSERT_TRUE(saveSettings(state.settings, dir / "s.ini").ok());
  const Settings again = loadSettings(dir / "s.ini");
  EXPECT_EQ(rememberedFileUnits(again, absoluteName(dir / "a.stl")), "in");
  EXPECT_EQ(rememberedFileUnits(again, absoluteName(dir / "b.stl")), "m");
}

// A section's position reads in fixed notation one decimal finer than the voxel ("y = 4.4e-05" was printed).
TEST(AppFormat, coordinatesReadToAVoxelNeverInExponents) {
  EXPECT_EQ(formatCoordinate(4.4e-05, "mm", 0.0127), "0.000 mm");
  EXPECT_EQ(formatCoordinate(-4.4e-05, "mm", 0.0127), "0.000 mm");
  EXPECT_EQ(formatCoordinate(78.105, "model", 3.81), "78.1 model units");
  EXPECT_EQ(formatCoordinate(-12.34567, "in", 0.01), "-12.346 in");
  EXPECT_EQ(formatCoordinate(1500.0, "mm", 20.0), "1500 mm");
}

TEST(AppDocument, modelUnitsAreSetForTheWholeDocument) {
  test::TempDir dir;
  AppState state;
  ASSERT_NO_FATAL_FAILURE(openBlockPeeledOnce(state, dir));
  setModelUnits(state, "in");
  EXPECT_EQ(state.model.frame().units, "in");
  peelTo(state, 2);  // from the depth map, computed when the units were still the file's
  EXPECT_EQ(state.doc.model->peeled, 2);
  EXPECT_EQ(state.model.frame().units, "in");
  undo(state);
  EXPECT_EQ(state.model.frame().units, "in");  // every step of the document
  ASSERT_TRUE(saveModel(state, dir / "inches.vxm"));
  auto back = io::loadVxm(dir / "inches.vxm");
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(back->frame().units, "in");
}

// Two picks give the distance between their centres in model units; a third starts again.
TEST(AppMeasure, twoPicksGiveTheDistanceAndAThirdStartsAgain) {
  AppState state;
  VoxelGrid g(Dims{10, 10, 10}, GridFrame{.origin = glm::dvec3(0.0), .voxel_size = 0.5, .units = "mm", .source = ""});
  state.model = g;
  addMeasurePick(state, glm::ivec3(1, 2, 3));
  addMeasurePick(state, glm::ivec3(4, 6, 3));
  const std::vector<std::string> lines = measureLines(state);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "A  voxel (1, 2, 3)  at (0.75, 1.25, 1.75) mm");
  EXPECT_EQ(lines[2], "distance 2.5 mm  (dx 1.5, dy 2, dz 0; centre to centre)");
  addMeasurePick(state, glm::ivec3(0, 0, 0));
  EXPECT_EQ(measurePicks(state).size(), 1u);
  state.model = VoxelGrid(Dims{20, 20, 20}, GridFrame{});  // another lattice: the picks no longer apply
  EXPECT_TRUE(measurePicks(state).empty());
}

// An export through the browser says where it wrote, as an absolute path (a relative name is easy to lose).
TEST(AppDocument, anExportSaysWhereItWrote) {
  test::TempDir dir;
  ASSERT_TRUE(io::saveVxm(block(), dir / "block.vxm").ok());
  AppState state;
  startOpen(state, dir / "block.vxm");
  ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
  state.panel = Panel::kSection;
  ASSERT_TRUE(pump(state, [&] { return currentSection(state) != nullptr; }));
  ASSERT_TRUE(givePath(state, ActionId::kExportSectionPng, dir / "cut.png"));
  EXPECT_EQ(state.status_message, "Wrote " + (dir / "cut.png").string());
  EXPECT_TRUE(std::filesystem::exists(dir / "cut.png"));
}

// A save that fails (here: a path below a regular file, which even root cannot create) reports the path, keeps the
// model and its unsaved state, and a save elsewhere then succeeds.
TEST(AppDocument, aFailedSaveKeepsTheModelAndAnotherPlaceWorks) {
  test::TempDir dir;
  AppState state;
  ASSERT_NO_FATAL_FAILURE(openBlockPeeledOnce(state, dir));
  ASSERT_TRUE(hasUnsavedChanges(state));

  const auto bad = dir / "block.vxm" / "sub.vxm";
  EXPECT_FALSE(saveModel(state, bad));
  ASSERT_EQ(state.errors.messages.size(), 1u);
  EXPECT_NE(state.errors.messages[0].find("sub.vxm"), std::string::npos) << state.errors.messages[0];
  EXPECT_TRUE(state.doc.model.has_value());
  EXPECT_EQ(state.doc.model->peeled, 1);
  EXPECT_TRUE(hasUnsavedChanges(state));

  EXPECT_TRUE(saveModel(state, dir / "elsewhere.vxm"));
  EXPECT_FALSE(hasUnsavedChanges(state));
  EXPECT_EQ(windowTitle(state), "voxmod - elsewhere.vxm");  // the document is the file it was saved as
  auto reread = io::loadVxm(dir / "elsewhere.vxm");
  ASSERT_TRUE(reread.ok()) << reread.error().message;
  EXPECT_LT(reread->filledCount(), block().filledCount());  // the peeled model was saved
}

// ---- The script harness drives the application through the action table ----

// Runs `text` as a --script on a window-less state: each "frame" updates the document and steps the script.
bool runScript(AppState& state, Harness& h, const std::string& text) {
  auto commands = parseScript(text, "t.script");
  EXPECT_TRUE(commands.ok()) << commands.error().message;
  if (!commands) return false;
  h.commands = std::move(commands).value();
  h.scripted = true;
  state.voxelize_dialog_on_open = false;
  for (int frame = 0; frame < 20000 && h.scriptRunning() && !state.quit_requested; ++frame) {
    updateDocument(state);
    stepScript(h, state);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return !h.failed && !h.scriptRunning();
}

// The measure's probe: a pick in a plate 4 voxels (2 mm) thick reads the wall there once the Thickness panel has the
// thickness (an axis-aligned plate of an even number of voxels reads exactly that many, docs/accuracy.md).
TEST(AppMeasure, aPickReadsTheWallThicknessOnceTheThicknessPanelHasIt) {
  test::TempDir dir;
  VoxelGrid plate(Dims{24, 24, 4},
                  GridFrame{.origin = glm::dvec3(0.0), .voxel_size = 0.5, .units = "mm", .source = ""});
  for (int32_t z = 0; z < 4; ++z) {
    for (int32_t y = 0; y < 24; ++y) plate.fillRun(y, z, 0, 24);
  }
  ASSERT_TRUE(io::saveVxm(plate, dir / "plate.vxm").ok());
  AppState state;
  Harness h;
  ASSERT_TRUE(runScript(state, h, "open " + (dir / "plate.vxm").string() + "\nmeasure 12 12 1\n")) << h.last_error;
  ASSERT_EQ(measureLines(state).size(), 1u);
  EXPECT_EQ(measureLines(state)[0], "A  voxel (12, 12, 1)  at (6.25, 6.25, 0.75) mm");  // no thickness yet
  Harness h2;
  ASSERT_TRUE(runScript(state, h2, "panel-thickness\n")) << h2.last_error;
  ASSERT_NE(currentThickness(state), nullptr);
  EXPECT_EQ(measureLines(state)[0], "A  voxel (12, 12, 1)  at (6.25, 6.25, 0.75) mm  wall 2 mm (spheres)");
}

// A click in a section snaps to the material's edge: the nearest filled cell with an empty neighbour within reach,
// else the cell clicked.
TEST(AppMeasure, aSectionClickSnapsToTheNearestEdgeCellWithinReach) {
  Image2D<uint8_t> mask(10, 10, 0);  // a band of columns 3 to 6, every row
  for (int32_t row = 0; row < 10; ++row) {
    for (int32_t u = 3; u <= 6; ++u) mask.at(u, row) = 1;
  }
  EXPECT_EQ(snapToEdge(mask, 1, 5, 3.0), glm::ivec2(3, 5));  // empty, two cells left of the band's left face
  EXPECT_EQ(snapToEdge(mask, 4, 5, 3.0), glm::ivec2(3, 5));  // inside: the nearer face, one cell away
  EXPECT_EQ(snapToEdge(mask, 6, 5, 3.0), glm::ivec2(6, 5));  // on the right face already
  EXPECT_EQ(snapToEdge(mask, 9, 5, 2.0), glm::ivec2(9, 5));  // the face three cells away: out of reach
  EXPECT_EQ(snapToEdge(mask, 1, 5, 0.0), glm::ivec2(1, 5));  // no reach: the cell clicked
  EXPECT_EQ(snapToEdge(mask, 4, 0, 3.0), glm::ivec2(4, 0));  // the picture's edge is the material's edge too
}

TEST(AppScriptRun, commandsReachTheDocumentThroughTheActions) {
  test::TempDir dir;
  ASSERT_TRUE(io::saveVxm(block(), dir / "block.vxm").ok());
  AppState state;
  Harness h;
  ASSERT_TRUE(runScript(state, h,
                        "open " + (dir / "block.vxm").string() +
                            "\npanel-skin\npeel 2\nlit off\nlit off\nsection x 3\nxray y max\nundo\n"
                            "save " +
                            (dir / "out.vxm").string() + "\n"))
      << h.last_error;
  ASSERT_TRUE(state.doc.model.has_value());
  EXPECT_EQ(state.doc.model->peeled, 0);  // peeled 2, then undone
  EXPECT_FALSE(state.view.lit);           // "lit off" twice: set, not toggled back
  EXPECT_EQ(state.section.axis, Axis::kX);
  EXPECT_EQ(state.section.index, 3);
  EXPECT_EQ(state.xray.params.axis, Axis::kY);
  EXPECT_EQ(state.xray.params.mode, XrayMode::kMax);
  EXPECT_EQ(state.panel, Panel::kXray);
  EXPECT_TRUE(std::filesystem::exists(dir / "out.vxm"));
  EXPECT_FALSE(hasUnsavedChanges(state));
}

// The Thickness panel: thickness computed in the background while the panel is open, thin walls under the minimum
// wall set by the script, and the round peel as an undoable change that leaves the thickness of the model before it
// in place for its undo.
TEST(AppScriptRun, thicknessPanelThinWallsAndPeelByDistance) {
  test::TempDir dir;
  ASSERT_TRUE(io::saveVxm(block(), dir / "block.vxm").ok());
  AppState state;
  Harness h;
  ASSERT_TRUE(runScript(state, h, "open " + (dir / "block.vxm").string() + "\npanel-thickness\nmin-wall 0.3\n"))
      << h.last_error;
  EXPECT_EQ(state.panel, Panel::kThickness);
  const uint64_t version = state.model_version;
  const ThicknessResult* r = currentThickness(state);
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->thickness.stats.voxels, block().filledCount());
  EXPECT_GT(r->thickness.stats.max, 0.3);
  ASSERT_FALSE(r->hot_spots.empty());
  EXPECT_DOUBLE_EQ(minWall(state), 0.3);
  const Walls* thin = currentThinWalls(state);
  ASSERT_NE(thin, nullptr);
  EXPECT_EQ(thin->voxels, 0);             // no wall in a 12 x 10 x 8 block is thinner than 0.3 voxels
  EXPECT_NEAR(thin->wall_min, 8.0, 1.0);  // its thinnest wall is its height, not an edge

  // A minimum wall thicker than the block: the block is one thin wall, its edges and corners aside.
  Harness h2;
  ASSERT_TRUE(runScript(state, h2, "min-wall 9\n")) << h2.last_error;
  thin = currentThinWalls(state);
  ASSERT_NE(thin, nullptr);
  ASSERT_EQ(thin->regions.size(), 1u);
  EXPECT_GT(thin->voxels, block().filledCount() / 2);
  EXPECT_LT(thin->voxels, block().filledCount());
  EXPECT_EQ(currentThickness(state), r);  // the minimum wall does not recompute the thickness
  // a smallest wall listed larger than the block's surface: the block is a speck, counted and not listed
  Harness ha;
  ASSERT_TRUE(runScript(state, ha, "min-area 1e9\n")) << ha.last_error;
  thin = currentThinWalls(state);
  ASSERT_NE(thin, nullptr);
  EXPECT_TRUE(thin->regions.empty());
  EXPECT_EQ(thin->specks, 1);
  Harness hb;
  ASSERT_TRUE(runScript(state, hb, "min-area -1\n")) << hb.last_error;  // back to the minimum wall squared
  thin = currentThinWalls(state);
  ASSERT_NE(thin, nullptr);
  EXPECT_EQ(thin->regions.size(), 1u);

  // The round peel by one voxel removes the outer shell (distance 1): a 10 x 8 x 6 block remains, undoably.
  Harness h3;
  ASSERT_TRUE(runScript(state, h3, "peel-distance 1\n")) << h3.last_error;
  EXPECT_EQ(state.panel, Panel::kSkin);
  EXPECT_EQ(state.model.filledCount(), 10 * 8 * 6);
  EXPECT_NE(state.model_version, version);
  EXPECT_EQ(currentThickness(state), nullptr);  // another model: its thickness is not the block's
  ASSERT_TRUE(canUndo(state));
  EXPECT_NE(state.doc.model->label.find("round"), std::string::npos) << state.doc.model->label;
  EXPECT_FALSE(state.doc.model->round_peels.empty());
  EXPECT_EQ(state.doc.model->peeled, 0);  // a new base: layer peels continue from it

  // Undo brings the block back with its version, and the thickness computed for it is still there.
  Harness h4;
  ASSERT_TRUE(runScript(state, h4, "undo\nlit off\npanel-thickness\n")) << h4.last_error;
  EXPECT_EQ(state.model_version, version);
  EXPECT_EQ(currentThickness(state), r);
  EXPECT_EQ(state.model.filledCount(), block().filledCount());

  // Values that do not fit are refused with the action's words.
  Harness h5;
  testing::internal::CaptureStderr();
  EXPECT_FALSE(runScript(state, h5, "min-wall -1\n"));
  EXPECT_NE(testing::internal::GetCapturedStderr().find("min-wall takes a length"), std::string::npos);
}

// A row of the Thickness panel's lists clicked (the thin-region and hot-spot actions) is selected and shown: the
// section along its axis through its middle, the 3D view turned about it and brought near. Another minimum wall drops
// the region's selection (its list is another); a number outside the list is refused, saying which are in it.
TEST(AppScriptRun, aThinRegionOrHotSpotClickedIsSelectedAndTheViewsGoThere) {
  test::TempDir dir;
  ASSERT_TRUE(io::saveVxm(block(), dir / "block.vxm").ok());
  AppState state;
  Harness h;
  ASSERT_TRUE(runScript(state, h,
                        "open " + (dir / "block.vxm").string() +
                            "\npanel-thickness\nmin-wall 9\nzoom 0.05\n"
                            "section x 0\nthin-region 1\n"))
      << h.last_error;
  EXPECT_EQ(state.panel, Panel::kThickness);
  const Walls* thin = currentThinWalls(state);
  ASSERT_NE(thin, nullptr);
  ASSERT_EQ(thin->regions.size(), 1u);  // the whole block is a wall thinner than 9
  EXPECT_EQ(selectedRegion(state), &thin->regions[0]);
  EXPECT_EQ(selectedHotSpot(state), nullptr);
  EXPECT_EQ(state.section.axis, Axis::kX);
  EXPECT_EQ(state.section.index, 5);  // (0 + 11) / 2
  EXPECT_EQ(state.view.camera.target, glm::dvec3(6.0, 5.0, 4.0));
  EXPECT_LE(state.view.camera.distance, 6.0 * 12.0);  // brought near from far away (zoomed out)

  Harness h2;
  ASSERT_TRUE(runScript(state, h2, "section y 0\nhot-spot 1\n")) << h2.last_error;
  const ThicknessResult* r = currentThickness(state);
  ASSERT_NE(r, nullptr);
  ASSERT_FALSE(r->hot_spots.empty());
  const HotSpot& spot = r->hot_spots[0];
  EXPECT_EQ(selectedHotSpot(state), &spot);
  EXPECT_EQ(state.section.axis, Axis::kY);
  EXPECT_EQ(state.section.index, spot.voxel.y);
  EXPECT_EQ(state.view.camera.target, glm::dvec3(spot.voxel) + 0.5);
  EXPECT_EQ(selectedRegion(state), &thin->regions[0]);  // both stay selected

  Harness h3;
  ASSERT_TRUE(runScript(state, h3, "min-wall 50\n")) << h3.last_error;
  EXPECT_EQ(selectedRegion(state), nullptr);
  EXPECT_EQ(selectedHotSpot(state), &spot);

  // Another model (peeled a voxel deep), its own thickness: a region selected in it drops the hot spot selected in
  // the block's.
  Harness h35;
  ASSERT_TRUE(runScript(state, h35, "peel-distance 1\npanel-thickness\nmin-wall 7\nthin-region 1\n")) << h35.last_error;
  ASSERT_NE(currentThickness(state), nullptr);
  EXPECT_EQ(currentThickness(state)->thickness.stats.voxels, 10 * 8 * 6);
  EXPECT_NE(selectedRegion(state), nullptr);
  EXPECT_EQ(selectedHotSpot(state), nullptr);

  Harness h4;
  testing::internal::CaptureStderr();
  EXPECT_FALSE(runScript(state, h4, "thin-region 2\n"));
  EXPECT_NE(testing::internal::GetCapturedStderr().find("1 to 1"), std::string::npos);
  const Action* hot = findAction("hot-spot");  // (a script stops at its first failure: the action alone)
  ASSERT_NE(hot, nullptr);
  const Status s0 = dispatch(state, *hot, ActionArgs{{"0"}, "0"});
  ASSERT_FALSE(s0.ok());
  EXPECT_NE(s0.error().message.find("hot-spot takes a row of the Thickness panel's list"), std::string::npos)
      << s0.error().message;
}

// A round peel deeper than the part is refused with how deep it goes; another file opened starts from its own
// minimum wall (a quarter of its thickest), not the length chosen for the previous part.
TEST(AppScriptRun, aRoundPeelOfEverythingIsRefusedAndTheMinimumWallIsPerFile) {
  test::TempDir dir;
  ASSERT_TRUE(io::saveVxm(block(), dir / "block.vxm").ok());
  AppState state;
  Harness h;
  testing::internal::CaptureStdout();
  EXPECT_TRUE(runScript(state, h,
                        "open " + (dir / "block.vxm").string() +
                            "\npanel-thickness\nmin-wall 3\nexpect-error would remove the whole model\n"
                            "peel-distance 100\n"))
      << h.last_error;
  EXPECT_NE(testing::internal::GetCapturedStdout().find("its deepest voxel is 4"), std::string::npos);
  EXPECT_EQ(state.model.filledCount(), block().filledCount());  // nothing was peeled
  EXPECT_DOUBLE_EQ(minWall(state), 3.0);
  Harness h2;
  ASSERT_TRUE(runScript(state, h2, "open " + (dir / "block.vxm").string() + "\n")) << h2.last_error;
  EXPECT_LT(state.thickness_ui.min_wall, 0.0);  // not chosen for this file yet
}

// Cancelling the thickness (Esc, or the panel's Cancel) stops it for this model version; it is not asked for again
// until the user does.
TEST(AppThickness, cancelStopsUntilRetried) {
  test::TempDir dir;
  ASSERT_TRUE(io::saveVxm(block(), dir / "block.vxm").ok());
  AppState state;
  Harness h;
  ASSERT_TRUE(runScript(state, h, "open " + (dir / "block.vxm").string() + "\n")) << h.last_error;
  state.panel = Panel::kThickness;
  updateDocument(state);
  ASSERT_TRUE(state.thickness.computing(state.model_version));
  EXPECT_TRUE(dispatch(state, ActionId::kCancelJob));  // Esc, as for voxelizing
  EXPECT_FALSE(state.thickness.busy());
  updateDocument(state);
  EXPECT_FALSE(state.thickness.busy());  // not asked again
  retryThickness(state);
  updateDocument(state);
  EXPECT_TRUE(state.thickness.computing(state.model_version));
}

// Undo back to a model whose thickness is here while the thickness of the model left is still being computed: that
// computation is dropped, and its end does not replace the result shown (it was computed again from scratch).
TEST(AppThickness, undoWhileTheNextModelsThicknessRunsKeepsTheResult) {
  test::TempDir dir;
  VoxelGrid big(Dims{120, 100, 80});  // large enough that its thickness takes far longer than the steps below
  for (int32_t z = 0; z < 80; ++z) {
    for (int32_t y = 0; y < 100; ++y) big.fillRun(y, z, 0, 120);
  }
  ASSERT_TRUE(io::saveVxm(big, dir / "big.vxm").ok());
  AppState state;
  Harness h;
  ASSERT_TRUE(runScript(state, h, "open " + (dir / "big.vxm").string() + "\npanel-thickness\n")) << h.last_error;
  const ThicknessResult* r = currentThickness(state);
  ASSERT_NE(r, nullptr);
  const uint64_t before = state.model_version;
  ASSERT_TRUE(peelDistance(state, 1.0).ok());
  state.panel = Panel::kThickness;
  updateDocument(state);
  ASSERT_TRUE(state.thickness.computing(state.model_version));
  undo(state);
  updateDocument(state);
  ASSERT_EQ(state.model_version, before);
  EXPECT_EQ(currentThickness(state), r);
  EXPECT_FALSE(state.thickness.busy());
  for (int i = 0; i < 200; ++i) {  // long enough for the dropped computation to have ended
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    updateDocument(state);
  }
  EXPECT_EQ(currentThickness(state), r);
}

// Every action a script names goes through dispatch: where the action is not enabled (no model yet), the script
// fails with dispatch's own words, for each of them.
TEST(AppScriptRun, everyActionCommandIsDispatched) {
  for (const Action& a : actionTable()) {
    if (!a.enabled) continue;
    AppState state;
    if (a.enabled(state)) continue;
    Harness h;
    std::string line = a.name;
    for (int i = 0; i < std::max(a.run ? 0 : a.min_values, 0); ++i) line += " 1";
    EXPECT_FALSE(runScript(state, h, line + "\n")) << line;
    EXPECT_EQ(h.exit_code, 1) << line;
  }
  // And the message is dispatch's.
  AppState state;
  Harness h;
  testing::internal::CaptureStderr();
  EXPECT_FALSE(runScript(state, h, "undo\n"));
  EXPECT_NE(testing::internal::GetCapturedStderr().find("'undo' is not available now"), std::string::npos);
}

// An error dialog raised by an action fails the script, unless expect-error announced it.
TEST(AppScriptRun, errorsFailTheRunUnlessExpected) {
  test::TempDir dir;
  AppState state;
  Harness h;
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  EXPECT_TRUE(runScript(state, h, "expect-error no such file\nopen " + (dir / "missing.stl").string() + "\n"));
  AppState state2;
  Harness h2;
  EXPECT_FALSE(runScript(state2, h2, "open " + (dir / "missing.stl").string() + "\n"));
  testing::internal::GetCapturedStdout();
  EXPECT_NE(testing::internal::GetCapturedStderr().find("missing.stl: no such file"), std::string::npos);
  EXPECT_EQ(state2.errors.messages.size(), 1u);
}

}  // namespace
}  // namespace vox::app

namespace vox::app {
namespace {

// The Thickness panel's method: rays follow the mesh the model was voxelized from. A 4 x 4 x 1 plate reads 1 through
// its thickness by rays; after a peel the model is no longer the mesh's voxelization and rays are refused with the
// reason, the views back on spheres.
TEST(AppScriptRun, theThicknessPanelShowsRaysForAMeshsOwnVoxelization) {
  test::TempDir dir;
  TriangleMesh plate = test::unitCubeMesh();
  for (Triangle& t : plate.triangles) {
    for (glm::vec3& v : t.v) v = v * glm::vec3(4, 4, 1);
  }
  ASSERT_TRUE(io::saveStlBinary(plate, dir / "plate.stl").ok());
  AppState state;
  startOpen(state, dir / "plate.stl");
  ASSERT_TRUE(pump(state, [&] { return state.doc.mesh != nullptr; }));
  startVoxelize(state, VoxelizeParams{.resolution = 40});
  ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
  Harness h;
  ASSERT_TRUE(runScript(state, h, "panel-thickness\nthickness-method ray\n")) << h.last_error;
  ASSERT_TRUE(pump(state, [&] {
    requestThickness(state);
    requestRays(state);
    const ThicknessResult* r = currentThickness(state);
    return r && shownRay(state, *r);
  }));
  const ThicknessResult* r = currentThickness(state);
  const RayThicknessResult* ray = shownRay(state, *r);
  ASSERT_NE(ray, nullptr);
  EXPECT_NEAR(ray->min, 1.0, 1e-4);  // the faces' rays cross the plate
  // the plate's middle layer, its rim aside: read 1 where a ray crossed, nearly everywhere
  const Dims d = state.model.dims();
  int64_t read = 0, total = 0;
  for (int32_t y = 2; y < d.ny - 2; ++y)
    for (int32_t x = 2; x < d.nx - 2; ++x) {
      const float t = ray->field.at(x, y, d.nz / 2);
      ++total;
      if (t > 0.0f) {
        ++read;
        EXPECT_NEAR(t, 1.0f, 1e-4);
      }
    }
  EXPECT_GT(read, total * 95 / 100);

  // Export section PNG on the Thickness panel writes the section it shows: the figure with its colour bar, not the
  // plain section (the plate's 40 x 10 voxels at one pixel each).
  Harness he;
  const std::filesystem::path png = dir / "ray_section.png";
  ASSERT_TRUE(runScript(state, he, "section z 4\npanel-thickness\nexport-section " + png.string() + "\n"))
      << he.last_error;
  auto picture = io::loadPng(png);
  ASSERT_TRUE(picture.ok());
  EXPECT_GT(picture->width, 400);

  Harness h2;
  ASSERT_TRUE(runScript(state, h2, "thickness-method sphere\n")) << h2.last_error;
  EXPECT_EQ(shownRay(state, *r), nullptr);
  // back to rays: the same thickness, its rays kept (a job of their own: nothing is computed again)
  const uint64_t id = r->id;
  ASSERT_TRUE(dispatch(state, ActionId::kThicknessMethod, ActionArgs{{"ray"}, "ray"}).ok());
  requestThickness(state);
  requestRays(state);
  EXPECT_EQ(currentThickness(state)->id, id);
  EXPECT_FALSE(state.thickness.busy());
  EXPECT_FALSE(state.rays.busy());
  EXPECT_EQ(shownRay(state, *r), ray);
  // cast again and cancelled: the views show spheres, nothing is cast until rays are asked for again
  state.rays.clear();
  requestRays(state);
  ASSERT_TRUE(state.rays.busy());
  ASSERT_TRUE(dispatch(state, ActionId::kCancelRays));
  EXPECT_FALSE(state.rays.busy());
  requestRays(state);
  EXPECT_FALSE(state.rays.busy());
  EXPECT_EQ(shownRay(state, *r), nullptr);
  ASSERT_TRUE(dispatch(state, ActionId::kThicknessMethod, ActionArgs{{"ray"}, "ray"}).ok());
  ASSERT_TRUE(pump(state, [&] {
    requestRays(state);
    return shownRay(state, *currentThickness(state)) != nullptr;
  }));
  ASSERT_TRUE(dispatch(state, ActionId::kThicknessMethod, ActionArgs{{"sphere"}, "sphere"}).ok());

  Harness h3;
  testing::internal::CaptureStderr();
  EXPECT_FALSE(runScript(state, h3, "peel 1\nthickness-method ray\n"));
  EXPECT_NE(testing::internal::GetCapturedStderr().find("follows the mesh"), std::string::npos);
  EXPECT_FALSE(state.thickness_ui.ray);
}

}  // namespace
}  // namespace vox::app

namespace vox::app {
namespace {

// The Print panel's actions on a block with a sealed void (tests/data/mesh/sealed_void.stl, 20 x 20 x 12 with an
// 8 x 8 x 4 void at its middle): the void found and its click taking the section through it; a side laid on the
// plate turning the build direction; a bad direction refused, leaving the one chosen.
TEST(AppScriptRun, thePrintPanelFindsTheVoidAndLaysAFaceOnThePlate) {
  AppState state;
  startOpen(state, test::sourceDir() / "tests/data/mesh/sealed_void.stl");
  ASSERT_TRUE(pump(state, [&] { return state.doc.mesh != nullptr; }));
  startVoxelize(state, VoxelizeParams{.resolution = 40});
  ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
  Harness h;
  ASSERT_TRUE(runScript(state, h, "panel-print\n")) << h.last_error;
  ASSERT_TRUE(pump(state, [&] {
    requestPrint(state);
    return currentPrint(state) != nullptr;
  }));
  const PrintResult* r = currentPrint(state);
  ASSERT_EQ(r->check.cavities.size(), 1u);
  EXPECT_NEAR(r->check.cavities[0].volume, 256.0, 1e-6);
  EXPECT_NEAR(r->check.support.support_volume, 256.0, 3.0);  // inside the void, under its ceiling
  EXPECT_TRUE(r->check.from_mesh);

  Harness hc;
  ASSERT_TRUE(runScript(state, hc, "section z 0\nprint-cavity 1\n")) << hc.last_error;
  EXPECT_EQ(state.panel, Panel::kPrint);
  const TrappedCavity* c = selectedCavity(state);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(state.section.index, (c->box_min.z + c->box_max.z) / 2);  // the section through the void

  // the block's face x = 0 laid on the plate: up is +x
  Harness hl;
  ASSERT_TRUE(runScript(state, hl, "print-lay-face 0 20 10\n")) << hl.last_error;
  EXPECT_EQ(printDirectionName(state.print_ui.up), "+x");
  Harness hb;
  EXPECT_TRUE(runScript(state, hb, "expect-error is zero\nprint-direction 0 0 0\n")) << hb.last_error;
  EXPECT_EQ(printDirectionName(state.print_ui.up), "+x");
  Harness hv;
  ASSERT_TRUE(runScript(state, hv, "print-direction 0 1 1\n")) << hv.last_error;
  EXPECT_NEAR(state.print_ui.up.y, std::sqrt(0.5), 1e-12);

  // File > Export report: the page written in the background, with the void among its trapped cavities
  test::TempDir dir;
  const std::filesystem::path html = dir / "void_report.html";
  Harness hr;
  ASSERT_TRUE(runScript(state, hr, "export-report " + html.string() + "\n")) << hr.last_error;
  ASSERT_TRUE(pump(state, [&] { return !state.volume_export_job.active() && std::filesystem::exists(html); }));
  std::ifstream in(html);
  const std::string page((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(page.find("sealed_void.stl"), std::string::npos);
  EXPECT_NE(page.find("Trapped cavities</th><td>1,"), std::string::npos);
  EXPECT_NE(page.find("data:image/png;base64,iVBORw0KGgo"), std::string::npos);  // the section at least
  Harness hx;
  EXPECT_TRUE(runScript(state, hx, "expect-error HTML page\nexport-report " + (dir / "r.txt").string() + "\n"))
      << hx.last_error;
  EXPECT_FALSE(std::filesystem::exists(dir / "r.txt"));
}

// The Casting panel's actions on the same block: refused without units (the document unchanged); once in mm,
// simulated, not sound without a feeder; a feeder placed on its top, simulated again with it; bad settings refused,
// leaving the ones chosen; a cancelled run leaves the last result shown.
TEST(AppScriptRun, theCastingPanelSimulatesAndPlacesAFeeder) {
  AppState state;
  startOpen(state, test::sourceDir() / "tests/data/mesh/sealed_void.stl");
  ASSERT_TRUE(pump(state, [&] { return state.doc.mesh != nullptr; }));
  startVoxelize(state, VoxelizeParams{.resolution = 20});
  ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
  const uint64_t version = state.model_version;
  Harness h;
  ASSERT_TRUE(runScript(state, h, "panel-casting\nsimulate-casting\n")) << h.last_error;
  ASSERT_TRUE(pump(state, [&] {
    requestCasting(state);
    return !state.casting.busy() && castingError(state) != nullptr;
  }));
  EXPECT_NE(castingError(state)->message.find("no length units"), std::string::npos);
  EXPECT_EQ(state.model_version, version);

  // asked again, the same refusal (the run is tried again, not the old error kept)
  Harness h2;
  ASSERT_TRUE(runScript(state, h2, "simulate-casting\n")) << h2.last_error;
  ASSERT_TRUE(pump(state, [&] {
    requestCasting(state);
    return !state.casting.busy() && castingError(state) != nullptr;
  }));
  // the units chosen (the Mass panel's or this panel's list): the same settings now run
  setModelUnits(state, "mm");
  // (a run is started by the action and waited for here: the script runner's frames run out under the sanitizers)
  ASSERT_TRUE(dispatch(state, ActionId::kSimulateCasting));
  ASSERT_TRUE(pump(state, [&] {
    requestCasting(state);
    return currentCasting(state) != nullptr && !state.casting.busy();
  }));
  EXPECT_EQ(currentCasting(state)->key.units, "mm");
  Harness hs;
  ASSERT_TRUE(runScript(state, hs, "casting-alloy aluminium\n")) << hs.last_error;
  ASSERT_TRUE(dispatch(state, ActionId::kSimulateCasting));
  ASSERT_TRUE(pump(state, [&] {
    requestCasting(state);
    return currentCasting(state) != nullptr && !castingStale(state) && !state.casting.busy();
  }));
  const CastingOutcome* r = currentCasting(state);
  EXPECT_FALSE(r->run.result.sound);
  ASSERT_FALSE(r->run.result.hot_spots.empty());
  EXPECT_EQ(r->key.alloy, "aluminium");

  Harness hsel;
  ASSERT_TRUE(runScript(state, hsel, "casting-hot-spot 1\n")) << hsel.last_error;
  ASSERT_NE(selectedCastingSpot(state), nullptr);

  Harness hb;
  EXPECT_TRUE(runScript(state, hb,
                        "expect-error unknown alloy\ncasting-alloy bronze\nexpect-error 0 to 1000\n"
                        "casting-superheat -5\nexpect-error time, niyama or modulus\ncasting-field heat\n"))
      << hb.last_error;
  EXPECT_EQ(state.casting_ui.chosen.alloy, "aluminium");
  EXPECT_EQ(state.casting_ui.chosen.superheat_k, 50.0);

  // a cancelled run (other settings) leaves the last result shown
  state.casting_ui.chosen.superheat_k = 60.0;
  simulateCasting(state);
  requestCasting(state);
  ASSERT_TRUE(state.casting.busy());
  cancelCasting(state);
  EXPECT_FALSE(state.casting.busy());
  EXPECT_EQ(currentCasting(state), r);
  state.casting_ui.chosen.superheat_k = 50.0;

  // the feeder is a part of the scene: placed (undoable), the model now holds its metal
  const int64_t block_voxels = state.model.filledCount();
  const double spot_modulus = r->run.result.hot_spots[0].modulus;
  Harness hf;
  ASSERT_TRUE(runScript(state, hf, "casting-place-feeder 10 10 11\n")) << hf.last_error;
  ASSERT_EQ(feederParts(state).size(), 1u);
  ASSERT_NE(currentParts(state), nullptr);
  EXPECT_EQ(currentParts(state)->size(), 2u);
  EXPECT_GT(state.model.filledCount(), block_voxels);
  const Feeder f = placedFeeders(state).at(0);
  EXPECT_NEAR(f.base.z, 12.0, 1e-9);  // on the block's top
  EXPECT_NEAR(feederModulus(f), 1.2 * spot_modulus, 1e-6);
  EXPECT_EQ(currentCasting(state), nullptr);  // the parts changed: the last run is not this model's
  EXPECT_EQ(wantedCastingKey(state).feeders.size(), 1u);

  ASSERT_TRUE(dispatch(state, ActionId::kSimulateCasting));
  ASSERT_TRUE(pump(state, [&] {
    requestCasting(state);
    return currentCasting(state) != nullptr && !castingStale(state) && !state.casting.busy();
  }));
  const CastingOutcome* fed = currentCasting(state);
  EXPECT_EQ(fed->run.result.feeders.size(), 1u);
  EXPECT_GT(fed->run.result.yield, 0.5);
  EXPECT_NEAR(fed->run.result.casting_volume, double(block_voxels) * std::pow(state.model.voxelSize(), 3), 1e-6);
  // the feeder's metal, a voxel of the model, has its time (the views colour it)
  const glm::dvec3 top = (f.base - state.model.frame().origin) / state.model.voxelSize();
  const glm::ivec3 in_feeder(int(top.x), int(top.y), int(top.z) + 1);
  ASSERT_TRUE(state.model.get(in_feeder.x, in_feeder.y, in_feeder.z));
  EXPECT_GT(castingFieldAt(*fed, CastingField::kTime, in_feeder), 0.0f);

  // moved in the Parts panel (the run's feeder moves with it), never turned; undo takes the move back
  const size_t k = feederParts(state)[0];
  const std::string n = std::to_string(k + 1);
  Harness hm;
  const std::string step = std::to_string(state.model.voxelSize());
  ASSERT_TRUE(
      runScript(state, hm, "place-part " + n + " " + step + " 0 0\nexpect-error never turned\nturn-part " + n + " x\n"))
      << hm.last_error;
  EXPECT_NEAR(placedFeeders(state).at(0).base.x, f.base.x + state.model.voxelSize(), 1e-9);
  EXPECT_TRUE(castingStale(state) || currentCasting(state) == nullptr);
  ASSERT_TRUE(dispatch(state, ActionId::kUndo));
  EXPECT_NEAR(placedFeeders(state).at(0).base.x, f.base.x, 1e-9);
  EXPECT_EQ(currentCasting(state), fed);  // the model the run was for is back

  Harness hd;
  ASSERT_TRUE(runScript(state, hd, "casting-time 1\ncasting-field niyama\ncasting-delete-feeder 1\n")) << hd.last_error;
  EXPECT_TRUE(feederParts(state).empty());
  EXPECT_EQ(state.model.filledCount(), block_voxels);
  ASSERT_TRUE(dispatch(state, ActionId::kUndo));  // the feeder back
  EXPECT_EQ(feederParts(state).size(), 1u);

  // typed feeders, one deleted, another typed: each feeder keeps a name of its own
  const std::string typed = "casting-feeder " + std::to_string(f.base.x) + " " + std::to_string(f.base.y) + " " +
                            std::to_string(f.base.z) + " 2 3\n";
  Harness ht;
  ASSERT_TRUE(runScript(state, ht, typed + typed + "casting-delete-feeder 1\n" + typed)) << ht.last_error;
  std::set<std::string> names;
  for (const size_t i : feederParts(state)) names.insert(currentParts(state)->part(i).name);
  EXPECT_EQ(names, (std::set<std::string>{"feeder 2", "feeder 3", "feeder 4"}));
}

}  // namespace
}  // namespace vox::app
