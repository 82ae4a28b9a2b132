// pthread_sigmask before any thread, sigwait in the one that drains.
#include "stop_signals.h"

#include <pthread.h>

namespace relmap::server {

StopSignals StopSignals::Block() {
  StopSignals stop;
  sigemptyset(&stop.signals_);
  sigaddset(&stop.signals_, SIGINT);
  sigaddset(&stop.signals_, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop.signals_, nullptr);
  return stop;
}

int StopSignals::Wait() {
  int signal = 0;
  sigwait(&signals_, &signal);
  return signal;
}

}  // namespace relmap::server
