// File > Export volume, Export thickness volume, Export depth volume and Export X-ray volume without a window
// (export_volume.h): each runs in the background and says where it wrote when done; the depth and the X-ray hold what
// voxmod peel --depth and voxmod xray --volume write; the model's volume is what the view shows (the cut-away's
// half); wrong extensions, missing results and unwritable places are error dialogs naming the file; Cancel leaves no
// file behind.
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
#include "vox/analysis/scalar_fields.h"
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
  EXPECT_FALSE(givePath(state, ActionId::kExportVolume, dir / "m.stl"));
  ASSERT_EQ(state.errors.messages.size(), 1u);
  EXPECT_NE(state.errors.messages[0].find("m.stl"), std::string::npos) << state.errors.messages[0];
  EXPECT_NE(state.errors.messages[0].find(".vox"), std::string::npos) << state.errors.messages[0];

  ASSERT_TRUE(givePath(state, ActionId::kExportVolume, dir / "missing" / "m.vdb"));
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
  EXPECT_EQ(disabledReason(state, action(ActionId::kExportThickness)), "");  // no model: off for a plain reason
  ASSERT_NO_FATAL_FAILURE(openGrid(state, dir, g));
  EXPECT_EQ(disabledReason(state, action(ActionId::kExportThickness)),
            "Needs the thickness: open the Thickness panel (Ctrl+6) and let it finish");
  EXPECT_FALSE(dispatch(state, ActionId::kExportThickness, ActionArgs{{"t.vti"}, (dir / "t.vti").string()}).ok());

  state.panel = Panel::kThickness;
  ASSERT_TRUE(pump(state, [&] { return currentThickness(state) != nullptr; }));
  EXPECT_EQ(disabledReason(state, action(ActionId::kExportThickness)), "");
  EXPECT_FALSE(givePath(state, ActionId::kExportThickness, dir / "t.vox"));  // voxels only
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

// A 16 x 12 x 10 grid: a box of 14 x 10 x 8 voxels with a 4 x 4 hole through it along z and a bump on top, so the
// skin layers, the X-ray's rays and the cut-away all have something to tell apart.
VoxelGrid holedBox() {
  VoxelGrid g(Dims{16, 12, 10});
  for (int32_t z = 1; z < 9; ++z)
    for (int32_t y = 1; y < 11; ++y) g.fillRun(y, z, 1, 15);
  for (int32_t z = 0; z < 10; ++z)
    for (int32_t y = 4; y < 8; ++y)
      for (int32_t x = 6; x < 10; ++x) g.set(x, y, z, false);
  g.fillRun(2, 9, 2, 5);
  g.frame().origin = {1.0, -2.0, 0.5};
  g.frame().voxel_size = 0.25;
  g.frame().units = "mm";
  return g;
}

void expectSameField(const ScalarField& a, const ScalarField& b) {
  EXPECT_EQ(a.dims, b.dims);
  EXPECT_DOUBLE_EQ(a.frame.voxel_size, b.frame.voxel_size);
  for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(a.frame.origin[i], b.frame.origin[i]) << "axis " << i;
  EXPECT_EQ(a.frame.units, b.frame.units);
  EXPECT_EQ(a.values, b.values);
}

