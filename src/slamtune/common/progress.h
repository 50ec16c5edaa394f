// Progress on long work, written to stderr: on a terminal one live line rewritten in place;
// otherwise (CI logs, pipes) a plain line at most every `interval_s` seconds; nothing when
// quiet. Thread-safe: workers may call Update concurrently.
#pragma once

#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>

namespace slamtune {

class Progress {
 public:
  enum class Mode { kAuto, kLive, kPlain, kQuiet };
  explicit Progress(Mode mode = Mode::kAuto, double interval_s = 10.0, std::FILE* out = stderr);
  ~Progress();

  // Shows `line` (live) or prints it if the plain interval has passed (or `force`).
  void Update(const std::string& line, bool force = false);
  // Ends the live line (newline) and prints `line` if not empty.
  void Finish(const std::string& line = "");
  bool quiet() const { return mode_ == Mode::kQuiet; }

 private:
  Mode mode_;
  double interval_s_;
  std::FILE* out_;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point last_;
  bool printed_once_ = false;
  bool live_open_ = false;
  std::size_t last_width_ = 0;
};

// "1h02m", "3m05s", "12s" for a duration in seconds (negative or non-finite -> "?").
std::string FormatDuration(double seconds);
// "950", "25.1 k", "1.20 M", "3.40 G" for a count (three significant digits from 1000 on;
// negative or non-finite -> "?").
std::string FormatCount(double count);

}  // namespace slamtune
