// Whole-file reads and atomic writes with POSIX calls, so every failure can report the path and errno's reason.
// The atomic save follows the usual recipe (write a temporary file in the target's directory, fsync it, rename it
// over the target, fsync the directory): rename() within one file system is atomic, so readers see either the old
// file or the complete new one, never a partial write.
#include "vox/io/file_util.h"

#include <cctype>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <random>

namespace vox::io {

std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::string quoteBytes(std::string_view bytes, size_t max_chars) {
  std::string s = "'";
  for (char c : bytes.substr(0, max_chars)) s += (c >= 32 && c < 127) ? c : '?';
  if (bytes.size() > max_chars) s += "...";
  return s + "'";
}

namespace {

std::string reason(int err) { return std::strerror(err); }

// Closes a descriptor on every path out of a function.
class FdCloser {
 public:
  explicit FdCloser(int fd) : fd_(fd) {}
  ~FdCloser() {
    if (fd_ >= 0) ::close(fd_);
  }
  FdCloser(const FdCloser&) = delete;
  FdCloser& operator=(const FdCloser&) = delete;
  int release() {
    const int fd = fd_;
    fd_ = -1;
    return fd;
  }

 private:
  int fd_;
};

// A name no other writer is likely to pick: the pid, a process-wide counter and a random number. O_EXCL makes a
// collision an EEXIST that we retry, never a shared file.
std::string tempSuffix() {
  static std::atomic<uint64_t> counter{0};
  thread_local std::mt19937_64 rng{std::random_device{}()};
  return ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1)) + "-" +
         std::to_string(rng() % 1000000);
}

}  // namespace

Result<std::vector<uint8_t>> readFileBytes(const std::filesystem::path& path) {
  const std::string p = path.string();
  int fd;
  do {
    fd = ::open(p.c_str(), O_RDONLY | O_CLOEXEC);
  } while (fd < 0 && errno == EINTR);
  if (fd < 0) return makeError(ErrorCode::kIo, p + ": cannot open: " + reason(errno));
  FdCloser closer(fd);
  struct stat st {};
  if (::fstat(fd, &st) != 0) return makeError(ErrorCode::kIo, p + ": cannot stat: " + reason(errno));
  if (S_ISDIR(st.st_mode)) return makeError(ErrorCode::kIo, p + ": is a directory, not a file");

  std::vector<uint8_t> bytes;
  // The size from fstat is only a hint (pipes report 0, files may grow): read until end of file. The spare 64 KiB
  // let the final read that sees end of file happen without growing (and copying) the buffer.
  if (S_ISREG(st.st_mode) && st.st_size > 0) bytes.reserve(size_t(st.st_size) + 65536);
  size_t used = 0;
  for (;;) {
    if (bytes.size() - used < 65536) bytes.resize(std::max<size_t>(used + 65536, bytes.capacity()));
    const ssize_t n = ::read(fd, bytes.data() + used, bytes.size() - used);
    if (n < 0) {
      if (errno == EINTR) continue;
      return makeError(ErrorCode::kIo, p + ": read failed: " + reason(errno));
    }
    if (n == 0) break;
    used += size_t(n);
  }
  bytes.resize(used);
  return bytes;
}

namespace {

// Writes to an open file descriptor; remembers errno of the first failure.
class FdSink final : public ByteSink {
 public:
  explicit FdSink(int fd) : fd_(fd) {}
  Status append(std::span<const uint8_t> bytes) override {
    if (Status s = writeAll(bytes, -1); !s.ok()) return s;
    size_ += bytes.size();
#ifdef SYNC_FILE_RANGE_WRITE
    // Large files: start writing back what is written so far while the caller makes the rest, so that the final
    // fsync waits for the last part only (Linux; a hint: errors surface in that fsync).
    if (size_ - flushed_ >= kWritebackBytes) {
      (void)::sync_file_range(fd_, off_t(flushed_), off_t(size_ - flushed_), SYNC_FILE_RANGE_WRITE);
      flushed_ = size_;
    }
#endif
    return Ok{};
  }
  Status overwrite(uint64_t offset, std::span<const uint8_t> bytes) override {
    if (offset + bytes.size() > size_)
      return makeError(ErrorCode::kInvalidArgument, "overwrite past the end of the data");
    return writeAll(bytes, int64_t(offset));
  }
  int error() const { return error_; }

 private:
  // write() at the end, or pwrite() at `offset` when it is >= 0, until every byte is written.
  Status writeAll(std::span<const uint8_t> bytes, int64_t offset) {
    size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = offset < 0
                            ? ::write(fd_, bytes.data() + done, bytes.size() - done)
                            : ::pwrite(fd_, bytes.data() + done, bytes.size() - done, off_t(offset) + off_t(done));
      if (n < 0) {
        if (errno == EINTR) continue;
        error_ = errno;
        return makeError(ErrorCode::kIo, reason(errno));
      }
      done += size_t(n);
    }
    return Ok{};
  }

  static constexpr uint64_t kWritebackBytes = uint64_t(8) << 20;
  int fd_;
  uint64_t size_ = 0, flushed_ = 0;
  int error_ = 0;
};

}  // namespace