TEST(AppExportVolume, theDepthVolumeNeedsTheSkinLayersAndHoldsWhatPeelDepthWrites) {
  test::TempDir dir;
  AppState state;
  const VoxelGrid g = holedBox();
  ASSERT_NO_FATAL_FAILURE(openGrid(state, dir, g));
  // Off until the Skin panel has computed the skin layers, and the menu item's tooltip says so; the browser's path
  // says why too, naming the file.
  EXPECT_FALSE(actions::hasDepth(state));
  EXPECT_EQ(disabledReason(state, action(ActionId::kExportDepth)),
            "Needs the skin layers: open the Skin removal panel (Ctrl+3) and let it finish");
  EXPECT_FALSE(dispatch(state, ActionId::kExportDepth, ActionArgs{{"d.vti"}, (dir / "d.vti").string()}).ok());
  EXPECT_FALSE(givePath(state, ActionId::kExportDepth, dir / "d.vti"));
  ASSERT_EQ(state.errors.messages.size(), 1u);
  EXPECT_NE(state.errors.messages[0].find("d.vti"), std::string::npos) << state.errors.messages[0];
  EXPECT_NE(state.errors.messages[0].find("Skin panel"), std::string::npos) << state.errors.messages[0];

  state.panel = Panel::kSkin;
  ASSERT_TRUE(pump(state, [&] { return actions::hasDepth(state); }));
  EXPECT_EQ(disabledReason(state, action(ActionId::kExportDepth)), "");
  EXPECT_FALSE(givePath(state, ActionId::kExportDepth, dir / "d.vox"));  // voxels only
  ASSERT_EQ(state.errors.messages.size(), 2u);
  EXPECT_NE(state.errors.messages[1].find("d.vox"), std::string::npos) << state.errors.messages[1];
  for (const char* name : {"d.vti", "d.vdb", "d.nrrd"}) {
    SCOPED_TRACE(name);
    state.status_message.clear();
    ASSERT_TRUE(dispatch(state, ActionId::kExportDepth, ActionArgs{{name}, (dir / name).string()}).ok());
    ASSERT_TRUE(pump(state, [&] { return !volumeExportRunning(state); }));
    EXPECT_EQ(state.status_message, "Wrote " + (dir / name).string());
    EXPECT_GT(std::filesystem::file_size(dir / name), 0u);
  }
  EXPECT_EQ(state.errors.messages.size(), 2u);

  // The analysis' depth field of the model, and what the CLI writes for the same file.
  auto depth = computeDepthMap(g, kPeelAll);
  ASSERT_TRUE(depth.ok());
  const ScalarField expected = depthField(*depth, g);
  EXPECT_GE(*std::max_element(expected.values.begin(), expected.values.end()), 3.0f);  // several layers to tell
  auto back = io::loadNrrdField(dir / "d.nrrd");
  ASSERT_TRUE(back.ok()) << back.error().message;
  EXPECT_EQ(back->dims, (Dims{16, 12, 10}));
  EXPECT_DOUBLE_EQ(back->frame.voxel_size, 0.25);
  EXPECT_EQ(back->frame.origin, g.frame().origin);
  EXPECT_EQ(back->frame.units, "mm");
  ASSERT_NO_FATAL_FAILURE(expectSameField(*back, expected));
  const test::RunResult cli = test::runVoxmod(
      {"peel", (dir / "model.vxm").string(), "--all", "--depth", (dir / "cli.nrrd").string(), "--json"});
  ASSERT_EQ(cli.exit_code, 0) << cli.err;
  auto by_cli = io::loadNrrdField(dir / "cli.nrrd");
  ASSERT_TRUE(by_cli.ok()) << by_cli.error().message;
  ASSERT_NO_FATAL_FAILURE(expectSameField(*back, *by_cli));
  // The .vti holds the field alone, under its name, as the CLI's does.
  const std::string vti = test::readFile(dir / "d.vti");
  EXPECT_NE(vti.find("Name=\"depth\""), std::string::npos);
  EXPECT_EQ(vti.find("Name=\"voxels\""), std::string::npos);

  // Peeled: still the Skin panel's layers of the whole model, and the status line says the peeled ones are in it.
  ASSERT_TRUE(dispatch(state, ActionId::kPeelN, ActionArgs{{"2"}, "2"}).ok());
  ASSERT_TRUE(pump(state, [&] { return state.doc.model->peeled == 2; }));
  ASSERT_TRUE(actions::hasDepth(state));
  ASSERT_TRUE(dispatch(state, ActionId::kExportDepth, ActionArgs{{"p.nrrd"}, (dir / "p.nrrd").string()}).ok());
  ASSERT_TRUE(pump(state, [&] { return !volumeExportRunning(state); }));
  EXPECT_EQ(state.status_message, "Wrote " + (dir / "p.nrrd").string() + " (all " + std::to_string(depth->layers()) +
                                      " skin layers, the 2 peeled ones included)");
  auto peeled = io::loadNrrdField(dir / "p.nrrd");
  ASSERT_TRUE(peeled.ok()) << peeled.error().message;
  EXPECT_EQ(peeled->values, expected.values);

  // Another model: off again until its skin layers are computed.
  state.panel = Panel::kModel;
  ASSERT_TRUE(io::saveVxm(test::randomGrid(Dims{8, 8, 8}, 0.5, 4), dir / "other.vxm").ok());
  startOpen(state, dir / "other.vxm");
  ASSERT_TRUE(pump(state, [&] { return state.model.dims() == Dims{8, 8, 8}; }));
  EXPECT_FALSE(actions::hasDepth(state));
}

