// Voxelizer benchmarks (docs/performance.md). For every shared mesh at R = 128, 256, 512 and 1000:
//   load/<mesh>              reading the STL (triangles + topology), the "time to read the triangles";
//   voxelize/<mesh>/<R>      voxelizeSolid in auto mode (nonzero on closed meshes, vote on broken ones), as the CLI;
//   floor/<mesh>/<R>         allocating a grid of the same dims and writing every word of every layer (fillRun on
//                            every row, parallel over layers like the voxelizer): the least any voxelizer that
//                            produces this grid can cost.
// With --voxmod_large, also igea_refined_508k at R = 2048 and 4096 (8.6 GB of bits at 4096: check the memory).
// Counters: fresh processes (this program run again with --voxmod_child=KIND/MESH/R) run each case five more times
// (once for R > 1000), cold as a command-line run is: cold_ms is their median wall time, peak_MiB the peak resident
// memory of such a process (program, mesh and work), extra_MiB the growth over its resident memory once the mesh is
// loaded, less the program's code and libraries first paged in by the work (file-backed pages, about 0.2 MiB): the
// work's own memory. grid_MiB is the result grid. The
// timed iterations run warm: each reuses the pages the previous one freed.
//
//   build-rel/bench/voxelize_bench --benchmark_filter='voxelize/armadillo'
//   build-rel/bench/voxelize_bench --voxmod_large --benchmark_filter='igea.*/(2048|4096)'
#include <malloc.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench_support.h"
#include "vox/core/grid_placement.h"
#include "vox/io/stl.h"
#include "vox/voxelize/voxelize.h"

