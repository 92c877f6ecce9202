// Errors as values for the tools/ layer: every fallible step returns a Status or a Result<T>.
#ifndef HULLPACK_TOOLS_COMMON_STATUS_H_
#define HULLPACK_TOOLS_COMMON_STATUS_H_

#include <optional>
#include <string>
#include <utility>

namespace hullpack {

enum class StatusCode {
  kOk = 0,
  kIoError,          // the file cannot be opened, read or written
  kUnknownFormat,    // no reader for this file type
  kParseError,       // the file is malformed or truncated
  kInvalidMesh,      // NaN/Inf coordinates, out-of-range indices, ...
  kInvalidArgument,  // a caller or command-line mistake
  kUnsupported,      // valid input this build cannot handle
  kCancelled,
  kInternal,
};

const char* StatusCodeName(StatusCode code);

class Status {
 public:
  Status() = default;
  Status(StatusCode code, std::string message) : code_(code), message_(std::move(message)) {}
  static Status Ok() { return Status(); }

  bool ok() const { return code_ == StatusCode::kOk; }
  StatusCode code() const { return code_; }
  const std::string& message() const { return message_; }
  // "parse error: <message>", or "ok".
  std::string ToString() const;

 private:
  StatusCode code_ = StatusCode::kOk;
  std::string message_;
};

// A value or the Status that explains why there is none.
template <typename T>
class Result {
 public:
  Result(T value) : value_(std::move(value)) {}          // NOLINT: implicit by design
  Result(Status status) : status_(std::move(status)) {}  // NOLINT
  bool ok() const { return status_.ok(); }
  const Status& status() const { return status_; }
  T& value() & { return *value_; }
  const T& value() const& { return *value_; }
  T&& value() && { return std::move(*value_); }
  T* operator->() { return &*value_; }
  const T* operator->() const { return &*value_; }

 private:
  Status status_;
  std::optional<T> value_;
};

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_COMMON_STATUS_H_
