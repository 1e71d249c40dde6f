// voxmod voxelize under `mpirun --oversubscribe -np 3` (docs/conventions.md, "Voxelizing over MPI ranks"): the
// slabs of one grid spread over the ranks give one .vxm file, byte for byte the one process's streamed file (and
// its in-memory file); a failure exits 2 with one message from rank 0 and leaves no file, nor a temporary one.
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/mpirun_support.h"
#include "support/test_support.h"

namespace vox {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using test::mpirunArgs;
using test::readFile;
using test::runProgram;
using test::runVoxmod;
using test::TempDir;

// A closed torus (major radius 3, minor 1, tilted so no facet lies along the grid) as an ASCII STL.
std::string torusStl(int around, int across) {
  auto point = [&](int i, int j) {
    const double u = 2 * M_PI * i / around, v = 2 * M_PI * j / across;
    const double x = (3 + std::cos(v)) * std::cos(u), y = (3 + std::cos(v)) * std::sin(u), z = std::sin(v);
    return std::vector<double>{x, 0.8 * y - 0.6 * z, 0.6 * y + 0.8 * z};
  };
  std::ostringstream s;
  s.precision(17);
  s << "solid torus\n";
  auto facet = [&](const std::vector<double>& a, const std::vector<double>& b, const std::vector<double>& c) {
    s << "facet normal 0 0 0\nouter loop\n";
    for (const auto* p : {&a, &b, &c}) s << "vertex " << (*p)[0] << ' ' << (*p)[1] << ' ' << (*p)[2] << '\n';
    s << "endloop\nendfacet\n";
  };
  for (int i = 0; i < around; ++i) {
    for (int j = 0; j < across; ++j) {
      const auto a = point(i, j), b = point(i + 1, j), c = point(i + 1, j + 1), d = point(i, j + 1);
      facet(a, b, c);
      facet(a, c, d);
    }
  }
  s << "endsolid torus\n";
  return s.str();
}

std::vector<std::string> under3Ranks(const std::vector<std::string>& voxmod_args) {
  std::vector<std::string> args = mpirunArgs(3);
  args.insert(args.end(), voxmod_args.begin(), voxmod_args.end());
  return args;
}

// `mesh` at `res`: in memory, streamed by one process under `limit`, and under mpirun -np 3 with the same limit
// (several slabs per rank) and without it (one slab per rank): the same file, byte for byte, and the same report.
void expectOneFileOverRanks(const std::string& mesh, const std::string& res, const std::string& limit,
                            const std::vector<std::string>& options = {}) {
  SCOPED_TRACE(mesh);
  TempDir tmp;
  const std::string mem = (tmp / "mem.vxm").string(), one = (tmp / "one.vxm").string();
  const std::string ranks = (tmp / "ranks.vxm").string(), fits = (tmp / "fits.vxm").string();
  auto with = [&](std::vector<std::string> args) {
    args.insert(args.end(), options.begin(), options.end());
    return args;
  };
  auto a = runVoxmod(with({"voxelize", mesh, "--res", res, "-o", mem, "--json"}));
  auto b = runVoxmod(with({"voxelize", mesh, "--res", res, "-o", one, "--json", "--memory-limit", limit}));
  auto c =
      runProgram(under3Ranks(with({"voxelize", mesh, "--res", res, "-o", ranks, "--json", "--memory-limit", limit})));
  auto d = runProgram(under3Ranks(with({"voxelize", mesh, "--res", res, "-o", fits, "--json"})));
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  ASSERT_EQ(c.exit_code, 0) << c.out << c.err;
  ASSERT_EQ(d.exit_code, 0) << d.out << d.err;
  const json ja = json::parse(a.out), jb = json::parse(b.out), jc = json::parse(c.out), jd = json::parse(d.out);
  ASSERT_TRUE(jb["streamed"].get<bool>());
  ASSERT_TRUE(jc["streamed"].get<bool>());
  EXPECT_EQ(jc["ranks"], 3);
  EXPECT_EQ(jc["peak_rss_bytes_per_rank"].size(), 3u);
  EXPECT_EQ(jc["slabs"], jb["slabs"]);
  EXPECT_EQ(jc["slab_layers"], jb["slab_layers"]);
  EXPECT_GE(jc["slabs"].get<int>(), 6) << "several slabs per rank";
  EXPECT_EQ(jd["slabs"], 3) << "one slab per rank when the grid fits";
  for (const char* key : {"dims", "voxel_size", "origin", "filled", "volume", "mode", "mode_reason", "warnings"}) {
    EXPECT_EQ(jc[key], jb[key]) << key;
    EXPECT_EQ(jd[key], ja[key]) << key;
  }
  const std::string bytes = readFile(one);
  EXPECT_TRUE(readFile(ranks) == bytes) << "the file of 3 ranks differs from the one process's";
  EXPECT_TRUE(readFile(fits) == bytes) << "the file of 3 ranks (one slab each) differs";
  EXPECT_TRUE(readFile(mem) == bytes) << "the streamed file differs from the in-memory one";
  // One report, from rank 0.
  EXPECT_EQ(c.out.find('\n'), c.out.size() - 1) << c.out;
}

TEST(CliVoxelizeMpi, slabsOverThreeRanksMakeTheOneProcessFile) {
  VOX_REQUIRE_MPI();
  TempDir tmp;
  test::writeFile(tmp / "torus.stl", torusStl(48, 24));
  expectOneFileOverRanks((tmp / "torus.stl").string(), "160", "8K");
  expectOneFileOverRanks((test::sourceDir() / "models/featuretype.stl").string(), "120", "1K", {"--mode", "parity"});
}

TEST(CliVoxelizeMpi, sharedMeshOverThreeRanksMakesTheOneProcessFile) {
  VOX_REQUIRE_MPI();
  VOX_REQUIRE_SHARED(shared);
  expectOneFileOverRanks((shared / "meshes/armadillo.stl").string(), "300", "1M");
  // An open mesh in nonzero mode: the warnings about its rays count every rank's rays, as one process counts them.
  expectOneFileOverRanks((shared / "meshes/stanford_bunny.stl").string(), "300", "1M", {"--mode", "nonzero"});
}

// What cannot be spread (vote mode, a .binvox output) rank 0 does alone, as one process does it.
TEST(CliVoxelizeMpi, whatCannotBeSpreadRankZeroDoesAlone) {
  VOX_REQUIRE_MPI();
  TempDir tmp;
  const std::string mesh = (test::sourceDir() / "models/featuretype.stl").string();
  for (const std::vector<std::string>& more : std::vector<std::vector<std::string>>{
           {"-o", "@.binvox"}, {"-o", "@.vxm", "--mode", "vote"}, {"-o", "@.vxm", "--remove-strays"}}) {
    std::vector<std::string> args = {"voxelize", mesh, "--res", "80"};
    for (const std::string& m : more) args.push_back(m[0] == '@' ? (tmp / ("one" + m.substr(1))).string() : m);
    const auto one = runVoxmod(args);
    std::vector<std::string> mpi_args = args;
    mpi_args[5] = (tmp / ("ranks" + fs::path(args[5]).extension().string())).string();
    const auto ranks = runProgram(under3Ranks(mpi_args));
    ASSERT_EQ(one.exit_code, 0) << one.err;
    ASSERT_EQ(ranks.exit_code, 0) << ranks.err;
    EXPECT_TRUE(readFile(args[5]) == readFile(mpi_args[5])) << args[5];
    EXPECT_NE(ranks.out.find("wrote"), std::string::npos) << ranks.out;
    EXPECT_EQ(ranks.out.find("wrote"), ranks.out.rfind("wrote")) << "one report, from rank 0: " << ranks.out;
  }
}

// A malformed mesh, an output directory that is not one, a disk that fills up in the middle (the other ranks still
// voxelizing): exit 2, one message naming the file and the problem, no file and no temporary file left.
TEST(CliVoxelizeMpi, aFailureExitsTwoAndLeavesNoFile) {
  VOX_REQUIRE_MPI();
  TempDir tmp;
  test::writeFile(tmp / "torus.stl", torusStl(48, 24));
  const std::string torus = (tmp / "torus.stl").string();
  const std::string bad = (test::sourceDir() / "tests/data/malformed/binary_truncated.stl").string();
  fs::create_directories(tmp / "out");
  auto r = runProgram(under3Ranks({"voxelize", bad, "--res", "100", "-o", (tmp / "out/bad.vxm").string(), "--json"}));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("binary_truncated.stl: binary STL truncated"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("voxmod: error:"), r.err.rfind("voxmod: error:")) << "one message: " << r.err;
  EXPECT_TRUE(json::parse(r.out).contains("error")) << r.out;
  test::writeFile(tmp / "file", "not a directory");
  r = runProgram(
      under3Ranks({"voxelize", torus, "--res", "100", "-o", (tmp / "file/t.vxm").string(), "--memory-limit", "8K"}));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("file/t.vxm: cannot create a temporary file"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("voxmod: error:"), r.err.rfind("voxmod: error:")) << "one message: " << r.err;
  EXPECT_TRUE(fs::is_empty(tmp / "out"));

  // A 48 KiB tmpfs in a private mount namespace: the torus at R = 400 (about 190 KB) does not fit.
  if (std::system("unshare -m true >/dev/null 2>&1") != 0) GTEST_SKIP() << "unshare -m not permitted here";
  fs::create_directories(tmp / "small");
  std::string command = "mount -t tmpfs -o size=48k tmpfs '" + (tmp / "small").string() + "' && echo old > '" +
                        (tmp / "small/t.vxm").string() + "' &&";
  for (const std::string& a :
       under3Ranks({"voxelize", torus, "--res", "400", "-o", (tmp / "small/t.vxm").string(), "--memory-limit", "64K"}))
    command += " '" + a + "'";
  command +=
      "; code=$?; ls -a '" + (tmp / "small").string() + "'; cat '" + (tmp / "small/t.vxm").string() + "'; exit $code";
  r = runProgram({"unshare", "-m", "sh", "-c", command});
  if (r.exit_code != 2 && r.err.find("mount") != std::string::npos) GTEST_SKIP() << "tmpfs mount refused: " << r.err;
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, ".\n..\nt.vxm\nold\n") << "the old file stays, and no temporary file";
}

}  // namespace
}  // namespace vox
