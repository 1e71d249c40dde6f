// I/O benchmarks: STL parsing (binary and ASCII, bytes/s and triangles/s), and .vxm / .binvox encoding and
// decoding of large grids. Files are read into memory once, outside the timed loop, so the figures are parser
// speed, not disc speed. parseStl includes the topology pass (analyzeTopology), which is timed on its own too.
// Rates are per CPU second (the code is single-threaded; on the shared development machine wall time is noisy).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstring>

#include "bench_support.h"
#include "vox/core/mesh.h"
#include "vox/io/file_util.h"
#include "vox/io/stl.h"
#include "vox/io/voxel_file.h"

namespace {

std::vector<uint8_t> readShared(const std::string& mesh) {
  auto r = vox::io::readFileBytes(vox::bench::sharedMesh(mesh));
  return r.ok() ? std::move(r.value()) : std::vector<uint8_t>{};
}

void parseStlBench(benchmark::State& state, const std::vector<uint8_t>& bytes, const std::string& name) {
  if (bytes.empty()) {
    state.SkipWithError(("cannot read " + name + " (set VOXMOD_SHARED_DIR)").c_str());
    return;
  }
  size_t triangles = 0;
  for (auto _ : state) {
    auto r = vox::io::parseStl(bytes, name);
    if (!r.ok()) {
      state.SkipWithError(r.error().message.c_str());
      return;
    }
    triangles = r->mesh.triangles.size();
    benchmark::DoNotOptimize(r->mesh.triangles.data());
  }
  state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(bytes.size()));
  state.counters["triangles"] = double(triangles);
  state.counters["triangles/s"] =
      benchmark::Counter(double(triangles) * double(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_ParseStl_BinaryIgea508k(benchmark::State& state) {
  static const std::vector<uint8_t> bytes = readShared("igea_refined_508k.stl");
  parseStlBench(state, bytes, "igea_refined_508k.stl");
}
BENCHMARK(BM_ParseStl_BinaryIgea508k)->Unit(benchmark::kMillisecond);

void BM_ParseStl_BinaryArmadillo(benchmark::State& state) {
  static const std::vector<uint8_t> bytes = readShared("armadillo.stl");
  parseStlBench(state, bytes, "armadillo.stl");
}
BENCHMARK(BM_ParseStl_BinaryArmadillo)->Unit(benchmark::kMillisecond);

void BM_ParseStl_AsciiOrion(benchmark::State& state) {
  static const std::vector<uint8_t> bytes = readShared("orion_capsule_ascii.stl");
  parseStlBench(state, bytes, "orion_capsule_ascii.stl");
}
BENCHMARK(BM_ParseStl_AsciiOrion)->Unit(benchmark::kMillisecond);

// One million triangles: igea twice (the copy shifted by its own width, so it is a second closed body) minus
// the surplus, as one binary STL in memory.
std::vector<uint8_t> millionTriangleStl() {
  const std::vector<uint8_t> igea = readShared("igea_refined_508k.stl");
  if (igea.size() < 84) return {};
  constexpr uint32_t kCount = 1000000;
  const size_t have = (igea.size() - 84) / 50;
  std::vector<uint8_t> out(84 + size_t(kCount) * 50);
  std::memcpy(out.data(), "one million triangles from igea", 31);
  std::memcpy(out.data() + 80, &kCount, 4);
  for (size_t i = 0; i < kCount; ++i) {
    uint8_t* dst = out.data() + 84 + 50 * i;
    std::memcpy(dst, igea.data() + 84 + 50 * (i % have), 50);
    if (i >= have) {
      for (int c = 0; c < 3; ++c) {
        float x;
        std::memcpy(&x, dst + 12 + 12 * c, 4);
        x += 0.1f;
        std::memcpy(dst + 12 + 12 * c, &x, 4);
      }
    }
  }
  return out;
}

void BM_ParseStl_Binary1MTriangles(benchmark::State& state) {
  static const std::vector<uint8_t> bytes = millionTriangleStl();
  parseStlBench(state, bytes, "1m.stl");
}
BENCHMARK(BM_ParseStl_Binary1MTriangles)->Unit(benchmark::kMillisecond);

void BM_AnalyzeTopology_Igea508k(benchmark::State& state) {
  static const std::vector<uint8_t> bytes = readShared("igea_refined_508k.stl");
  auto r = vox::io::parseStl(bytes, "igea_refined_508k.stl");
  if (!r.ok()) {
    state.SkipWithError(r.error().message.c_str());
    return;
  }
  for (auto _ : state) benchmark::DoNotOptimize(vox::analyzeTopology(r->mesh));
  state.counters["triangles/s"] =
      benchmark::Counter(double(r->mesh.triangles.size()) * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_AnalyzeTopology_Igea508k)->Unit(benchmark::kMillisecond);

// A solid ball filling most of an n^3 grid: two runs per row through it, long empty runs around it.
vox::VoxelGrid ball(int32_t n) {
  vox::VoxelGrid g(vox::Dims{n, n, n});
  const double c = (n - 1) / 2.0, r2 = (0.47 * n) * (0.47 * n);
  for (int32_t z = 0; z < n; ++z)
    for (int32_t y = 0; y < n; ++y) {
      const double d2 = (y - c) * (y - c) + (z - c) * (z - c);
      if (d2 >= r2) continue;
      const double half = std::sqrt(r2 - d2);
      g.fillRun(y, z, int64_t(std::ceil(c - half)), int64_t(std::floor(c + half)) + 1);
    }
  return g;
}

void setVoxelCounters(benchmark::State& state, const vox::VoxelGrid& g, size_t file_bytes) {
  state.counters["voxels/s"] =
      benchmark::Counter(double(g.dims().count()) * double(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["file_bytes"] = double(file_bytes);
}

void BM_EncodeVxm_Ball(benchmark::State& state) {
  const vox::VoxelGrid g = ball(int32_t(state.range(0)));
  size_t size = 0;
  for (auto _ : state) size = vox::io::encodeVxm(g).size();
  setVoxelCounters(state, g, size);
}
BENCHMARK(BM_EncodeVxm_Ball)->Arg(512)->Arg(1000)->Unit(benchmark::kMillisecond);

void BM_DecodeVxm_Ball(benchmark::State& state) {
  const vox::VoxelGrid g = ball(int32_t(state.range(0)));
  const std::vector<uint8_t> bytes = vox::io::encodeVxm(g);
  for (auto _ : state) {
    auto r = vox::io::decodeVxm(bytes, "ball.vxm");
    if (!r.ok()) {
      state.SkipWithError(r.error().message.c_str());
      return;
    }
    benchmark::DoNotOptimize(r->nx());
  }
  setVoxelCounters(state, g, bytes.size());
}
BENCHMARK(BM_DecodeVxm_Ball)->Arg(512)->Arg(1000)->Unit(benchmark::kMillisecond);

void BM_EncodeBinvox_Ball(benchmark::State& state) {
  const vox::VoxelGrid g = ball(int32_t(state.range(0)));
  size_t size = 0;
  for (auto _ : state) size = vox::io::encodeBinvox(g).size();
  setVoxelCounters(state, g, size);
}
BENCHMARK(BM_EncodeBinvox_Ball)->Arg(512)->Arg(1000)->Unit(benchmark::kMillisecond);

void BM_DecodeBinvox_Ball(benchmark::State& state) {
  const vox::VoxelGrid g = ball(int32_t(state.range(0)));
  const std::vector<uint8_t> bytes = vox::io::encodeBinvox(g);
  for (auto _ : state) {
    auto r = vox::io::decodeBinvox(bytes, "ball.binvox");
    if (!r.ok()) {
      state.SkipWithError(r.error().message.c_str());
      return;
    }
    benchmark::DoNotOptimize(r->nx());
  }
  setVoxelCounters(state, g, bytes.size());
}
BENCHMARK(BM_DecodeBinvox_Ball)->Arg(512)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
