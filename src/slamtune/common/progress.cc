#include "slamtune/common/progress.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cmath>

namespace slamtune {

Progress::Progress(Mode mode, double interval_s, std::FILE* out) : mode_(mode), interval_s_(interval_s), out_(out) {
  if (mode_ == Mode::kAuto) mode_ = isatty(fileno(out_)) ? Mode::kLive : Mode::kPlain;
  last_ = std::chrono::steady_clock::now();
}

Progress::~Progress() {
  if (live_open_) std::fputc('\n', out_);
}

void Progress::Update(const std::string& line, bool force) {
  if (mode_ == Mode::kQuiet) return;
  std::lock_guard guard(mutex_);
  const auto now = std::chrono::steady_clock::now();
  if (mode_ == Mode::kLive) {
    if (!force && std::chrono::duration<double>(now - last_).count() < 0.2 && printed_once_) return;
    std::string padded = line;
    if (padded.size() < last_width_) padded.append(last_width_ - padded.size(), ' ');
    std::fprintf(out_, "\r%s", padded.c_str());
    std::fflush(out_);
    last_width_ = line.size();
    live_open_ = true;
  } else {
    if (!force && printed_once_ && std::chrono::duration<double>(now - last_).count() < interval_s_) return;
    std::fprintf(out_, "%s\n", line.c_str());
    std::fflush(out_);
  }
  printed_once_ = true;
  last_ = now;
}

void Progress::Finish(const std::string& line) {
  if (mode_ == Mode::kQuiet) return;
  std::lock_guard guard(mutex_);
  if (live_open_) {
    std::fputc('\n', out_);
    live_open_ = false;
  }
  if (!line.empty()) std::fprintf(out_, "%s\n", line.c_str());
  std::fflush(out_);
}

std::string FormatDuration(double s) {
  if (!std::isfinite(s) || s < 0) return "?";
  const long total = std::lround(s);
  if (total >= 3600) return fmt::format("{}h{:02}m", total / 3600, (total % 3600) / 60);
  if (total >= 60) return fmt::format("{}m{:02}s", total / 60, total % 60);
  return fmt::format("{}s", total);
}

std::string FormatCount(double n) {
  if (!std::isfinite(n) || n < 0) return "?";
  if (n < 999.5) return fmt::format("{}", std::lround(n));
  static constexpr const char* kUnits[] = {"k", "M", "G", "T"};
  int unit = -1;
  // Divide until the mantissa, as it will be printed, is below 1000 (999.96 k prints 1.00 M).
  while (unit < 3 && n >= 999.5) {
    n /= 1000.0;
    ++unit;
  }
  const char* format = n < 9.995 ? "{:.2f} {}" : n < 99.95 ? "{:.1f} {}" : "{:.0f} {}";
  return fmt::format(fmt::runtime(format), n, kUnits[unit]);
}

}  // namespace slamtune