namespace {

const std::vector<std::string> kMeshes = {
    "featuretype",         "plate_holes",       "rocker_arm",       "fandisk",           "tray_bottom_ascii",
    "orion_capsule_ascii", "stanford_bunny",    "armadillo",        "femur_right",       "igea_refined_508k",
    "cycloidal_assembly",  "cube_axis_aligned", "cube_rotated_45z", "two_disjoint_cubes"};

const vox::io::StlLoad& mesh(const std::string& name) {
  static std::map<std::string, vox::io::StlLoad> cache;
  auto it = cache.find(name);
  if (it == cache.end()) {
    auto stl = vox::io::loadStl(vox::bench::sharedMesh(name + ".stl"));
    if (!stl) {
      std::fprintf(stderr, "%s\n", stl.error().message.c_str());
      std::exit(1);
    }
    it = cache.emplace(name, std::move(stl).value()).first;
  }
  return it->second;
}

// Resident memory (VmRSS) and its peak (VmHWM) of this process, in bytes.
uint64_t procStatus(const char* key) {
  std::ifstream f("/proc/self/status");
  std::string line;
  while (std::getline(f, line)) {
    if (line.rfind(key, 0) == 0) return std::stoull(line.substr(std::strlen(key))) * 1024;
  }
  return 0;
}

struct ChildRun {
  uint64_t peak = 0, start = 0;  // resident bytes: peak, and at the start of the timed work
  uint64_t code = 0;             // file-backed resident bytes (code, libraries) first paged in by the work
  double seconds = 0;            // wall time of the timed work
  bool ok = false;
};

vox::VoxelizeParams paramsFor(int64_t resolution) {
  vox::VoxelizeParams params;
  params.resolution = resolution;
  return params;
}

// Allocate a grid and write every word of every layer, in parallel over layers.
vox::VoxelGrid writeFloor(const vox::Dims& dims) {
  vox::VoxelGrid g(dims);
  const int threads = std::max(1, int(std::thread::hardware_concurrency()));
  std::atomic<int32_t> next{0};
  auto worker = [&] {
    for (int32_t z; (z = next.fetch_add(1)) < dims.nz;) {
      for (int32_t y = 0; y < dims.ny; ++y) g.fillRun(y, z, 0, dims.nx);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();
  return g;
}

// The child side of a cold run (this program started again with --voxmod_child=KIND/MESH/R): loads the mesh, then
// times one voxelization (KIND = voxelize) or one floor (KIND = floor) and prints "peak start seconds code", code
// being the growth of file-backed resident memory (RssFile) during the work.
int runChild(const std::string& spec) {
  const size_t a = spec.find('/'), b = spec.rfind('/');
  if (a == std::string::npos || b == a) return 2;
  const std::string kind = spec.substr(0, a), name = spec.substr(a + 1, b - a - 1);
  const int64_t resolution = std::stoll(spec.substr(b + 1));
  auto stl = vox::io::loadStl(vox::bench::sharedMesh(name + ".stl"));
  if (!stl) return 1;
  std::function<void()> work;
  if (kind == "voxelize") {
    work = [&] {
      auto r = vox::voxelizeSolid(stl->mesh, paramsFor(resolution), {}, &stl->topology);
      benchmark::DoNotOptimize(r);
    };
  } else {
    auto placement = vox::placeGridByResolution(stl->mesh.bounds(), resolution);
    if (!placement) return 1;
    const vox::Dims dims = placement->dims;
    work = [dims] {
      vox::VoxelGrid g = writeFloor(dims);
      benchmark::DoNotOptimize(g.layerWords(0));
    };
  }
  malloc_trim(0);  // the loader's freed memory goes back to the system: the baseline is what is really in use
  {
    std::ofstream reset("/proc/self/clear_refs");
    reset << "5";  // resets VmHWM to the current VmRSS
  }
  const uint64_t start = procStatus("VmRSS:"), file_start = procStatus("RssFile:");
  const auto t0 = std::chrono::steady_clock::now();
  work();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const uint64_t file_end = procStatus("RssFile:");
  std::printf("%llu %llu %.9f %llu\n", static_cast<unsigned long long>(procStatus("VmHWM:")),
              static_cast<unsigned long long>(start), seconds,
              static_cast<unsigned long long>(file_end > file_start ? file_end - file_start : 0));
  return 0;
}

// Runs one case cold: in a fresh process (this program again), as a command-line run is, with nothing of this
// process's heap, page tables or caches of its own.
ChildRun measureChild(const std::string& spec) {
  ChildRun r;
  int fds[2];
  if (pipe(fds) != 0) return r;
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    dup2(fds[1], STDOUT_FILENO);
    const std::string arg = "--voxmod_child=" + spec;
    char* argv[] = {const_cast<char*>("voxelize_bench"), const_cast<char*>(arg.c_str()), nullptr};
    execv("/proc/self/exe", argv);
    _exit(127);
  }
  close(fds[1]);
  std::string out;
  char buf[256];
  for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;) out.append(buf, size_t(n));
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  unsigned long long peak = 0, start = 0, code = 0;
  double seconds = 0;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0 &&
      std::sscanf(out.c_str(), "%llu %llu %lf %llu", &peak, &start, &seconds, &code) == 4) {
    r = ChildRun{peak, start, code, seconds, true};
  }
  return r;
}

constexpr double kMiB = 1024.0 * 1024.0;

// Cold runs are `runs` fresh processes: cold_ms is the median wall time (a single cold run varies by half on this
// machine, mostly in page-fault cost), the memory counters the largest seen.
void setChildCounters(benchmark::State& state, const std::string& spec, int runs) {
  std::vector<double> seconds;
  uint64_t peak = 0, extra = 0;
  for (int i = 0; i < runs; ++i) {
    const ChildRun r = measureChild(spec);
    if (!r.ok) {
      state.SkipWithError(("cold run failed: " + spec).c_str());
      return;
    }
    seconds.push_back(r.seconds);
    peak = std::max(peak, r.peak);
    extra = std::max(extra, r.peak > r.start + r.code ? r.peak - r.start - r.code : 0);
  }
  std::sort(seconds.begin(), seconds.end());
  state.counters["peak_MiB"] = double(peak) / kMiB;
  state.counters["extra_MiB"] = double(extra) / kMiB;
  state.counters["cold_ms"] = seconds[seconds.size() / 2] * 1e3;
}

