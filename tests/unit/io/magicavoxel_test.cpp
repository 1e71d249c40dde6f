// .vox export checked by parsing its chunks here, as the public format description reads them: "VOX " 150, MAIN,
// SIZE + XYZI per model, the scene graph (nTRN -> nGRP -> nTRN -> nSHP) placing each model by its centre, RGBA. The
// scene is put back together into a grid and compared voxel for voxel, each voxel counted once.
#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

#include "support/grids.h"
#include "vox/io/magicavoxel.h"

namespace vox::io {
namespace {

// A little-endian reader over the file that fails the test on a read past the end.
struct Reader {
  const std::vector<uint8_t>& b;
  size_t at = 0;
  int32_t i32() {
    EXPECT_LE(at + 4, b.size());
    if (at + 4 > b.size()) throw std::runtime_error("truncated");
    const uint32_t v =
        uint32_t(b[at]) | uint32_t(b[at + 1]) << 8 | uint32_t(b[at + 2]) << 16 | uint32_t(b[at + 3]) << 24;
    at += 4;
    return int32_t(v);
  }
  std::string id() {
    if (at + 4 > b.size()) throw std::runtime_error("truncated");
    std::string s(b.begin() + std::ptrdiff_t(at), b.begin() + std::ptrdiff_t(at + 4));
    at += 4;
    return s;
  }
  std::string str() {
    const int32_t n = i32();
    std::string s(b.begin() + std::ptrdiff_t(at), b.begin() + std::ptrdiff_t(at + size_t(n)));
    at += size_t(n);
    return s;
  }
  std::map<std::string, std::string> dict() {
    std::map<std::string, std::string> d;
    for (int32_t n = i32(); n > 0; --n) {
      std::string k = str();
      d[k] = str();
    }
    return d;
  }
};

struct Model {
  glm::ivec3 size{0};
  std::vector<glm::ivec3> voxels;
};

struct Scene {
  std::vector<Model> models;
  std::map<int32_t, glm::ivec3> model_translation;  // model id -> its transform node's _t
  int rgba_chunks = 0;
  int layers = 0;
};

// Reads the whole file; the scene graph must be the flat one voxmod writes (root transform, one group, a
// transform + shape per model).
Scene parse(const std::vector<uint8_t>& bytes) {
  Reader r{bytes};
  EXPECT_EQ(r.id(), "VOX ");
  EXPECT_EQ(r.i32(), 150);
  EXPECT_EQ(r.id(), "MAIN");
  EXPECT_EQ(r.i32(), 0);
  const int32_t children = r.i32();
  EXPECT_EQ(size_t(children), bytes.size() - 20);
  Scene scene;
  std::map<int32_t, glm::ivec3> node_t;        // transform node -> translation
  std::map<int32_t, int32_t> transform_child;  // transform node -> child node
  std::map<int32_t, int32_t> shape_model;      // shape node -> model id
  while (r.at < bytes.size()) {
    const std::string id = r.id();
    const int32_t content = r.i32();
    EXPECT_EQ(r.i32(), 0) << id << " has no children";
    const size_t end = r.at + size_t(content);
    if (id == "SIZE") {
      scene.models.emplace_back();
      const int32_t x = r.i32(), y = r.i32(), z = r.i32();  // in this order (not as arguments of one call)
      scene.models.back().size = glm::ivec3(x, y, z);
    } else if (id == "XYZI") {
      Model& m = scene.models.back();
      const int32_t n = r.i32();
      EXPECT_EQ(content, 4 + 4 * n);
      for (int32_t i = 0; i < n; ++i) {
        const glm::ivec3 v(bytes[r.at], bytes[r.at + 1], bytes[r.at + 2]);
        EXPECT_EQ(bytes[r.at + 3], 1);  // colour index 1
        EXPECT_TRUE(v.x < m.size.x && v.y < m.size.y && v.z < m.size.z);
        m.voxels.push_back(v);
        r.at += 4;
      }
    } else if (id == "nTRN") {
      const int32_t node = r.i32();
      r.dict();
      transform_child[node] = r.i32();
      EXPECT_EQ(r.i32(), -1);
      r.i32();  // layer
      EXPECT_EQ(r.i32(), 1);
      auto frame = r.dict();
      glm::ivec3 t(0);
      if (frame.count("_t")) std::istringstream(frame["_t"]) >> t.x >> t.y >> t.z;
      node_t[node] = t;
    } else if (id == "nSHP") {
      const int32_t node = r.i32();
      r.dict();
      EXPECT_EQ(r.i32(), 1);
      shape_model[node] = r.i32();
      r.dict();
    } else if (id == "RGBA") {
      EXPECT_EQ(content, 1024);
      ++scene.rgba_chunks;
    } else if (id == "LAYR") {
      ++scene.layers;
    }
    r.at = end;
  }
  EXPECT_EQ(node_t[0], glm::ivec3(0));
  for (const auto& [node, child] : transform_child) {
    if (auto s = shape_model.find(child); s != shape_model.end()) scene.model_translation[s->second] = node_t[node];
  }
  return scene;
}

// The scene put back into a grid of `dims`: a model's voxel (x, y, z) lies at _t - floor(size / 2) + (x, y, z).
// Voxels placed twice or outside the grid are counted.
struct Rebuilt {
  VoxelGrid grid;
  int64_t twice = 0, outside = 0;
};
Rebuilt rebuild(const Scene& scene, Dims dims) {
  Rebuilt out{VoxelGrid(dims)};
  for (size_t i = 0; i < scene.models.size(); ++i) {
    const Model& m = scene.models[i];
    const glm::ivec3 first = scene.model_translation.at(int32_t(i)) - m.size / 2;
    for (const glm::ivec3& v : m.voxels) {
      const glm::ivec3 p = first + v;
      if (!out.grid.inBounds(p.x, p.y, p.z)) {
        ++out.outside;
      } else if (out.grid.get(p.x, p.y, p.z)) {
        ++out.twice;
      } else {
        out.grid.set(p.x, p.y, p.z);
      }
    }
  }
  return out;
}

void expectSameVoxels(const VoxelGrid& a, const VoxelGrid& b) {
  for (int32_t z = 0; z < a.nz(); ++z)
    for (int32_t y = 0; y < a.ny(); ++y)
      for (int32_t w = 0; w < a.wordsPerRow(); ++w)
        ASSERT_EQ(a.rowWords(y, z)[w], b.rowWords(y, z)[w]) << "row y " << y << " z " << z;
}

TEST(MagicaVoxel, aSmallGridIsOneModelWithItsSceneGraphAndPalette) {
  VoxelGrid g = test::randomGrid(Dims{20, 30, 10}, 0.3, 9);
  auto bytes = encodeMagicaVoxel(g);
  ASSERT_TRUE(bytes.ok()) << bytes.error().message;
  EXPECT_EQ(bytes->size(), magicaVoxelFileBytes(planMagicaVoxel(g)));
  const Scene scene = parse(*bytes);
  ASSERT_EQ(scene.models.size(), 1u);
  EXPECT_EQ(scene.models[0].size, glm::ivec3(20, 30, 10));
  EXPECT_EQ(scene.model_translation.at(0), glm::ivec3(10, 15, 5));  // the centre of a model at the origin
  EXPECT_EQ(scene.rgba_chunks, 1);
  EXPECT_EQ(scene.layers, 1);
  const Rebuilt back = rebuild(scene, g.dims());
  EXPECT_EQ(back.twice, 0);
  EXPECT_EQ(back.outside, 0);
  expectSameVoxels(back.grid, g);
}

TEST(MagicaVoxel, a300CubedGridSplitsInto256CubedModelsPlacedWhereTheyBelong) {
  VoxelGrid g(Dims{300, 300, 300});
  // Every block holds voxels, among them both ends of every axis, a voxel on each side of the 256 seams, and a
  // solid run across the seam along x.
  for (int32_t z = 0; z < 300; z += 7)
    for (int32_t y = 0; y < 300; y += 5)
      for (int32_t x = (y + z) % 3; x < 300; x += 3) g.set(x, y, z);
  for (int32_t a : {0, 255, 256, 299}) g.set(a, a, a);
  g.fillRun(100, 200, 200, 290);
  const auto plan = planMagicaVoxel(g);
  ASSERT_EQ(plan.size(), 8u);
  int64_t planned = 0;
  for (const MagicaVoxelModel& m : plan) {
    for (int a = 0; a < 3; ++a) {
      EXPECT_TRUE((m.first[a] == 0 && m.size[a] == 256) || (m.first[a] == 256 && m.size[a] == 44));
    }
    planned += m.voxels;
  }
  EXPECT_EQ(planned, g.filledCount());
  EXPECT_EQ(plan[1].first, glm::ivec3(256, 0, 0));  // x fastest, then y, then z
  EXPECT_EQ(plan[7].first, glm::ivec3(256, 256, 256));

  auto bytes = encodeMagicaVoxel(g);
  ASSERT_TRUE(bytes.ok()) << bytes.error().message;
  const Scene scene = parse(*bytes);
  ASSERT_EQ(scene.models.size(), 8u);
  for (size_t i = 0; i < 8; ++i) {
    EXPECT_EQ(scene.models[i].size, plan[i].size);
    EXPECT_EQ(int64_t(scene.models[i].voxels.size()), plan[i].voxels);
    EXPECT_EQ(scene.model_translation.at(int32_t(i)), plan[i].first + plan[i].size / 2);
  }
  const Rebuilt back = rebuild(scene, g.dims());
  EXPECT_EQ(back.twice, 0) << "every voxel once";
  EXPECT_EQ(back.outside, 0);
  EXPECT_EQ(back.grid.filledCount(), g.filledCount());
  expectSameVoxels(back.grid, g);
}

TEST(MagicaVoxel, emptyBlocksGiveNoModelAndAnEmptyGridOneEmptyModel) {
  VoxelGrid g(Dims{600, 10, 10});
  g.set(550, 5, 5);
  const auto plan = planMagicaVoxel(g);
  ASSERT_EQ(plan.size(), 1u);
  EXPECT_EQ(plan[0].first, glm::ivec3(512, 0, 0));
  EXPECT_EQ(plan[0].size, glm::ivec3(88, 10, 10));
  const auto empty = planMagicaVoxel(VoxelGrid(Dims{300, 3, 3}));
  ASSERT_EQ(empty.size(), 1u);
  EXPECT_EQ(empty[0].voxels, 0);
  auto bytes = encodeMagicaVoxel(VoxelGrid(Dims{300, 3, 3}));
  ASSERT_TRUE(bytes.ok());
  EXPECT_EQ(parse(*bytes).models.size(), 1u);
}

TEST(MagicaVoxel, aSceneOver2GiBIsRefusedBeforeAnythingIsWritten) {
  VoxelGrid g(Dims{830, 830, 830});  // 572 million filled voxels: 2.3 GB of XYZI entries
  for (int32_t z = 0; z < 830; ++z)
    for (int32_t y = 0; y < 830; ++y) g.fillRun(y, z, 0, 830);
  VectorSink sink;
  const Status s = writeMagicaVoxel(g, sink);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().code, ErrorCode::kLimit);
  EXPECT_NE(s.error().message.find("2 GiB"), std::string::npos) << s.error().message;
  EXPECT_NE(s.error().message.find("571787000 filled voxels"), std::string::npos) << s.error().message;
  EXPECT_TRUE(sink.bytes.empty());
}

}  // namespace
}  // namespace vox::io
