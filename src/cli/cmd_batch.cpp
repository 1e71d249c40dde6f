// voxmod batch INPUTS... | --list FILE -o OUTDIR --format EXT [--resume] [--report FILE.jsonl] (docs/conventions.md,
// "Batch"; docs/conventions.md, "Batch"). One output per input, files in parallel on this machine or over MPI ranks; a
// report line per input whatever happens, in input order at the end. Exit 0 when every input is ok or skipped, 2
// otherwise.
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <mutex>
#include <thread>

#include <CLI/CLI.hpp>

#include "cli/batch.h"
#include "cli/cmd_list.h"
#include "cli/commands.h"
#include "vox/io/file_util.h"

namespace vox::cli {
namespace {

namespace fs = std::filesystem;

struct BatchOptions {
  std::vector<std::string> inputs;
  std::string list, outdir, format_text, report;
  bool resume = false, json = false;
  int jobs = 0;
  MeshOptions mesh;
};

// The CPUs this process may run on (its affinity mask: taskset, Slurm's --cpus-per-task).
int availableCpus() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1, int(std::thread::hardware_concurrency()));
}

// "1m20s", "45s", "2h05m".
std::string shortDuration(double s) {
  const int64_t t = int64_t(s + 0.5);
  char text[32];
  if (t >= 3600)
    std::snprintf(text, sizeof text, "%lldh%02lldm", (long long)(t / 3600), (long long)(t % 3600 / 60));
  else if (t >= 60)
    std::snprintf(text, sizeof text, "%lldm%02llds", (long long)(t / 60), (long long)(t % 60));
  else
    std::snprintf(text, sizeof text, "%llds", (long long)t);
  return text;
}

// The progress bar on stderr when it is a terminal: files done, failed, and the time left from the input bytes done
// so far (files differ in size far more than in time per byte).
class BatchProgress {
 public:
  BatchProgress(size_t total, uint64_t bytes_total)
      : tty_(isatty(STDERR_FILENO) != 0), total_(total), bytes_total_(bytes_total), t0_(nowSeconds()) {}
  void finished(bool failed, uint64_t bytes) {
    ++done_;
    failed_ += failed ? 1 : 0;
    bytes_done_ += bytes;
    draw();
  }
  void end() const {
    if (tty_ && total_ > 0) std::fputc('\n', stderr);
  }

 private:
  void draw() const {
    if (!tty_) return;
    constexpr int kWidth = 30;
    const int filled = total_ ? int(kWidth * done_ / total_) : kWidth;
    std::string left = "--";
    const double elapsed = nowSeconds() - t0_;
    if (bytes_done_ > 0 && bytes_total_ > bytes_done_)
      left = shortDuration(elapsed * double(bytes_total_ - bytes_done_) / double(bytes_done_));
    else if (done_ == total_)
      left = "0s";
    std::fprintf(stderr, "\rbatch [%s%s] %zu/%zu done, %zu failed, %s left  ", std::string(filled, '#').c_str(),
                 std::string(kWidth - filled, '.').c_str(), done_, total_, failed_, left.c_str());
    std::fflush(stderr);
  }

  bool tty_;
  size_t total_, done_ = 0, failed_ = 0;
  uint64_t bytes_total_, bytes_done_ = 0;
  double t0_;
};

// Files at once on this machine: `workers` threads each take the next file. A file gets the cores divided among the
// files still open (running or waiting) up to `workers` of them, so while the queue is long each file has
// cores / workers threads, and the last files, with the other workers idle, get the cores those leave.
void runLocal(const std::vector<BatchItem>& items, const std::vector<size_t>& todo, const BatchSettings& settings,
              int workers, int cores, const std::function<void(BatchOutcome&&)>& finished,
              const std::function<bool()>& stop) {
  std::mutex mutex;
  size_t next = 0, running = 0;
  auto work = [&] {
    std::unique_lock lock(mutex);
    while (next < todo.size() && !stop()) {
      const size_t i = todo[next++];
      const size_t open = todo.size() - next + 1 + running;
      const int threads = std::max(1, cores / int(std::min<size_t>(size_t(workers), open)));
      ++running;
      lock.unlock();
      BatchOutcome outcome = convertItem(items[i], settings, threads);
      lock.lock();
      --running;
      finished(std::move(outcome));
    }
  };
  std::vector<std::thread> pool;
  for (int w = 1; w < workers; ++w) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
}

// Biggest inputs first (longest processing time first): the small ones fill the gaps at the end.
std::vector<size_t> handOutOrder(const std::vector<BatchItem>& items, const std::vector<size_t>& todo) {
  std::vector<size_t> order = todo;
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return items[a].input_bytes > items[b].input_bytes; });
  return order;
}

}  // namespace

