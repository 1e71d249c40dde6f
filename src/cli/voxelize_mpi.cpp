// voxmod voxelize over MPI ranks (cli/voxelize_mpi.h). Every rank reads the mesh and plans the same grid and the
// same slabs (those of one process when the grid does not fit under the memory limit, otherwise one slab per rank);
// slab k is voxelized on rank k mod N (voxelizeInSlabs with a SlabShare) and encoded there as its runs
// (io::encodeVxmLayers). Rank 0 opens the output's temporary file, and appends the slabs in order: its own as it
// voxelizes them, the others' fetched one at a time (it asks the owner for slab k, the owner sends its runs), so a
// rank holds one slab and its runs besides the mesh, and rank 0 one slab's runs from another rank. The encoder joins
// runs across slab boundaries, so the file is byte for byte the one process's (io::VxmLayerWriter::appendRuns).
//
// Messages, all between rank 0 and one other rank: START (the output is open: voxelize), GO k (send slab k), END
// code (stop: the job's exit code), then from a rank the slab's head (k, ok, error code, bytes) and its bytes (the
// runs, or the error's text), and after END 0 its figures (ray counts for the warnings, peak memory). Waiting ranks
// poll with short sleeps rather than block (batch_mpi.cpp says why). Only the main thread calls MPI.
#include "cli/voxelize_mpi.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>
#include <span>
#include <thread>
#include <vector>

#include "cli/batch.h"
#include "cli/voxelize_stream.h"
#include "vox/core/text.h"
#include "vox/io/file_util.h"
#include "vox/io/vxm_stream.h"
#include "vox/voxelize/stream.h"

#if VOXMOD_HAVE_MPI
#include <mpi.h>
#endif

