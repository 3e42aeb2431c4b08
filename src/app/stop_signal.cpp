#include "app/stop_signal.h"

#include <atomic>
#include <csignal>

namespace coilsim::app {
namespace {

std::atomic<int> stopSignalNumber{0};
static_assert(std::atomic<int>::is_always_lock_free, "set from a signal handler");

extern "C" void onStopSignal(int signal) { stopSignalNumber.store(signal); }

}  // namespace

void installStopHandlers() {
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;  // the second signal takes the default action: a stuck run still ends
  for (const int s : {SIGINT, SIGTERM}) sigaction(s, &action, nullptr);
}

bool stopRequested() { return stopSignalNumber.load(std::memory_order_relaxed) != 0; }

int stopExitCode() {
  const int s = stopSignalNumber.load();
  return s ? 128 + s : 0;
}

const char* stopReason() {
  return stopSignalNumber.load() == SIGTERM ? "terminated (SIGTERM)" : "interrupted (SIGINT)";
}

}  // namespace coilsim::app
