#include "app/progress.h"

#include <unistd.h>

#include <atomic>
#include <cmath>

namespace coilsim::app {
namespace {

std::atomic<bool> quietFlag{false};

// Erases the current terminal line.
constexpr const char* kClearLine = "\r\033[K";

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

}  // namespace

Progress::Progress(std::string label, double total, std::string unit)
    : label_(std::move(label)), unit_(std::move(unit)), total_(total), start_(Clock::now()), last_(start_) {}

Progress::~Progress() { finish(); }

bool Progress::shown() { return !quietFlag && isatty(STDERR_FILENO); }

void Progress::setQuiet(bool quiet) { quietFlag = quiet; }

double Progress::seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

std::string Progress::duration(double s) {
  char buf[48];
  if (!std::isfinite(s)) return "?";
  if (s < 60)
    std::snprintf(buf, sizeof buf, "%.0f s", s);
  else if (s < 3600)
    std::snprintf(buf, sizeof buf, "%d min %02d s", int(s / 60), int(std::fmod(s, 60)));
  else
    std::snprintf(buf, sizeof buf, "%d h %02d min", int(s / 3600), int(std::fmod(s, 3600) / 60));
  return buf;
}

void Progress::update(double done, const std::string& note) {
  if (!shown()) return;
  const auto now = Clock::now();
  std::lock_guard lock(mutex_);
  // The first line after half a second, then ten a second: a quick command draws nothing.
  if (now - last_ < std::chrono::milliseconds(drawn_ ? 100 : 500)) return;
  last_ = now;
  draw(done, note);
}

void Progress::draw(double done, const std::string& note) {
  const double elapsed = seconds();
  const double rate = elapsed > 0 ? done / elapsed : 0;
  std::string line = label_ + ": " + number(done);
  if (total_ > 0) line += " of " + number(total_);
  line += " " + unit_;
  if (total_ > 0) line += " (" + std::to_string(int(std::floor(100 * done / total_ + 1e-6))) + " %)";  // 60 of 60 mm summed in metres is 99.99...
  line += ", " + number(rate) + " " + unit_ + " per s";
  if (total_ > 0 && rate > 0) line += ", ETA " + duration((total_ - done) / rate);
  if (!note.empty()) line += "; " + note;
  std::fprintf(stderr, "%s%s", kClearLine, line.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void Progress::note(const std::string& line) {
  if (!shown()) return;
  std::lock_guard lock(mutex_);
  std::fprintf(stderr, "%s%s: %s\n", kClearLine, label_.c_str(), line.c_str());
  std::fflush(stderr);
  last_ = Clock::time_point{};  // redraw the progress line at the next update
  drawn_ = true;
}

void Progress::line(const std::string& text) {
  std::lock_guard lock(mutex_);
  std::fprintf(stderr, "%s%s\n", drawn_ && shown() ? kClearLine : "", text.c_str());
  std::fflush(stderr);
  if (drawn_) last_ = Clock::time_point{};
}

void Progress::finish() {
  std::lock_guard lock(mutex_);
  if (!drawn_ || !shown()) return;
  std::fprintf(stderr, "%s", kClearLine);
  std::fflush(stderr);
  drawn_ = false;
}

}  // namespace coilsim::app
