// Cloud sources over a byte stream of PCD files (see pcd_stream.h): standard input
// (`camera | relmap-robot run …`), or TCP connections from the camera's side, which
// relmap-robot listens for — a camera script needs no more than bash's
// `cat frame.pcd > /dev/tcp/HOST/PORT` per frame, or one connection for all of them.
#pragma once

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "cloud_source.h"
#include "pcd_stream.h"
#include "posix_io.h"

namespace relmap::robot {

// The PCD files of one stream (standard input, a pipe), in order.
class StreamSource final : public CloudSource {
 public:
  // Reads `fd`, which it does not own; `stop` ends a wait for bytes.
  StreamSource(int fd, const std::atomic<bool>* stop);
  // nullopt at the end of the stream (or on a stop); DATA_LOSS when it ends inside a
  // file, INVALID_ARGUMENT when it holds something else than PCD files.
  StatusOr<std::optional<SourceFrame>> Next() override;

 private:
  PcdStream stream_;
};

// The PCD files sent by cameras that connect, one connection at a time: when one ends
// between two files, the next connection is awaited.
class TcpSource final : public CloudSource {
 public:
  struct Options {
    // Give up waiting for a connection (or its next file) after this long; 0: wait
    // until stopped.
    std::chrono::milliseconds wait_timeout{0};
  };
  // Listens on `address` ("host:port"; port 0 picks a free one).
  static StatusOr<std::unique_ptr<TcpSource>> Listen(const std::string& address, Options options,
                                                     const std::atomic<bool>* stop);
  // The port it listens on.
  int port() const { return LocalPort(listener_.get()); }

  // nullopt when the wait timed out or was stopped. A connection that ends inside a
  // file or sends something else than PCD is closed, and that is the error.
  StatusOr<std::optional<SourceFrame>> Next() override;

 private:
  TcpSource(UniqueFd listener, Options options, const std::atomic<bool>* stop);

  UniqueFd listener_;
  Options options_;
  const std::atomic<bool>* stop_;
  UniqueFd connection_;
  std::optional<PcdStream> stream_;
};

}  // namespace relmap::robot
