#pragma once
// How subcommands talk: with --json, exactly one JSON object on stdout and human messages on stderr; without it,
// a short human summary on stdout. Errors always go to stderr (and into the JSON object as "error").
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "vox/core/progress.h"
#include "vox/core/result.h"
#include "vox/core/scalar_field.h"
#include "vox/io/file_util.h"

namespace vox::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitUsage = 1;
inline constexpr int kExitIo = 2;
inline constexpr int kExitNoGL = 3;

class Output {
 public:
  explicit Output(bool json) : json_(json) {}
  // Prints nothing at all (an MPI rank other than 0, whose messages rank 0 prints); still collects the JSON object.
  void silence() { quiet_ = true; }
  const std::vector<std::string>& warnings() const { return warnings_; }
  const std::vector<std::string>& notes() const { return notes_; }
  bool json() const { return json_; }
  nlohmann::ordered_json& data() { return data_; }
  // Human line: stdout without --json, stderr with it (stdout then holds only the JSON object).
  void say(const std::string& line) const;
  void warn(const std::string& line);
  void note(const std::string& line);  // information on stderr ("note: ..."), and in the JSON object's "notes"  // on
                                       // stderr, and collected into the JSON object's "warnings" list
  // Prints the error, emits the JSON object (with "error") and returns the exit code for it.
  int fail(const Error& error);
  int fail(int exit_code, const std::string& message);
  // Emits the JSON object (when --json) and returns 0.
  int finish();

 private:
  bool json_;
  bool quiet_ = false;
  nlohmann::ordered_json data_ = nlohmann::ordered_json::object();
  std::vector<std::string> warnings_;
  std::vector<std::string> notes_;
};

// Exit code for an error: usage problems 1, no OpenGL 3, everything else (input/output) 2.
int exitCodeFor(const Error& e);

// Empty when `path` ends in .png (any case); otherwise the message that refuses it as a usage error, as convert
// refuses an unknown format: voxmod writes images only as PNG and never puts PNG bytes under another name.
std::string pngOutputProblem(const std::string& path);
// Empty when `path` names a volume format that holds scalar fields (.nrrd, .vti, .vdb: vox/io/volume_export.h);
// otherwise the message that refuses it as a usage error (a .vox file holds voxels only).
std::string fieldOutputProblem(const std::string& path);
// A scalar field as the bytes of the volume file `path` names (checked first with fieldOutputProblem), under `name`.
Result<std::vector<uint8_t>> encodeFieldFile(const std::string& name, const ScalarField& field, const std::string& path,
                                             const ProgressFn& progress = {});

// Writes `files` together or not at all (io::writeFilesAtomic) and says "wrote A, B"; nothing when there are none.
Status writeOutputs(const std::vector<io::PendingFile>& files, const Output& out);

// A number for a human line: `digits` significant digits ("%.6g"): 0.000279412, 1e-09, 12345.7; never "0.000000".
std::string significant(double v, int digits = 6);

// JSON helpers.
template <class V>
nlohmann::ordered_json jsonVec3(const V& v) {
  return nlohmann::ordered_json::array({v[0], v[1], v[2]});
}

}  // namespace vox::cli