namespace {

// A file written completely under a temporary name beside its target, not yet renamed over it.
struct StagedFile {
  std::string temp, target;
  std::filesystem::path dir;
};

// Writes `produce`'s content to a temporary file in the target's directory and flushes it. Any failure removes the
// temporary file; the target is never touched here.
Result<StagedFile> stageFile(const std::filesystem::path& path, const std::function<Status(ByteSink&)>& produce) {
  const std::string p = path.string();
  if (path.filename().empty()) return makeError(ErrorCode::kIo, p + ": cannot write: the path names no file");
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");

  // Keep the mode of a file we replace; a new file gets 0666 minus the umask, like any other created file.
  // (A target that is a directory is not special-cased: rename() refuses it, and that path is the one that
  // exercises the clean-up of the temporary file.)
  const mode_t mode = 0666;
  struct stat old {};
  const bool replacing = ::stat(p.c_str(), &old) == 0 && S_ISREG(old.st_mode);

  std::string temp;
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    // The name is cut so that the temporary name stays within NAME_MAX (255) even for a long target name.
    // (Built with append rather than "." + string: GCC 12 at -O3 warns falsely about that, GCC bug 105329.)
    std::string temp_name(1, '.');
    temp_name.append(path.filename().string(), 0, 150).append(tempSuffix());
    temp = (dir / temp_name).string();
    fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
    if (fd < 0 && errno != EEXIST && errno != EINTR) break;
  }
  if (fd < 0) {
    return makeError(ErrorCode::kIo,
                     p + ": cannot create a temporary file in '" + dir.string() + "': " + reason(errno));
  }
  FdCloser closer(fd);
  // From here on every failure removes the temporary file.
  auto fail = [&](const std::string& what, int err) -> Error {
    ::close(closer.release());
    ::unlink(temp.c_str());
    return makeError(ErrorCode::kIo, p + ": " + what + ": " + reason(err));
  };
  if (replacing && ::fchmod(fd, old.st_mode & 07777) != 0) return fail("cannot set permissions", errno);

  FdSink sink(fd);
  if (Status s = produce(sink); !s.ok()) {
    if (sink.error() != 0) return fail("write failed", sink.error());
    ::close(closer.release());
    ::unlink(temp.c_str());
    return s.error();
  }
  if (::fsync(fd) != 0) return fail("fsync failed", errno);
  const int fd_to_close = closer.release();
  if (::close(fd_to_close) != 0) {
    const int err = errno;
    ::unlink(temp.c_str());
    return makeError(ErrorCode::kIo, p + ": close failed: " + reason(err));
  }
  return StagedFile{temp, p, dir};
}

// Renames a staged file over its target and makes the rename durable.
Status publish(const StagedFile& f) {
  if (::rename(f.temp.c_str(), f.target.c_str()) != 0) {
    const int err = errno;
    ::unlink(f.temp.c_str());
    return makeError(ErrorCode::kIo, f.target + ": cannot replace the file: " + reason(err));
  }
  // Best effort: some file systems refuse fsync on a directory, and the data is already complete under its name.
  const int dir_fd = ::open(f.dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd >= 0) {
    (void)::fsync(dir_fd);
    ::close(dir_fd);
  }
  return Ok{};
}

}  // namespace

Status writeFileAtomic(const std::filesystem::path& path, const std::function<Status(ByteSink&)>& produce) {
  auto staged = stageFile(path, produce);
  if (!staged) return staged.error();
  return publish(*staged);
}

Status writeFilesAtomic(const std::vector<PendingFile>& files) {
  std::vector<StagedFile> staged;
  for (const PendingFile& f : files) {
    auto s = stageFile(f.path, [&](ByteSink& sink) { return sink.append(f.bytes); });
    if (!s) {
      for (const StagedFile& done : staged) ::unlink(done.temp.c_str());
      return s.error();
    }
    staged.push_back(std::move(s).value());
  }
  // Every file is complete on disk: only renames are left, which fail only if a directory changes under us.
  for (size_t i = 0; i < staged.size(); ++i) {
    if (Status s = publish(staged[i]); !s.ok()) {
      for (size_t j = i + 1; j < staged.size(); ++j) ::unlink(staged[j].temp.c_str());
      return s;
    }
  }
  return Ok{};
}

Status writeFileAtomic(const std::filesystem::path& path, std::span<const uint8_t> bytes) {
  return writeFileAtomic(path, [&](ByteSink& sink) { return sink.append(bytes); });
}

Status VectorSink::append(std::span<const uint8_t> data) {
  bytes.insert(bytes.end(), data.begin(), data.end());
  return Ok{};
}

Status VectorSink::overwrite(uint64_t offset, std::span<const uint8_t> data) {
  if (offset + data.size() > bytes.size())
    return makeError(ErrorCode::kInvalidArgument, "overwrite past the end of the data");
  std::copy(data.begin(), data.end(), bytes.begin() + std::ptrdiff_t(offset));
  return Ok{};
}

Status writeFileAtomic(const std::filesystem::path& path, const std::string& text) {
  return writeFileAtomic(path, std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(text.data()), text.size()));
}

}  // namespace vox::io
