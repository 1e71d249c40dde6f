#pragma once
// voxmod batch: many inputs to one output each (docs/conventions.md, "Batch"). The pieces shared by the command
// (cmd_batch.cpp: options, the local worker pool, progress, the report), the plan and the journal (batch_plan.cpp),
// the conversion of one file (batch_convert.cpp) and the MPI distribution (batch_mpi.cpp).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/model_input.h"
#include "vox/core/result.h"

namespace vox::cli {

using Json = nlohmann::ordered_json;

// What every file of a batch is converted with.
struct BatchSettings {
  std::string format;  // the output extension without its dot, lower case: "binvox", "vxm", "vti", "stl", ...
  MeshOptions mesh;    // --res / --voxel-size / --mode / --units / --memory-limit (threads: set per file)
  // The settings that change an output's bytes, as one string: a journal entry made with other settings is stale.
  std::string key() const;
};

// One input and the output it goes to. `index` is the input's place in the command line or list (the report's
// order). `problem`, when set, is a reason known before any work (a duplicate output, an output over its input).
struct BatchItem {
  size_t index = 0;
  std::string input;             // as given
  std::filesystem::path output;  // OUTDIR / relative
  std::string relative;          // the output's path below OUTDIR, as the journal and the report name it
  std::string problem;           // non-empty: reported as an error without being attempted
  uint64_t input_bytes = 0;      // for the order of hand-out and the time-left estimate
};

// The outcome of one item: its report line (docs/conventions.md, "Batch") and, when it was converted, the journal entry
// that lets a later --resume check the output.
struct BatchOutcome {
  size_t index = 0;
  Json line;
  Json journal;             // null unless status is "ok"
  bool stop_batch = false;  // the output directory refuses writes (disk full, quota): nothing more can be written
};

// Output extensions batch writes (voxel, volume and surface formats), without dots.
std::vector<std::string> batchFormats();
// The format named by --format ("binvox", ".BINVOX"), or an empty string when it is not one of batchFormats().
std::string normalizeBatchFormat(const std::string& text);

// The inputs from the command line, or from a list file (one path a line; blank lines and lines starting with '#'
// skipped; relative paths relative to the current directory).
Result<std::vector<std::string>> readInputList(const std::filesystem::path& list);

// Output names (docs/conventions.md, "Batch"): the input's path relative to the deepest directory holding every
// input, with its extension replaced by the format's; where two inputs would share a name (part.stl and part.obj
// side by side), each keeps its own extension before the new one (part.stl.binvox). Inputs that still collide (the
// same file given twice) get a problem; so does an output that would replace its own input.
std::vector<BatchItem> planBatch(const std::vector<std::string>& inputs, const std::filesystem::path& outdir,
                                 const std::string& format);

// The journal: OUTDIR/.voxmod-batch.jsonl, one JSON line appended (and flushed to disk) per output written, naming
// the output, its size and CRC-32, the input's size and modification time and the settings' key. --resume skips an
// item only when its entry matches all of them and the file on disk has that size and CRC-32.
using Journal = std::map<std::string, Json>;  // by output, relative to OUTDIR; the last entry of each
std::filesystem::path journalPath(const std::filesystem::path& outdir);
// A missing journal is empty; a torn line (a batch killed while appending) is ignored.
Journal readJournal(const std::filesystem::path& outdir);
// The "skipped" report line when `item`'s output is complete and current per `journal`; nullopt when it must be done.
std::optional<Json> checkDone(const BatchItem& item, const Journal& journal, const BatchSettings& settings);

// A regular file's size and modification time (nanoseconds); nullopt when it is not one.
struct FileStamp {
  uint64_t size = 0;
  int64_t mtime_ns = 0;
};
std::optional<FileStamp> fileStamp(const std::string& path);
// The journal entry of an output just written (read back for its CRC-32); `input` was taken before it was read.
Result<Json> journalEntry(const BatchItem& item, const BatchSettings& settings, const FileStamp& input,
                          const Json& line);
// One line appended with one write(), then flushed to the disk. Errors name the file.
Status appendJournal(const std::filesystem::path& outdir, const Json& entry);
Status appendReportLine(const std::filesystem::path& report, const Json& line);
// Rewrites the journal atomically with the last entry of each output.
Status compactJournal(const std::filesystem::path& outdir);
// Removes the temporary files an interrupted batch left beside the items' outputs (".NAME.tmp-*", io/file_util.h).
void removeStaleTemporaries(const std::vector<BatchItem>& items);
// Creates OUTDIR and proves it writable (a file created and removed); the error says why not.
Status prepareOutdir(const std::filesystem::path& outdir);

// Converts one item with `threads` threads: reads the input, voxelizes a mesh, writes the output atomically and
// checksums it. Never throws for bad input: every failure is the outcome's "error".
BatchOutcome convertItem(const BatchItem& item, const BatchSettings& settings, int threads);
// The report line of an item that was not attempted (status "error", the reason given).
Json errorLine(const BatchItem& item, const std::string& error, double seconds = 0.0);
// True for an error that means the output directory refuses writes (no space left, quota exceeded).
bool isDiskFull(const std::string& message);

// Distribution over MPI ranks (batch_mpi.cpp), when voxmod is built with MPI and launched by mpirun or srun.
// Rank 0 hands out one item at a time to whichever rank asks (itself included: a thread of rank 0 works too), each
// rank writes its outputs and sends back the outcome; rank 0 keeps the journal and the report.
struct MpiWorld {
  int rank = 0;
  int size = 1;
  int threads = 1;  // per file on this rank: its CPUs shared with the other ranks on the node
};
// True when mpirun or srun launched this process (Open MPI's, PMIx's or PMI's environment variables).
bool launchedByMpi();
// The number of processes the launcher started, from its environment (1 when it says nothing).
int mpiWorldSizeFromEnvironment();
// True when voxmod was built with MPI (Open MPI found at configure time).
bool mpiBuilt();
// MPI_Init (threads funnelled through the main thread); `threads` from --threads when given (> 0).
MpiWorld startMpi(int threads);
void stopMpi();
// Ranks other than 0: convert what rank 0 hands out until it says stop.
void serveRankZero(const BatchSettings& settings, const MpiWorld& world);
// Rank 0: hands out `todo` (in that order) and calls `finished` for each outcome, one at a time, until `todo` is done
// or `stop()` says no more should start.
void dispatchOverRanks(const std::vector<BatchItem>& items, const std::vector<size_t>& todo,
                       const BatchSettings& settings, const MpiWorld& world,
                       const std::function<void(BatchOutcome&&)>& finished, const std::function<bool()>& stop);

}  // namespace vox::cli
