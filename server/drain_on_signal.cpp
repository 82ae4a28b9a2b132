// In-flight calls get 10 s after the drain before the shutdown cancels them.
#include "drain_on_signal.h"

#include <grpcpp/health_check_service_interface.h>
#include <spdlog/spdlog.h>

#include <chrono>

namespace relmap::server {

DrainOnSignal::DrainOnSignal(StopSignals& signals, grpc::Server& server, long long drain_seconds)
    : thread_([&signals, &server, drain_seconds] {
        const int signal = signals.Wait();
        server.GetHealthCheckService()->SetServingStatus(false);
        spdlog::info("signal {}: NOT_SERVING, draining for {} s, then stopping", signal,
                     drain_seconds);
        std::this_thread::sleep_for(std::chrono::seconds(drain_seconds));
        server.Shutdown(std::chrono::system_clock::now() + std::chrono::seconds(10));
      }) {}

DrainOnSignal::~DrainOnSignal() { thread_.join(); }

}  // namespace relmap::server
