// voxmod projects (.vxp): an assembly's parts come back with their names, colours, visibility, placements, lattice and
// voxels; a peeled model with both its grids; and every kind of damaged project is refused naming the file.
#include "vox/io/project_file.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/zip_package.h"
#include "support/test_support.h"
#include "vox/core/feeder.h"
#include "vox/io/voxel_file.h"

namespace vox::io {
namespace {

VoxelGrid block(Dims d, const GridFrame& f, int32_t margin) {
  VoxelGrid g(d, f);
  for (int32_t z = margin; z < d.nz - margin; ++z)
    for (int32_t y = margin; y < d.ny - margin; ++y)
      for (int32_t x = margin; x < d.nx - margin; ++x) g.set(x, y, z);
  return g;
}

ProjectFile assemblyProject() {
  Lattice lattice{{-2.5, 1.0, 0.25}, 0.5, "mm"};
  Assembly parts(lattice);
  parts.addPart(LatticeGrid{block({6, 5, 4}, lattice.frameAt({0, 0, 0}), 0), {0, 0, 0}}, "bolt");
  const size_t nut = parts.addPart(LatticeGrid{block({7, 7, 3}, lattice.frameAt({3, -2, 5}), 1), {3, -2, 5}}, "nut");
  parts.part(nut).colour = {0.1f, 0.9f, 0.25f};
  parts.part(nut).visible = false;
  parts.setPlacement(nut, PartPlacement{{4, 0, -1}, {0, 1, 3}});
  ProjectFile p;
  p.source = "/parts/as1-oc-214.stp";
  p.origin = "2 parts on one lattice";
  p.resolution = 200;
  p.units = "mm";
  p.parts = std::move(parts);
  p.panel = "parts";
  p.section_axis = "y";
  p.section_index = 3;
  p.selected = {1};
  return p;
}

TEST(ProjectFile, anAssemblysPartsComeBackWithNamesColoursVisibilityAndPlacements) {
  const ProjectFile p = assemblyProject();
  auto bytes = encodeProject(p, "a.vxp");
  ASSERT_TRUE(bytes.ok()) << bytes.error().message;
  auto back = decodeProject(*bytes, "a.vxp");
  ASSERT_TRUE(back.ok()) << back.error().message;
  EXPECT_EQ(back->source, p.source);
  EXPECT_EQ(back->origin, p.origin);
  EXPECT_EQ(back->resolution, 200);
  EXPECT_EQ(back->units, "mm");
  EXPECT_EQ(back->panel, "parts");
  EXPECT_EQ(back->section_axis, "y");
  EXPECT_EQ(back->section_index, 3);
  EXPECT_EQ(back->selected, std::vector<size_t>{1});
  EXPECT_TRUE(back->base.empty()) << "with parts and nothing peeled the union is made again, not stored";
  ASSERT_TRUE(back->parts.has_value());
  const Assembly& a = *back->parts;
  EXPECT_EQ(a.lattice(), p.parts->lattice());
  ASSERT_EQ(a.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const Part& want = p.parts->part(i);
    const Part& got = a.part(i);
    EXPECT_EQ(got.name, want.name);
    EXPECT_EQ(got.colour, want.colour);
    EXPECT_EQ(got.visible, want.visible);
    EXPECT_EQ(got.placement, want.placement);
    EXPECT_EQ(got.voxels.first, want.voxels.first);
    EXPECT_TRUE(got.voxels.grid.sameVoxels(want.voxels.grid)) << want.name;
    EXPECT_EQ(got.voxels.grid.frame().origin, want.voxels.grid.frame().origin);
    EXPECT_EQ(a.placedVoxels(i).box(), p.parts->placedVoxels(i).box());
  }
}

TEST(ProjectFile, aPeeledModelKeepsBothGridsAndItsPeels) {
  GridFrame f;
  f.origin = {1.0, 2.0, 3.0};
  f.voxel_size = 0.25;
  f.units = "in";
  ProjectFile p;
  p.units = "in";
  p.base = block({9, 8, 7}, f, 0);
  p.shown = block({9, 8, 7}, f, 2);
  p.peeled = 2;
  p.round_peels = "0.5 in";
  test::TempDir dir;
  ASSERT_TRUE(saveProject(p, dir / "m.vxp").ok());
  auto back = loadProject(dir / "m.vxp");
  ASSERT_TRUE(back.ok()) << back.error().message;
  EXPECT_FALSE(back->parts.has_value());
  EXPECT_EQ(back->peeled, 2);
  EXPECT_EQ(back->round_peels, "0.5 in");
  EXPECT_TRUE(back->base.sameVoxels(p.base));
  EXPECT_TRUE(back->shown.sameVoxels(p.shown));
  EXPECT_EQ(back->base.frame().units, "in");
  EXPECT_EQ(back->shown.frame().origin, f.origin);
}

// The project's entries, each replaced or dropped by `edit`, zipped again.
std::vector<uint8_t> edited(const std::function<void(std::vector<ZipEntry>&)>& edit) {
  auto bytes = encodeProject(assemblyProject(), "a.vxp");
  auto entries = readZip(*bytes, "a.vxp", "voxmod project", 1 << 30);
  edit(*entries);
  return *writeZip(*entries, "a.vxp", false);
}

void setManifest(std::vector<ZipEntry>& entries, const std::string& text) {
  for (ZipEntry& e : entries) {
    if (e.name == "project.json") e.bytes.assign(text.begin(), text.end());
  }
}

std::string manifestOf(const std::vector<ZipEntry>& entries) {
  for (const ZipEntry& e : entries) {
    if (e.name == "project.json") return std::string(e.bytes.begin(), e.bytes.end());
  }
  return {};
}

void expectRefused(const std::vector<uint8_t>& bytes, ErrorCode code, const std::string& words) {
  auto r = decodeProject(bytes, "broken.vxp");
  ASSERT_FALSE(r.ok()) << "expected: " << words;
  EXPECT_EQ(r.error().code, code) << r.error().message;
  EXPECT_NE(r.error().message.find("broken.vxp"), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find(words), std::string::npos) << r.error().message;
}

TEST(ProjectFile, damagedProjectsAreRefusedNamingTheFileAndTheProblem) {
  const std::string text = "not a zip at all";
  expectRefused({text.begin(), text.end()}, ErrorCode::kParse, "not a voxmod project: it is not a zip archive");
  expectRefused(edited([](auto& e) { std::erase_if(e, [](const ZipEntry& z) { return z.name == "project.json"; }); }),
                ErrorCode::kParse, "holds no project.json");
  expectRefused(edited([](auto& e) { setManifest(e, "{ \"format\": "); }), ErrorCode::kParse, "is not JSON");
  expectRefused(edited([](auto& e) { setManifest(e, "[1, 2]"); }), ErrorCode::kParse, "not a JSON object");
  expectRefused(edited([](auto& e) { setManifest(e, "1E11111"); }), ErrorCode::kParse, "is not JSON");  // fuzzer
  expectRefused(edited([](auto& e) { setManifest(e, "{\"format\": \"something else\"}"); }), ErrorCode::kParse,
                "not a voxmod project");
  expectRefused(edited([](auto& e) {
                  std::string m = manifestOf(e);
                  m.replace(m.find("\"version\": 1"), 12, "\"version\": 7");
                  setManifest(e, m);
                }),
                ErrorCode::kUnsupported, "version 7");
  expectRefused(edited([](auto& e) { std::erase_if(e, [](const ZipEntry& z) { return z.name == "parts/002.vxm"; }); }),
                ErrorCode::kParse, "does not hold it");
  expectRefused(edited([](auto& e) {
                  std::string m = manifestOf(e);
                  m.replace(m.find("\"name\": \"nut\""), 13, "\"name\": 12");
                  setManifest(e, m);
                }),
                ErrorCode::kParse, "'name' is not text");
  expectRefused(edited([](auto& e) {
                  for (ZipEntry& z : e) {
                    if (z.name == "parts/001.vxm") z.bytes.resize(z.bytes.size() / 2);
                  }
                }),
                ErrorCode::kParse, "parts/001.vxm");
}

// A casting's feeder is a part that remembers its cylinder: it comes back as a feeder, moved with its placement; a
// feeder whose size is not positive, or a turned one, is refused.
TEST(ProjectFile, aFeederPartComesBackAsAFeeder) {
  ProjectFile p = assemblyProject();
  const Feeder feeder{{-1.0, 2.0, 2.25}, 2.0, 3.0};
  auto voxels = feederVoxels(feeder, p.parts->lattice());
  ASSERT_TRUE(voxels.ok()) << voxels.error().message;
  const size_t k = p.parts->addPart(std::move(voxels).value(), "feeder 1");
  p.parts->part(k).feeder = feeder;
  p.parts->setPlacement(k, PartPlacement{{2, 0, 0}, {0, 0, 0}});
  auto bytes = encodeProject(p, "f.vxp");
  ASSERT_TRUE(bytes.ok()) << bytes.error().message;
  auto back = decodeProject(*bytes, "f.vxp");
  ASSERT_TRUE(back.ok()) << back.error().message;
  ASSERT_EQ(back->parts->size(), 3u);
  EXPECT_FALSE(back->parts->part(0).feeder.has_value());
  ASSERT_TRUE(back->parts->part(k).feeder.has_value());
  EXPECT_EQ(*back->parts->part(k).feeder, feeder);
  const std::optional<Feeder> placed = back->parts->placedFeeder(k);
  ASSERT_TRUE(placed.has_value());
  EXPECT_DOUBLE_EQ(placed->base.x, feeder.base.x + 2 * 0.5);

  const auto refused = [&](const std::function<void(nlohmann::json&)>& edit, const std::string& words) {
    auto entries = readZip(*bytes, "f.vxp", "voxmod project", 1 << 30);
    nlohmann::json m = nlohmann::json::parse(manifestOf(*entries));
    edit(m["parts"]["list"][k]);
    setManifest(*entries, m.dump(2));
    expectRefused(*writeZip(*entries, "broken.vxp", false), ErrorCode::kParse, words);
  };
  refused([](nlohmann::json& f) { f["feeder"]["diameter"] = -2.0; }, "'diameter' is not a positive number");
  refused([](nlohmann::json& f) { f["feeder"]["height"] = 0.0; }, "'height' is not a positive number");
  refused([](nlohmann::json& f) { f["feeder"] = 5; }, "'feeder' is not a JSON object");
  refused([](nlohmann::json& f) { f["feeder"].erase("base"); }, "no 'base'");
  refused([](nlohmann::json& f) { f["quarter_turns"] = {1, 0, 0}; }, "a feeder stands upright");
}

// Values a reader must not take on trust: each is refused before any grid is allocated from it.
TEST(ProjectFile, absurdValuesAreRefusedBeforeAnythingIsAllocated) {
  const auto replaced = [](const std::string& from, const std::string& to) {
    return edited([&](auto& e) {
      std::string m = manifestOf(e);
      const size_t at = m.find(from);
      ASSERT_NE(at, std::string::npos) << from;
      m.replace(at, from.size(), to);
      setManifest(e, m);
    });
  };
  // A move of a billion voxels (the union would be a grid of a billion layers).
  expectRefused(replaced("\"translation\": [\n          4,", "\"translation\": [\n          1000000000,"),
                ErrorCode::kParse, "'translation' is 1000000000, outside");
  // A coordinate as a float, or past 32 bits, never cast to an integer.
  expectRefused(replaced("\"first\": [\n          3,", "\"first\": [\n          1e10,"), ErrorCode::kParse,
                "'first' is not a whole number");
  expectRefused(replaced("\"section_index\": 3", "\"section_index\": 4294967296"), ErrorCode::kParse,
                "'section_index' is 4294967296, outside");
  // Peeled without the grids a peel needs.
  expectRefused(replaced("\"peeled\": 0", "\"peeled\": 2"), ErrorCode::kParse, "no base grid");
  // A selected part that is not there.
  expectRefused(replaced("\"selected_parts\": [\n      2\n    ]", "\"selected_parts\": [\n      9\n    ]"),
                ErrorCode::kParse, "'selected_parts' is 9, outside 1..2");
}

// The memory limit holds for all the grids together: many parts naming one small file of a large grid.
TEST(ProjectFile, theMemoryLimitIsForAllTheGridsTogether) {
  ProjectFile p = assemblyProject();
  auto bytes = encodeProject(p, "a.vxp");
  ASSERT_TRUE(bytes.ok());
  const uint64_t one = estimateGridBytes(p.parts->part(1).voxels.grid.dims());
  // Enough for each grid alone and for the union, not for all of them at once.
  ASSERT_TRUE(decodeProject(*bytes, "a.vxp", 64 * one).ok());
  auto r = decodeProject(*bytes, "a.vxp", one + one / 2);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kLimit) << r.error().message;
  EXPECT_NE(r.error().message.find("more than the"), std::string::npos) << r.error().message;
}

// A manifest nested very deep is refused without exhausting the stack.
TEST(ProjectFile, aDeeplyNestedManifestIsRefused) {
  std::string deep(200000, '[');
  deep += std::string(200000, ']');
  const std::vector<uint8_t> bytes = edited([&](auto& e) {
    std::string m = manifestOf(e);
    m.replace(m.find("\"round_peels\": \"\""), 17, "\"round_peels\": " + deep);
    setManifest(e, m);
  });
  expectRefused(bytes, ErrorCode::kParse, "'round_peels' is not text");
}

}  // namespace
}  // namespace vox::io
