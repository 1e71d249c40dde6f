// voxmod casting (SPEC 10) as a user runs it: a 40 mm aluminium cube in sand with a large and a small feeder, every
// key, the fields and the section written all or none, and bad input refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/test_meshes.h"
#include "support/test_support.h"
#include "vox/io/stl.h"

namespace vox {
namespace {

using test::runVoxmod;

std::string cubeStl(const test::TempDir& dir) {
  const std::string stl = (dir / "cube.stl").string();
  EXPECT_TRUE(io::saveStlBinary(test::boxMesh({0, 0, 0}, {40, 40, 40}), stl).ok());
  return stl;
}

TEST(CliCasting, aCubeWithALargeFeederIsSoundAndEveryKeyIsThere) {
  test::TempDir dir;
  const std::string stl = cubeStl(dir);
  auto r = runVoxmod({"casting", stl, "--units", "mm", "--res", "20", "--alloy", "aluminium", "--superheat", "0",
                      "--feeder", "cylinder:20,20,40,40,80", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"alloy", "mould", "superheat_k", "solidification_s", "modulus_max", "hot_spots", "sound",
                          "feeders", "yield", "simulate_s"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["alloy"]["name"], "aluminium");
  EXPECT_DOUBLE_EQ(j["alloy"]["liquidus_c"].get<double>(), 660.3);
  for (const char* key : {"solidus_c", "density_kg_m3", "latent_heat_j_kg", "conductivity_w_mk", "specific_heat_j_kgk"})
    EXPECT_GT(j["alloy"][key].get<double>(), 0.0) << key;
  EXPECT_EQ(j["mould"]["name"], "silica-sand");
  EXPECT_DOUBLE_EQ(j["mould"]["temperature_c"].get<double>(), 20.0);
  EXPECT_NEAR(j["modulus_max"].get<double>(), 40.0 / 6.0, 0.1 * 40.0 / 6.0);  // a cube: its side / 6
  EXPECT_TRUE(j["sound"].get<bool>()) << j["verdict"];
  const auto& last = j["hot_spots"][0];
  EXPECT_TRUE(last["in_feeder"].get<bool>());
  for (const char* key : {"centre", "solidification_s", "modulus", "isolated", "in_feeder"})
    EXPECT_TRUE(last.contains(key)) << key;
  ASSERT_EQ(j["feeders"].size(), 1u);
  const auto& f = j["feeders"][0];
  EXPECT_NEAR(f["modulus"].get<double>(), 40.0 * 80.0 / (4 * 80.0 + 40.0), 1e-9);
  EXPECT_EQ(f["diameter"].get<double>(), 40.0);
  EXPECT_EQ(f["height"].get<double>(), 80.0);
  const double volume = f["volume"].get<double>();
  EXPECT_NEAR(j["yield"].get<double>(), 64000.0 / (64000.0 + volume), 1e-6);
  EXPECT_GT(j["solidification_s"].get<double>(), 60.0);
  EXPECT_LT(j["solidification_s"].get<double>(), 600.0);
}

TEST(CliCasting, aSmallFeederLeavesTheCubeUnsoundAndTheFilesAreWrittenTogether) {
  test::TempDir dir;
  const std::string stl = cubeStl(dir);
  const std::string time = (dir / "time.nrrd").string(), modulus = (dir / "modulus.vti").string(),
                    niyama = (dir / "niyama.nrrd").string(), png = (dir / "section.png").string();
  auto r = runVoxmod({"casting", stl, "--units", "mm", "--res", "20", "--alloy", "a356", "--feeder",
                      "cylinder:20,20,40,12,18", "-o", time, "--modulus", modulus, "--niyama", niyama, "--png", png,
                      "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j["sound"].get<bool>());
  EXPECT_FALSE(j["hot_spots"][0]["in_feeder"].get<bool>());
  EXPECT_TRUE(j["hot_spots"][0]["isolated"].get<bool>());
  EXPECT_NE(j["verdict"].get<std::string>().find("Not sound"), std::string::npos);
  for (const std::string& p : {time, modulus, niyama, png}) EXPECT_TRUE(std::filesystem::exists(p)) << p;

  for (const std::string& p : {time, modulus, niyama, png}) std::filesystem::remove(p);
  r = runVoxmod({"casting", stl, "--units", "mm", "--res", "20", "-o", time, "--png",
                 (dir / "missing" / "section.png").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_FALSE(std::filesystem::exists(time));
}

TEST(CliCasting, refusesAPartWithoutUnitsAndBadOptions) {
  test::TempDir dir;
  const std::string stl = cubeStl(dir);
  auto r = runVoxmod({"casting", stl, "--res", "20"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no length units"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("cube.stl"), std::string::npos) << r.err;
  const auto casting = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"casting", stl, "--units", "mm", "--res", "20"};
    args.insert(args.end(), extra.begin(), extra.end());
    return runVoxmod(args);
  };
  r = casting({"--alloy", "bronze"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("a356"), std::string::npos) << r.err;
  EXPECT_EQ(casting({"--mould", "clay"}).exit_code, 1);
  EXPECT_EQ(casting({"--feeder", "cylinder:1,2,3"}).exit_code, 1);
  EXPECT_EQ(casting({"--feeder", "cylinder:20,20,40,0.01,0.01"}).exit_code, 1);  // smaller than a voxel
  EXPECT_EQ(casting({"--feeder", "cylinder:1e10,0,0,10,10"}).exit_code, 1);      // far off
  r = casting({"--feeder", "cylinder:20,20,60,10,10"});                          // floating above the cube
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("does not touch the part"), std::string::npos) << r.err;
  EXPECT_EQ(casting({"-o", (dir / "t.stl").string()}).exit_code, 1);
  EXPECT_EQ(casting({"--mould-temperature", "900"}).exit_code, 1);
  EXPECT_EQ(casting({"--mould-temperature", "-500"}).exit_code, 1);
  r = casting({"--memory-limit", "1"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("needs about"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace vox
