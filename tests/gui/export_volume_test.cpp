// File > Export volume and Export thickness volume without a window (export_volume.h): each runs in the background
// and says where it wrote when done; wrong extensions, missing results and unwritable places are error dialogs
// naming the file; Cancel leaves no file behind.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

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
