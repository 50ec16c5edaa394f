#include "slamtune/slam/front_end_evidence.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::slam {

SequentialMatchStep StepOf(const ProcessResult& result, int log_index, double time, const MapperParams& params) {
  SLAMTUNE_CHECK(result.sequential_response >= 0.0);
  SequentialMatchStep s;
  s.log_index = log_index;
  s.time = time;
  s.response = result.sequential_response;
  s.x = result.sequential_mean.x;
  s.y = result.sequential_mean.y;
  s.dx = result.sequential_mean.x - result.sequential_guess.x;
  s.dy = result.sequential_mean.y - result.sequential_guess.y;
  s.dtheta = NormalizeAngle(result.sequential_mean.theta - result.sequential_guess.theta);
  // Principal standard deviations of the positional covariance: the larger one is the match's
  // positional uncertainty, their ratio says whether the scan constrained both directions.
  const double a = result.sequential_covariance(0, 0), b = result.sequential_covariance(0, 1);
  const double d = result.sequential_covariance(1, 1);
  const double mid = 0.5 * (a + d), spread = std::hypot(0.5 * (a - d), b);
  s.sigma_xy = std::sqrt(std::max(0.0, mid + spread));
  s.sigma_minor = std::sqrt(std::max(0.0, mid - spread));
  // The search offsets run to +-D/2 in steps of rho (§4.2); the mean of the best poses of a
  // match that hit the border lies within a step or so of it.
  const double half = 0.5 * params.correlation_search_space_dimension;
  const double rho = params.correlation_search_space_resolution;
  s.at_window_edge = std::max(std::fabs(s.dx), std::fabs(s.dy)) >= half - 1.5 * rho;
  s.at_heading_edge = std::fabs(s.dtheta) >= params.coarse_search_angle_offset - params.coarse_angle_resolution;
  return s;
}

void FrontEndEvidenceOptions::Validate() const {
  if (!(low_response_fraction > 0.0 && low_response_fraction < 1.0)) {
    throw InputError(
        fmt::format("FrontEndEvidenceOptions.low_response_fraction = {}: must be in (0, 1)", low_response_fraction));
  }
  if (max_gap < 0) throw InputError(fmt::format("FrontEndEvidenceOptions.max_gap = {}: must be >= 0", max_gap));
  if (min_suspects < 1) {
    throw InputError(fmt::format("FrontEndEvidenceOptions.min_suspects = {}: must be >= 1", min_suspects));
  }
  if (!(break_response_fraction > 0.0 && break_response_fraction <= low_response_fraction)) {
    throw InputError(
        fmt::format("FrontEndEvidenceOptions.break_response_fraction = {}: must be in (0, "
                    "low_response_fraction = {}]",
                    break_response_fraction, low_response_fraction));
  }
  if (recovery_matches < 1) {
    throw InputError(fmt::format("FrontEndEvidenceOptions.recovery_matches = {}: must be >= 1", recovery_matches));
  }
  if (!(recovered_fraction > 0.0 && recovered_fraction < 1.0)) {
    throw InputError(
        fmt::format("FrontEndEvidenceOptions.recovered_fraction = {}: must be in (0, 1)", recovered_fraction));
  }
  if (!(degenerate_anisotropy > 1.0 && std::isfinite(degenerate_anisotropy))) {
    throw InputError(
        fmt::format("FrontEndEvidenceOptions.degenerate_anisotropy = {}: must be a number > 1", degenerate_anisotropy));
  }
  if (!(min_degenerate_length_m > 0.0 && std::isfinite(min_degenerate_length_m))) {
    throw InputError(fmt::format("FrontEndEvidenceOptions.min_degenerate_length_m = {}: must be a number > 0",
                                 min_degenerate_length_m));
  }
}

bool IsDegenerate(const SequentialMatchStep& step, const FrontEndEvidenceOptions& options) {
  return step.sigma_xy > 0.0 && step.sigma_xy >= options.degenerate_anisotropy * step.sigma_minor;
}

