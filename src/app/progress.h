#pragma once
// Progress of a long command on stderr: done of total, rate, time left.
// Drawn in place on one line, and only when stderr is a terminal (a log
// file or a pipe gets none) and --quiet was not given. Safe to call from
// several threads (plan's candidates).
#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>

namespace coilsim::app {

class Progress {
 public:
  // `label` starts the line ("run scenes/default.json"); `total` units of
  // `unit` ("s simulated", "runs", "evaluations") make the whole job, 0 when
  // unknown (then no ETA).
  Progress(std::string label, double total, std::string unit);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // `done` units so far; `note` ends the line ("coil 2 of 3: filling-4x80").
  // Redraws at most ten times a second; cheap to call every step.
  void update(double done, const std::string& note = "");
  // A line that stays ("candidate 2 of 9 started"): printed above the
  // progress line on a terminal, nowhere otherwise.
  void note(const std::string& line);
  // A line of the command's own log on stderr, always printed (terminal or
  // not); on a terminal the progress line is cleared first so they do not mix.
  void line(const std::string& text);
  // Clears the progress line (the destructor does too).
  void finish();

  // Wall seconds since construction.
  double seconds() const;

  // Whether progress is drawn at all: stderr is a terminal and not quiet.
  static bool shown();
  // --quiet: no progress for the rest of the process.
  static void setQuiet(bool quiet);

  // "12.3 s", "4 min 05 s", "1 h 02 min".
  static std::string duration(double seconds);

 private:
  void draw(double done, const std::string& note);  // mutex held

  using Clock = std::chrono::steady_clock;
  std::string label_, unit_;
  double total_;
  Clock::time_point start_, last_;
  bool drawn_ = false;
  std::mutex mutex_;
};

}  // namespace coilsim::app