namespace vox::cli {

#if VOXMOD_HAVE_MPI

namespace {

enum Tag : int { kTagStart = 11, kTagGo, kTagEnd, kTagSlabHead, kTagSlabBytes, kTagReport, kTagPrepareError };
constexpr size_t kChunkBytes = size_t(1) << 28;  // per message: MPI counts are ints

// Waits for a message from `source` with `tag` (either may be a wildcard), sleeping between polls: 50 us at first,
// up to 1 ms (each slab costs a request and a reply, so the wait adds to every slab; a thousand polls a second
// take no noticeable CPU).
MPI_Status waitFor(int source, int tag) {
  MPI_Status status;
  int flag = 0;
  for (int pause_us = 50;; pause_us = std::min(pause_us * 2, 1000)) {
    MPI_Iprobe(source, tag, MPI_COMM_WORLD, &flag, &status);
    if (flag) return status;
    std::this_thread::sleep_for(std::chrono::microseconds(pause_us));
  }
}

void sendInts(const std::vector<int64_t>& v, int dest, int tag) {
  MPI_Send(v.data(), int(v.size()), MPI_INT64_T, dest, tag, MPI_COMM_WORLD);
}

std::vector<int64_t> receiveInts(int source, int tag) {
  const MPI_Status status = waitFor(source, tag);
  int count = 0;
  MPI_Get_count(&status, MPI_INT64_T, &count);
  std::vector<int64_t> v(size_t(std::max(count, 0)));
  MPI_Recv(v.data(), count, MPI_INT64_T, source, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return v;
}

// Bytes in messages of at most kChunkBytes (one message when empty); the receiver knows the size.
void sendBytes(std::span<const uint8_t> bytes, int dest, int tag) {
  size_t at = 0;
  do {
    const size_t n = std::min(kChunkBytes, bytes.size() - at);
    MPI_Send(bytes.data() + at, int(n), MPI_BYTE, dest, tag, MPI_COMM_WORLD);
    at += n;
  } while (at < bytes.size());
}

std::vector<uint8_t> receiveBytes(int source, int tag, uint64_t size) {
  std::vector<uint8_t> bytes(size);
  size_t at = 0;
  do {
    const size_t n = size_t(std::min<uint64_t>(kChunkBytes, size - at));
    waitFor(source, tag);
    MPI_Recv(bytes.data() + at, int(n), MPI_BYTE, source, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    at += n;
  } while (at < size);
  return bytes;
}

std::span<const uint8_t> textBytes(const std::string& text) {
  return {reinterpret_cast<const uint8_t*>(text.data()), text.size()};
}

// What every rank works out before voxelizing: the mesh, the parameters and the slabs.
struct Prepared {
  bool spread = false;  // false: rank 0 does the job alone
  std::optional<io::MeshFileLoad> mesh;
  VoxelizeParams params;
  Dims dims;
  GridFrame frame;
  int32_t slab_layers = 0, slabs = 0;
  bool fits = false;  // the whole grid fits under the memory limit (one slab per rank)
};

Status prepare(const MpiVoxelizeJob& job, const MpiWorld& world, Output& out, Prepared& p) {
  // A .binvox output (written whole) or a result that needs the whole grid: not spread.
  if (io::lowerExtension(job.out_path) != ".vxm" || job.needs_whole_grid) return Ok{};
  auto mesh = loadMesh(job.mesh_path, job.mesh_options, out);
  if (!mesh) return mesh.error();
  p.mesh = std::move(mesh).value();
  auto params = voxelizeParams(job.mesh_options);
  if (!params) return params.error();
  p.params = *params;
  p.params.units = p.mesh->units;
  p.params.threads = world.threads;
  const FillMode mode = p.params.mode == FillMode::kAuto ? resolveAutoMode(p.mesh->topology).mode : p.params.mode;
  if (mode == FillMode::kVote) return Ok{};  // its rays along Y and Z need every layer: not spread
  const TriangleMesh& m = p.mesh->mesh;
  auto layers = streamSlabLayers(m.bounds(), p.params, mode, meshHeldBytes(m));
  if (!layers) return Error{layers.error().code, job.mesh_path + ": " + layers.error().message};
  auto plan = planVoxelization(m.bounds(), p.params);
  if (!plan) return Error{plan.error().code, job.mesh_path + ": " + plan.error().message};
  p.dims = plan->placement.dims;
  p.frame = plan->placement.frame;
  p.frame.units = p.params.units;
  p.frame.source = std::filesystem::path(job.mesh_path).filename().string();
  p.fits = *layers == 0;
  p.slab_layers = p.fits ? std::max(1, (p.dims.nz + world.size - 1) / world.size) : *layers;
  p.slabs = (p.dims.nz + p.slab_layers - 1) / p.slab_layers;
  p.spread = true;
  return Ok{};
}

// Rank 0: writes the file, its own slabs voxelized here and the others' fetched in order, then reports.
int runRankZero(const MpiVoxelizeJob& job, const MpiWorld& world, Prepared& p, Output& out, double t0,
                double t_loaded) {
  const int32_t L = p.slab_layers;
  int32_t next = 0;  // the next slab to append
  std::optional<StreamedVoxelization> done;
  std::optional<Error> worker_error;
  uint64_t filled = 0;
  // Appends slabs next .. upto - 1 (none of them rank 0's), each asked of its rank.
  auto fetch = [&](io::VxmLayerWriter& w, int32_t upto) -> Status {
    for (; next < upto; ++next) {
      const int owner = next % world.size;
      sendInts({next}, owner, kTagGo);
      const std::vector<int64_t> head = receiveInts(owner, kTagSlabHead);  // slab, ok, error code, bytes
      const std::vector<uint8_t> bytes = receiveBytes(owner, kTagSlabBytes, uint64_t(head.at(3)));
      if (head.at(1) == 0) {
        worker_error = Error{ErrorCode(head.at(2)), std::string(bytes.begin(), bytes.end())};
        return *worker_error;
      }
      const int32_t layers = std::min(p.dims.nz, (next + 1) * L) - next * L;
      if (Status s = w.appendRuns(bytes, layers); !s) return s;
    }
    return Ok{};
  };
  const Status written = io::saveVxmInSlabs(job.out_path, p.dims, p.frame, [&](io::VxmLayerWriter& w) -> Status {
    for (int r = 1; r < world.size; ++r) sendInts({0}, r, kTagStart);
    auto r = voxelizeInSlabs(
        p.mesh->mesh, p.params, L,
        [&](const VoxelGrid& slab, int32_t z0, int32_t z1) -> Status {
          if (Status s = fetch(w, z0 / L); !s) return s;
          ++next;
          return w.append(slab, 0, z1 - z0);
        },
        terminalProgress("voxelizing"), &p.mesh->topology, SlabShare{0, world.size});
    if (worker_error) return *worker_error;
    if (!r) return Error{r.error().code, job.mesh_path + ": " + r.error().message};
    done = std::move(r).value();
    if (Status s = fetch(w, p.slabs); !s) return s;
    filled = w.filled();
    return Ok{};
  });
  const int code = written ? kExitOk : exitCodeFor(written.error());
  for (int r = 1; r < world.size; ++r) sendInts({code}, r, kTagEnd);
  if (!written) return out.fail(written.error());
  const double t_written = nowSeconds();
  // Every rank's figures: the warnings about the rays count them over all slabs.
  RayCounts rays = done->rays;
  nlohmann::ordered_json per_rank = nlohmann::ordered_json::array({peakRssBytes()});
  for (int r = 1; r < world.size; ++r) {
    const std::vector<int64_t> v = receiveInts(r, kTagReport);  // odd, unbalanced, peak memory, largest slab
    rays.odd += v.at(0);
    rays.unbalanced += v.at(1);
    per_rank.push_back(v.at(2));
    done->largest_slab_bytes = std::max<uint64_t>(done->largest_slab_bytes, uint64_t(v.at(3)));
  }
  addRayWarnings(*done, rays);
  done->filled = int64_t(filled);
  done->slabs = p.slabs;
  auto& d = out.data();
  d["ranks"] = world.size;
  d["peak_rss_bytes_per_rank"] = per_rank;
  StreamedVoxelizeJob report{job.mesh_path, job.out_path, L, t0, t_loaded};
  report.reason =
      p.fits ? "spread over " + std::to_string(world.size) + " MPI ranks"
             : "the grid does not fit under the memory limit; spread over " + std::to_string(world.size) + " MPI ranks";
  return reportStreamedVoxelize(report, *p.mesh, p.frame, *done, t_written, out);
}

// Another rank: voxelizes its slabs once rank 0 says START, sends each when asked, until END.
int runOtherRank(const MpiVoxelizeJob& job, const MpiWorld& world, Prepared& p) {
  {
    const MPI_Status status = waitFor(0, MPI_ANY_TAG);
    const std::vector<int64_t> v = receiveInts(0, status.MPI_TAG);
    if (status.MPI_TAG == kTagEnd) return int(v.at(0));  // the output could not be opened
  }
  std::optional<int> stopped;  // END came while slabs were left: rank 0's exit code
  auto r = voxelizeInSlabs(
      p.mesh->mesh, p.params, p.slab_layers,
      [&](const VoxelGrid& slab, int32_t z0, int32_t z1) -> Status {
        const std::vector<uint8_t> runs = io::encodeVxmLayers(slab, 0, z1 - z0);
        const MPI_Status status = waitFor(0, MPI_ANY_TAG);
        const std::vector<int64_t> v = receiveInts(0, status.MPI_TAG);
        if (status.MPI_TAG == kTagEnd) {
          stopped = int(v.at(0));
          return makeError(ErrorCode::kCancelled, "stopped by rank 0");
        }
        sendInts({v.at(0), 1, 0, int64_t(runs.size())}, 0, kTagSlabHead);
        sendBytes(runs, 0, kTagSlabBytes);
        return Ok{};
      },
      {}, &p.mesh->topology, SlabShare{world.rank, world.size});
  if (stopped) return *stopped;
  int code = kExitOk;
  bool ended = false;
  if (!r) {
    // Rank 0 asks for the slab that failed (or ends the job first): it gets the error instead.
    const MPI_Status status = waitFor(0, MPI_ANY_TAG);
    const std::vector<int64_t> v = receiveInts(0, status.MPI_TAG);
    if (status.MPI_TAG == kTagEnd) {
      code = int(v.at(0));
      ended = true;
    } else {
      const std::string text = "rank " + std::to_string(world.rank) + ": " + job.mesh_path + ": " + r.error().message;
      sendInts({v.at(0), 0, int64_t(r.error().code), int64_t(text.size())}, 0, kTagSlabHead);
      sendBytes(textBytes(text), 0, kTagSlabBytes);
    }
  }
  if (!ended) code = int(receiveInts(0, kTagEnd).at(0));
  // Rank 0 waits for every rank's figures once the file is written (a rank that failed after its last slab, with
  // nothing of the file left to give, sends zeros).
  if (code == kExitOk) {
    const RayCounts rays = r ? r->rays : RayCounts{};
    sendInts({rays.odd, rays.unbalanced, peakRssBytes(), r ? int64_t(r->largest_slab_bytes) : 0}, 0, kTagReport);
  }
  return code;
}

int spreadOverRanks(const MpiVoxelizeJob& job, const MpiWorld& world, const std::function<int()>& alone) {
  Output out(job.json);
  if (world.rank != 0) out.silence();
  const double t0 = nowSeconds();
  Prepared p;
  Output loading(job.json);  // the mesh's warnings and notes: rank 0 passes them on when the job is spread
  loading.silence();
  const Status prepared = prepare(job, world, loading, p);
  const double t_loaded = nowSeconds();
  // Every rank says how it went: the first failure is reported by rank 0, and all ranks exit with its code.
  int mine[2] = {prepared ? 0 : exitCodeFor(prepared.error()), p.spread ? 1 : 0};
  std::vector<int> all(size_t(2 * world.size));
  MPI_Allgather(mine, 2, MPI_INT, all.data(), 2, MPI_INT, MPI_COMM_WORLD);
  int failed = -1;
  bool spread = true;
  for (int r = 0; r < world.size; ++r) {
    if (failed < 0 && all[size_t(2 * r)] != 0) failed = r;
    spread = spread && all[size_t(2 * r + 1)] == 1;
  }
  if (failed >= 0) {
    const int code = all[size_t(2 * failed)];
    if (world.rank == failed && failed != 0) {
      const std::string text = prepared.error().message;
      sendInts({int64_t(text.size())}, 0, kTagPrepareError);
      sendBytes(textBytes(text), 0, kTagPrepareError);
    }
    if (world.rank != 0) return code;
    if (failed == 0) {
      for (const std::string& w : loading.warnings()) out.warn(w);
      for (const std::string& n : loading.notes()) out.note(n);
      return out.fail(prepared.error());
    }
    const uint64_t size = uint64_t(receiveInts(failed, kTagPrepareError).at(0));
    const std::vector<uint8_t> text = receiveBytes(failed, kTagPrepareError, size);
    return out.fail(code, "rank " + std::to_string(failed) + ": " + std::string(text.begin(), text.end()));
  }
  if (!spread) {  // rank 0 alone; the others wait for its exit code
    if (world.rank != 0) return int(receiveInts(0, kTagEnd).at(0));
    p.mesh.reset();
    const int code = alone();
    for (int r = 1; r < world.size; ++r) sendInts({code}, r, kTagEnd);
    return code;
  }
  if (world.rank != 0) return runOtherRank(job, world, p);
  for (const std::string& w : loading.warnings()) out.warn(w);
  for (const std::string& n : loading.notes()) out.note(n);
  return runRankZero(job, world, p, out, t0, t_loaded);
}

}  // namespace

int voxelizeOverMpiRanks(const MpiVoxelizeJob& job, const std::function<int()>& alone) {
  const MpiWorld world = startMpi(job.mesh_options.params.threads);
  const int code = world.size == 1 ? alone() : spreadOverRanks(job, world, alone);
  stopMpi();
  return code;
}

#else

int voxelizeOverMpiRanks(const MpiVoxelizeJob&, const std::function<int()>& alone) { return alone(); }

#endif

}  // namespace vox::cli
