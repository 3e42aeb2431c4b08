#include "physics/contact/detect_parallel.h"

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>

#include "physics/contact/scratch.h"

namespace coilsim {

// One thread waiting for a part to run. `job` is set, then `pending`; the
// thread runs it, clears `pending` and signals.
struct DetectionThreads::Worker {
  std::mutex mutex;
  std::condition_variable wake, done;
  const std::function<void(int, ContactScratch&)>* job = nullptr;
  bool pending = false, stop = false;
  std::exception_ptr error;
  ContactScratch scratch;
  std::thread thread;

  Worker() : thread([this] { loop(); }) {}
  ~Worker() {
    {
      std::lock_guard<std::mutex> lock(mutex);
      stop = true;
    }
    wake.notify_one();
    thread.join();
  }
  void loop() {
    std::unique_lock<std::mutex> lock(mutex);
    for (;;) {
      wake.wait(lock, [this] { return pending || stop; });
      if (stop) return;
      lock.unlock();
      std::exception_ptr e;
      try {
        (*job)(1, scratch);
      } catch (...) {
        e = std::current_exception();
      }
      lock.lock();
      error = e;
      pending = false;
      done.notify_one();
    }
  }
};

DetectionThreads::DetectionThreads() = default;
DetectionThreads::~DetectionThreads() = default;
DetectionThreads::DetectionThreads(const DetectionThreads& other)
    : minSegmentsToSplit(other.minSegmentsToSplit), count_(other.count_) {}
DetectionThreads& DetectionThreads::operator=(const DetectionThreads& other) {
  count_ = other.count_;  // the thread stays this object's own
  minSegmentsToSplit = other.minSegmentsToSplit;
  return *this;
}

void DetectionThreads::setCount(int n) {
  count_ = std::clamp(n, 1, 2);
  if (count_ == 1) worker_.reset();
}

void DetectionThreads::run(bool split, ContactScratch& main, const std::function<void(int, ContactScratch&)>& part) {
  if (!split || count_ < 2) {
    part(0, main);
    part(1, main);
    return;
  }
  if (!worker_) worker_ = std::make_unique<Worker>();
  ++splits_;
  Worker& w = *worker_;
  {
    std::lock_guard<std::mutex> lock(w.mutex);
    w.job = &part;
    w.pending = true;
  }
  w.wake.notify_one();
  std::exception_ptr mine;
  try {
    part(0, main);
  } catch (...) {
    mine = std::current_exception();
  }
  std::unique_lock<std::mutex> lock(w.mutex);
  w.done.wait(lock, [&] { return !w.pending; });
  w.job = nullptr;
  if (mine) std::rethrow_exception(mine);
  if (w.error) std::rethrow_exception(std::exchange(w.error, nullptr));
}

}  // namespace coilsim
