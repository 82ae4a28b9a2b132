// PCD files from standard input or from TCP connections.
#include "stream_source.h"

#include <sys/socket.h>

#include <cerrno>
#include <cstring>

#include "relevance_client.h"

namespace relmap::robot {
namespace {

StatusOr<std::optional<SourceFrame>> AsFrame(StatusOr<std::optional<std::string>> pcd) {
  if (!pcd.ok()) return pcd.status();
  if (!pcd->has_value()) return std::optional<SourceFrame>();
  SourceFrame frame;
  frame.cloud = client::PcdCloud(std::move(**pcd));
  return std::optional<SourceFrame>(std::move(frame));
}

}  // namespace

StreamSource::StreamSource(int fd, const std::atomic<bool>* stop) : stream_(fd, stop) {}

StatusOr<std::optional<SourceFrame>> StreamSource::Next() { return AsFrame(stream_.Next()); }

StatusOr<std::unique_ptr<TcpSource>> TcpSource::Listen(const std::string& address, Options options,
                                                       const std::atomic<bool>* stop) {
  StatusOr<UniqueFd> listener = ListenTcp(address);
  if (!listener.ok()) return listener.status();
  return std::unique_ptr<TcpSource>(new TcpSource(std::move(listener).value(), options, stop));
}

TcpSource::TcpSource(UniqueFd listener, Options options, const std::atomic<bool>* stop)
    : listener_(std::move(listener)), options_(options), stop_(stop) {}

StatusOr<std::optional<SourceFrame>> TcpSource::Next() {
  const Clock::time_point deadline = options_.wait_timeout.count() > 0
                                         ? Clock::now() + options_.wait_timeout
                                         : Clock::time_point::max();
  for (;;) {
    if (!connection_.valid()) {
      StatusOr<Wait> ready = WaitReadable(listener_.get(), deadline, stop_);
      if (!ready.ok()) return ready.status();
      if (*ready != Wait::kReady) return std::optional<SourceFrame>();
      connection_.reset(::accept4(listener_.get(), nullptr, nullptr, SOCK_CLOEXEC));
      if (!connection_.valid()) {
        if (errno == EINTR || errno == ECONNABORTED) continue;
        return Status(StatusCode::kUnavailable, std::string("accept: ") + std::strerror(errno));
      }
      stream_.emplace(connection_.get(), stop_);
    }
    // The next file of this connection, within what is left of the wait.
    StatusOr<std::optional<SourceFrame>> frame = AsFrame(stream_->Next(deadline));
    if (frame.ok() && frame->has_value()) return frame;
    if (frame.ok() && !stream_->ended()) return frame;  // stopped or timed out
    // Ended between two files (wait for the next camera), or broken: closed either way.
    stream_.reset();
    connection_.reset();
    if (!frame.ok()) return frame.status();
  }
}

}  // namespace relmap::robot
