// Parts on one lattice: components, Booleans between parts with different boxes, interference and clearance, each
// against a voxel-by-voxel count (docs/conventions.md, "Assemblies").
#include "vox/analysis/assembly.h"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <algorithm>
#include <vector>

#include "grids.h"
#include "vox/analysis/analysis.h"
#include "vox/core/assembly.h"

namespace vox {
namespace {

// A random part: `boxes` random boxes inside a grid of `size` placed at lattice voxel `first`.
LatticeGrid randomPart(glm::ivec3 first, glm::ivec3 size, int boxes, uint32_t seed) {
  return LatticeGrid{test::randomBoxes(Dims{size.x, size.y, size.z}, boxes, seed), first};
}

bool at(const LatticeGrid& g, glm::ivec3 p) {
  const glm::ivec3 q = p - g.first;
  return g.grid.inBounds(q.x, q.y, q.z) && g.grid.get(q.x, q.y, q.z);
}

TEST(Components, faceAndAllNeighbours) {
  VoxelGrid g(Dims{20, 10, 10});
  test::fillBox(g, {0, 0, 0}, {5, 5, 5});    // 125 voxels
  g.set(5, 5, 5);                            // touches the box only at a corner
  test::fillBox(g, {10, 0, 0}, {20, 2, 1});  // 20 voxels, a separate slab
  const Components face = findComponents(g, Connectivity::kFace);
  ASSERT_EQ(face.components.size(), 3u);
  EXPECT_EQ(face.components[0].voxels, 125);
  EXPECT_EQ(face.components[1].voxels, 20);
  EXPECT_EQ(face.components[2].voxels, 1);
  EXPECT_EQ(face.components[1].box_min, glm::ivec3(10, 0, 0));
  EXPECT_EQ(face.components[1].box_max, glm::ivec3(19, 1, 0));
  const Components all = findComponents(g, Connectivity::kAll);
  ASSERT_EQ(all.components.size(), 2u);
  EXPECT_EQ(all.components[0].voxels, 126);
  EXPECT_EQ(componentGrid(g, all, 1).filledCount(), 20);
}

TEST(Components, randomGridMatchesFloodFill) {
  const VoxelGrid g = test::randomGrid(Dims{70, 23, 17}, 0.3, 7);
  for (Connectivity c : {Connectivity::kFace, Connectivity::kAll}) {
    const Components comps = findComponents(g, c);
    // Flood fill from each component's voxels: every voxel reached belongs to that component only.
    int64_t total = 0;
    for (size_t i = 0; i < comps.components.size(); ++i) total += comps.components[i].voxels;
    EXPECT_EQ(total, g.filledCount());
    std::vector<int> label(size_t(g.dims().count()), -1);
    int next = 0;
    std::vector<int64_t> sizes;
    const int reach = c == Connectivity::kAll ? 1 : 0;
    for (int64_t start = 0; start < g.dims().count(); ++start) {
      const glm::ivec3 s = g.coordinates(start);
      if (!g.get(s.x, s.y, s.z) || label[size_t(start)] >= 0) continue;
      std::vector<glm::ivec3> stack{s};
      label[size_t(start)] = next;
      int64_t n = 0;
      while (!stack.empty()) {
        const glm::ivec3 p = stack.back();
        stack.pop_back();
        ++n;
        for (int dz = -1; dz <= 1; ++dz)
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              if (std::abs(dx) + std::abs(dy) + std::abs(dz) != 1 && reach == 0) continue;
              const glm::ivec3 q = p + glm::ivec3(dx, dy, dz);
              if (!g.inBounds(q.x, q.y, q.z) || !g.get(q.x, q.y, q.z)) continue;
              int& l = label[size_t(g.index(q.x, q.y, q.z))];
              if (l < 0) {
                l = next;
                stack.push_back(q);
              }
            }
      }
      sizes.push_back(n);
      ++next;
    }
    std::stable_sort(sizes.begin(), sizes.end(), std::greater<>());
    ASSERT_EQ(comps.components.size(), sizes.size());
    for (size_t i = 0; i < sizes.size(); ++i) EXPECT_EQ(comps.components[i].voxels, sizes[i]);
  }
}

// b's box starts a whole word (64 voxels) past a's, then at offsets that are not whole words, on either side of a's
// and past its end: every row of one operand or both is read across word boundaries.
TEST(PartBoolean, shiftedBoxesMatchSetOperations) {
  const Lattice lattice;
  const LatticeGrid a = randomPart({-3, 2, 0}, {150, 20, 9}, 6, 1);
  for (int bx : {61, 5, -70, 130}) {
    SCOPED_TRACE(bx);
    const LatticeGrid b = randomPart({bx, -4, 3}, {70, 30, 12}, 6, 2);
    for (PartOp op : {PartOp::kUnion, PartOp::kIntersection, PartOp::kDifference, PartOp::kXor}) {
      const LatticeGrid r = booleanParts(a, b, op, lattice);
      EXPECT_EQ(r.box(), unite(a.box(), b.box()));
      const Box3i box = r.box();
      int64_t want_count = 0;
      for (int z = box.min.z; z < box.max.z; ++z)
        for (int y = box.min.y; y < box.max.y; ++y)
          for (int x = box.min.x; x < box.max.x; ++x) {
            const bool va = at(a, {x, y, z}), vb = at(b, {x, y, z});
            const bool want = op == PartOp::kUnion          ? (va || vb)
                              : op == PartOp::kIntersection ? (va && vb)
                              : op == PartOp::kDifference   ? (va && !vb)
                                                            : (va != vb);
            want_count += want ? 1 : 0;
            ASSERT_EQ(at(r, {x, y, z}), want) << partOpName(op) << " at " << x << " " << y << " " << z;
          }
      EXPECT_EQ(r.grid.filledCount(), want_count) << partOpName(op);  // nothing in the padding
    }
  }
}

TEST(PartBoolean, equalBoxesAndXorOnBooleanOp) {
  const VoxelGrid a = test::randomBoxes(Dims{70, 20, 30}, 5, 3), b = test::randomBoxes(Dims{70, 20, 30}, 5, 4);
  const VoxelGrid x = *booleanOp(a, b, BoolOp::kXor);
  for (int z = 0; z < 30; ++z)
    for (int y = 0; y < 20; ++y)
      for (int i = 0; i < 70; ++i) ASSERT_EQ(x.get(i, y, z), a.get(i, y, z) != b.get(i, y, z));
  const LatticeGrid r = booleanParts(LatticeGrid{a, {5, 5, 5}}, LatticeGrid{b, {5, 5, 5}}, PartOp::kXor, Lattice{});
  EXPECT_EQ(r.first, glm::ivec3(5));
  EXPECT_EQ(r.grid.filledCount(), x.filledCount());
}

// Parts whose boxes start at columns on and off the 64-voxel word boundaries, overlapping and apart, some with empty
// layers: their union over a box that cuts some of them, voxel by voxel.
std::vector<LatticeGrid> scatteredParts() {
  return {randomPart({0, 0, 0}, {70, 9, 8}, 6, 1), randomPart({63, 4, 2}, {130, 7, 9}, 8, 2),
          randomPart({-37, -3, 5}, {45, 12, 6}, 5, 3), randomPart({150, 1, -4}, {9, 5, 20}, 3, 4),
          randomPart({5, 2, 1}, {1, 3, 3}, 1, 5)};
}

void expectUnionOf(const LatticeGrid& u, const std::vector<LatticeGrid>& parts, const Box3i& box) {
  ASSERT_EQ(u.box(), box);
  int64_t filled = 0;
  for (int32_t z = box.min.z; z < box.max.z; ++z) {
    for (int32_t y = box.min.y; y < box.max.y; ++y) {
      for (int32_t x = box.min.x; x < box.max.x; ++x) {
        bool any = false;
        for (const LatticeGrid& p : parts) any = any || at(p, {x, y, z});
        ASSERT_EQ(at(u, {x, y, z}), any) << x << " " << y << " " << z;
        filled += any;
      }
    }
  }
  EXPECT_EQ(u.grid.filledCount(), filled);
}

TEST(PartUnion, manyPartsAtOnceMatchVoxelByVoxel) {
  const std::vector<LatticeGrid> parts = scatteredParts();
  Box3i extent;
  for (const LatticeGrid& p : parts) extent = unite(extent, p.box());
  const LatticeGrid u = unionOfParts(parts, extent, Lattice{});
  expectUnionOf(u, parts, extent);
  // The same as Booleans one part at a time.
  LatticeGrid chain = parts[0];
  for (size_t i = 1; i < parts.size(); ++i) chain = booleanParts(chain, parts[i], PartOp::kUnion, Lattice{});
  EXPECT_EQ(reframe(chain, extent, Lattice{}).grid.filledCount(), u.grid.filledCount());
  // A box that cuts parts on columns inside a word keeps only what lies in it.
  const Box3i cut{{-20, 1, 0}, {100, 8, 7}};
  expectUnionOf(unionOfParts(parts, cut, Lattice{}), parts, cut);
}

// A part moved: the union made again over its old and new boxes is the union of the parts in their new places, and
// the layers neither box reaches are still shared with the union it was copied from.
TEST(PartUnion, redoneOverAMovedPartsBoxesIsTheNewUnion) {
  std::vector<LatticeGrid> parts = scatteredParts();
  Box3i extent;
  for (const LatticeGrid& p : parts) extent = unite(extent, p.box());
  const LatticeGrid before = unionOfParts(parts, extent, Lattice{});
  const Box3i old_box = parts[1].box();
  parts[1].first += glm::ivec3(-29, 1, 0);  // still inside the extent, over part 0 and part 2
  LatticeGrid u = before;
  redoUnionIn(u, parts, old_box);
  redoUnionIn(u, parts, parts[1].box());
  expectUnionOf(u, parts, extent);
  for (int32_t z = 0; z < extent.size().z; ++z) {
    const int32_t Z = extent.min.z + z;
    const bool reached =
        (Z >= old_box.min.z && Z < old_box.max.z) || (Z >= parts[1].box().min.z && Z < parts[1].box().max.z);
    if (!reached) {
      EXPECT_TRUE(u.grid.sharesLayerWith(before.grid, z)) << Z;
    }
  }
  // A region outside the grid changes nothing.
  redoUnionIn(u, parts, Box3i{{1000, 0, 0}, {1010, 5, 5}});
  expectUnionOf(u, parts, extent);
}

TEST(Interference, twoBoxesOverlapInAKnownBlock) {
  Lattice lattice{glm::dvec3(0.0), 0.5, "model"};
  const LatticeGrid a{test::boxGrid(Dims{10, 10, 10}, {0, 0, 0}, {10, 10, 10}), {0, 0, 0}};
  const LatticeGrid b{test::boxGrid(Dims{10, 10, 10}, {0, 0, 0}, {10, 10, 10}), {6, 5, 4}};
  const std::vector<LatticeGrid> parts{a, b};
  const Interference r = findInterference(parts, lattice);
  ASSERT_EQ(r.pairs.size(), 1u);
  EXPECT_EQ(r.pairs[0].voxels, 4 * 5 * 6);
  EXPECT_EQ(r.pairs[0].box, (Box3i{{6, 5, 4}, {10, 10, 10}}));
  // Mean of the voxel centres: x 6..9, y 5..9, z 4..9, times h = 0.5.
  EXPECT_DOUBLE_EQ(r.pairs[0].centre.x, 8.0 * 0.5);
  EXPECT_DOUBLE_EQ(r.pairs[0].centre.y, 7.5 * 0.5);
  EXPECT_DOUBLE_EQ(r.pairs[0].centre.z, 7.0 * 0.5);
  EXPECT_EQ(r.overlap_voxels, 120);
  EXPECT_EQ(r.multiple_overlap_voxels, 0);
  EXPECT_EQ(sharedVoxels(a, b, lattice).grid.filledCount(), 120);
}

// An overlap's thickness: a slab k voxels thick where two blocks overlap reads k voxels (k odd) or k - 1 (k even),
// whichever way it lies; a block inside another reads its least side the same way. Contact is a thickness at most
// the tolerance.
TEST(Interference, anOverlapsThicknessIsItsSlabs) {
  Lattice lattice{glm::dvec3(0.0), 0.25, "mm"};
  const LatticeGrid a{test::boxGrid(Dims{20, 20, 20}, {0, 0, 0}, {20, 20, 20}), {0, 0, 0}};
  for (int k : {1, 2, 3, 5, 6}) {
    for (int axis = 0; axis < 3; ++axis) {
      glm::ivec3 at(0);
      at[axis] = 20 - k;
      const LatticeGrid b{test::boxGrid(Dims{20, 20, 20}, {0, 0, 0}, {20, 20, 20}), at};
      const std::vector<LatticeGrid> parts{a, b};
      const Interference r = findInterference(parts, lattice);
      ASSERT_EQ(r.pairs.size(), 1u) << k;
      EXPECT_EQ(r.pairs[0].voxels, int64_t(k) * 400) << k;
      const int expected = k % 2 ? k : k - 1;
      EXPECT_DOUBLE_EQ(r.pairs[0].thickness, expected * 0.25) << "k " << k << " axis " << axis;
      EXPECT_TRUE(isContact(r.pairs[0], 0.25 * expected));
      EXPECT_FALSE(isContact(r.pairs[0], 0.25 * expected - 0.01));
      EXPECT_FALSE(isContact(r.pairs[0], 0.0));  // no tolerance: every overlap interferes
    }
  }
  // A 5 x 7 x 9 block inside the big one: 5 voxels, its least side.
  const LatticeGrid inner{test::boxGrid(Dims{5, 7, 9}, {0, 0, 0}, {5, 7, 9}), {4, 4, 4}};
  const std::vector<LatticeGrid> nested{a, inner};
  const Interference n = findInterference(nested, lattice);
  ASSERT_EQ(n.pairs.size(), 1u);
  EXPECT_DOUBLE_EQ(n.pairs[0].thickness, 5 * 0.25);
}

TEST(Interference, progressReachesTheEndAndCancelStops) {
  const Lattice lattice;
  std::vector<LatticeGrid> parts;
  for (int i = 0; i < 6; ++i) parts.push_back(randomPart({8 * i, 0, 0}, {40, 20, 20}, 4, uint32_t(30 + i)));
  const Interference plain = findInterference(parts, lattice);
  ASSERT_FALSE(plain.pairs.empty());
  // With a callback: the same pairs, fractions that never go back, ending at 1.
  std::vector<double> seen;
  auto with = findInterference(parts, lattice, [&](double f) {
    seen.push_back(f);
    return true;
  });
  ASSERT_TRUE(with.ok());
  ASSERT_EQ(with->pairs.size(), plain.pairs.size());
  for (size_t i = 0; i < plain.pairs.size(); ++i) {
    EXPECT_EQ(with->pairs[i].a, plain.pairs[i].a);
    EXPECT_EQ(with->pairs[i].b, plain.pairs[i].b);
    EXPECT_EQ(with->pairs[i].voxels, plain.pairs[i].voxels);
  }
  EXPECT_EQ(with->overlap_voxels, plain.overlap_voxels);
  ASSERT_GE(seen.size(), 2u);
  for (size_t i = 1; i < seen.size(); ++i) EXPECT_GE(seen[i], seen[i - 1]);
  EXPECT_DOUBLE_EQ(seen.back(), 1.0);
  // A callback that asks to stop: cancelled, whether it asks at once or half way.
  for (int after : {0, 3}) {
    int calls = 0;
    auto stopped = findInterference(parts, lattice, [&](double) { return calls++ < after; });
    ASSERT_FALSE(stopped.ok()) << after;
    EXPECT_EQ(stopped.error().code, ErrorCode::kCancelled);
  }
}

TEST(Interference, randomPartsMatchVoxelCounts) {
  const Lattice lattice;
  std::vector<LatticeGrid> parts;
  std::mt19937 rng(5);
  for (int i = 0; i < 9; ++i) {
    std::uniform_int_distribution<int> pos(-40, 40), size(5, 90);
    parts.push_back(randomPart({pos(rng), pos(rng) / 4, pos(rng) / 4},
                               {size(rng), size(rng) / 3 + 2, size(rng) / 3 + 2}, 3, uint32_t(10 + i)));
  }
  parts.push_back(randomPart({150, 0, 0}, {10, 10, 10}, 2, 99));  // far from the rest: never compared
  const Interference r = findInterference(parts, lattice);
  // Slow counts over the union of the boxes.
  Box3i all;
  for (const LatticeGrid& p : parts) all = unite(all, p.box());
  std::map<std::pair<int, int>, int64_t> want;
  int64_t twos = 0, threes = 0;
  for (int z = all.min.z; z < all.max.z; ++z)
    for (int y = all.min.y; y < all.max.y; ++y)
      for (int x = all.min.x; x < all.max.x; ++x) {
        std::vector<int> in;
        for (int i = 0; i < int(parts.size()); ++i) {
          if (boxesMeet(parts[size_t(i)].box(), Box3i{{x, y, z}, {x + 1, y + 1, z + 1}}) &&
              at(parts[size_t(i)], {x, y, z}))
            in.push_back(i);
        }
        twos += in.size() >= 2 ? 1 : 0;
        threes += in.size() >= 3 ? 1 : 0;
        for (size_t i = 0; i < in.size(); ++i)
          for (size_t j = i + 1; j < in.size(); ++j) ++want[{in[i], in[j]}];
      }
  ASSERT_EQ(r.pairs.size(), want.size());
  for (const InterferencePair& p : r.pairs) EXPECT_EQ(p.voxels, (want[{p.a, p.b}])) << p.a << " " << p.b;
  for (size_t i = 1; i < r.pairs.size(); ++i) EXPECT_GE(r.pairs[i - 1].voxels, r.pairs[i].voxels);
  EXPECT_EQ(r.overlap_voxels, twos);
  EXPECT_EQ(r.multiple_overlap_voxels, threes);
  EXPECT_GT(threes, 0);  // the case is meant to have triple overlaps
}

TEST(Clearance, gapBetweenTwoBoxes) {
  Lattice lattice{glm::dvec3(1.0, 2.0, 3.0), 0.25, "mm"};
  const LatticeGrid a{test::boxGrid(Dims{5, 5, 5}, {0, 0, 0}, {5, 5, 5}), {0, 0, 0}};
  const LatticeGrid b{test::boxGrid(Dims{5, 5, 5}, {0, 0, 0}, {5, 5, 5}), {10, 2, 0}};  // x 10..14: 5 empty between
  auto c = findClearance(a, b, lattice);
  ASSERT_TRUE(c.ok()) << c.error().message;
  ASSERT_TRUE(c->found);
  EXPECT_FALSE(c->touching);
  EXPECT_DOUBLE_EQ(c->centre_distance_voxels, 6.0);  // centres x = 4 and x = 10
  EXPECT_DOUBLE_EQ(c->gap, 5.0 * 0.25);
  EXPECT_EQ(c->voxel_a.x, 4);
  EXPECT_EQ(c->voxel_b.x, 10);
  EXPECT_EQ(c->voxel_a.y, c->voxel_b.y);
  // Diagonal gap: b moved up by 3 as well: the closest centres are (4, 4) and (10, 7) in x, z.
  const LatticeGrid d{b.grid, {10, 0, 8}};
  auto e = findClearance(a, d, lattice);
  ASSERT_TRUE(e.ok());
  EXPECT_DOUBLE_EQ(e->centre_distance_voxels, std::sqrt(36.0 + 16.0));
  // Overlapping parts touch.
  auto f = findClearance(a, LatticeGrid{b.grid, {3, 3, 3}}, lattice);
  ASSERT_TRUE(f.ok());
  EXPECT_TRUE(f->touching);
  EXPECT_EQ(f->gap, 0.0);
  // A bound shorter than the gap finds nothing.
  auto g = findClearance(a, b, lattice, ClearanceParams{1.0});
  ASSERT_TRUE(g.ok());
  EXPECT_FALSE(g->found);
}

TEST(Clearance, reportsProgressAndCancels) {
  Lattice lattice{glm::dvec3(0.0), 1.0, "mm"};
  const LatticeGrid a{test::boxGrid(Dims{40, 40, 40}, {0, 0, 0}, {40, 40, 40}), {0, 0, 0}};
  const LatticeGrid b{test::boxGrid(Dims{40, 40, 40}, {0, 0, 0}, {40, 40, 40}), {60, 0, 0}};
  std::vector<double> seen;
  auto c = findClearance(a, b, lattice, {}, [&](double f) {
    seen.push_back(f);
    return true;
  });
  ASSERT_TRUE(c.ok()) << c.error().message;
  EXPECT_TRUE(c->found);
  ASSERT_GE(seen.size(), 2u);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_DOUBLE_EQ(seen.back(), 1.0);
  int calls = 0;
  auto stopped = findClearance(a, b, lattice, {}, [&](double) { return ++calls < 3; });
  ASSERT_FALSE(stopped.ok());
  EXPECT_EQ(stopped.error().code, ErrorCode::kCancelled);
  EXPECT_EQ(calls, 3);  // nothing asked again after the answer was no
}

TEST(AssemblyModel, sharedLatticeTranslationAndTurns) {
  Assembly asmb;
  VoxelGrid g = test::boxGrid(Dims{4, 2, 1}, {0, 0, 0}, {4, 2, 1}, GridFrame{glm::dvec3(1.0), 0.5, "mm", "a.vxm"});
  ASSERT_TRUE(asmb.addGrid(g, "a").ok());
  // Origin 1.5 = 1 + 1 voxel: shares the lattice, placed one voxel further along each axis.
  VoxelGrid h = test::boxGrid(Dims{2, 2, 2}, {0, 0, 0}, {2, 2, 2}, GridFrame{glm::dvec3(1.5), 0.5, "mm", "b.vxm"});
  auto added = asmb.addGrid(h, "b");
  ASSERT_TRUE(added.ok()) << added.error().message;
  EXPECT_EQ(asmb.part(1).voxels.first, glm::ivec3(1));
  EXPECT_EQ(asmb.extent(), (Box3i{{0, 0, 0}, {4, 3, 3}}));
  // Off the lattice by a third of a voxel: refused, saying how.
  VoxelGrid off = h;
  off.frame().origin.x += 0.5 / 3.0;
  auto refused = asmb.addGrid(off, "c");
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("not a whole number of voxels"), std::string::npos) << refused.error().message;
  off.frame() = GridFrame{glm::dvec3(1.0), 0.25, "mm", ""};
  refused = asmb.addGrid(off, "c");
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("voxel sizes differ"), std::string::npos);
  // Translation snapped to whole voxels; a quarter turn about Z turns the 4 x 2 box into 2 x 4 about its centre.
  EXPECT_EQ(asmb.snapTranslation({1.2, -0.3, 0.0}), glm::ivec3(2, -1, 0));
  asmb.setPlacement(0, PartPlacement{{2, 0, 0}, {0, 0, 1}});
  const LatticeGrid placed = asmb.placedVoxels(0);
  EXPECT_EQ(placed.grid.dims(), (Dims{2, 4, 1}));
  EXPECT_EQ(placed.first, glm::ivec3(1 + 2, -1, 0));
  EXPECT_EQ(placed.grid.filledCount(), 8);
  EXPECT_EQ(asmb.extent(), unite(placed.box(), asmb.part(1).voxels.box()));
  // Four quarter turns about any axis give the part back, voxel for voxel.
  const LatticeGrid part{test::randomBoxes(Dims{7, 5, 3}, 3, 8), {2, 3, 4}};
  for (int axis = 0; axis < 3; ++axis) {
    glm::ivec3 one(0), three(0);
    one[axis] = 1;
    three[axis] = 3;
    const LatticeGrid back = turnQuarter(turnQuarter(part, one, asmb.lattice()), three, asmb.lattice());
    ASSERT_EQ(back.box(), part.box()) << axis;
    EXPECT_EQ(booleanParts(back, part, PartOp::kXor, asmb.lattice()).grid.filledCount(), 0) << axis;
  }
}

}  // namespace
}  // namespace vox
