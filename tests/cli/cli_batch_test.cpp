// voxmod batch (SPEC §8, docs/conventions.md "Batch"): every good input converted byte for byte as the one-file
// commands convert it, every bad one reported and the batch going on, exit 2 when any failed; a batch killed in the
// middle and resumed does nothing twice and leaves nothing missing or partial; under mpirun the outputs are those
// of one process; a full disk and an unusable output directory stop it with a clear message.
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli/mpirun_support.h"
#include "support/test_support.h"

namespace vox {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using test::mpiMissing;
using test::mpirunArgs;
using test::runProgram;
using test::runVoxmod;
using test::TempDir;

constexpr const char* kRes = "64";

std::vector<json> readReport(const fs::path& p) {
  std::vector<json> lines;
  std::ifstream f(p);
  std::string line;
  while (std::getline(f, line)) lines.push_back(json::parse(line));
  return lines;
}

std::vector<std::string> sharedMeshes(const fs::path& shared) {
  std::vector<std::string> meshes;
  for (const auto& e : fs::directory_iterator(shared / "meshes"))
    if (e.path().extension() == ".stl") meshes.push_back(e.path().string());
  std::sort(meshes.begin(), meshes.end());
  return meshes;
}

// A few files from the refusal corpus, each malformed in its own way and format.
std::vector<std::string> malformedFiles() {
  const fs::path dir = test::sourceDir() / "tests/data/malformed";
  std::vector<std::string> files;
  for (const char* name : {"binary_truncated.stl", "ascii_nan.stl", "not_zip.3mf", "truncated.step",
                           "ply_bad_index.ply", "vxm_crc_mismatch.vxm"})
    files.push_back((dir / name).string());
  return files;
}

// Every file below `dir` (relative path -> bytes), temporaries (".NAME.tmp-*") included.
std::map<std::string, std::string> filesBelow(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = test::readFile(e.path());
  return files;
}

bool isTemporary(const std::string& relative) { return relative.find(".tmp-") != std::string::npos; }

// What `voxmod voxelize MESH --res 64 -o OUT.binvox` writes for each shared mesh, by output name: the batch's
// reference, made once for the tests that need it.
const std::map<std::string, std::string>& voxelizeOneByOne(const std::vector<std::string>& meshes) {
  static std::map<std::string, std::string> expected;
  if (!expected.empty()) return expected;
  TempDir tmp;
  const fs::path dir = tmp.path();
  for (const std::string& mesh : meshes) {
    const std::string name = fs::path(mesh).stem().string() + ".binvox";
    auto r = runVoxmod({"voxelize", mesh, "--res", kRes, "-o", (dir / name).string()});
    EXPECT_EQ(r.exit_code, 0) << mesh << ": " << r.err;
    expected[name] = test::readFile(dir / name);
  }
  return expected;
}

// The report's lines, checked against the inputs: one per input, in input order, with SPEC §8's keys.
void expectReportInInputOrder(const std::vector<json>& report, const std::vector<std::string>& inputs) {
  ASSERT_EQ(report.size(), inputs.size());
  for (size_t i = 0; i < inputs.size(); ++i) {
    EXPECT_EQ(report[i]["input"], inputs[i]);
    for (const char* key : {"input", "status", "output", "dims", "filled", "warnings", "seconds", "error"})
      EXPECT_TRUE(report[i].contains(key)) << key << " in " << report[i].dump();
  }
}

std::vector<std::string> batchArgs(const std::vector<std::string>& inputs, const fs::path& outdir,
                                   const std::string& format, const std::vector<std::string>& more = {}) {
  std::vector<std::string> args = {"batch"};
  args.insert(args.end(), inputs.begin(), inputs.end());
  for (const std::string& a :
       {std::string("-o"), outdir.string(), std::string("--format"), format, std::string("--res"), std::string(kRes)})
    args.push_back(a);
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

TEST(CliBatch, convertsEveryGoodFileAsVoxelizeDoesAndReportsEveryBadOne) {
  VOX_REQUIRE_SHARED(shared);
  TempDir tmp;
  const std::vector<std::string> meshes = sharedMeshes(shared);
  ASSERT_GE(meshes.size(), 10u);
  const auto expected = voxelizeOneByOne(meshes);
  std::vector<std::string> inputs = meshes;
  const auto bad = malformedFiles();
  inputs.insert(inputs.begin() + 3, bad.begin(), bad.end());  // mixed in, not at the end

  auto r = runVoxmod(batchArgs(inputs, tmp / "out", "binvox", {"--report", (tmp / "report.jsonl").string(), "--json"}));
  EXPECT_EQ(r.exit_code, 2) << r.err;  // some failed
  const json summary = json::parse(r.out);
  EXPECT_EQ(summary["ok"], meshes.size());
  EXPECT_EQ(summary["failed"], bad.size());
  const auto report = readReport(tmp / "report.jsonl");
  expectReportInInputOrder(report, inputs);
  for (const json& line : report) {
    const std::string input = line["input"];
    if (std::find(bad.begin(), bad.end(), input) != bad.end()) {
      EXPECT_EQ(line["status"], "error") << input;
      EXPECT_TRUE(line["output"].is_null());
      const std::string error = line["error"];
      EXPECT_NE(error.find(fs::path(input).filename().string()), std::string::npos) << error;  // names the file
    } else {
      EXPECT_EQ(line["status"], "ok") << line.dump();
      EXPECT_TRUE(line["error"].is_null());
      EXPECT_EQ(line["dims"].size(), 3u);
    }
  }
  // Each output, byte for byte voxelize's (the inputs span two directories: the outputs mirror them).
  size_t compared = 0;
  for (const json& line : report) {
    if (line["status"] != "ok") continue;
    const std::string name = fs::path(line["input"].get<std::string>()).stem().string() + ".binvox";
    EXPECT_TRUE(test::readFile(line["output"].get<std::string>()) == expected.at(name)) << name << " differs";
    ++compared;
  }
  EXPECT_EQ(compared, expected.size());
  for (const auto& [name, bytes] : filesBelow(tmp / "out")) EXPECT_FALSE(isTemporary(name)) << name;
}

// Files of one directory that share a stem keep their extensions; different directories are mirrored below OUTDIR;
// .vxm outputs equal voxelize's too.
TEST(CliBatch, namesOutputsSoThatInputsNeverCollide) {
  TempDir tmp;
  const fs::path src = test::sourceDir();
  const std::vector<std::string> inputs = {
      (src / "tests/data/mesh/cube.obj").string(), (src / "tests/data/mesh/cube.off").string(),
      (src / "tests/data/mesh/cube_binary.ply").string(), (src / "models/featuretype.stl").string()};
  auto r = runVoxmod(batchArgs(inputs, tmp / "out", "vxm"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto written = filesBelow(tmp / "out");
  for (const char* name : {"tests/data/mesh/cube.obj.vxm", "tests/data/mesh/cube.off.vxm",
                           "tests/data/mesh/cube_binary.vxm", "models/featuretype.vxm", "report.jsonl"})
    EXPECT_TRUE(written.contains(name)) << name;
  ASSERT_EQ(runVoxmod({"voxelize", inputs[3], "--res", kRes, "-o", (tmp / "f.vxm").string()}).exit_code, 0);
  EXPECT_TRUE(written.at("models/featuretype.vxm") == test::readFile(tmp / "f.vxm"));
  // A file given twice is one error, not a second write of the same output.
  auto twice = runVoxmod(batchArgs({inputs[3], inputs[3]}, tmp / "twice", "vxm"));
  EXPECT_EQ(twice.exit_code, 2);
  const auto report = readReport(tmp / "twice/report.jsonl");
  ASSERT_EQ(report.size(), 2u);
  EXPECT_EQ(report[0]["status"], "ok");
  EXPECT_EQ(report[1]["status"], "error");
}

// Killed (SIGKILL) after a few outputs, then resumed: the outputs the journal lists are checked and skipped (same
// file, untouched), the rest converted; nothing missing, no temporary file left, every output voxelize's.
TEST(CliBatch, killedInTheMiddleAndResumedDoesNothingTwice) {
  VOX_REQUIRE_SHARED(shared);
  TempDir tmp;
  const std::vector<std::string> meshes = sharedMeshes(shared);
  const auto expected = voxelizeOneByOne(meshes);
  const fs::path out = tmp / "out";
  std::vector<std::string> args = batchArgs(meshes, out, "binvox", {"--jobs", "1", "--threads", "1"});
  args.insert(args.begin(), test::voxmodExecutable());
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    if (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr)) _exit(126);
    execv(argv[0], argv.data());
    _exit(127);
  }
  // Wait for three journal lines (three outputs complete), then kill.
  const fs::path journal = out / ".voxmod-batch.jsonl";
  for (int i = 0; i < 6000; ++i) {
    std::ifstream f(journal);
    const auto lines = std::count(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>(), '\n');
    if (lines >= 3) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_EQ(kill(pid, SIGKILL), 0);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the batch finished before it was killed";

  // What the killed batch left: complete outputs (temporaries aside), and the journal's list of them.
  std::map<std::string, struct stat> before;
  for (const auto& [name, bytes] : filesBelow(out)) {
    if (isTemporary(name) || !name.ends_with(".binvox")) continue;
    EXPECT_TRUE(bytes == expected.at(name)) << name << " is partial or wrong after the kill";
    stat((out / name).c_str(), &before[name]);
  }
  ASSERT_GE(before.size(), 3u);
  ASSERT_LT(before.size(), meshes.size());

  auto r = runVoxmod(batchArgs(meshes, out, "binvox", {"--resume", "--json"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto report = readReport(out / "report.jsonl");
  expectReportInInputOrder(report, meshes);
  size_t skipped = 0;
  for (const json& line : report) {
    const std::string name = fs::path(line["output"].get<std::string>()).filename().string();
    if (line["status"] == "skipped") {
      ++skipped;
      ASSERT_TRUE(before.contains(name)) << name << " skipped but not there before";
      struct stat now {};
      stat((out / name).c_str(), &now);
      EXPECT_EQ(now.st_ino, before[name].st_ino) << name << " was written again";
      EXPECT_EQ(now.st_mtim.tv_nsec, before[name].st_mtim.tv_nsec) << name << " was written again";
    } else {
      EXPECT_EQ(line["status"], "ok") << line.dump();
    }
  }
  // Every output the killed batch had journalled is skipped (an output renamed in place just before the kill, and
  // not yet journalled, is done again: the journal, not the file's presence, proves an output complete).
  EXPECT_GE(skipped, 3u);
  const auto after = filesBelow(out);
  for (const auto& [name, bytes] : expected) {
    ASSERT_TRUE(after.contains(name)) << name << " missing after the resume";
    EXPECT_TRUE(after.at(name) == bytes) << name;
  }
  for (const auto& [name, bytes] : after) EXPECT_FALSE(isTemporary(name)) << name << " left behind";
}

// --resume checks the output, not its presence: a damaged output (same size, one byte changed) and an output made
// with other settings are done again; a temporary left by a killed batch is removed.
TEST(CliBatch, resumeRedoesDamagedAndStaleOutputs) {
  TempDir tmp;
  const fs::path src = test::sourceDir();
  const std::vector<std::string> inputs = {(src / "models/featuretype.stl").string(),
                                           (src / "models/plate_holes.stl").string()};
  const fs::path out = tmp / "out";
  ASSERT_EQ(runVoxmod(batchArgs(inputs, out, "binvox")).exit_code, 0);
  const std::string good = test::readFile(out / "featuretype.binvox");
  std::string damaged = good;
  damaged[damaged.size() - 2] ^= 1;
  test::writeFile(out / "featuretype.binvox", damaged);
  // What a batch killed while writing leaves: a temporary beside the output (io::writeFileAtomic's name).
  test::writeFile(out / ".plate_holes.binvox.tmp-12345-0-678", "#binvox 1\ndim");
  auto r = runVoxmod(batchArgs(inputs, out, "binvox", {"--resume"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto report = readReport(out / "report.jsonl");
  EXPECT_EQ(report[0]["status"], "ok");  // damaged: done again
  EXPECT_EQ(report[1]["status"], "skipped");
  EXPECT_TRUE(test::readFile(out / "featuretype.binvox") == good);
  EXPECT_FALSE(fs::exists(out / ".plate_holes.binvox.tmp-12345-0-678")) << "a killed batch's temporary left behind";
  // Another resolution: every output is stale.
  std::vector<std::string> args = batchArgs(inputs, out, "binvox", {"--resume"});
  *std::find(args.begin(), args.end(), std::string(kRes)) = "32";
  ASSERT_EQ(runVoxmod(args).exit_code, 0);
  report = readReport(out / "report.jsonl");
  EXPECT_EQ(report[0]["status"], "ok");
  EXPECT_EQ(report[1]["status"], "ok");
}

// An output directory that cannot be made: one clear message, exit 2, every input reported as not converted.
TEST(CliBatch, unusableOutdirIsReportedForEveryInput) {
  TempDir tmp;
  test::writeFile(tmp / "a_file", "x");
  const std::vector<std::string> inputs = {(test::sourceDir() / "models/featuretype.stl").string(),
                                           (test::sourceDir() / "models/plate_holes.stl").string()};
  auto r = runVoxmod(
      batchArgs(inputs, tmp / "a_file/out", "binvox", {"--report", (tmp / "report.jsonl").string(), "--json"}));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("a_file/out"), std::string::npos) << r.err;
  const auto report = readReport(tmp / "report.jsonl");
  expectReportInInputOrder(report, inputs);
  for (const json& line : report) {
    EXPECT_EQ(line["status"], "error");
    EXPECT_NE(line["error"].get<std::string>().find("a_file/out"), std::string::npos);
  }
}

TEST(CliBatch, usageErrors) {
  TempDir tmp;
  const std::string mesh = (test::sourceDir() / "models/featuretype.stl").string();
  EXPECT_EQ(runVoxmod({"batch", mesh, "-o", (tmp / "o").string(), "--format", "png"}).exit_code, 1);
  EXPECT_EQ(runVoxmod({"batch", "-o", (tmp / "o").string(), "--format", "vxm"}).exit_code, 1);
  EXPECT_EQ(runVoxmod({"batch", mesh, "--list", mesh, "-o", (tmp / "o").string(), "--format", "vxm"}).exit_code, 1);
  // --list names the inputs; '#' lines and blank lines are skipped.
  test::writeFile(tmp / "list.txt", "# inputs\n\n" + mesh + "\n");
  auto r = runVoxmod(
      {"batch", "--list", (tmp / "list.txt").string(), "-o", (tmp / "o").string(), "--format", "vxm", "--res", kRes});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(tmp / "o/featuretype.vxm"));
}

// A disk that fills up (a small tmpfs in a private mount namespace, where unshare and mount are allowed): exit 2,
// the failing file and the ones not started reported, only complete files on the disk.
TEST(CliBatch, fullDiskStopsTheBatchWithOnlyCompleteFiles) {
  if (std::system("unshare -m true >/dev/null 2>&1") != 0) GTEST_SKIP() << "unshare -m not permitted here";
  TempDir tmp;
  const fs::path src = test::sourceDir();
  std::vector<std::string> inputs;
  for (const char* m : {"featuretype.stl", "plate_holes.stl", "tray_bottom_ascii.stl", "cube_rotated_45z.stl"})
    inputs.push_back((src / "models" / m).string());
  fs::create_directories(tmp / "small");
  std::string command =
      "mount -t tmpfs -o size=128k tmpfs '" + (tmp / "small").string() + "' && '" + test::voxmodExecutable() + "'";
  for (const std::string& a :
       batchArgs(inputs, tmp / "small/out", "stl", {"--report", (tmp / "r.jsonl").string(), "--jobs", "1"}))
    command += " '" + a + "'";
  command += "; code=$?; cp -a '" + (tmp / "small/out").string() + "' '" + (tmp / "copy").string() + "'; exit $code";
  auto r = runProgram({"unshare", "-m", "sh", "-c", command});
  if (r.exit_code != 2 && r.err.find("mount") != std::string::npos) GTEST_SKIP() << "tmpfs mount refused: " << r.err;
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
  const auto report = readReport(tmp / "r.jsonl");
  expectReportInInputOrder(report, inputs);
  for (const auto& [name, bytes] : filesBelow(tmp / "copy")) EXPECT_FALSE(isTemporary(name)) << name;
  // One file at a time, biggest first: tray_bottom's surface (49 KB) fits, featuretype's (89 KB) does not, and the
  // two after it are not started.
  size_t failed = 0, ok = 0;
  for (const json& line : report) {
    if (line["status"] == "ok") {
      ++ok;
      // A complete surface: what convert writes, byte for byte.
      const std::string input = line["input"];
      const std::string name = fs::path(input).stem().string() + ".stl";
      ASSERT_EQ(runVoxmod({"convert", input, (tmp / name).string(), "--res", kRes}).exit_code, 0);
      EXPECT_TRUE(test::readFile(tmp / "copy" / name) == test::readFile(tmp / name)) << name;
    } else {
      ++failed;
    }
  }
  EXPECT_GE(ok, 1u);
  EXPECT_GE(failed, 1u);
}

// The same batch under `mpirun --oversubscribe -np 3`: byte for byte the outputs and report lines of one process.
TEST(CliBatch, mpiRanksWriteWhatOneProcessWrites) {
  if (const std::string why = mpiMissing(); !why.empty()) {
    if (test::inCI()) FAIL() << why << " in CI";
    GTEST_SKIP() << why << "; skipping";
  }
  TempDir tmp;
  const fs::path src = test::sourceDir();
  std::vector<std::string> inputs;
  for (const char* m : {"models/featuretype.stl", "models/plate_holes.stl", "models/tray_bottom_ascii.stl",
                        "models/cube_rotated_45z.stl", "tests/data/mesh/cube.obj", "tests/data/malformed/ascii_nan.stl",
                        "tests/data/mesh/cube_binary.ply"})
    inputs.push_back((src / m).string());
  auto one = runVoxmod(batchArgs(inputs, tmp / "one", "binvox"));
  EXPECT_EQ(one.exit_code, 2) << one.err;
  std::vector<std::string> args = mpirunArgs(3);
  for (const std::string& a : batchArgs(inputs, tmp / "mpi", "binvox", {"--json"})) args.push_back(a);
  auto r = runProgram(args);
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.out.find("\"ranks\":3"), std::string::npos) << r.out;
  auto a = filesBelow(tmp / "one"), b = filesBelow(tmp / "mpi");
  a.erase("report.jsonl"), b.erase("report.jsonl");
  a.erase(".voxmod-batch.jsonl"), b.erase(".voxmod-batch.jsonl");
  ASSERT_EQ(a.size(), 6u);
  ASSERT_EQ(a.size(), b.size());
  for (const auto& [name, bytes] : a) EXPECT_TRUE(b.contains(name) && b.at(name) == bytes) << name;
  auto ra = readReport(tmp / "one/report.jsonl"), rb = readReport(tmp / "mpi/report.jsonl");
  ASSERT_EQ(ra.size(), rb.size());
  for (size_t i = 0; i < ra.size(); ++i) {
    ra[i].erase("seconds"), rb[i].erase("seconds"), ra[i].erase("output"), rb[i].erase("output");
    EXPECT_EQ(ra[i], rb[i]) << i;
  }
}

// A rank killed (SIGKILL) in the middle of an MPI batch: the job ends with an error, the report lists the files
// finished before (each complete), no other file is there, and --resume converts the rest without redoing those.
TEST(CliBatch, mpiRankKilledInTheMiddleThenResumed) {
  VOX_REQUIRE_SHARED(shared);
  if (const std::string why = mpiMissing(); !why.empty()) {
    if (test::inCI()) FAIL() << why << " in CI";
    GTEST_SKIP() << why << "; skipping";
  }
  TempDir tmp;
  // The shared meshes three times over (links in three directories): enough work to kill a rank in the middle.
  std::vector<std::string> inputs;
  for (const char* copy : {"a", "b", "c"}) {
    fs::create_directories(tmp / "in" / copy);
    for (const std::string& mesh : sharedMeshes(shared)) {
      const fs::path link = tmp / "in" / copy / fs::path(mesh).filename();
      fs::create_symlink(mesh, link);
      inputs.push_back(link.string());
    }
  }
  const fs::path out = tmp / "out";
  std::vector<std::string> args = mpirunArgs(3);
  for (const std::string& a : batchArgs(inputs, out, "binvox", {"--threads", "1"})) args.push_back(a);
  std::fflush(nullptr);
  const pid_t mpirun = fork();
  if (mpirun == 0) {
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    if (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr)) _exit(126);
    execvp(argv[0], argv.data());
    _exit(127);
  }
  const fs::path journal = out / ".voxmod-batch.jsonl";
  for (int i = 0; i < 6000; ++i) {
    std::ifstream f(journal);
    if (std::count(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>(), '\n') >= 3) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  // The last rank mpirun started (its children are the ranks, in rank order).
  auto ranks = runProgram({"pgrep", "-P", std::to_string(mpirun)});
  std::istringstream pids(ranks.out);
  std::vector<pid_t> children;
  for (pid_t p; pids >> p;) children.push_back(p);
  ASSERT_EQ(children.size(), 3u) << ranks.out;
  ASSERT_EQ(kill(*std::max_element(children.begin(), children.end()), SIGKILL), 0);
  int status = 0;
  waitpid(mpirun, &status, 0);
  ASSERT_FALSE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "the batch finished before a rank was killed";

  // The report lists the files finished, each complete; nothing else is there but temporaries.
  const auto report = readReport(out / "report.jsonl");
  ASSERT_GE(report.size(), 3u);
  ASSERT_LT(report.size(), inputs.size());
  const auto& expected = voxelizeOneByOne(sharedMeshes(shared));
  std::set<std::string> done;
  for (const json& line : report) {
    ASSERT_EQ(line["status"], "ok") << line.dump();
    const std::string output = line["output"];
    EXPECT_TRUE(test::readFile(output) == expected.at(fs::path(output).filename().string())) << output;
    done.insert(fs::relative(output, out).string());
  }
  // A rank killed between renaming its output into place and journaling it leaves a file the report does not list:
  // complete all the same (outputs are atomic), and converted again by the resume.
  for (const auto& [name, bytes] : filesBelow(out)) {
    if (name.ends_with(".binvox") && !isTemporary(name) && !done.contains(name)) {
      EXPECT_TRUE(bytes == expected.at(fs::path(name).filename().string())) << name << " unreported and incomplete";
    }
  }

  auto r = runVoxmod(batchArgs(inputs, out, "binvox", {"--resume", "--json"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json summary = json::parse(r.out);
  EXPECT_EQ(summary["skipped"], done.size());
  EXPECT_EQ(summary["ok"], inputs.size() - done.size());
  for (const auto& [name, bytes] : filesBelow(out)) {
    EXPECT_FALSE(isTemporary(name)) << name << " left behind";
    if (name.ends_with(".binvox")) {
      EXPECT_TRUE(bytes == expected.at(fs::path(name).filename().string())) << name;
    }
  }
}

// Other subcommands, and a batch without mpirun, never start MPI: they run as before.
TEST(CliBatch, plainVoxmodNeedsNoMpi) {
  TempDir tmp;
  const std::string mesh = (test::sourceDir() / "models/featuretype.stl").string();
  auto r = runVoxmod(batchArgs({mesh}, tmp / "o", "vxm", {"--json"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"ranks\":1"), std::string::npos) << r.out;
  EXPECT_EQ(runVoxmod({"info", (tmp / "o/featuretype.vxm").string(), "--json"}).exit_code, 0);
}

}  // namespace
}  // namespace vox
