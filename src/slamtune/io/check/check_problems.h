// How the checks of log_check.h record what they find: the occurrences of one problem (how many,
// and the first few scans and times, which the report lists), and the median step of a series of
// stamps, from which gaps and stalls are judged. Shared by log_check.cc and odometry_check.cc.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "slamtune/io/check/log_check.h"

namespace slamtune::io {

// Occurrences of one problem: how many, and the first few scans and times.
struct ProblemOccurrences {
  static constexpr std::size_t kListed = 5;  // scans listed per problem

  std::size_t count = 0;
  std::vector<std::size_t> scans;
  std::vector<double> times;
  void Add(std::size_t scan, double time) {
    if (count++ < kListed) {
      scans.push_back(scan);
      times.push_back(time);
    }
  }
};

// Adds the problem to `report` when it occurred at all.
inline void ReportOccurrences(CheckReport* report, ProblemKind kind, const ProblemOccurrences& o, std::string what) {
  if (o.count == 0) return;
  report->problems.push_back({kind, std::move(what), o.count, o.scans, o.times});
}

// The median of `v` (the upper one of an even count); 0 when empty.
inline double MedianOf(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

}  // namespace slamtune::io
