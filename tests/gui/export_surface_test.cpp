// File > Export surface mesh without a window: the model as it is, or with the Section panel's cut-away on, the
// half the view keeps (the cut face included), read back as STL and re-voxelized on the model's lattice.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "app/action_functions.h"
#include "app/actions.h"
#include "app/app_state.h"
#include "app/operations.h"
#include "support/grids.h"
#include "support/test_support.h"
#include "vox/io/stl.h"
#include "vox/io/voxel_file.h"

namespace vox::app {
namespace {

bool pump(AppState& state) {
  for (int i = 0; i < 10000; ++i) {
    updateDocument(state);
    if (state.doc.model.has_value()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return false;
}

// Triangles of a binary STL written by the export.
size_t stlTriangles(const std::filesystem::path& path) {
  auto load = io::loadStl(path);
  EXPECT_TRUE(load.ok());
  return load.ok() ? load->mesh.triangles.size() : 0;
}

TEST(AppExportSurface, theCutAwayExportsTheHalfTheViewKeeps) {
  test::TempDir dir;
  AppState state;
  // A 10 x 10 x 10 cube in a 12^3 grid: its whole surface is 6 squares, two triangles each after merging.
  VoxelGrid cube(Dims{12, 12, 12});
  for (int z = 1; z < 11; ++z)
    for (int y = 1; y < 11; ++y) cube.fillRun(y, z, 1, 11);
  ASSERT_TRUE(io::saveVxm(cube, dir / "cube.vxm").ok());
  startOpen(state, dir / "cube.vxm");
  ASSERT_TRUE(pump(state));

  ASSERT_TRUE(dispatch(state, ActionId::kExportSurface, ActionArgs{{"whole.stl"}, (dir / "whole.stl").string()}).ok());
  EXPECT_EQ(stlTriangles(dir / "whole.stl"), 12u);

  // The section at z = 4, keeping z <= 4: a 10 x 10 x 4 box (layers 1 to 4), again 12 triangles.
  ASSERT_TRUE(dispatch(state, ActionId::kSectionAt, ActionArgs{{"z", "4"}, ""}).ok());
  ASSERT_EQ(state.panel, Panel::kSection);
  ASSERT_TRUE(state.view.cut_away);
  state.view.keep_above = false;
  ASSERT_TRUE(dispatch(state, ActionId::kExportSurface, ActionArgs{{"half.stl"}, (dir / "half.stl").string()}).ok());
  EXPECT_NE(state.status_message.find("the half the cut-away keeps"), std::string::npos) << state.status_message;
  auto half = io::loadStl(dir / "half.stl");
  ASSERT_TRUE(half.ok());
  EXPECT_EQ(half->mesh.triangles.size(), 12u);
  float top = -1e9f;
  for (const auto& t : half->mesh.triangles)
    for (const auto& v : t.v) top = std::max(top, v.z);
  EXPECT_FLOAT_EQ(top, float(cube.frame().origin.z + 5 * cube.voxelSize()));  // the top of voxel layer 4

  // Without the cut-away the whole model again.
  state.view.cut_away = false;
  ASSERT_TRUE(dispatch(state, ActionId::kExportSurface, ActionArgs{{"again.stl"}, (dir / "again.stl").string()}).ok());
  auto again = io::loadStl(dir / "again.stl");
  ASSERT_TRUE(again.ok());
  float top2 = -1e9f;
  for (const auto& t : again->mesh.triangles)
    for (const auto& v : t.v) top2 = std::max(top2, v.z);
  EXPECT_FLOAT_EQ(top2, float(cube.frame().origin.z + 11 * cube.voxelSize()));
}

}  // namespace
}  // namespace vox::app
