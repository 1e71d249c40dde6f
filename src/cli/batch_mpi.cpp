// voxmod batch over MPI ranks (docs/conventions.md, "Batch"; README, "Batches on a cluster"). Rank 0 hands out one
// file at a time to whichever rank asks for work, large and small files mixed, and works on files itself in a
// thread beside the hand-out loop; every rank writes its own outputs and sends the outcome (report line and journal
// entry) back, and rank 0 keeps the journal and the report. Only the main thread of each rank calls MPI
// (MPI_THREAD_FUNNELED). Waiting ranks poll with short sleeps rather than block: Open MPI's blocking receive spins a
// core, which ranks sharing a machine's cores would take from the ranks that convert.
//
// Without MPI in the build (VOXMOD_HAVE_MPI undefined) mpiLaunched() is false and the rest is never called.
#include <cstdlib>
#include <mutex>
#include <thread>

#include "cli/batch.h"

#if VOXMOD_HAVE_MPI
#include <mpi.h>
#include <sched.h>
#endif

namespace vox::cli {

bool launchedByMpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"}) {
    if (const char* v = std::getenv(name); v && *v) return true;
  }
  return false;
}

int mpiWorldSizeFromEnvironment() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "SLURM_NTASKS"}) {
    if (const char* v = std::getenv(name); v && *v) return std::atoi(v);
  }
  return 1;
}

#if VOXMOD_HAVE_MPI

bool mpiBuilt() { return true; }

namespace {

enum Tag : int { kTagReady = 1, kTagResult = 2, kTagJob = 3, kTagStop = 4 };

void sendText(const std::string& text, int dest, int tag) {
  MPI_Send(text.data(), int(text.size()), MPI_CHAR, dest, tag, MPI_COMM_WORLD);
}

// Receives the message `status` announced (MPI_Iprobe), whatever its length.
std::string receiveText(const MPI_Status& status) {
  int count = 0;
  MPI_Get_count(&status, MPI_CHAR, &count);
  std::string text(size_t(count), '\0');
  MPI_Recv(text.data(), count, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return text;
}

// Waits for a message from `source` (or any), sleeping between polls: 0.2 ms at first, up to 5 ms.
MPI_Status waitForMessage(int source) {
  MPI_Status status;
  int flag = 0;
  for (int pause_us = 200;; pause_us = std::min(pause_us * 2, 5000)) {
    MPI_Iprobe(source, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
    if (flag) return status;
    std::this_thread::sleep_for(std::chrono::microseconds(pause_us));
  }
}

Json itemJson(const BatchItem& item) {
  return Json{{"index", item.index},
              {"input", item.input},
              {"output", item.output.string()},
              {"relative", item.relative},
              {"input_bytes", item.input_bytes}};
}

BatchItem itemFromJson(const Json& j) {
  BatchItem item;
  item.index = j["index"];
  item.input = j["input"];
  item.output = j["output"].get<std::string>();
  item.relative = j["relative"];
  item.input_bytes = j["input_bytes"];
  return item;
}

Json outcomeJson(const BatchOutcome& o) {
  return Json{{"index", o.index}, {"line", o.line}, {"journal", o.journal}, {"stop", o.stop_batch}};
}

BatchOutcome outcomeFromJson(const Json& j) { return BatchOutcome{j["index"], j["line"], j["journal"], j["stop"]}; }

// The ranks on this rank's node (they share its cores).
int ranksOnThisNode() {
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int size = 1;
  MPI_Comm_size(node, &size);
  MPI_Comm_free(&node);
  return size;
}

int cpusOfThisProcess() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1, int(std::thread::hardware_concurrency()));
}

}  // namespace

MpiWorld startMpi(int threads) {
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  MpiWorld world;
  MPI_Comm_rank(MPI_COMM_WORLD, &world.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &world.size);
  // A rank bound to one core (mpirun's default for two ranks) sees one CPU; unbound ranks share the node's.
  const int hw = std::max(1, int(std::thread::hardware_concurrency()));
  world.threads = threads > 0 ? threads : std::max(1, std::min(cpusOfThisProcess(), hw / ranksOnThisNode()));
  return world;
}

void stopMpi() { MPI_Finalize(); }

void serveRankZero(const BatchSettings& settings, const MpiWorld& world) {
  sendText("", 0, kTagReady);
  for (;;) {
    const MPI_Status status = waitForMessage(0);
    const std::string text = receiveText(status);
    if (status.MPI_TAG == kTagStop) return;
    const BatchItem item = itemFromJson(Json::parse(text));
    sendText(outcomeJson(convertItem(item, settings, world.threads)).dump(), 0, kTagResult);
  }
}

void dispatchOverRanks(const std::vector<BatchItem>& items, const std::vector<size_t>& todo,
                       const BatchSettings& settings, const MpiWorld& world,
                       const std::function<void(BatchOutcome&&)>& finished, const std::function<bool()>& stop) {
  std::mutex mutex;  // guards next and every call of finished and stop
  size_t next = 0;
  auto take = [&]() -> std::optional<size_t> {
    if (next >= todo.size() || stop()) return std::nullopt;
    return todo[next++];
  };
  std::thread local([&] {  // rank 0's own share of the work
    std::unique_lock lock(mutex);
    while (auto i = take()) {
      lock.unlock();
      BatchOutcome outcome = convertItem(items[*i], settings, world.threads);
      lock.lock();
      finished(std::move(outcome));
    }
  });
  // Every other rank says ready, then sends each outcome; each message gets the next file, or waits for the end.
  std::vector<int> waiting;
  for (int busy = world.size - 1; busy > 0;) {
    const MPI_Status status = waitForMessage(MPI_ANY_SOURCE);
    const std::string text = receiveText(status);
    std::unique_lock lock(mutex);
    if (status.MPI_TAG == kTagResult) finished(outcomeFromJson(Json::parse(text)));
    if (auto i = take()) {
      sendText(itemJson(items[*i]).dump(), status.MPI_SOURCE, kTagJob);
    } else {
      waiting.push_back(status.MPI_SOURCE);
      --busy;
    }
  }
  local.join();
  // Idle ranks wait polling (not spinning in MPI_Finalize) until every file is done, then all stop together.
  for (int rank : waiting) sendText("", rank, kTagStop);
}

#else

bool mpiBuilt() { return false; }
MpiWorld startMpi(int) { return {}; }
void stopMpi() {}
void serveRankZero(const BatchSettings&, const MpiWorld&) {}
void dispatchOverRanks(const std::vector<BatchItem>&, const std::vector<size_t>&, const BatchSettings&, const MpiWorld&,
                       const std::function<void(BatchOutcome&&)>&, const std::function<bool()>&) {}

#endif

}  // namespace vox::cli
