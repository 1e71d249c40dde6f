// The Parts panel's logic without a window (app/parts.h), driven through the action table as the panel and a
// script drive it: splitting a mesh into bodies and a voxel model into components, adding a part from a file,
// Booleans and their undo, and the interference list, compared with the library's own results.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <thread>

#include "app/actions.h"
#include "app/app_state.h"
#include "app/casting.h"
#include "app/document.h"
#include "app/operations.h"
#include "app/parts.h"
#include "app/parts_view.h"
#include "app/update.h"
#include "app/viewport.h"
#include "gui/app_test_support.h"
#include "support/cad_parts.h"
#include "support/test_support.h"
#include "vox/analysis/assembly.h"
#include "vox/io/stl.h"
#include "vox/io/voxel_file.h"
#include "vox/render/context.h"
#include "vox/render/framebuffer.h"
#include "vox/voxelize/bodies.h"

namespace vox::app {
namespace {

using test_app::llvmpipeContext;
using test_app::pump;
using test_app::run;

// A box [lo, hi] as 12 outward triangles (the unit cube scaled and moved).
void addBox(TriangleMesh& mesh, glm::vec3 lo, glm::vec3 hi) {
  for (Triangle t : test::unitCubeMesh().triangles) {
    for (glm::vec3& v : t.v) v = lo + v * (hi - lo);
    mesh.triangles.push_back(t);
  }
}

// A small "gear train": three boxes in one mesh, the first two interpenetrating, the third apart; like the cycloidal
// drive, bodies are shells of one file.
TriangleMesh threeBodies() {
  TriangleMesh m;
  addBox(m, {0.0f, 0.0f, 0.0f}, {4.0f, 4.0f, 2.0f});
  addBox(m, {3.0f, 1.0f, 0.5f}, {7.0f, 3.0f, 1.5f});
  addBox(m, {0.0f, 6.0f, 0.0f}, {2.0f, 8.0f, 2.0f});
  return m;
}

void openVoxelized(AppState& state, const std::filesystem::path& path, int resolution) {
  state.voxelize_dialog_on_open = false;
  ASSERT_TRUE(run(state, "open " + path.string()).ok());
  ASSERT_TRUE(pump(state, [&] { return state.doc.mesh != nullptr; }));
  ASSERT_TRUE(run(state, "voxelize " + std::to_string(resolution)).ok());
  ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
}

TEST(AppParts, aMeshSplitsIntoItsBodiesOnTheModelsLattice) {
  test::TempDir dir;
  ASSERT_TRUE(io::saveStlBinary(threeBodies(), dir / "train.stl").ok());
  AppState state;
  openVoxelized(state, dir / "train.stl", 64);
  const int64_t whole = state.model.filledCount();
  EXPECT_FALSE(actionEnabled(state, action(ActionId::kInterference)));  // one model: no parts yet

  ASSERT_TRUE(run(state, "split-bodies").ok());
  ASSERT_TRUE(pump(state, [&] { return currentParts(state) != nullptr; }));
  const Assembly& parts = *currentParts(state);
  ASSERT_EQ(parts.size(), 3u);
  EXPECT_EQ(parts.part(0).name, "body 0");
  EXPECT_EQ(state.panel, Panel::kParts);
  // The union of the bodies is the whole mesh voxelized (boxes are closed: nonzero fill on both).
  EXPECT_EQ(state.model.filledCount(), whole);
  EXPECT_TRUE(canUndo(state));

  // The same bodies as the library gives on the mesh's lattice, voxel for voxel.
  auto lib = voxelizeBodies(threeBodies(), VoxelizeParams{.resolution = 64});
  ASSERT_TRUE(lib.ok());
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(parts.part(i).voxels.grid.filledCount(), lib->bodies[i].filled) << i;
  }

  // Interference: the list equals the library's findInterference on the same parts.
  ASSERT_TRUE(run(state, "interference").ok());
  ASSERT_TRUE(pump(state, [&] { return currentInterference(state) != nullptr; }));
  const Interference* inter = currentInterference(state);
  std::vector<LatticeGrid> placed;
  for (const BodyVoxels& b : lib->bodies) placed.push_back(b.voxels);
  const Interference expected = findInterference(placed, lib->lattice);
  ASSERT_EQ(inter->pairs.size(), 1u);
  ASSERT_EQ(expected.pairs.size(), 1u);
  EXPECT_EQ(inter->pairs[0].a, 0);
  EXPECT_EQ(inter->pairs[0].b, 1);
  EXPECT_EQ(inter->pairs[0].voxels, expected.pairs[0].voxels);
  EXPECT_GT(inter->pairs[0].voxels, 0);
  EXPECT_DOUBLE_EQ(inter->pairs[0].thickness, expected.pairs[0].thickness);
  // The contact tolerance, as the panel's field sets it: the overlap (the boxes interpenetrate by a voxel size and
  // more) is contact only under a tolerance as thick as it.
  EXPECT_FALSE(isContact(inter->pairs[0], state.parts_ui.contact));
  ASSERT_TRUE(run(state, "contact " + std::to_string(inter->pairs[0].thickness)).ok());
  EXPECT_TRUE(isContact(inter->pairs[0], state.parts_ui.contact));
  EXPECT_FALSE(run(state, "contact -1").ok());
  EXPECT_FALSE(run(state, "contact nan").ok());
  ASSERT_TRUE(run(state, "contact 0").ok());

