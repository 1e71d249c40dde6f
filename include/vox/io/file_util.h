#pragma once
// File helpers with honest errors. Saves are atomic: written to a temporary file in the same directory, flushed,
// then renamed over the target, so a failed save never damages the previous file.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "vox/core/result.h"

namespace vox::io {

// Bytes from a file, quoted for a message: printable ASCII kept, anything else (control bytes, bytes that are not
// UTF-8) shown as '?', at most `max_chars` characters then "...". Messages built from file content stay valid text.
std::string quoteBytes(std::string_view bytes, size_t max_chars = 40);

// The path's extension in lower case, with its dot: ".png" for "a.PNG", "" without one. Formats go by it.
std::string lowerExtension(const std::filesystem::path& path);

// Whole file into memory. Errors: "<path>: no such file", "<path>: permission denied", ...
Result<std::vector<uint8_t>> readFileBytes(const std::filesystem::path& path);
// Atomic replace (temp file + fsync + rename). Errors name the path and the reason (e.g. "No space left on device").
Status writeFileAtomic(const std::filesystem::path& path, std::span<const uint8_t> bytes);
Status writeFileAtomic(const std::filesystem::path& path, const std::string& text);

// Where an encoder streams its output: append() adds bytes at the end, overwrite() replaces bytes already written
// (a header completed after the body). A failure is returned by the call that met it.
class ByteSink {
 public:
  virtual ~ByteSink() = default;
  virtual Status append(std::span<const uint8_t> bytes) = 0;
  virtual Status overwrite(uint64_t offset, std::span<const uint8_t> bytes) = 0;
};

// Into memory.
class VectorSink final : public ByteSink {
 public:
  Status append(std::span<const uint8_t> bytes) override;
  Status overwrite(uint64_t offset, std::span<const uint8_t> bytes) override;
  std::vector<uint8_t> bytes;
};

// Atomic replace, streamed: `produce` writes the file's content into the temporary file through the sink, so an
// encoder never needs the whole file in memory. The target is replaced only when produce succeeds and the data is
// flushed; any failure (produce's own or the disk's) leaves the previous file untouched and is returned.
Status writeFileAtomic(const std::filesystem::path& path, const std::function<Status(ByteSink&)>& produce);

// Several files written as one: each is written and flushed under a temporary name first, and only when all are
// complete are they renamed over their targets. A failure leaves every target as it was (no half of a pair).
struct PendingFile {
  std::filesystem::path path;
  std::vector<uint8_t> bytes;
};
Status writeFilesAtomic(const std::vector<PendingFile>& files);

}  // namespace vox::io