namespace {

// What the batch has done so far: every item's report line (appended to the report as it comes, kept for the
// report in input order at the end), the journal, the progress bar, and why the batch stopped early if it did.
// finished() is called for one outcome at a time.
class BatchRecord {
 public:
  BatchRecord(const std::vector<BatchItem>& items, fs::path outdir, fs::path report)
      : items_(items), lines_(items.size()), outdir_(std::move(outdir)), report_(std::move(report)) {}

  void startProgress(size_t files, uint64_t bytes) { progress_.emplace(files, bytes); }
  void endProgress() const {
    if (progress_) progress_->end();
  }
  bool stopped() const { return !stop_reason_.empty(); }
  const std::string& stopReason() const { return stop_reason_; }
  const std::vector<Json>& lines() const { return lines_; }

  void finished(BatchOutcome&& outcome) {
    if (!outcome.journal.is_null()) {
      if (Status s = appendJournal(outdir_, outcome.journal); !s.ok()) stop(s.error().message);
    }
    if (outcome.stop_batch) stop(outcome.line["error"].get<std::string>());
    if (Status s = appendReportLine(report_, outcome.line); !s.ok()) stop(s.error().message);
    const bool failed = outcome.line["status"] == "error";
    if (progress_) progress_->finished(failed, items_[outcome.index].input_bytes);
    lines_[outcome.index] = std::move(outcome.line);
  }
  void record(size_t index, Json line) { finished(BatchOutcome{index, std::move(line), nullptr, false}); }

  // Items never attempted because the batch stopped get their line now.
  void closeUnfinished() {
    for (const BatchItem& item : items_) {
      if (lines_[item.index].is_null())
        lines_[item.index] = errorLine(item, "not converted: the batch stopped: " + stop_reason_);
    }
  }

 private:
  void stop(const std::string& reason) {
    if (stop_reason_.empty()) stop_reason_ = reason;
  }