  // Clicking the pair: both parts selected, the overlap as a grid on the model's frame, the section through it.
  ASSERT_TRUE(run(state, "interference-pair 1").ok());
  EXPECT_EQ(state.parts_ui.selected, (std::vector<size_t>{0, 1}));
  EXPECT_EQ(state.parts_ui.pair_overlap.dims(), state.model.dims());
  EXPECT_EQ(state.parts_ui.pair_overlap.filledCount(), inter->pairs[0].voxels);
  const Box3i box = inter->pairs[0].box;
  const int a = int(state.section.axis);
  const int32_t index = state.section.index + parts.extent().min[a];
  EXPECT_GE(index, box.min[a]);
  EXPECT_LT(index, box.max[a]);
  EXPECT_FALSE(interferencePairText(state).empty());
  // ... and the section's picture zoomed onto the overlap: its middle in the middle of what is shown
  EXPECT_GT(state.section.zoom, 1.0);
  const int r = int(imageRightAxis(state.section.axis));
  const double mid = (double(box.min[r] + box.max[r]) * 0.5 - parts.extent().min[r]) / axisLength(state, Axis(r));
  const double half = 0.5 / state.section.zoom;
  EXPECT_NEAR(state.section.centre.x, std::clamp(mid, half, 1.0 - half), 1e-9);
  const int u = int(imageUpAxis(state.section.axis));  // up: the fraction from the picture's bottom
  const double mid_up = (double(box.min[u] + box.max[u]) * 0.5 - parts.extent().min[u]) / axisLength(state, Axis(u));
  EXPECT_NEAR(state.section.centre.y, std::clamp(mid_up, half, 1.0 - half), 1e-9);

  // Selecting another part leaves the pair: its banner and red overlap go (they stayed, naming parts not selected).
  ASSERT_TRUE(run(state, "select-part 3").ok());
  EXPECT_EQ(state.parts_ui.pair, -1);
  EXPECT_TRUE(interferencePairText(state).empty());
  EXPECT_TRUE(state.parts_ui.pair_overlap.empty());
  // Selecting the pair's two parts again by hand does not bring the pair back uninvited; a click on it does.
  ASSERT_TRUE(run(state, "interference-pair 1").ok());
  ASSERT_TRUE(run(state, "select-part add 2").ok());  // Ctrl+click takes part 2 out of the selection
  EXPECT_EQ(state.parts_ui.pair, -1);
  ASSERT_TRUE(run(state, "interference-pair 1").ok());
  EXPECT_FALSE(interferencePairText(state).empty());

