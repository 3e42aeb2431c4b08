#pragma once
// Contact detection on a second thread. Each segment's wall query and each
// grid cell's pair visits are independent of the others, so detection is
// split into two parts of about equal work, one per thread, each with its
// own scratch and its own output; the caller then joins the outputs in the
// parts' order. The contacts, their order and every bit of them are
// therefore those of one thread, whatever the thread count
// (tests/physics/contact/detect_parallel_test.cpp).
//
// A plain std::thread kept waiting on a condition variable rather than
// OpenMP: the work is exactly two parts with a join in a fixed order, the
// thread must belong to one State (plan candidates step States on threads
// of their own, and OpenMP's team would be shared among them or nested
// under them), and a waiting worker must not spin on a machine whose two
// cores are shared (libgomp spins by default).
#include <functional>
#include <memory>

namespace coilsim {

struct ContactScratch;

class DetectionThreads {
 public:
  DetectionThreads();
  ~DetectionThreads();
  // A copy (a State copied for a plan candidate or a snapshot) has the
  // same count and its own thread, started when it first needs one.
  DetectionThreads(const DetectionThreads& other);
  DetectionThreads& operator=(const DetectionThreads& other);

  // How many threads detection uses: 1 (the caller's only) or 2.
  int count() const { return count_; }
  // Sets the count; values outside [1, 2] are clamped into it.
  void setCount(int n);
  // Below this many segments a detection stays on the caller's thread:
  // handing half of it to the other thread costs tens of microseconds.
  // (Tests set 0, to split small problems.)
  int minSegmentsToSplit = 200;
  // How many detections were split over two threads so far.
  long splits() const { return splits_; }

  // Whether a detection over `segments` segments is split.
  bool splits(long segments) const { return count_ > 1 && segments >= minSegmentsToSplit; }

  // Calls part(0, main) and part(1, s): on two threads when count() is 2
  // and `split` (s is then the worker's own scratch), else one after the
  // other on this thread (s is `main`). Returns when both are done; an
  // exception of the worker's part is rethrown here.
  void run(bool split, ContactScratch& main, const std::function<void(int, ContactScratch&)>& part);

 private:
  struct Worker;
  int count_ = 1;
  long splits_ = 0;
  std::unique_ptr<Worker> worker_;
};

}  // namespace coilsim
