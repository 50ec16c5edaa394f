// Ground-truth relations checked against the log they belong to, before any SLAM run.
//
// Why: a relation is used only when both of its timestamps are those of scans of the log
// (gt_error.h). Relations of another log, or timestamps in another clock, match nothing, and
// every error would be NaN after a long run; `run`, `optimize` and `sweep` therefore refuse
// such a file at once, as `gt-error` refuses a trajectory that matches none of them.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "slamtune/io/laser_log.h"
#include "slamtune/io/relations.h"
#include "slamtune/metrics/gt_error.h"

namespace slamtune::metrics {

struct RelationMatch {
  std::size_t total = 0;     // relations in the file
  std::size_t matching = 0;  // both timestamps at a scan of the log (GtErrorOptions::time_tolerance_s)

  bool complete() const { return matching == total; }
  // "N of M relations match scans of the log".
  std::string Brief() const;
};

// Counts the relations whose t1 and t2 are both scan times (`scan_times`, any order).
RelationMatch MatchRelations(const std::vector<double>& scan_times, const std::vector<io::Relation>& relations,
                             const GtErrorOptions& options = {});

// MatchRelations against the ipc times of `log`'s scans. Throws InputError naming
// `relations_file` when the file holds no relation ("no relations in the file") or when no
// relation matches: "no relation's timestamps match a scan of the log (the log's scans span
// A .. B s; the M relations span C .. D s)".
RelationMatch RequireMatchingRelations(const io::LaserLog& log, const std::vector<io::Relation>& relations,
                                       const std::string& relations_file, const GtErrorOptions& options = {});

}  // namespace slamtune::metrics
