#include "slamtune/metrics/relation_match.h"

#include <fmt/format.h>

#include <algorithm>

#include "slamtune/common/error.h"

namespace slamtune::metrics {
namespace {

// Whether a value of `sorted` lies within `tolerance` of t.
bool Contains(const std::vector<double>& sorted, double t, double tolerance) {
  const auto it = std::lower_bound(sorted.begin(), sorted.end(), t - tolerance);
  return it != sorted.end() && *it <= t + tolerance;
}

std::string Span(double first, double last) { return fmt::format("{:.3f} .. {:.3f} s", first, last); }

std::string ScanSpan(const io::LaserLog& log) {
  if (log.scans.empty()) return "the log has no scans";
  const auto [lo, hi] = std::minmax_element(log.scans.begin(), log.scans.end(),
                                            [](const auto& a, const auto& b) { return a.ipc_time < b.ipc_time; });
  return "the log's scans span " + Span(lo->ipc_time, hi->ipc_time);
}

std::string RelationSpan(const std::vector<io::Relation>& relations) {
  double lo = relations.front().t1, hi = lo;
  for (const io::Relation& r : relations) {
    lo = std::min({lo, r.t1, r.t2});
    hi = std::max({hi, r.t1, r.t2});
  }
  if (relations.size() == 1) return "the relation spans " + Span(lo, hi);
  return fmt::format("the {} relations span {}", relations.size(), Span(lo, hi));
}

}  // namespace

std::string RelationMatch::Brief() const {
  return fmt::format("{} of {} relations match scans of the log", matching, total);
}

RelationMatch MatchRelations(const std::vector<double>& scan_times, const std::vector<io::Relation>& relations,
                             const GtErrorOptions& options) {
  options.Validate();
  std::vector<double> sorted = scan_times;
  std::sort(sorted.begin(), sorted.end());
  RelationMatch match;
  match.total = relations.size();
  for (const io::Relation& r : relations) {
    if (Contains(sorted, r.t1, options.time_tolerance_s) && Contains(sorted, r.t2, options.time_tolerance_s)) {
      ++match.matching;
    }
  }
  return match;
}

RelationMatch RequireMatchingRelations(const io::LaserLog& log, const std::vector<io::Relation>& relations,
                                       const std::string& relations_file, const GtErrorOptions& options) {
  if (relations.empty()) throw InputError(relations_file, 0, "no relations in the file");
  std::vector<double> times;
  times.reserve(log.scans.size());
  for (const io::LaserScanRecord& scan : log.scans) times.push_back(scan.ipc_time);
  const RelationMatch match = MatchRelations(times, relations, options);
  if (match.matching == 0) {
    throw InputError(relations_file, 0,
                     fmt::format("no relation's timestamps match a scan of the log ({}; {})", ScanSpan(log),
                                 RelationSpan(relations)));
  }
  return match;
}

}  // namespace slamtune::metrics