// Five cold runs up to R = 1000; one for the large grids (seconds each, gigabytes of memory).
int coldRuns(int64_t resolution) { return resolution <= 1000 ? 5 : 1; }

void loadCase(benchmark::State& state, const std::string& name) {
  int64_t triangles = 0;
  for (auto _ : state) {
    auto stl = vox::io::loadStl(vox::bench::sharedMesh(name + ".stl"));
    if (!stl) {
      state.SkipWithError(stl.error().message.c_str());
      return;
    }
    triangles = int64_t(stl->mesh.triangles.size());
    benchmark::DoNotOptimize(stl->mesh.triangles.data());
  }
  state.counters["triangles"] = double(triangles);
}

void voxelizeCase(benchmark::State& state, const std::string& name, int64_t resolution) {
  const vox::io::StlLoad& stl = mesh(name);
  const vox::VoxelizeParams params = paramsFor(resolution);
  int64_t filled = 0, disputed = 0;
  double grid_bytes = 0;
  std::string mode;
  for (auto _ : state) {
    auto r = vox::voxelizeSolid(stl.mesh, params, {}, &stl.topology);
    if (!r) {
      state.SkipWithError(r.error().message.c_str());
      return;
    }
    state.PauseTiming();  // counting and freeing the grid is not part of voxelizing
    filled = r->grid.filledCount();
    disputed = r->disputed_count;
    grid_bytes = double(r->grid.memoryBytes());
    mode = vox::fillModeName(r->mode_used);
    r = vox::Error{};
    state.ResumeTiming();
  }
  state.SetLabel(mode);
  state.counters["triangles"] = double(stl.mesh.triangles.size());
  state.counters["filled"] = double(filled);
  if (mode == "vote") state.counters["disputed"] = double(disputed);
  state.counters["grid_MiB"] = grid_bytes / kMiB;
  setChildCounters(state, "voxelize/" + name + "/" + std::to_string(resolution), coldRuns(resolution));
}

void floorCase(benchmark::State& state, const std::string& name, int64_t resolution) {
  auto placement = vox::placeGridByResolution(mesh(name).mesh.bounds(), resolution);
  if (!placement) {
    state.SkipWithError(placement.error().message.c_str());
    return;
  }
  const vox::Dims dims = placement->dims;
  for (auto _ : state) {
    vox::VoxelGrid g = writeFloor(dims);
    benchmark::DoNotOptimize(g.layerWords(0));
    state.PauseTiming();
    g = vox::VoxelGrid();
    state.ResumeTiming();
  }
  state.counters["voxels"] = double(dims.count());
  setChildCounters(state, "floor/" + name + "/" + std::to_string(resolution), coldRuns(resolution));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::strncmp(argv[1], "--voxmod_child=", 15) == 0) return runChild(argv[1] + 15);
  bool large = false;
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    if (std::string(argv[i]) == "--voxmod_large") {
      large = true;
    } else {
      args.push_back(argv[i]);
    }
  }
  int n = int(args.size());
  for (const std::string& name : kMeshes) {
    benchmark::RegisterBenchmark(("load/" + name).c_str(), loadCase, name)->Unit(benchmark::kMillisecond);
    for (int64_t r : {128, 256, 512, 1000}) {
      const std::string suffix = name + "/" + std::to_string(r);
      benchmark::RegisterBenchmark(("voxelize/" + suffix).c_str(), voxelizeCase, name, r)
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
      benchmark::RegisterBenchmark(("floor/" + suffix).c_str(), floorCase, name, r)
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
    }
  }
  if (large) {
    for (int64_t r : {2048, 4096}) {
      const std::string suffix = "igea_refined_508k/" + std::to_string(r);
      benchmark::RegisterBenchmark(("voxelize/" + suffix).c_str(), voxelizeCase, "igea_refined_508k", r)
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->Iterations(1);
      benchmark::RegisterBenchmark(("floor/" + suffix).c_str(), floorCase, "igea_refined_508k", r)
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->Iterations(1);
    }
  }
  benchmark::Initialize(&n, args.data());
  if (benchmark::ReportUnrecognizedArguments(n, args.data())) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