  const std::vector<BatchItem>& items_;
  std::vector<Json> lines_;
  fs::path outdir_, report_;
  std::optional<BatchProgress> progress_;
  std::string stop_reason_;
};

// The items that still need work, after the problems known in advance and (with --resume) the outputs the journal
// proves complete have been recorded.
std::vector<size_t> itemsToDo(const std::vector<BatchItem>& items, const BatchSettings& settings, bool resume,
                              const fs::path& outdir, BatchRecord& record) {
  const Journal journal = resume ? readJournal(outdir) : Journal{};
  removeStaleTemporaries(items);
  std::vector<size_t> todo;
  for (const BatchItem& item : items) {
    if (!item.problem.empty()) {
      record.record(item.index, errorLine(item, item.problem));
      continue;
    }
    if (resume) {
      if (auto done = checkDone(item, journal, settings)) {
        record.record(item.index, std::move(*done));
        continue;
      }
    }
    todo.push_back(item.index);
  }
  return todo;
}

// The summary on stdout (--json: one object) and each failure on stderr; the exit code.
int summarize(const BatchOptions& o, Output& out, const BatchRecord& record, const fs::path& report, int workers,
              int ranks, double seconds) {
  size_t ok = 0, skipped = 0, failed = 0;
  for (const Json& line : record.lines()) {
    const std::string status = line["status"];
    (status == "ok" ? ok : status == "skipped" ? skipped : failed) += 1;
    if (status == "error") std::fprintf(stderr, "%s\n", line["error"].get<std::string>().c_str());
  }
  auto& d = out.data();
  d["inputs"] = record.lines().size();
  d["ok"] = ok;
  d["skipped"] = skipped;
  d["failed"] = failed;
  d["outdir"] = o.outdir;
  d["report"] = report.string();
  d["format"] = normalizeBatchFormat(o.format_text);
  d["workers"] = workers;
  d["ranks"] = ranks;
  d["stopped"] = record.stopped() ? Json(record.stopReason()) : Json(nullptr);
  d["seconds"] = seconds;
  if (record.stopped()) std::fprintf(stderr, "voxmod batch: stopped early: %s\n", record.stopReason().c_str());
  out.say("batch: " + std::to_string(ok) + " ok, " + std::to_string(skipped) + " skipped, " + std::to_string(failed) +
          " failed in " + significant(seconds, 3) + " s; report " + report.string());
  out.finish();
  return failed > 0 ? kExitIo : kExitOk;
}

// Rank 0, or the only process: plans, skips what is done, runs the rest here or over the ranks, writes the report.
int runRankZero(const BatchOptions& o, Output& out, const BatchSettings& settings,
                const std::vector<std::string>& inputs, const MpiWorld* world) {
  const double t0 = nowSeconds();
  const fs::path outdir = o.outdir;
  const fs::path report = o.report.empty() ? outdir / "report.jsonl" : fs::path(o.report);
  const std::vector<BatchItem> items = planBatch(inputs, outdir, settings.format);
  BatchRecord record(items, outdir, report);
  std::vector<size_t> todo;
  const Status outdir_ok = prepareOutdir(outdir);
  const Status report_ok = io::writeFileAtomic(report, std::string());  // the lines come as the files finish
  const Status& fatal = !outdir_ok.ok() ? outdir_ok : report_ok;
  if (!fatal.ok()) {
    std::fprintf(stderr, "voxmod batch: %s\n", fatal.error().message.c_str());
    for (const BatchItem& item : items) record.record(item.index, errorLine(item, fatal.error().message));
  } else {
    todo = handOutOrder(items, itemsToDo(items, settings, o.resume, outdir, record));
  }
  uint64_t bytes = 0;
  for (size_t i : todo) bytes += items[i].input_bytes;
  record.startProgress(todo.size(), bytes);
  const int cores = o.mesh.params.threads > 0 ? o.mesh.params.threads : availableCpus();
  const int workers = world ? world->size : std::max(1, o.jobs > 0 ? o.jobs : std::min<int>(cores, int(todo.size())));
  auto finished = [&](BatchOutcome&& outcome) { record.finished(std::move(outcome)); };
  auto stop = [&] { return record.stopped(); };
  if (world)
    dispatchOverRanks(items, todo, settings, *world, finished, stop);
  else
    runLocal(items, todo, settings, workers, cores, finished, stop);
  record.endProgress();
  record.closeUnfinished();
  if (outdir_ok.ok()) {
    if (Status s = compactJournal(outdir); !s.ok())
      std::fprintf(stderr, "voxmod batch: %s\n", s.error().message.c_str());
  }
  if (report_ok.ok()) {
    std::string text;
    for (const Json& line : record.lines()) text += line.dump() + "\n";
    if (Status s = io::writeFileAtomic(report, text); !s.ok()) {
      std::fprintf(stderr,
                   "voxmod batch: the report in input order could not be written (%s); %s holds the lines "
                   "in the order the files finished\n",
                   s.error().message.c_str(), report.string().c_str());
    }
  }
  return summarize(o, out, record, report, workers, world ? world->size : 1, nowSeconds() - t0);
}

int runBatch(const BatchOptions& o) {
  Output out(o.json);
  BatchSettings settings;
  settings.format = normalizeBatchFormat(o.format_text);
  settings.mesh = o.mesh;
  if (settings.format.empty()) {
    std::string names;
    for (const std::string& f : batchFormats()) names += (names.empty() ? "" : ", ") + f;
    return out.fail(kExitUsage, "--format " + o.format_text + ": unknown format (use one of " + names + ")");
  }
  if (!o.list.empty() && !o.inputs.empty()) return out.fail(kExitUsage, "give INPUTS or --list, not both");
  if (auto params = voxelizeParams(settings.mesh); !params) return out.fail(kExitUsage, params.error().message);
  std::vector<std::string> inputs = o.inputs;
  if (!o.list.empty()) {
    auto listed = readInputList(o.list);
    if (!listed) return out.fail(listed.error());
    inputs = std::move(listed).value();
  }
  if (inputs.empty()) return out.fail(kExitUsage, "no inputs: give INPUTS or --list FILE");
  if (!launchedByMpi()) return runRankZero(o, out, settings, inputs, nullptr);
  if (!mpiBuilt()) {
    if (mpiWorldSizeFromEnvironment() > 1) {
      return out.fail(kExitUsage, "this voxmod was built without MPI: run 'voxmod batch' without mpirun or srun");
    }
    return runRankZero(o, out, settings, inputs, nullptr);
  }
  const MpiWorld world = startMpi(o.mesh.params.threads);
  int code = kExitOk;
  if (world.rank == 0)
    code = runRankZero(o, out, settings, inputs, &world);
  else
    serveRankZero(settings, world);
  stopMpi();
  return code;
}

}  // namespace

void addBatchCommand(CLI::App& sub, CommandContext& ctx) {
  auto o = std::make_shared<BatchOptions>();
  sub.add_option("INPUTS", o->inputs, kFileHelp);
  sub.add_option("--list", o->list, "A file naming the inputs, one path a line ('#' starts a comment line)");
  sub.add_option("-o,--outdir", o->outdir, "Output directory (created when missing)")->required();
  sub.add_option("--format", o->format_text,
                 "Output format: binvox, vxm; volumes nrrd, vti, vdb, vox; surfaces stl, ply, obj, 3mf")
      ->required();
  sub.add_flag("--resume", o->resume,
               "Skip inputs whose output the journal (OUTDIR/.voxmod-batch.jsonl) proves complete and current");
  sub.add_option("--report", o->report, "The report, one JSON line per input (default OUTDIR/report.jsonl)");
  sub.add_option("--jobs", o->jobs, "Files converted at once on this machine (default: one per core)")
      ->check(CLI::Range(1, 1024));
  sub.add_flag("--json", o->json, "Print one JSON object (the summary) on stdout");
  addMeshOptions(sub, o->mesh);
  sub.callback([o, &ctx] { ctx.exit_code = runBatch(*o); });
}

}  // namespace vox::cli