std::vector<DegenerateStretch> FindDegenerateStretches(const std::vector<SequentialMatchStep>& steps,
                                                       const FrontEndEvidenceOptions& options) {
  std::vector<DegenerateStretch> out;
  DegenerateStretch current;
  std::size_t first = 0, last = 0;  // indices of the current stretch's first and last degenerate step
  auto close = [&] {
    if (current.matches == 0) return;
    for (std::size_t k = first + 1; k <= last; ++k) {
      current.length_m += std::hypot(steps[k].x - steps[k - 1].x, steps[k].y - steps[k - 1].y);
    }
    if (current.length_m >= options.min_degenerate_length_m) out.push_back(current);
    current = {};
  };
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const SequentialMatchStep& s = steps[i];
    if (!IsDegenerate(s, options)) continue;
    if (current.matches > 0 && i - last > static_cast<std::size_t>(options.max_gap) + 1) close();
    if (current.matches == 0) {
      first = i;
      current.first_log_index = s.log_index;
      current.first_time = s.time;
    }
    last = i;
    current.last_log_index = s.log_index;
    current.last_time = s.time;
    ++current.matches;
    const double ratio = s.sigma_minor > 0.0 ? s.sigma_xy / s.sigma_minor : HUGE_VAL;
    current.max_anisotropy = std::max(current.max_anisotropy, ratio);
  }
  close();
  return out;
}

bool IsSuspect(const SequentialMatchStep& step, double median_response, const FrontEndEvidenceOptions& options) {
  return step.at_window_edge || step.at_heading_edge || step.response < options.low_response_fraction * median_response;
}

bool IsBreak(const std::vector<SequentialMatchStep>& steps, std::size_t i, double median_response,
             const FrontEndEvidenceOptions& options) {
  const SequentialMatchStep& s = steps[i];
  if (!(s.at_window_edge || s.at_heading_edge)) return false;
  if (!(s.response < options.break_response_fraction * median_response)) return false;
  double x = 0.0, y = 0.0, theta = 0.0;  // net correction of the step and the ones after it
  const std::size_t end = std::min(steps.size(), i + 1 + static_cast<std::size_t>(options.recovery_matches));
  for (std::size_t k = i; k < end; ++k) {
    x += steps[k].dx;
    y += steps[k].dy;
    theta += steps[k].dtheta;
  }
  const double f = options.recovered_fraction;
  if (s.at_heading_edge) return std::fabs(theta) >= f * std::fabs(s.dtheta);
  return std::hypot(x, y) >= f * std::hypot(s.dx, s.dy);
}

FrontEndEvidence AssessFrontEnd(const std::vector<SequentialMatchStep>& steps, const FrontEndEvidenceOptions& options) {
  options.Validate();
  FrontEndEvidence out;
  out.matches = static_cast<int>(steps.size());
  if (steps.empty()) return out;
  std::vector<double> responses;
  for (const auto& s : steps) responses.push_back(s.response);
  std::nth_element(responses.begin(), responses.begin() + static_cast<long>(responses.size() / 2), responses.end());
  out.median_response = responses[responses.size() / 2];

  SuspectStretch current;
  int last_suspect = -1;  // index into steps
  auto close = [&] {
    if (current.suspects >= options.min_suspects || current.strong()) out.stretches.push_back(current);
    current = {};
  };
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const SequentialMatchStep& s = steps[i];
    const bool edge = s.at_window_edge || s.at_heading_edge;
    const bool low = s.response < options.low_response_fraction * out.median_response;
    const bool broke = IsBreak(steps, i, out.median_response, options);
    out.at_edge += edge ? 1 : 0;
    out.low_response += low ? 1 : 0;
    out.breaks += broke ? 1 : 0;
    if (!edge && !low) continue;
    if (current.suspects > 0 && static_cast<int>(i) - last_suspect > options.max_gap + 1) close();
    if (current.suspects == 0) {
      current.first_log_index = s.log_index;
      current.first_time = s.time;
    }
    current.last_log_index = s.log_index;
    current.last_time = s.time;
    ++current.suspects;
    current.at_edge += edge ? 1 : 0;
    current.low_response += low ? 1 : 0;
    current.breaks += broke ? 1 : 0;
    current.min_response = std::min(current.min_response, s.response);
    last_suspect = static_cast<int>(i);
  }
  if (current.suspects > 0) close();
  for (const SequentialMatchStep& s : steps) out.degenerate += IsDegenerate(s, options) ? 1 : 0;
  out.degenerate_stretches = FindDegenerateStretches(steps, options);
  return out;
}

