// An exclusive advisory lock on a file (flock), held for an object's lifetime: how
// a process claims a resource that only one process may use at a time. The kernel
// drops it when the process dies, however it dies.
#pragma once

#include <string>

#include "common/status.h"

namespace relmap::session {

class FileLock {
 public:
  // Creates `path` if needed and locks it without waiting. Held by another process
  // (or another FileLock of this one) → FAILED_PRECONDITION; a file that cannot be
  // created → UNAVAILABLE.
  static StatusOr<FileLock> Acquire(const std::string& path);
  FileLock() = default;  // holds nothing
  FileLock(FileLock&& other) noexcept;
  FileLock& operator=(FileLock&& other) noexcept;
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;
  ~FileLock();

 private:
  explicit FileLock(int fd) : fd_(fd) {}
  int fd_ = -1;
};

}  // namespace relmap::session
