#pragma once
// Expected failures are values, not exceptions: loaders and algorithms return Result<T>, whose Error carries a
// code and a message that names the file and the problem (e.g. "part.stl:88: expected 'vertex', found 'endloop'").
// Parsers and algorithms never print, exit or open dialogs.
#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace vox {

enum class ErrorCode {
  kInvalidArgument,  // a parameter out of range (resolution 0, negative voxel size, ...)
  kIo,               // the file system refused: missing file, unwritable directory, disk full
  kParse,            // the content is malformed: bad token, truncated, NaN coordinates
  kUnsupported,      // a valid file of a kind or version this build does not read (e.g. a newer .vxm)
  kCorrupt,          // a checksum or structural check failed
  kLimit,            // would exceed a resource limit (memory, dimensions)
  kCancelled,        // the progress callback asked to stop
  kNoOpenGL,         // no usable OpenGL context could be created
};

struct Error {
  ErrorCode code = ErrorCode::kInvalidArgument;
  std::string message;
};

// Result<T> holds either a T or an Error. Access the value only after checking ok().
template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : v_(std::move(value)) {}      // NOLINT(google-explicit-constructor): implicit by design
  Result(Error error) : v_(std::move(error)) {}  // NOLINT(google-explicit-constructor)

  bool ok() const { return v_.index() == 0; }
  explicit operator bool() const { return ok(); }

  T& value() & {
    assert(ok());
    return std::get<0>(v_);
  }
  const T& value() const& {
    assert(ok());
    return std::get<0>(v_);
  }
  T&& value() && {
    assert(ok());
    return std::get<0>(std::move(v_));
  }
  const Error& error() const {
    assert(!ok());
    return std::get<1>(v_);
  }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }

 private:
  std::variant<T, Error> v_;
};

struct Ok {};
using Status = Result<Ok>;

inline Error makeError(ErrorCode code, std::string message) { return Error{code, std::move(message)}; }

}  // namespace vox