namespace {

std::string BreakSummary(const std::vector<const SuspectStretch*>& strong) {
  std::string parts;
  const std::size_t shown = std::min<std::size_t>(strong.size(), 3);
  for (std::size_t k = 0; k < shown; ++k) {
    const SuspectStretch& s = *strong[k];
    std::string what;
    if (s.at_edge > 0) what = fmt::format("{} match{} at the search's edge", s.at_edge, s.at_edge == 1 ? "" : "es");
    if (s.low_response > 0) {
      what += fmt::format("{}{} with a collapsed response (down to {:.2f})", what.empty() ? "" : ", ", s.low_response,
                          s.min_response);
    }
    parts += fmt::format("{}scans {}-{}, {:.1f}-{:.1f} s into the log: {}", k ? "; " : "", s.first_log_index,
                         s.last_log_index, s.first_time, s.last_time, what);
  }
  if (strong.size() > shown) parts += fmt::format("; {} more", strong.size() - shown);
  return fmt::format("front end: {} stretch{} where sequential matching lost its place ({})", strong.size(),
                     strong.size() == 1 ? "" : "es", parts);
}

std::string DegenerateSummary(const std::vector<DegenerateStretch>& stretches) {
  std::string parts;
  const std::size_t shown = std::min<std::size_t>(stretches.size(), 3);
  for (std::size_t k = 0; k < shown; ++k) {
    const DegenerateStretch& s = stretches[k];
    parts += fmt::format("{}scans {}-{}, {:.1f}-{:.1f} s into the log: {:.0f} m", k ? "; " : "", s.first_log_index,
                         s.last_log_index, s.first_time, s.last_time, s.length_m);
  }
  if (stretches.size() > shown) parts += fmt::format("; {} more", stretches.size() - shown);
  return fmt::format(
      "front end: {} stretch{} where the scans saw structure in one direction only and the map "
      "follows the odometry along it ({})",
      stretches.size(), stretches.size() == 1 ? "" : "es", parts);
}

}  // namespace

std::string FrontEndEvidence::Summary() const {
  if (matches == 0) return "front end: no sequential match was made";
  if (!points_at_front_end()) {
    return fmt::format(
        "front end: no sign of a broken sequential match ({} matches, median response {:.2f}; {} "
        "at the search's edge, {} with a collapsed response, {} minor stretch{})",
        matches, median_response, at_edge, low_response, stretches.size(), stretches.size() == 1 ? "" : "es");
  }
  std::vector<const SuspectStretch*> strong;
  for (const SuspectStretch& s : stretches)
    if (s.strong()) strong.push_back(&s);
  std::string lines;
  if (!strong.empty()) lines = BreakSummary(strong);
  if (!degenerate_stretches.empty()) {
    if (!lines.empty()) lines += '\n';
    lines += DegenerateSummary(degenerate_stretches);
  }
  return lines;
}

BreakWatch::BreakWatch(const FrontEndEvidenceOptions& options, int min_matches)
    : options_(options), min_matches_(min_matches) {
  options_.Validate();
  SLAMTUNE_CHECK(min_matches_ >= 1);
}

void BreakWatch::Insert(double response) {
  if (low_.empty() || response <= low_.front()) {
    low_.push_back(response);
    std::push_heap(low_.begin(), low_.end());
  } else {
    high_.push_back(response);
    std::push_heap(high_.begin(), high_.end(), std::greater<>());
  }
  // Balance: low_ holds the lower half, one more when the count is odd.
  if (low_.size() > high_.size() + 1) {
    std::pop_heap(low_.begin(), low_.end());
    high_.push_back(low_.back());
    low_.pop_back();
    std::push_heap(high_.begin(), high_.end(), std::greater<>());
  } else if (high_.size() > low_.size()) {
    std::pop_heap(high_.begin(), high_.end(), std::greater<>());
    low_.push_back(high_.back());
    high_.pop_back();
    std::push_heap(low_.begin(), low_.end());
  }
}

// The element AssessFrontEnd takes as the median: index n / 2 of the sorted responses.
double BreakWatch::Median() const { return low_.size() > high_.size() ? low_.front() : high_.front(); }

std::optional<std::size_t> BreakWatch::Add(const std::vector<SequentialMatchStep>& steps) {
  SLAMTUNE_CHECK(steps.size() == seen_ + 1);
  ++seen_;
  Insert(steps.back().response);
  if (seen_ < static_cast<std::size_t>(min_matches_)) return std::nullopt;
  // Every step whose recovery matches are all in now and that was not judged yet.
  const auto delay = static_cast<std::size_t>(options_.recovery_matches);
  const double median = Median();
  while (next_ + delay < seen_) {
    const std::size_t i = next_++;
    if (IsBreak(steps, i, median, options_)) return i;
  }
  return std::nullopt;
}

}  // namespace slamtune::slam
