// Grids larger than memory (docs/file-format.md, "Streamed .vxm files"): voxelize in Z slabs, and info, section,
// xray, mass and convert to .binvox reading a .vxm file in windows, forced with a small --memory-limit on grids
// that fit, give exactly what the in-memory paths give.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/test_support.h"

namespace vox {
namespace {

using test::readFile;
using test::runVoxmod;
using test::TempDir;
using json = nlohmann::json;

class CliStream : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return (tmp_ / name).string(); }
  static std::string model(const std::string& name) { return (test::sourceDir() / "models" / name).string(); }

  // Voxelizes `mesh` in memory and streamed (in slabs under `limit`) and expects the same file, byte for byte.
  void expectSameVoxelization(const std::string& mesh, const std::vector<std::string>& options,
                              const std::string& limit) {
    std::vector<std::string> mem = {"voxelize", mesh, "-o", path("mem.vxm"), "--json"};
    mem.insert(mem.end(), options.begin(), options.end());
    std::vector<std::string> str = {"voxelize", mesh, "-o", path("str.vxm"), "--json", "--memory-limit", limit};
    str.insert(str.end(), options.begin(), options.end());
    const auto a = runVoxmod(mem), b = runVoxmod(str);
    ASSERT_EQ(a.exit_code, 0) << a.err;
    ASSERT_EQ(b.exit_code, 0) << b.err;
    const json ja = json::parse(a.out), jb = json::parse(b.out);
    EXPECT_FALSE(ja["streamed"].get<bool>()) << mesh;
    ASSERT_TRUE(jb["streamed"].get<bool>()) << mesh;
    EXPECT_GT(jb["slabs"].get<int>(), 1) << mesh;
    for (const char* key : {"dims", "voxel_size", "origin", "filled", "volume", "mode", "mode_reason", "warnings"}) {
      EXPECT_EQ(ja[key], jb[key]) << mesh << ": " << key;
    }
    EXPECT_TRUE(readFile(path("mem.vxm")) == readFile(path("str.vxm"))) << mesh << ": the files differ";
  }

  TempDir tmp_;
};

TEST_F(CliStream, streamedVoxelizationIsTheInMemoryOneByteForByte) {
  for (const char* name : {"featuretype.stl", "plate_holes.stl", "cube_rotated_45z.stl", "tray_bottom_ascii.stl"}) {
    SCOPED_TRACE(name);
    expectSameVoxelization(model(name), {"--res", "200"}, "8K");
  }
  // Parity mode, and slabs of one layer (a limit the mesh alone exceeds).
  expectSameVoxelization(model("featuretype.stl"), {"--res", "120", "--mode", "parity"}, "1K");
}

TEST_F(CliStream, voteModeAndBinvoxOutputAreNotStreamedButSaySo) {
  auto vote = runVoxmod({"voxelize", model("featuretype.stl"), "--res", "200", "--mode", "vote", "-o", path("v.vxm"),
                         "--memory-limit", "64K"});
  EXPECT_EQ(vote.exit_code, 2);
  EXPECT_NE(vote.err.find("vote"), std::string::npos) << vote.err;
  auto binvox = runVoxmod(
      {"voxelize", model("featuretype.stl"), "--res", "200", "-o", path("v.binvox"), "--memory-limit", "64K"});
  EXPECT_EQ(binvox.exit_code, 2);
  EXPECT_NE(binvox.err.find(".vxm"), std::string::npos) << binvox.err;
  EXPECT_FALSE(std::filesystem::exists(path("v.vxm")));
  EXPECT_FALSE(std::filesystem::exists(path("v.binvox")));
  auto bad = runVoxmod({"info", model("featuretype.stl"), "--memory-limit", "lots"});
  EXPECT_EQ(bad.exit_code, 1) << bad.err;
}

// The JSON of a reader without the keys that say how it read (and the output names, which differ).
json comparable(const std::string& out) {
  json j = json::parse(out);
  for (const char* key : {"notes", "memory_bytes", "streamed", "output", "csv"}) j.erase(key);
  return j;
}

