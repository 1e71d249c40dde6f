// The Parts panel's logic without a window (app/parts.h), driven through the action table as the panel and a
// script drive it: splitting a mesh into bodies and a voxel model into components, adding a part from a file,
// Booleans and their undo, and the interference list, compared with the library's own results.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "app/actions.h"
#include "app/app_state.h"
#include "app/operations.h"
#include "app/parts.h"
#include "support/test_support.h"
#include "vox/analysis/assembly.h"
#include "vox/io/stl.h"
#include "vox/io/voxel_file.h"
#include "vox/voxelize/bodies.h"

namespace vox::app {
namespace {

template <class F>
bool pump(AppState& state, F done) {
  for (int i = 0; i < 5000; ++i) {
    updateDocument(state);
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return false;
}

Status run(AppState& state, const std::string& line) {
  std::vector<std::string> words;
  std::string rest;
  size_t start = 0;
  while (start < line.size()) {
    const size_t end = std::min(line.find(' ', start), line.size());
    words.push_back(line.substr(start, end - start));
    start = end + 1;
  }
  const Action* a = findAction(words[0]);
  if (!a) return makeError(ErrorCode::kInvalidArgument, "no action " + words[0]);
  words.erase(words.begin());
  if (const size_t sp = line.find(' '); sp != std::string::npos) rest = line.substr(sp + 1);
  return dispatch(state, *a, ActionArgs{words, rest});
}

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

  // Undo goes back to the one model; the interference of the parts is not shown for it.
  undo(state);
  EXPECT_EQ(currentParts(state), nullptr);
  EXPECT_EQ(state.model.filledCount(), whole);
  EXPECT_EQ(currentInterference(state), nullptr);
}

TEST(AppParts, booleansAreNewPartsAndUndoable) {
  test::TempDir dir;
  // Two blocks on one lattice: a is 6 x 4 x 4 at the origin, b the same shifted by 4 voxels in X (2 x 4 x 4 shared).
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
  AppState state;
  ASSERT_TRUE(run(state, "open " + (dir / "a.vxm").string()).ok());
  ASSERT_TRUE(pump(state, [&] { return state.doc.model.has_value(); }));
  ASSERT_TRUE(run(state, "add-part " + (dir / "b.vxm").string()).ok());
  ASSERT_TRUE(pump(state, [&] { return currentParts(state) && currentParts(state)->size() == 2; }));
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

}  // namespace
}  // namespace vox::app
