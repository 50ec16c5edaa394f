#include "slamtune/report/front_end_json.h"

namespace slamtune::report {

nlohmann::json FrontEndEvidenceJson(const slam::FrontEndEvidence& e) {
  nlohmann::json stretches = nlohmann::json::array();
  for (const slam::SuspectStretch& s : e.stretches) {
    stretches.push_back({{"first_log_index", s.first_log_index},
                         {"last_log_index", s.last_log_index},
                         {"first_time", s.first_time},
                         {"last_time", s.last_time},
                         {"suspects", s.suspects},
                         {"at_edge", s.at_edge},
                         {"low_response", s.low_response},
                         {"min_response", s.min_response},
                         {"breaks", s.breaks}});
  }
  nlohmann::json degenerate = nlohmann::json::array();
  for (const slam::DegenerateStretch& s : e.degenerate_stretches) {
    degenerate.push_back({{"first_log_index", s.first_log_index},
                          {"last_log_index", s.last_log_index},
                          {"first_time", s.first_time},
                          {"last_time", s.last_time},
                          {"matches", s.matches},
                          {"length_m", s.length_m},
                          {"max_anisotropy", s.max_anisotropy}});
  }
  return {{"sequential_matches", e.matches},
          {"median_response", e.median_response},
          {"at_edge", e.at_edge},
          {"low_response", e.low_response},
          {"breaks", e.breaks},
          {"degenerate", e.degenerate},
          {"points_at_front_end", e.points_at_front_end()},
          {"stretches", stretches},
          {"degenerate_stretches", degenerate}};
}

}  // namespace slamtune::report