  // Undo goes back to the one model; the interference of the parts is not shown for it.
  undo(state);
  EXPECT_EQ(currentParts(state), nullptr);
  EXPECT_EQ(state.model.filledCount(), whole);
  EXPECT_EQ(currentInterference(state), nullptr);
}

// Two 6 x 4 x 4 blocks as voxel files on one lattice (voxel size 1): a at the origin, b 4 voxels along X, so they
// share a 2 x 4 x 4 block. The document is a with b added as a part.
void openTwoBlocks(AppState& state, const test::TempDir& dir) {
  VoxelGrid a(Dims{6, 4, 4}), b(Dims{6, 4, 4});
  for (int32_t z = 0; z < 4; ++z) {
    for (int32_t y = 0; y < 4; ++y) {
      a.fillRun(y, z, 0, 6);
      b.fillRun(y, z, 0, 6);
    }
  }
  b.frame().origin = glm::dvec3(4.0, 0.0, 0.0);
  ASSERT_TRUE(io::saveVxm(a, dir / "a.vxm").ok());
  ASSERT_TRUE(io::saveVxm(b, dir / "b.vxm").ok());
  ASSERT_TRUE(run(state, "open " + (dir / "a.vxm").string()).ok());
  ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
  ASSERT_TRUE(run(state, "add-part " + (dir / "b.vxm").string()).ok());
  ASSERT_TRUE(pump(state, [&] { return currentParts(state) && currentParts(state)->size() == 2; }));
  ASSERT_EQ(state.model.filledCount(), 10 * 4 * 4);
}

// A STEP file splits into its solids, named as the file's reader names them, though they touch: the two boxes share
// the face x = 10, where welding by position would join them into one shell.
TEST(AppParts, aStepFileSplitsIntoItsSolidsThoughTheyTouch) {
  test::TempDir dir;
  using test::CadShape;
  test::writeStep(dir / "pair.step",
                  {{CadShape::kBox, {0, 0, 0}, {10, 10, 10}}, {CadShape::kBox, {10, 0, 0}, {10, 10, 10}}});
  AppState state;
  openVoxelized(state, dir / "pair.step", 20);
  ASSERT_TRUE(state.doc.mesh != nullptr);
  ASSERT_EQ(state.doc.mesh->bodies.size(), 2u);
  ASSERT_TRUE(run(state, "split-bodies").ok());
  ASSERT_TRUE(pump(state, [&] { return currentParts(state) != nullptr; }));
  const Assembly& parts = *currentParts(state);
  ASSERT_EQ(parts.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(parts.part(i).name, "solid " + std::to_string(i + 1));
    EXPECT_EQ(parts.part(i).voxels.grid.filledCount(), 1000) << i;  // h = 1: 10 x 10 x 10 voxels each
  }
  EXPECT_EQ(state.model.filledCount(), 2000);
}
TEST(AppParts, booleansAreNewPartsAndUndoable) {
  test::TempDir dir;
  AppState state;
  openTwoBlocks(state, dir);
  EXPECT_EQ(state.model.filledCount(), 10 * 4 * 4);  // the union on the extent's frame
  EXPECT_EQ(state.model.dims(), (Dims{10, 4, 4}));

  const auto counts = [&] { return partVoxelCounts(state); };
  ASSERT_TRUE(run(state, "part-boolean intersection 1 2").ok());
  ASSERT_EQ(currentParts(state)->size(), 3u);
  EXPECT_EQ(counts()[2], 2 * 4 * 4);
  EXPECT_EQ(currentParts(state)->part(2).name, "a.vxm intersection b.vxm");
  EXPECT_EQ(state.parts_ui.selected, (std::vector<size_t>{2}));

  ASSERT_TRUE(run(state, "select-part 1 2").ok());
  ASSERT_TRUE(run(state, "part-boolean xor").ok());
  ASSERT_EQ(currentParts(state)->size(), 4u);
  EXPECT_EQ(counts()[3], 2 * (4 * 4 * 4));
  ASSERT_TRUE(run(state, "part-boolean difference 2 1").ok());
  EXPECT_EQ(counts()[4], 4 * 4 * 4);

  // Section, X-ray and mass on the selected part: the model shown is that part alone, on the same frame.
  ASSERT_TRUE(run(state, "select-part 5").ok());
  ASSERT_TRUE(run(state, "parts-scope selected").ok());
  EXPECT_EQ(state.model.filledCount(), 4 * 4 * 4);
  EXPECT_EQ(state.model.dims(), (Dims{10, 4, 4}));
  ASSERT_TRUE(run(state, "parts-scope union").ok());
  EXPECT_EQ(state.model.filledCount(), 10 * 4 * 4);

  ASSERT_TRUE(run(state, "remove-part 5").ok());
  EXPECT_EQ(currentParts(state)->size(), 4u);
  for (int i = 0; i < 4; ++i) undo(state);  // remove, difference, xor, intersection
  EXPECT_EQ(currentParts(state)->size(), 2u);
  redo(state);
  EXPECT_EQ(currentParts(state)->size(), 3u);

  // Bad values say why; a hidden part stays in the model (visibility is the view's).
  EXPECT_FALSE(run(state, "part-boolean union 1 9").ok());
  EXPECT_FALSE(run(state, "part-boolean nand 1 2").ok());
  EXPECT_FALSE(run(state, "part-boolean union 1 1").ok());
  ASSERT_TRUE(run(state, "part-visible 2 off").ok());
  EXPECT_FALSE(currentParts(state)->part(1).visible);
  EXPECT_EQ(state.model.filledCount(), 10 * 4 * 4);
}

TEST(AppParts, aVoxelFileOffTheLatticeIsRefusedSayingHow) {
  test::TempDir dir;
  VoxelGrid a(Dims{4, 4, 4}), b(Dims{4, 4, 4});
  a.fillRun(0, 0, 0, 4);
  b.fillRun(0, 0, 0, 4);
  b.frame().origin = glm::dvec3(0.5, 0.0, 0.0);
  ASSERT_TRUE(io::saveVxm(a, dir / "a.vxm").ok());
  ASSERT_TRUE(io::saveVxm(b, dir / "b.vxm").ok());
  AppState state;
  ASSERT_TRUE(run(state, "open " + (dir / "a.vxm").string()).ok());
  ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
  ASSERT_TRUE(run(state, "add-part " + (dir / "b.vxm").string()).ok());
  ASSERT_TRUE(pump(state, [&] { return !partsBusy(state); }));
  updateDocument(state);
  EXPECT_EQ(currentParts(state), nullptr);  // the document is as it was
  ASSERT_FALSE(state.errors.messages.empty());
  EXPECT_NE(state.errors.messages.back().find("not a whole number of voxels"), std::string::npos)
      << state.errors.messages.back();
}

TEST(AppParts, aVoxelModelSplitsIntoConnectedComponents) {
  test::TempDir dir;
  // A 3 x 3 x 3 block, a single voxel touching its corner diagonally, and a 2-voxel bar apart.
  VoxelGrid g(Dims{12, 6, 6});
  for (int32_t z = 0; z < 3; ++z) {
    for (int32_t y = 0; y < 3; ++y) g.fillRun(y, z, 0, 3);
  }
  g.fillRun(3, 3, 3, 4);
  g.fillRun(0, 0, 9, 11);
  ASSERT_TRUE(io::saveVxm(g, dir / "g.vxm").ok());
  for (const auto& [conn, n] : {std::pair{"6", 3u}, std::pair{"26", 2u}}) {
    AppState state;
    ASSERT_TRUE(run(state, "open " + (dir / "g.vxm").string()).ok());
    ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
    ASSERT_TRUE(run(state, std::string("split-bodies ") + conn).ok());
    ASSERT_TRUE(pump(state, [&] { return currentParts(state) != nullptr; }));
    EXPECT_EQ(currentParts(state)->size(), n) << conn;
    EXPECT_EQ(partVoxelCounts(state)[0], conn == std::string("6") ? 27 : 28);
    EXPECT_EQ(state.model.filledCount(), 27 + 1 + 2);
  }
}

// A split into bodies leaves the solid as it was: the thickness computed before is the scene's too, and the split's
// undo keeps it, none computed again; the 3D view draws the model coloured by it, not the parts, while the Thickness
// panel shows it. A part moved makes another solid: its thickness is computed anew.
TEST(AppParts, theThicknessOfASolidASplitLeavesAsItWasIsKept) {
  test::TempDir dir;
  // Two 4 x 6 x 6 blocks 2 voxels apart, filling their box: the parts' extent is the model's box.
  VoxelGrid g(Dims{10, 6, 6});
  for (int32_t z = 0; z < 6; ++z) {
    for (int32_t y = 0; y < 6; ++y) {
      g.fillRun(y, z, 0, 4);
      g.fillRun(y, z, 6, 10);
    }
  }
  ASSERT_TRUE(io::saveVxm(g, dir / "g.vxm").ok());
  AppState state;
  ASSERT_TRUE(run(state, "open " + (dir / "g.vxm").string()).ok());
  ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
  ASSERT_TRUE(run(state, "panel-thickness").ok());
  ASSERT_TRUE(pump(state, [&] { return currentThickness(state) != nullptr; }));
  const ThicknessResult* r = currentThickness(state);
  const uint64_t before = state.model_version;

  ASSERT_TRUE(run(state, "split-bodies").ok());
  ASSERT_TRUE(pump(state, [&] { return currentParts(state) != nullptr; }));
  ASSERT_EQ(currentParts(state)->size(), 2u);
  ASSERT_NE(state.model_version, before);
  ASSERT_TRUE(run(state, "panel-thickness").ok());
  updateDocument(state);
  EXPECT_EQ(currentThickness(state), r);
  EXPECT_FALSE(state.thickness.busy());

  undo(state);
  updateDocument(state);
  EXPECT_EQ(state.model_version, before);
  EXPECT_EQ(currentThickness(state), r);
  EXPECT_FALSE(state.thickness.busy());

  redo(state);
  ASSERT_TRUE(run(state, "place-part 2 1 0 0").ok());  // the second block a voxel along X: another solid
  ASSERT_TRUE(run(state, "panel-thickness").ok());
  updateDocument(state);
  EXPECT_EQ(currentThickness(state), nullptr);
  EXPECT_TRUE(state.thickness.computing(state.model_version));
  ASSERT_TRUE(pump(state, [&] { return currentThickness(state) != nullptr; }));
  EXPECT_NE(currentThickness(state)->grid.dims(), g.dims());  // the model grew to the new extent
}

// While the Thickness panel shows the thickness of a scene of parts, the 3D view draws the model's points, coloured
// by it (its renderer holds the model and the thickness volume), not the parts in their colours; the other panels
// draw the parts.
TEST(AppParts, theThicknessPanelDrawsTheModelColouredNotTheParts) {
  auto context = llvmpipeContext();
  VOX_SKIP_WITHOUT_GL(context);
  test::TempDir dir;
  ASSERT_TRUE(io::saveStlBinary(threeBodies(), dir / "train.stl").ok());
  AppState state;
  ASSERT_TRUE(initViewport(state).ok());
  openVoxelized(state, dir / "train.stl", 48);
  ASSERT_TRUE(run(state, "split-bodies").ok());
  ASSERT_TRUE(pump(state, [&] { return currentParts(state) != nullptr; }));
  syncRenderers(state);
  ASSERT_TRUE(drawsParts(state));
  ASSERT_TRUE(run(state, "panel-thickness").ok());
  ASSERT_TRUE(pump(state, [&] { return currentThickness(state) != nullptr; }));
  syncRenderers(state);
  EXPECT_FALSE(drawsParts(state));
  EXPECT_EQ(state.viewport.uploaded_version, state.model_version);
  EXPECT_TRUE(state.viewport.renderer->hasScalarVolume());
  ASSERT_TRUE(run(state, "panel-parts").ok());
  syncRenderers(state);
  EXPECT_TRUE(drawsParts(state));
  shutdownViewport(state);
}

// So do the Casting panel's colours on a casting with a feeder (a part of the scene): the model's points, the feeder's
// metal among them, coloured by when they froze.
TEST(AppParts, theCastingPanelDrawsTheModelColouredNotTheParts) {
  auto context = llvmpipeContext();
  VOX_SKIP_WITHOUT_GL(context);
  test::TempDir dir;
  ASSERT_TRUE(io::saveStlBinary(threeBodies(), dir / "train.stl").ok());
  AppState state;
  ASSERT_TRUE(initViewport(state).ok());
  openVoxelized(state, dir / "train.stl", 32);
  setModelUnits(state, "mm");
  glm::ivec3 top(-1);  // a voxel of the part's top layer: the feeder stands on it
  for (int32_t z = 0; z < state.model.nz(); ++z)
    for (int32_t y = 0; y < state.model.ny(); ++y)
      for (int32_t x = 0; x < state.model.nx(); ++x)
        if (state.model.get(x, y, z)) top = glm::ivec3(x, y, z);
  ASSERT_GE(top.z, 0);
  const glm::dvec3 at = state.model.frame().voxelCentre(top.x, top.y, top.z);
  const double h = state.model.voxelSize();
  ASSERT_TRUE(run(state, "casting-feeder " + std::to_string(at.x) + " " + std::to_string(at.y) + " " +
                             std::to_string(at.z + 0.5 * h) + " " + std::to_string(4 * h) + " " + std::to_string(6 * h))
                  .ok());
  ASSERT_NE(currentParts(state), nullptr);
  syncRenderers(state);
  ASSERT_TRUE(drawsParts(state));
  ASSERT_TRUE(dispatch(state, ActionId::kSimulateCasting));
  // (waited for up to two minutes: the simulation runs for tens of seconds under the thread sanitizer)
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!(currentCasting(state) && !state.casting.busy()) && std::chrono::steady_clock::now() < until) {
    updateDocument(state);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_NE(currentCasting(state), nullptr);
  syncRenderers(state);
  EXPECT_FALSE(drawsParts(state));
  EXPECT_EQ(state.viewport.uploaded_version, state.model_version);
  EXPECT_TRUE(state.viewport.renderer->hasScalarVolume());
  EXPECT_EQ(currentCasting(state)->run.result.feeders.size(), 1u);
  ASSERT_TRUE(run(state, "panel-parts").ok());
  syncRenderers(state);
  EXPECT_TRUE(drawsParts(state));
  shutdownViewport(state);
}

TEST(AppParts, aPartMovesAndTurnsOnTheLatticeUndoably) {
  test::TempDir dir;
  AppState state;
  openTwoBlocks(state, dir);
  ASSERT_TRUE(run(state, "select-part 2").ok());

  // Moved 2 model units (2 voxels) along X: the blocks no longer overlap, the model grows to the new extent.
  ASSERT_TRUE(run(state, "place-part 2 2 0 0").ok());
  EXPECT_EQ(currentParts(state)->part(1).placement.translation, glm::ivec3(2, 0, 0));
  EXPECT_EQ(state.model.dims(), (Dims{12, 4, 4}));
  EXPECT_EQ(state.model.filledCount(), 2 * 6 * 4 * 4);
  EXPECT_EQ(state.parts_ui.selected, (std::vector<size_t>{1}));  // the selection stays
  // A translation snaps to the nearest whole voxel: 0.6 is one voxel (overlap 1 x 4 x 4).
  ASSERT_TRUE(run(state, "place-part 2 0.6 0 0").ok());
  EXPECT_EQ(currentParts(state)->part(1).placement.translation, glm::ivec3(1, 0, 0));
  EXPECT_EQ(state.model.filledCount(), 11 * 4 * 4);
  // Undo goes back one placement at a time.
  undo(state);
  EXPECT_EQ(currentParts(state)->part(1).placement.translation, glm::ivec3(2, 0, 0));
  EXPECT_EQ(state.model.dims(), (Dims{12, 4, 4}));
  undo(state);
  EXPECT_TRUE(currentParts(state)->part(1).placement.identity());
  EXPECT_EQ(state.model.dims(), (Dims{10, 4, 4}));
  redo(state);
  EXPECT_EQ(state.model.dims(), (Dims{12, 4, 4}));

  // A quarter turn of a (6 x 4 x 4) about Z: 4 x 6 x 4 about its centre, so it covers X 1..4 and Y -1..4; with b at
  // X 6..11 the model is the box X 1..11, Y -1..4 (11 x 6 x 4 voxels).
  ASSERT_TRUE(run(state, "turn-part 1 z").ok());
  const Assembly& turned = *currentParts(state);
  EXPECT_EQ(turned.part(0).placement.quarter_turns, glm::ivec3(0, 0, 1));
  const LatticeGrid a_placed = turned.placedVoxels(0);
  EXPECT_EQ(a_placed.box(), (Box3i{{1, -1, 0}, {5, 5, 4}}));
  EXPECT_EQ(a_placed.grid.filledCount(), 6 * 4 * 4);
  EXPECT_EQ(state.model.dims(), (Dims{11, 6, 4}));
  EXPECT_EQ(state.model.filledCount(), 2 * 6 * 4 * 4);
  // Four quarter turns are none; the model is the moved pair again.
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(run(state, "turn-part 1 z").ok());
  EXPECT_TRUE(currentParts(state)->part(0).placement.identity());
  EXPECT_EQ(state.model.dims(), (Dims{12, 4, 4}));
  // Both at once, and back to where they were added: the interference sees the placement.
  ASSERT_TRUE(run(state, "place-part 1 0 0 0 1 0 0").ok());
  EXPECT_EQ(currentParts(state)->part(0).placement.quarter_turns, glm::ivec3(1, 0, 0));
  ASSERT_TRUE(run(state, "place-part 1 0 0 0 0 0 0").ok());
  ASSERT_TRUE(run(state, "place-part 2 0 0 0").ok());
  EXPECT_EQ(state.model.dims(), (Dims{10, 4, 4}));
  ASSERT_TRUE(run(state, "interference").ok());
  ASSERT_TRUE(pump(state, [&] { return currentInterference(state) != nullptr; }));
  ASSERT_EQ(currentInterference(state)->pairs.size(), 1u);
  EXPECT_EQ(currentInterference(state)->pairs[0].voxels, 2 * 4 * 4);

  // Bad values say why.
  EXPECT_FALSE(run(state, "place-part 3 0 0 0").ok());
  EXPECT_FALSE(run(state, "place-part 1 a 0 0").ok());
  EXPECT_FALSE(run(state, "place-part 1 0 0 0 1 0").ok());
  EXPECT_FALSE(run(state, "turn-part 1 w").ok());
}

TEST(AppParts, aPartsColourIsSetAndDrawnWithoutANewModelState) {
  test::TempDir dir;
  AppState state;
  openTwoBlocks(state, dir);
  const uint64_t version = state.doc.model->version;
  ASSERT_TRUE(run(state, "part-colour 1 #ff8000").ok());
  EXPECT_EQ(currentParts(state)->part(0).colour, glm::vec3(1.0f, 128.0f / 255.0f, 0.0f));
  ASSERT_TRUE(run(state, "part-colour 2 0 0.5 1").ok());
  EXPECT_EQ(currentParts(state)->part(1).colour, glm::vec3(0.0f, 0.5f, 1.0f));
  // How the parts are shown: the voxels and the model version stay, so the document is not unsaved by it.
  EXPECT_EQ(state.doc.model->version, version);
  EXPECT_FALSE(run(state, "part-colour 1 1.5 0 0").ok());
  EXPECT_FALSE(run(state, "part-colour 1 #12345").ok());
  EXPECT_FALSE(run(state, "part-colour 1 red").ok());
  EXPECT_FALSE(run(state, "part-colour 1 0 0 drag").ok());
  EXPECT_EQ(currentParts(state)->part(0).colour, glm::vec3(1.0f, 128.0f / 255.0f, 0.0f));
}

// Colour and visibility are undone and redone like the other changes of the document, one step each; a drag in the
// colour picker (its changes after the first say "drag", as the panel sends them) is one step; what was found for
// the voxels (the interference) stays through them, as the voxels do.
TEST(AppParts, colourAndVisibilityAreUndoneAndRedone) {
  test::TempDir dir;
  AppState state;
  openTwoBlocks(state, dir);
  const glm::vec3 first = currentParts(state)->part(0).colour;
  const glm::vec3 second = currentParts(state)->part(1).colour;
  ASSERT_TRUE(run(state, "interference").ok());
  ASSERT_TRUE(pump(state, [&] { return currentInterference(state) != nullptr; }));
  const size_t depth = state.doc.undo_stack.size();

  ASSERT_TRUE(run(state, "part-colour 1 #ff0000").ok());
  EXPECT_EQ(state.doc.undo_stack.size(), depth + 1);
  EXPECT_EQ(state.doc.model->label, "colour of a.vxm");
  undo(state);
  EXPECT_EQ(currentParts(state)->part(0).colour, first);
  redo(state);
  EXPECT_EQ(currentParts(state)->part(0).colour, glm::vec3(1.0f, 0.0f, 0.0f));

  // A drag: the first change a step of its own, the others in it; undo goes back to before the drag.
  ASSERT_TRUE(run(state, "part-colour 2 0.1 0.2 0.3").ok());
  for (const char* c : {"0.2 0.2 0.3", "0.3 0.2 0.3", "0.4 0.25 0.3"}) {
    ASSERT_TRUE(run(state, std::string("part-colour 2 ") + c + " drag").ok());
  }
  EXPECT_EQ(currentParts(state)->part(1).colour, glm::vec3(0.4f, 0.25f, 0.3f));
  EXPECT_EQ(state.doc.undo_stack.size(), depth + 2);
  // A drag of another part's colour is not the same drag.
  ASSERT_TRUE(run(state, "part-colour 1 0 1 0 drag").ok());
  EXPECT_EQ(state.doc.undo_stack.size(), depth + 3);
  undo(state);
  EXPECT_EQ(currentParts(state)->part(0).colour, glm::vec3(1.0f, 0.0f, 0.0f));
  EXPECT_EQ(currentParts(state)->part(1).colour, glm::vec3(0.4f, 0.25f, 0.3f));
  undo(state);
  EXPECT_EQ(currentParts(state)->part(1).colour, second);
  EXPECT_EQ(currentParts(state)->part(0).colour, glm::vec3(1.0f, 0.0f, 0.0f));
  // After an undo a "drag" change starts a step of its own: the step it would join is gone.
  ASSERT_TRUE(run(state, "part-colour 2 0 0 1 drag").ok());
  EXPECT_EQ(state.doc.undo_stack.size(), depth + 2);
  EXPECT_FALSE(canRedo(state));
  undo(state);
  EXPECT_EQ(currentParts(state)->part(1).colour, second);

  // Visibility: hiding is a step, undone and redone; the union (the model) keeps the hidden part.
  ASSERT_TRUE(run(state, "part-visible 2 off").ok());
  EXPECT_FALSE(currentParts(state)->part(1).visible);
  EXPECT_EQ(state.doc.model->label, "hide b.vxm");
  EXPECT_EQ(state.model.filledCount(), 10 * 4 * 4);
  undo(state);
  EXPECT_TRUE(currentParts(state)->part(1).visible);
  redo(state);
  EXPECT_FALSE(currentParts(state)->part(1).visible);
  // The voxels never changed: the interference found before is still the current one.
  EXPECT_NE(currentInterference(state), nullptr);

  // Undoing a placement brings back the colours and visibility the parts had before it.
  ASSERT_TRUE(run(state, "place-part 2 3 0 0").ok());
  ASSERT_TRUE(run(state, "part-visible 2 on").ok());
  ASSERT_TRUE(run(state, "part-colour 2 #00ff00").ok());
  undo(state);
  undo(state);
  EXPECT_FALSE(currentParts(state)->part(1).visible);
  EXPECT_EQ(currentParts(state)->part(1).placement.translation, glm::ivec3(3, 0, 0));
  undo(state);
  EXPECT_TRUE(currentParts(state)->part(1).placement.identity());
}

// The parts drawn by renderers on the model's frame, as the 3D view drew them before a part's renderer held the part
// on its own box: the picture to compare with.
ImageRgba drawnOnTheModelsFrame(const AppState& state, render::Framebuffer& fb, const render::DrawParams& params) {
  const Assembly& parts = *currentParts(state);
  fb.bind();
  fb.clear(Rgba8{0, 0, 0, 255});
  for (size_t i = 0; i < parts.size(); ++i) {
    auto r = render::PointRenderer::create();
    EXPECT_TRUE(r.ok());
    if (!r) return {};
    (*r)->setGrid(partOnExtent(parts, i));
    render::DrawParams p = params;
    p.colour = parts.part(i).colour;
    (*r)->draw(state.view.camera, fb.width(), fb.height(), p);
  }
  return fb.readPixels();
}

ImageRgba drawnByTheView(AppState& state, render::Framebuffer& fb, const render::DrawParams& params) {
  fb.bind();
  fb.clear(Rgba8{0, 0, 0, 255});
  drawParts(state, fb.width(), fb.height(), params);
  return fb.readPixels();
}

// Pixels whose channels differ by more than 24 (of 255), and pixels that are not the black background.
std::pair<int64_t, int64_t> differingAndDrawn(const ImageRgba& a, const ImageRgba& b) {
  int64_t differing = 0, drawn = 0;
  for (size_t k = 0; k < a.pixels.size() && k < b.pixels.size(); ++k) {
    const Rgba8 p = a.pixels[k], q = b.pixels[k];
    differing += std::abs(p.r - q.r) > 24 || std::abs(p.g - q.g) > 24 || std::abs(p.b - q.b) > 24;
    drawn += p.r + p.g + p.b > 0;
  }
  return {differing, drawn};
}

// Each part's renderer holds the placed part on its own box and is drawn moved to where that box lies in the model's
// frame: a move or turn refills the renderer of the part that moved and no other (nor the model's: the union is not
// drawn), undo refills it again, removing a part refills none; the picture, with a section cut-away too, is the one
// renderers holding each part on the model's frame draw; the model is the union of the parts where they now are.
TEST(AppParts, aMoveRefillsOnlyTheMovedPartsRenderer) {
  auto context = llvmpipeContext();
  VOX_SKIP_WITHOUT_GL(context);
  test::TempDir dir;
  ASSERT_TRUE(io::saveStlBinary(threeBodies(), dir / "train.stl").ok());
  AppState state;
  ASSERT_TRUE(initViewport(state).ok());
  openVoxelized(state, dir / "train.stl", 64);
  ASSERT_TRUE(run(state, "split-bodies").ok());
  ASSERT_TRUE(pump(state, [&] { return currentParts(state) != nullptr; }));
  syncRenderers(state);
  ASSERT_TRUE(drawsParts(state));
  EXPECT_EQ(state.viewport.part_fills, 3);
  std::vector<const render::PointRenderer*> held;
  for (const Viewport::PartView& v : state.viewport.parts) held.push_back(v.renderer.get());
  const uint64_t model_uploaded = state.viewport.uploaded_version;

  // Body 1 moved (about a voxel and a half along -X, 4 along Y) and turned a quarter about Z at once.
  ASSERT_TRUE(run(state, "place-part 2 -0.2 0.5 0 0 0 1").ok());
  syncRenderers(state);
  EXPECT_EQ(state.viewport.part_fills, 4);
  EXPECT_EQ(state.viewport.parts[0].renderer.get(), held[0]);
  EXPECT_EQ(state.viewport.parts[2].renderer.get(), held[2]);
  const Assembly& parts = *currentParts(state);
  EXPECT_EQ(state.viewport.parts[1].box, parts.placedVoxels(1).box());
  EXPECT_EQ(state.viewport.uploaded_version, model_uploaded);

  // The model: the union of the parts where they are now, voxel for voxel (Booleans one part at a time).
  const Box3i extent = parts.extent();
  LatticeGrid expected = parts.placedVoxels(0);
  for (size_t i = 1; i < parts.size(); ++i) {
    expected = booleanParts(expected, parts.placedVoxels(i), PartOp::kUnion, parts.lattice());
  }
  expected = reframe(expected, extent, parts.lattice());
  EXPECT_EQ(state.model.dims(), (Dims{extent.size().x, extent.size().y, extent.size().z}));
  EXPECT_EQ(
      booleanParts(LatticeGrid{state.model, extent.min}, expected, PartOp::kXor, parts.lattice()).grid.filledCount(),
      0);
  EXPECT_GT(state.model.filledCount(), 0);

  // The picture: the same as renderers on the model's frame give, whole and cut by a section.
  ASSERT_TRUE(state.model_bounds.has_value());
  state.view.camera.fitToBox(*state.model_bounds, 1.0);
  render::Framebuffer fb;
  ASSERT_TRUE(fb.resize(200, 200).ok());
  render::DrawParams params;
  params.lut = render::Lut::kLit;
  for (int cut = 0; cut < 2; ++cut) {
    if (cut) {
      params.section.axis = render::SectionAxis::kX;
      params.section.index = state.model.nx() / 2;
    }
    const auto [differing, drawn] =
        differingAndDrawn(drawnByTheView(state, fb, params), drawnOnTheModelsFrame(state, fb, params));
    EXPECT_GT(drawn, 2000) << cut;
    EXPECT_LE(differing, drawn / 200) << cut;  // the same points: at most a pixel's rounding here and there
  }

  // Undo: the part's renderer is filled again for where it was; removing a part keeps the others' renderers.
  undo(state);
  syncRenderers(state);
  EXPECT_EQ(state.viewport.part_fills, 5);
  EXPECT_EQ(state.viewport.parts[0].renderer.get(), held[0]);
  ASSERT_TRUE(run(state, "remove-part 1").ok());
  syncRenderers(state);
  EXPECT_EQ(state.viewport.part_fills, 5);
  ASSERT_EQ(state.viewport.parts.size(), 2u);
  EXPECT_EQ(state.viewport.parts[1].renderer.get(), held[2]);
  shutdownViewport(state);
  state.viewport.parts.clear();  // GL objects go while the context is current
}

TEST(AppParts, eachPartIsSavedToAFolderOnTheLattice) {
  test::TempDir dir;
  AppState state;
  openTwoBlocks(state, dir);
  ASSERT_TRUE(run(state, "place-part 2 2 0 0").ok());
  ASSERT_TRUE(run(state, "save-parts " + (dir / "out").string()).ok());
  auto a = io::loadVxm(dir / "out" / "01_a.vxm");
  auto b = io::loadVxm(dir / "out" / "02_b.vxm");
  ASSERT_TRUE(a.ok()) << a.error().message;
  ASSERT_TRUE(b.ok()) << b.error().message;
  EXPECT_EQ(a->filledCount(), 6 * 4 * 4);
  EXPECT_EQ(b->filledCount(), 6 * 4 * 4);
  EXPECT_EQ(a->frame().origin, glm::dvec3(0.0));
  EXPECT_EQ(b->frame().origin, glm::dvec3(6.0, 0.0, 0.0));  // added at 4, moved by 2
  EXPECT_NE(state.status_message.find("2 parts"), std::string::npos) << state.status_message;
  // Read back as parts, they make the same scene (the union the model shows).
  AppState again;
  ASSERT_TRUE(run(again, "open " + (dir / "out" / "01_a.vxm").string()).ok());
  ASSERT_TRUE(pump(again, [&] { return again.doc.model.has_value(); }));
  ASSERT_TRUE(run(again, "add-part " + (dir / "out" / "02_b.vxm").string()).ok());
  ASSERT_TRUE(pump(again, [&] { return currentParts(again) && currentParts(again)->size() == 2; }));
  EXPECT_EQ(again.model.dims(), state.model.dims());
  EXPECT_EQ(again.model.filledCount(), state.model.filledCount());
  // Save (the union) is the other choice, as before.
  ASSERT_TRUE(run(state, "save " + (dir / "union.vxm").string()).ok());
  auto u = io::loadVxm(dir / "union.vxm");
  ASSERT_TRUE(u.ok());
  EXPECT_EQ(u->filledCount(), 12 * 4 * 4);
  // A folder that cannot be made: an error naming it, no file written.
  ASSERT_TRUE(io::saveVxm(VoxelGrid(Dims{1, 1, 1}), dir / "taken.vxm").ok());
  const Status s = run(state, "save-parts " + (dir / "taken.vxm" / "sub").string());
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().message.find("taken.vxm"), std::string::npos) << s.error().message;
  // Without parts there is nothing to save part by part.
  AppState one;
  ASSERT_TRUE(run(one, "open " + (dir / "a.vxm").string()).ok());
  ASSERT_TRUE(pump(one, [&] { return one.doc.model.has_value(); }));
  EXPECT_FALSE(actionEnabled(one, action(ActionId::kSaveParts)));
}

