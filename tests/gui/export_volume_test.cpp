// File > Export volume and Export thickness volume without a window (export_volume.h): each runs in the background
// and says where it wrote when done; the model's volume is what the view shows (the cut-away's half); wrong extensions,
// missing results and unwritable places are error dialogs naming the file; Cancel leaves no file behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <thread>
#include <utility>

#include "app/action_functions.h"
#include "app/actions.h"
#include "app/app_state.h"
#include "app/operations.h"
#include "support/grids.h"
#include "support/test_support.h"
#include "vox/analysis/thickness_map.h"
#include "vox/io/nrrd.h"
#include "vox/io/voxel_file.h"

namespace vox::app {
namespace {

// Runs the window's per-frame update until `done` holds (or about 20 s pass).
template <class F>
bool pump(AppState& state, F done) {
  for (int i = 0; i < 10000; ++i) {
    updateDocument(state);
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return false;
}

int entries(const std::filesystem::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

// `grid` saved as model.vxm in `dir` and opened.
void openGrid(AppState& state, const test::TempDir& dir, const VoxelGrid& grid) {
  ASSERT_TRUE(io::saveVxm(grid, dir / "model.vxm").ok());
  startOpen(state, dir / "model.vxm");
  ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
}

TEST(AppExportVolume, everyFormatIsWrittenInTheBackgroundAndSaysWhereItWrote) {
  test::TempDir dir;
  AppState state;
  ASSERT_NO_FATAL_FAILURE(openGrid(state, dir, test::randomGrid(Dims{30, 20, 10}, 0.4, 1)));
  for (const char* name : {"m.vti", "m.vdb", "m.nrrd", "m.vox"}) {
    SCOPED_TRACE(name);
    state.status_message.clear();
    ASSERT_TRUE(dispatch(state, ActionId::kExportVolume, ActionArgs{{name}, (dir / name).string()}).ok());
    ASSERT_TRUE(pump(state, [&] { return !volumeExportRunning(state); }));
    EXPECT_EQ(state.status_message, "Wrote " + (dir / name).string());
    EXPECT_GT(std::filesystem::file_size(dir / name), 0u);
  }
  auto back = io::loadNrrdField(dir / "m.nrrd");
  ASSERT_TRUE(back.ok()) << back.error().message;
  int64_t filled = 0;
  for (float v : back->values) filled += v > 0.0f;
  EXPECT_EQ(filled, state.model.filledCount());
  EXPECT_TRUE(state.errors.messages.empty());
}

TEST(AppExportVolume, aWrongExtensionOrAnUnwritablePlaceIsAnErrorNamingTheFile) {
  test::TempDir dir;
  AppState state;
  ASSERT_NO_FATAL_FAILURE(openGrid(state, dir, test::randomGrid(Dims{8, 8, 8}, 0.5, 2)));
  EXPECT_FALSE(acceptBrowserPath(state, BrowserPurpose::kExportVolume, dir / "m.stl"));
  ASSERT_EQ(state.errors.messages.size(), 1u);
  EXPECT_NE(state.errors.messages[0].find("m.stl"), std::string::npos) << state.errors.messages[0];
  EXPECT_NE(state.errors.messages[0].find(".vox"), std::string::npos) << state.errors.messages[0];

  ASSERT_TRUE(acceptBrowserPath(state, BrowserPurpose::kExportVolume, dir / "missing" / "m.vdb"));
  ASSERT_TRUE(pump(state, [&] { return !volumeExportRunning(state); }));
  ASSERT_EQ(state.errors.messages.size(), 2u);
  EXPECT_NE(state.errors.messages[1].find("m.vdb"), std::string::npos) << state.errors.messages[1];
  EXPECT_EQ(entries(dir.path()), 1);  // model.vxm only
}

TEST(AppExportVolume, theThicknessVolumeNeedsTheThicknessAndHoldsItFieldForField) {
  test::TempDir dir;
  AppState state;
  VoxelGrid g(Dims{16, 12, 10});
  for (int32_t z = 1; z < 9; ++z)
    for (int32_t y = 1; y < 11; ++y) g.fillRun(y, z, 1, 15);
  ASSERT_NO_FATAL_FAILURE(openGrid(state, dir, g));
  EXPECT_FALSE(dispatch(state, ActionId::kExportThickness, ActionArgs{{"t.vti"}, (dir / "t.vti").string()}).ok());

  state.panel = Panel::kThickness;
  ASSERT_TRUE(pump(state, [&] { return currentThickness(state) != nullptr; }));
  EXPECT_FALSE(acceptBrowserPath(state, BrowserPurpose::kExportThickness, dir / "t.vox"));  // voxels only
  for (const char* name : {"t.vti", "t.vdb", "t.nrrd"}) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(dispatch(state, ActionId::kExportThickness, ActionArgs{{name}, (dir / name).string()}).ok());
    ASSERT_TRUE(pump(state, [&] { return !volumeExportRunning(state); }));
    EXPECT_TRUE(std::filesystem::exists(dir / name));
  }
  ASSERT_EQ(state.errors.messages.size(), 1u);  // the .vox refusal
  auto back = io::loadNrrdField(dir / "t.nrrd");
  ASSERT_TRUE(back.ok()) << back.error().message;
  EXPECT_EQ(back->values, thicknessField(currentThickness(state)->thickness).values);
}

TEST(AppExportVolume, theCutAwayExportsTheHalfTheViewKeeps) {
  test::TempDir dir;
  AppState state;
  // A 10 x 10 x 10 cube in a 12^3 grid.
  VoxelGrid cube(Dims{12, 12, 12});
  for (int z = 1; z < 11; ++z)
    for (int y = 1; y < 11; ++y) cube.fillRun(y, z, 1, 11);
  ASSERT_NO_FATAL_FAILURE(openGrid(state, dir, cube));
  const auto filledIn = [](const std::filesystem::path& path) {
    auto back = io::loadNrrdField(path);
    EXPECT_TRUE(back.ok()) << back.error().message;
    int64_t filled = 0, top = -1;
    if (!back.ok()) return std::pair<int64_t, int64_t>{-1, -1};
    for (int32_t z = 0; z < back->dims.nz; ++z)
      for (int32_t y = 0; y < back->dims.ny; ++y)
        for (int32_t x = 0; x < back->dims.nx; ++x) {
          if (back->at(x, y, z) > 0.0f) {
            ++filled;
            top = std::max<int64_t>(top, z);
          }
        }
    return std::pair<int64_t, int64_t>{filled, top};
  };

  // The section at z = 4, keeping z <= 4: layers 1 to 4 of the cube, the plane's own included.
  ASSERT_TRUE(dispatch(state, ActionId::kSectionAt, ActionArgs{{"z", "4"}, ""}).ok());
  ASSERT_EQ(state.panel, Panel::kSection);
  ASSERT_TRUE(state.view.cut_away);
  state.view.keep_above = false;
  ASSERT_TRUE(dispatch(state, ActionId::kExportVolume, ActionArgs{{"half.nrrd"}, (dir / "half.nrrd").string()}).ok());
  ASSERT_TRUE(pump(state, [&] { return !volumeExportRunning(state); }));
  EXPECT_EQ(state.status_message, "Wrote " + (dir / "half.nrrd").string() + " (the half the cut-away keeps)");
  EXPECT_EQ(filledIn(dir / "half.nrrd"), (std::pair<int64_t, int64_t>{400, 4}));
  auto half = io::loadNrrdField(dir / "half.nrrd");
  ASSERT_TRUE(half.ok());
  EXPECT_EQ(half->dims, cube.dims());  // the model's lattice, the other half empty

  // Keeping the half above: layers 4 to 10.
  state.view.keep_above = true;
  ASSERT_TRUE(dispatch(state, ActionId::kExportVolume, ActionArgs{{"above.nrrd"}, (dir / "above.nrrd").string()}).ok());
  ASSERT_TRUE(pump(state, [&] { return !volumeExportRunning(state); }));
  EXPECT_EQ(filledIn(dir / "above.nrrd"), (std::pair<int64_t, int64_t>{700, 10}));

  // A cut-away that keeps nothing is an error naming the file, and nothing is written.
  state.view.keep_above = false;
  ASSERT_TRUE(dispatch(state, ActionId::kSectionAt, ActionArgs{{"z", "0"}, ""}).ok());
  EXPECT_FALSE(acceptBrowserPath(state, BrowserPurpose::kExportVolume, dir / "none.nrrd"));
  ASSERT_EQ(state.errors.messages.size(), 1u);
  EXPECT_NE(state.errors.messages[0].find("none.nrrd"), std::string::npos) << state.errors.messages[0];
  EXPECT_FALSE(std::filesystem::exists(dir / "none.nrrd"));

  // Without the cut-away the whole model again, and no note.
  state.view.cut_away = false;
  ASSERT_TRUE(dispatch(state, ActionId::kExportVolume, ActionArgs{{"whole.nrrd"}, (dir / "whole.nrrd").string()}).ok());
  ASSERT_TRUE(pump(state, [&] { return !volumeExportRunning(state); }));
  EXPECT_EQ(state.status_message, "Wrote " + (dir / "whole.nrrd").string());
  EXPECT_EQ(filledIn(dir / "whole.nrrd"), (std::pair<int64_t, int64_t>{1000, 10}));
}

TEST(AppExportVolume, cancelLeavesNoFileAndNoMessage) {
  test::TempDir dir;
  AppState state;
  ASSERT_NO_FATAL_FAILURE(openGrid(state, dir, test::randomGrid(Dims{300, 300, 200}, 0.5, 3)));
  ASSERT_TRUE(acceptBrowserPath(state, BrowserPurpose::kExportVolume, dir / "big.vox"));
  EXPECT_TRUE(actions::canCancel(state));
  ASSERT_TRUE(dispatch(state, ActionId::kCancelJob));
  ASSERT_TRUE(pump(state, [&] { return !volumeExportRunning(state); }));
  EXPECT_TRUE(state.errors.messages.empty());
  EXPECT_EQ(state.status_message.find("Wrote"), std::string::npos);
  EXPECT_EQ(entries(dir.path()), 1);  // model.vxm only: no file, no temporary
}

}  // namespace
}  // namespace vox::app
