// relmap's error vocabulary: a Status (code + message, and a reason where a client
// acts on the error) and StatusOr<T>. The codes are gRPC's canonical codes, so the
// service edge maps them one to one.
#pragma once

#include <cassert>
#include <map>
#include <string>
#include <utility>
#include <variant>

namespace relmap {

enum class StatusCode {
  kOk = 0,
  kCancelled = 1,
  kUnknown = 2,
  kInvalidArgument = 3,
  kDeadlineExceeded = 4,
  kNotFound = 5,
  kAlreadyExists = 6,
  kPermissionDenied = 7,
  kResourceExhausted = 8,
  kFailedPrecondition = 9,
  kAborted = 10,
  kOutOfRange = 11,
  kUnimplemented = 12,
  kInternal = 13,
  kUnavailable = 14,
  kDataLoss = 15,
  kUnauthenticated = 16,
};

// Why an error happened, for the errors a client acts on; the API sends it as the
// relmap.v1.ErrorReason of the same name (proto/relmap/v1/error_reason.proto, which
// says what each means and which metadata it has).
enum class ErrorReason { kNone, kFrameGone, kSessionOwnedElsewhere, kBusy };

// The outcome of an operation that can fail. Cheap to copy when ok.
class [[nodiscard]] Status {
 public:
  using Metadata = std::map<std::string, std::string>;

  Status() = default;
  Status(StatusCode code, std::string message) : code_(code), message_(std::move(message)) {}

  bool ok() const { return code_ == StatusCode::kOk; }
  StatusCode code() const { return code_; }
  const std::string& message() const { return message_; }
  ErrorReason reason() const { return reason_; }
  // Facts about this error for programs, lowerCamelCase keys, as its reason documents.
  const Metadata& metadata() const { return metadata_; }

  // This error with a reason and its metadata; code and message stay.
  Status WithReason(ErrorReason reason, Metadata metadata = {}) const {
    Status status = *this;
    status.reason_ = reason;
    status.metadata_ = std::move(metadata);
    return status;
  }

 private:
  StatusCode code_ = StatusCode::kOk;
  std::string message_;
  ErrorReason reason_ = ErrorReason::kNone;
  Metadata metadata_;
};

inline Status OkStatus() { return {}; }
inline Status InvalidArgumentError(std::string m) {
  return {StatusCode::kInvalidArgument, std::move(m)};
}
inline Status NotFoundError(std::string m) { return {StatusCode::kNotFound, std::move(m)}; }
inline Status FailedPreconditionError(std::string m) {
  return {StatusCode::kFailedPrecondition, std::move(m)};
}
inline Status ResourceExhaustedError(std::string m) {
  return {StatusCode::kResourceExhausted, std::move(m)};
}
inline Status InternalError(std::string m) { return {StatusCode::kInternal, std::move(m)}; }
inline Status DataLossError(std::string m) { return {StatusCode::kDataLoss, std::move(m)}; }

// Either a value or a non-ok Status.
template <typename T>
class [[nodiscard]] StatusOr {
 public:
  StatusOr(T value) : state_(std::move(value)) {}        // NOLINT: implicit by design
  StatusOr(Status status) : state_(std::move(status)) {  // NOLINT: implicit by design
    assert(!std::get<Status>(state_).ok() && "StatusOr needs a value or an error");
  }

  bool ok() const { return std::holds_alternative<T>(state_); }
  Status status() const { return ok() ? OkStatus() : std::get<Status>(state_); }

  const T& value() const& { return std::get<T>(state_); }
  T& value() & { return std::get<T>(state_); }
  T&& value() && { return std::get<T>(std::move(state_)); }
  const T& operator*() const& { return value(); }
  T& operator*() & { return value(); }
  const T* operator->() const { return &value(); }
  T* operator->() { return &value(); }

 private:
  std::variant<T, Status> state_;
};

}  // namespace relmap