TEST(AppParts, theClearanceOfTwoPartsIsTheLibrarysAndMarksTwoVoxels) {
  test::TempDir dir;
  AppState state;
  openTwoBlocks(state, dir);
  // Touching (sharing voxels): no gap.
  ASSERT_TRUE(run(state, "clearance 1 2").ok());
  ASSERT_TRUE(pump(state, [&] { return currentClearance(state) != nullptr; }));
  EXPECT_TRUE(currentClearance(state)->touching);
  EXPECT_NE(clearanceText(state).find("touch"), std::string::npos) << clearanceText(state);
  glm::ivec3 va, vb;
  EXPECT_FALSE(clearanceVoxels(state, va, vb));

  // b moved 4 voxels on: a covers X 0..5, b X 8..13; the closest voxels' centres are 3 voxels apart, a gap of 2.
  ASSERT_TRUE(run(state, "place-part 2 4 0 0").ok());
  EXPECT_EQ(currentClearance(state), nullptr);  // found for the previous state
  ASSERT_TRUE(run(state, "select-part 1 2").ok());
  ASSERT_TRUE(dispatch(state, ActionId::kClearance));  // the panel's button: the two selected
  ASSERT_TRUE(pump(state, [&] { return currentClearance(state) != nullptr; }));
  const Clearance& c = *currentClearance(state);
  const Assembly& parts = *currentParts(state);
  auto lib = findClearance(parts.placedVoxels(0), parts.placedVoxels(1), parts.lattice());
  ASSERT_TRUE(lib.ok());
  EXPECT_FALSE(c.touching);
  EXPECT_DOUBLE_EQ(c.gap, 2.0);
  EXPECT_DOUBLE_EQ(c.gap, lib->gap);
  EXPECT_EQ(c.voxel_a, lib->voxel_a);
  EXPECT_EQ(c.voxel_b, lib->voxel_b);
  EXPECT_EQ(c.voxel_a.x, 5);
  EXPECT_EQ(c.voxel_b.x, 8);
  ASSERT_TRUE(clearanceVoxels(state, va, vb));
  EXPECT_EQ(va, c.voxel_a - parts.extent().min);  // the model's voxel coordinates
  EXPECT_EQ(vb, c.voxel_b - parts.extent().min);
  // The view turned to the gap (its marker was off screen until a Fit).
  EXPECT_EQ(state.view.camera.target, (glm::dvec3(va) + glm::dvec3(vb)) * 0.5 + 0.5);
  EXPECT_NE(clearanceText(state).find("Gap between a.vxm and b.vxm: 2 model units"), std::string::npos)
      << clearanceText(state);
  // Shown while the two parts are the selection.
  ASSERT_TRUE(run(state, "select-part 2").ok());
  EXPECT_TRUE(clearanceText(state).empty());
  EXPECT_FALSE(clearanceVoxels(state, va, vb));
  ASSERT_TRUE(run(state, "select-part 2 1").ok());
  EXPECT_TRUE(clearanceVoxels(state, va, vb));
  // File > Export report: the parts, no pair interfering, and the clearance found, as the panel says it.
  const std::filesystem::path html = dir / "parts.html";
  ASSERT_TRUE(run(state, "export-report " + html.string()).ok());
  ASSERT_TRUE(pump(state, [&] { return !state.volume_export_job.active() && std::filesystem::exists(html); }));
  std::ifstream in(html);
  const std::string page((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const char* words : {"Assembly: 2 parts", "<td>a.vxm</td>", "<td>b.vxm</td>", "0 pairs of parts interfere",
                            "Clearance between a.vxm and b.vxm: a gap of 2 model units"}) {
    EXPECT_NE(page.find(words), std::string::npos) << words;
  }
  EXPECT_FALSE(run(state, "clearance 1 1").ok());
  EXPECT_FALSE(run(state, "clearance 1 3").ok());
  // Esc (Model > Cancel) drops a clearance under way: nothing arrives for it.
  ASSERT_TRUE(run(state, "place-part 2 5 0 0").ok());
  ASSERT_TRUE(run(state, "clearance 1 2").ok());
  ASSERT_TRUE(actionEnabled(state, action(ActionId::kCancelJob)));
  ASSERT_TRUE(run(state, "cancel").ok());
  EXPECT_FALSE(state.clearance_job.active());
  for (int i = 0; i < 20; ++i) updateDocument(state);
  EXPECT_EQ(currentClearance(state), nullptr);
}

TEST(AppParts, theInterferenceSearchShowsProgressAndCancels) {
  test::TempDir dir;
  AppState state;
  openTwoBlocks(state, dir);
  EXPECT_FALSE(actionEnabled(state, action(ActionId::kCancelInterference)));  // nothing running
  // A scene whose interference takes a while: 30 blocks of 128^3 voxels, every pair overlapping (the parts are set
  // in place, as visibility is, to skip 30 part jobs).
  // 30 cubes of n^3 voxels side by side, each a voxel along X from the last: every pair overlaps.
  const Lattice lattice = currentParts(state)->lattice();
  const auto blocks = [&lattice](int32_t n) {
    auto scene = std::make_shared<Assembly>(lattice);
    for (int i = 0; i < 30; ++i) {
      VoxelGrid g(Dims{n, n, n});
      for (int32_t z = 0; z < n; ++z) {
        for (int32_t y = 0; y < n; ++y) g.fillRun(y, z, 0, n);
      }
      scene->addPart(LatticeGrid{std::move(g), glm::ivec3(i, 0, 0)}, "block " + std::to_string(i));
    }
    return scene;
  };
  state.doc.model->parts = blocks(128);
  ASSERT_TRUE(run(state, "interference").ok());
  ASSERT_TRUE(actionEnabled(state, action(ActionId::kCancelInterference)));
  ASSERT_TRUE(run(state, "cancel-interference").ok());
  ASSERT_TRUE(pump(state, [&] { return !state.interference_job.active(); }));
  EXPECT_EQ(currentInterference(state), nullptr);
  EXPECT_EQ(state.parts_ui.interference_cancelled_version, state.doc.model->version);
  EXPECT_TRUE(state.errors.messages.empty());  // a cancel is not an error
  // Esc (Model > Cancel) stops it too, as it stops the other background jobs.
  ASSERT_TRUE(run(state, "interference").ok());
  ASSERT_TRUE(actionEnabled(state, action(ActionId::kCancelJob)));
  ASSERT_TRUE(run(state, "cancel").ok());
  ASSERT_TRUE(pump(state, [&] { return !state.interference_job.active(); }));
  EXPECT_EQ(currentInterference(state), nullptr);
  EXPECT_EQ(state.parts_ui.interference_cancelled_version, state.doc.model->version);
  // Asked again, it runs to the end: every pair of 30 blocks of 32^3 (each overlap's thickness is a distance
  // transform: the large blocks' would take minutes under the thread sanitizer).
  state.doc.model->parts = blocks(32);
  ASSERT_TRUE(run(state, "interference").ok());
  EXPECT_EQ(state.parts_ui.interference_cancelled_version, 0u);
  ASSERT_TRUE(pump(state, [&] { return currentInterference(state) != nullptr; }));
  EXPECT_EQ(currentInterference(state)->pairs.size(), 30u * 29u / 2u);
}

}  // namespace
}  // namespace vox::app