TEST_F(CliStream, readersInWindowsGiveTheInMemoryResults) {
  auto v = runVoxmod({"voxelize", model("featuretype.stl"), "--res", "200", "-o", path("part.vxm"), "--units", "mm"});
  ASSERT_EQ(v.exit_code, 0) << v.err;
  const std::string part = path("part.vxm");
  const std::vector<std::vector<std::string>> commands = {
      {"info"},
      {"mass", "--material", "aluminium"},
      {"section", "--axis", "x", "--index", "57", "-o", "@.png"},
      {"section", "--axis", "y", "--index", "20", "-o", "@.png"},
      {"section", "--axis", "z", "--index", "11", "-o", "@.png"},
      {"xray", "--axis", "x", "--mode", "max", "-o", "@.png", "--csv", "@.csv"},
      {"xray", "--axis", "y", "--mode", "min", "-o", "@.png", "--csv", "@.csv"},
      {"xray", "--axis", "z", "--mode", "total", "-o", "@.png", "--csv", "@.csv"},
      {"xray", "--axis", "z", "--mode", "min", "-o", "@.png"},
      {"xray", "--axis", "z", "--mode", "max", "-o", "@.png"},
  };
  for (const auto& command : commands) {
    std::string line;
    for (const auto& w : command) line += w + " ";
    SCOPED_TRACE(line);
    auto args = [&](const std::string& tag, bool streamed) {
      std::vector<std::string> a = {command[0], part, "--json"};
      for (size_t i = 1; i < command.size(); ++i) {
        std::string w = command[i];
        if (w[0] == '@') w = path(tag + w.substr(1));
        a.push_back(w);
      }
      if (streamed) a.insert(a.end(), {"--memory-limit", "64K"});
      return a;
    };
    const auto mem = runVoxmod(args("mem", false)), str = runVoxmod(args("str", true));
    ASSERT_EQ(mem.exit_code, 0) << mem.err;
    ASSERT_EQ(str.exit_code, 0) << str.err;
    EXPECT_NE(str.err.find("windows"), std::string::npos) << str.err;
    EXPECT_EQ(comparable(mem.out), comparable(str.out));
    for (const char* ext : {".png", ".csv"}) {
      if (!std::filesystem::exists(path(std::string("mem") + ext))) continue;
      EXPECT_TRUE(readFile(path(std::string("mem") + ext)) == readFile(path(std::string("str") + ext))) << ext;
      std::filesystem::remove(path(std::string("mem") + ext));
      std::filesystem::remove(path(std::string("str") + ext));
    }
  }
  // .binvox, x-major: the streamed converter's bytes are the in-memory encoder's (here in four passes of 64, 64,
  // 64 and 8 x values).
  auto a = runVoxmod({"convert", part, path("mem.binvox")});
  ASSERT_EQ(a.exit_code, 0) << a.err;
  for (const char* limit : {"64K"}) {
    auto b = runVoxmod({"convert", part, path("str.binvox"), "--memory-limit", limit, "--json"});
    ASSERT_EQ(b.exit_code, 0) << b.err;
    EXPECT_TRUE(json::parse(b.out)["streamed"].get<bool>());
    EXPECT_TRUE(readFile(path("mem.binvox")) == readFile(path("str.binvox"))) << limit;
  }
}

TEST_F(CliStream, damagedFilesAreRefusedAsTheInMemoryReaderRefusesThem) {
  auto v = runVoxmod(
      {"voxelize", model("featuretype.stl"), "--res", "200", "-o", path("part.vxm"), "--memory-limit", "64K"});
  ASSERT_EQ(v.exit_code, 0) << v.err;
  const std::string bytes = readFile(path("part.vxm"));
  test::writeFile(path("short.vxm"), bytes.substr(0, bytes.size() - 100));
  std::string flipped = bytes;
  flipped[bytes.size() / 2] = char(flipped[bytes.size() / 2] ^ 0x10);
  test::writeFile(path("flipped.vxm"), flipped);
  for (const char* name : {"short.vxm", "flipped.vxm"}) {
    for (const char* command : {"info", "mass", "xray"}) {
      SCOPED_TRACE(std::string(command) + " " + name);
      std::vector<std::string> args = {command, path(name)};
      if (std::string(command) == "xray")
        args.insert(args.end(), {"--axis", "z", "--mode", "max", "-o", path("x.png")});
      const auto mem = runVoxmod(args);
      args.insert(args.end(), {"--memory-limit", "64K"});
      const auto str = runVoxmod(args);
      EXPECT_EQ(mem.exit_code, 2);
      EXPECT_EQ(str.exit_code, 2);
      EXPECT_NE(str.err.find(path(name)), std::string::npos) << str.err;
      EXPECT_NE(str.err.find(mem.err), std::string::npos) << mem.err << " / " << str.err;  // and a note
      EXPECT_FALSE(std::filesystem::exists(path("x.png")));
    }
  }
}

// The proof at scale: shared meshes at R = 1000, streamed in slabs of a few layers (CI only: minutes of work).
TEST_F(CliStream, sharedMeshesAtResolution1000StreamToTheSameFile) {
  VOX_REQUIRE_SHARED(shared);
  if (!test::inCI()) GTEST_SKIP() << "R = 1000 on the shared meshes runs in CI (CI=true) only";
  for (const char* name :
       {"armadillo.stl", "fandisk.stl", "rocker_arm.stl", "cycloidal_assembly.stl", "igea_refined_508k.stl"}) {
    SCOPED_TRACE(name);
    expectSameVoxelization((shared / "meshes" / name).string(), {"--res", "1000"}, "16M");
  }
}

}  // namespace
}  // namespace vox
