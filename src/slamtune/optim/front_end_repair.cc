#include "slamtune/optim/front_end_repair.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "slamtune/common/error.h"
#include "slamtune/slam/log_runner.h"

namespace slamtune::optim {
namespace {

constexpr const char* kHeadingRange = "coarse_search_angle_offset";
constexpr const char* kWindow = "correlation_search_space_dimension";
constexpr double kLadder[] = {1.5, 2.0, 2.5, 3.0, 4.0};

const Dimension* FindDimension(const SearchSpace& space, const std::string& name) {
  for (const Dimension& d : space.dimensions) {
    if (d.name == name) return &d;
  }
  return nullptr;
}

// The values to try for `d` above `current`: the ladder's multiples of `base` rounded up to the
// dimension's lattice, then its upper bound, increasing, without repeats.
std::vector<double> LadderOf(const Dimension& d, double base, double current) {
  std::vector<double> values;
  for (const double factor : kLadder)
    values.push_back(d.ValueOf(std::ceil((base * factor - d.lower) / d.step) * d.step + d.lower));
  values.push_back(d.upper);
  std::vector<double> out;
  for (const double v : values) {
    if (v > current + 1e-12 && (out.empty() || v > out.back() + 1e-12)) out.push_back(v);
  }
  return out;
}

// Runs the log's prefix with `assignment` until `margin` sequential matches past log scan
// `at` (the base's break); true when no break was seen and no match from `at` on is suspect (at
// the search's edge, or a response below half the median so far): a search that is still too
// narrow need not end at its edge — it may settle on a wrong pose inside, with a poor fit.
bool Holds(const SlamEvaluationContext& context, const Assignment& assignment, int at, int margin) {
  slam::LogRunner runner(context.log, context.ParamsFor(assignment), context.shared_work);
  slam::BreakWatch watch;
  std::vector<double> responses;
  std::size_t seen = 0;
  int after = 0;
  while (!runner.Done()) {
    runner.Step();
    const std::vector<slam::SequentialMatchStep>& steps = runner.sequential_matches();
    if (steps.size() == seen) continue;
    seen = steps.size();
    if (watch.Add(steps)) return false;
    const slam::SequentialMatchStep& s = steps.back();
    responses.push_back(s.response);
    if (s.log_index < at) continue;
    std::vector<double> sorted = responses;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2), sorted.end());
    if (slam::IsSuspect(s, sorted[sorted.size() / 2], {})) return false;
    if (++after >= margin) return true;
  }
  return true;
}

std::string SettingText(const std::string& name, double v) {
  return name == kHeadingRange ? fmt::format("the heading range {:.2f} rad", v) : fmt::format("the window {:.2f} m", v);
}

}  // namespace

void FrontEndRepairOptions::Validate() const {
  if (margin_matches < 1) {
    throw InputError(
        fmt::format("front-end repair: margin_matches = {} is out of range: must be >= 1", margin_matches));
  }
}

std::string FrontEndRepair::Describe() const {
  if (tries.empty()) return "";
  std::string out = "informed start:";
  for (std::size_t i = 0; i < tries.size(); ++i) out += (i ? "; " : " ") + tries[i];
  return out + fmt::format(" ({} prefix runs, {:.1f} s)", prefix_runs, wall_s);
}

FrontEndRepair RepairFrontEnd(const SlamEvaluationContext& context, const std::vector<slam::SequentialMatchStep>& steps,
                              const slam::FrontEndEvidence& evidence, const SearchSpace& space,
                              const FrontEndRepairOptions& options) {
  options.Validate();
  const auto start = std::chrono::steady_clock::now();
  FrontEndRepair repair;
  Assignment current;  // the widened values so far
  int held_past = -1;  // log scan the last try that held went past
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (!slam::IsBreak(steps, i, evidence.median_response, {})) continue;
    const slam::SequentialMatchStep& b = steps[i];
    if (b.log_index <= held_past) continue;  // the values kept already hold here
    std::vector<std::string> names;
    if (b.at_heading_edge && FindDimension(space, kHeadingRange)) names.push_back(kHeadingRange);
    if (b.at_window_edge && FindDimension(space, kWindow)) names.push_back(kWindow);
    if (names.empty()) continue;
    // One ladder per parameter, stepped together.
    std::vector<std::vector<double>> ladders;
    std::size_t rungs = 0;
    for (const std::string& name : names) {
      const double base = slam::GetNumeric(context.base, name);
      const double now = current.count(name) ? current.at(name) : base;
      ladders.push_back(LadderOf(*FindDimension(space, name), base, now));
      rungs = std::max(rungs, ladders.back().size());
    }
    std::string line = fmt::format("at log scan {} ({:.1f} s)", b.log_index, b.time);
    Assignment tried = current;
    bool held = false;
    for (std::size_t r = 0; r < rungs && !held; ++r) {
      Assignment attempt = current;
      for (std::size_t k = 0; k < names.size(); ++k) {
        if (ladders[k].empty()) continue;
        attempt[names[k]] = ladders[k][std::min(r, ladders[k].size() - 1)];
      }
      ++repair.prefix_runs;
      held = Holds(context, attempt, b.log_index, options.margin_matches);
      if (!held) {
        for (const std::string& name : names) {
          if (attempt.count(name)) repair.lower_bounds[name] = std::max(repair.lower_bounds[name], attempt.at(name));
        }
      }
      tried = attempt;
    }
    for (const std::string& name : names) {
      // The base's own value broke here whatever was tried.
      const double base = slam::GetNumeric(context.base, name);
      repair.lower_bounds[name] = std::max(repair.lower_bounds[name], base);
      if (tried.count(name)) current[name] = tried.at(name);
      const double kept = current.count(name) ? current.at(name) : base;
      line += fmt::format(": {} broke, {:.2f} {}", SettingText(name, repair.lower_bounds.at(name)), kept,
                          held ? "held" : "(the widest) did not hold either");
    }
    if (held) held_past = b.log_index;
    repair.tries.push_back(line);
  }
  repair.repaired = current;
  repair.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return repair;
}

SearchSpace WithLowerBounds(SearchSpace space, const std::map<std::string, double>& lower_bounds) {
  for (Dimension& d : space.dimensions) {
    const auto it = lower_bounds.find(d.name);
    if (it == lower_bounds.end()) continue;
    if (it->second > d.lower && it->second < d.upper) d.lower = it->second;
  }
  return space;
}

}  // namespace slamtune::optim
