#include "cli/output.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "vox/io/file_util.h"
#include "vox/io/volume_export.h"

namespace vox::cli {

void Output::say(const std::string& line) const {
  if (quiet_) return;
  std::FILE* f = json_ ? stderr : stdout;
  std::fprintf(f, "%s\n", line.c_str());
}

void Output::warn(const std::string& line) {
  warnings_.push_back(line);
  if (quiet_) return;
  std::fprintf(stderr, "warning: %s\n", line.c_str());
}

std::string significant(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string pngOutputProblem(const std::string& path) {
  if (io::lowerExtension(path) == ".png") return {};
  return path + ": unknown image format '" + std::filesystem::path(path).extension().string() +
         "' (voxmod writes PNG images: use a .png file name)";
}

std::string fieldOutputProblem(const std::string& path) {
  const auto format = io::volumeFormatOf(path);
  if (format && io::holdsFields(*format)) return {};
  return path + ": scalar fields are written as " + io::volumeExtensionList(true) +
         (format ? " (a .vox file holds voxels only)" : "");
}

Result<std::vector<uint8_t>> encodeFieldFile(const std::string& name, const ScalarField& field, const std::string& path,
                                             const ProgressFn& progress) {
  const auto format = io::volumeFormatOf(path);
  if (!format) return makeError(ErrorCode::kInvalidArgument, fieldOutputProblem(path));
  return io::encodeVolume(io::oneField(name, field), *format, path, progress);
}

void Output::note(const std::string& line) {
  // the same input read twice (a report of an assembly reads its file as a whole and by bodies) says it once
  if (std::find(notes_.begin(), notes_.end(), line) != notes_.end()) return;
  if (quiet_) {
    notes_.push_back(line);
    return;
  }
  std::fprintf(stderr, "note: %s\n", line.c_str());
  notes_.push_back(line);
}

Status writeOutputs(const std::vector<io::PendingFile>& files, const Output& out) {
  if (files.empty()) return Ok{};
  if (Status st = io::writeFilesAtomic(files); !st) return st;
  std::string wrote;
  for (const io::PendingFile& f : files) wrote += (wrote.empty() ? "" : ", ") + f.path.string();
  out.say("wrote " + wrote);
  return Ok{};
}

int exitCodeFor(const Error& e) {
  switch (e.code) {
    case ErrorCode::kInvalidArgument:
      return kExitUsage;
    case ErrorCode::kNoOpenGL:
      return kExitNoGL;
    default:
      return kExitIo;
  }
}

int Output::fail(const Error& error) { return fail(exitCodeFor(error), error.message); }

int Output::fail(int exit_code, const std::string& message) {
  if (quiet_) return exit_code;
  std::fprintf(stderr, "voxmod: error: %s\n", message.c_str());
  if (json_) {
    data_["error"] = message;
    data_["warnings"] = warnings_;
    if (!notes_.empty()) data_["notes"] = notes_;
    std::cout << data_.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << std::endl;
  }
  return exit_code;
}

int Output::finish() {
  if (quiet_) return kExitOk;
  data_["warnings"] = warnings_;
  if (!notes_.empty()) data_["notes"] = notes_;
  if (json_) std::cout << data_.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << std::endl;
  return kExitOk;
}

}  // namespace vox::cli