TEST(AppExportVolume, theXrayVolumeNeedsTheXrayAndHoldsWhatXrayVolumeWrites) {
  test::TempDir dir;
  AppState state;
  const VoxelGrid g = holedBox();
  ASSERT_NO_FATAL_FAILURE(openGrid(state, dir, g));
  EXPECT_FALSE(actions::hasXray(state));
  EXPECT_EQ(disabledReason(state, action(ActionId::kExportXrayVolume)),
            "Needs the X-ray: open the X-ray panel (Ctrl+4) and let it finish");
  EXPECT_FALSE(dispatch(state, ActionId::kExportXrayVolume, ActionArgs{{"x.vti"}, (dir / "x.vti").string()}).ok());
  EXPECT_FALSE(givePath(state, ActionId::kExportXrayVolume, dir / "x.vti"));
  ASSERT_EQ(state.errors.messages.size(), 1u);
  EXPECT_NE(state.errors.messages[0].find("x.vti"), std::string::npos) << state.errors.messages[0];
  EXPECT_NE(state.errors.messages[0].find("X-ray panel"), std::string::npos) << state.errors.messages[0];

  ASSERT_TRUE(dispatch(state, ActionId::kXray, ActionArgs{{"y", "max"}, "y max"}).ok());
  ASSERT_TRUE(pump(state, [&] { return actions::hasXray(state); }));
  EXPECT_EQ(disabledReason(state, action(ActionId::kExportXrayVolume)), "");
  EXPECT_FALSE(givePath(state, ActionId::kExportXrayVolume, dir / "x.vox"));
  ASSERT_EQ(state.errors.messages.size(), 2u);
  EXPECT_NE(state.errors.messages[1].find("x.vox"), std::string::npos) << state.errors.messages[1];
  for (const char* name : {"x.vti", "x.vdb", "x.nrrd"}) {
    SCOPED_TRACE(name);
    state.status_message.clear();
    ASSERT_TRUE(dispatch(state, ActionId::kExportXrayVolume, ActionArgs{{name}, (dir / name).string()}).ok());
    ASSERT_TRUE(pump(state, [&] { return !volumeExportRunning(state); }));
    EXPECT_EQ(state.status_message, "Wrote " + (dir / name).string());
    EXPECT_GT(std::filesystem::file_size(dir / name), 0u);
  }
  EXPECT_EQ(state.errors.messages.size(), 2u);

  auto x = computeXray(g, XrayParams{Axis::kY, XrayMode::kMax});
  ASSERT_TRUE(x.ok());
  const ScalarField expected = xrayField(*x, g);
  auto back = io::loadNrrdField(dir / "x.nrrd");
  ASSERT_TRUE(back.ok()) << back.error().message;
  EXPECT_EQ(back->dims, (Dims{16, 1, 10}));  // one voxel thick along the X-ray's axis
  EXPECT_DOUBLE_EQ(back->frame.voxel_size, 0.25);
  ASSERT_NO_FATAL_FAILURE(expectSameField(*back, expected));
  EXPECT_FLOAT_EQ(*std::max_element(back->values.begin(), back->values.end()), 10.0f * 0.25f);  // model units
  const test::RunResult cli =
      test::runVoxmod({"xray", (dir / "model.vxm").string(), "--axis", "y", "--mode", "max", "-o",
                       (dir / "cli.png").string(), "--volume", (dir / "cli.nrrd").string(), "--json"});
  ASSERT_EQ(cli.exit_code, 0) << cli.err;
  auto by_cli = io::loadNrrdField(dir / "cli.nrrd");
  ASSERT_TRUE(by_cli.ok()) << by_cli.error().message;
  ASSERT_NO_FATAL_FAILURE(expectSameField(*back, *by_cli));
  const std::string vti = test::readFile(dir / "x.vti");
  EXPECT_NE(vti.find("Name=\"xray\""), std::string::npos);

  // Another axis: off until that X-ray is computed.
  ASSERT_TRUE(dispatch(state, ActionId::kXray, ActionArgs{{"x", "total"}, "x total"}).ok());
  EXPECT_FALSE(actions::hasXray(state));
  ASSERT_TRUE(pump(state, [&] { return actions::hasXray(state); }));
  ASSERT_TRUE(dispatch(state, ActionId::kExportXrayVolume, ActionArgs{{"t.nrrd"}, (dir / "t.nrrd").string()}).ok());
  ASSERT_TRUE(pump(state, [&] { return !volumeExportRunning(state); }));
  auto total = io::loadNrrdField(dir / "t.nrrd");
  ASSERT_TRUE(total.ok()) << total.error().message;
  EXPECT_EQ(total->dims, (Dims{1, 12, 10}));
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

  // At an angle, through the corners' voxels (1, 1, 10), (10, 1, 1), (1, 10, 1): the plane i + j + k = 12 through
  // their centres, kept below with its slab (centres within half the normal's L1 norm, i + j + k <= 13). Voxels 1..10
  // each way with i + j + k <= 13: C(13, 3) = 286 less the 3 with one index at 11.
  state.view.keep_above = false;
  ASSERT_TRUE(
      dispatch(state, ActionId::kSectionPlaneThrough, ActionArgs{{"1", "1", "10", "10", "1", "1", "1", "10", "1"}, ""})
          .ok());
  ASSERT_TRUE(state.section.oblique);
  ASSERT_TRUE(
      dispatch(state, ActionId::kExportVolume, ActionArgs{{"tilted.nrrd"}, (dir / "tilted.nrrd").string()}).ok());
  ASSERT_TRUE(pump(state, [&] { return !volumeExportRunning(state); }));
  EXPECT_EQ(filledIn(dir / "tilted.nrrd").first, 283);
  state.section.oblique = false;

  // A cut-away that keeps nothing is an error naming the file, and nothing is written.
  state.view.keep_above = false;
  ASSERT_TRUE(dispatch(state, ActionId::kSectionAt, ActionArgs{{"z", "0"}, ""}).ok());
  EXPECT_FALSE(givePath(state, ActionId::kExportVolume, dir / "none.nrrd"));
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
  ASSERT_TRUE(givePath(state, ActionId::kExportVolume, dir / "big.vox"));
  EXPECT_TRUE(actions::canCancel(state));
  ASSERT_TRUE(dispatch(state, ActionId::kCancelJob));
  ASSERT_TRUE(pump(state, [&] { return !volumeExportRunning(state); }));
  EXPECT_TRUE(state.errors.messages.empty());
  EXPECT_EQ(state.status_message.find("Wrote"), std::string::npos);
  EXPECT_EQ(entries(dir.path()), 1);  // model.vxm only: no file, no temporary
}

}  // namespace
}  // namespace vox::app
