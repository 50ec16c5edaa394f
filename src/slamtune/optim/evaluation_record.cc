#include "slamtune/optim/evaluation_record.h"

#include <fmt/format.h>

#include "slamtune/common/error.h"

namespace slamtune::optim {

const char* NameOf(RunStatus status) {
  switch (status) {
    case RunStatus::kOk: return "ok";
    case RunStatus::kFailed: return "failed";
  }
  SLAMTUNE_CHECK(false);
  return "";
}

RunStatus ParseRunStatus(std::string_view name) {
  for (const RunStatus status : {RunStatus::kOk, RunStatus::kFailed}) {
    if (name == NameOf(status)) return status;
  }
  throw InputError(fmt::format("unknown evaluation status '{}' (known: ok, failed)", name));
}

EvaluationRecord EvaluationRecord::Failed(const std::string& key, const std::map<std::string, double>& params,
                                          const std::string& reason) {
  EvaluationRecord r;
  r.key = key;
  r.params = params;
  r.status = RunStatus::kFailed;
  r.reason = reason;
  return r;
}

void to_json(nlohmann::json& j, const EvaluationRecord& r) {
  j = nlohmann::json{{"key", r.key},
                     {"params", r.params},
                     {"status", NameOf(r.status)},
                     {"reason", r.reason},
                     {"objectives",
                      {{"occupied_ratio", r.occupied_ratio},
                       {"corner_pixels", r.corner_pixels},
                       {"enclosed_areas", r.enclosed_areas}}},
                     {"second",
                      {{"occupied_ratio_known", r.occupied_ratio_known},
                       {"corners", r.corners},
                       {"contours", r.contours},
                       {"occupied_cells", r.occupied_cells},
                       {"hits", r.hits},
                       {"hits_in_free_cells", r.hits_in_free_cells},
                       {"hits_in_unknown_cells", r.hits_in_unknown_cells},
                       {"drawn_wall_cells", r.drawn_wall_cells}}},
                     {"nodes", r.nodes},
                     {"loop_closures", r.loop_closures},
                     {"loop_scans", r.loop_scans},
                     {"wall_s", r.wall_s}};
  if (r.has_gt) {
    j["gt_error"] = {{"trans_mean_m", r.trans_mean_m},
                     {"trans_std_m", r.trans_std_m},
                     {"rot_mean_deg", r.rot_mean_deg},
                     {"rot_std_deg", r.rot_std_deg},
                     {"relations_used", r.relations_used}};
  }
}

void from_json(const nlohmann::json& j, EvaluationRecord& r) {
  r.key = j.at("key").get<std::string>();
  r.params = j.at("params").get<std::map<std::string, double>>();
  r.status = ParseRunStatus(j.at("status").get<std::string>());
  r.reason = j.at("reason").get<std::string>();
  const auto& o = j.at("objectives");
  r.occupied_ratio = o.at("occupied_ratio").get<double>();
  r.corner_pixels = o.at("corner_pixels").get<double>();
  r.enclosed_areas = o.at("enclosed_areas").get<double>();
  const auto& s = j.at("second");
  r.occupied_ratio_known = s.at("occupied_ratio_known").get<double>();
  r.corners = s.at("corners").get<double>();
  r.contours = s.at("contours").get<double>();
  // Absent from records stored before these figures existed.
  r.occupied_cells = s.value("occupied_cells", 0.0);
  r.hits = s.value("hits", 0.0);
  r.hits_in_free_cells = s.value("hits_in_free_cells", 0.0);
  r.hits_in_unknown_cells = s.value("hits_in_unknown_cells", 0.0);
  r.drawn_wall_cells = s.value("drawn_wall_cells", 0.0);
  r.nodes = j.at("nodes").get<int>();
  r.loop_closures = j.at("loop_closures").get<int>();
  r.loop_scans = j.at("loop_scans").get<std::vector<int>>();
  r.wall_s = j.at("wall_s").get<double>();
  r.has_gt = j.contains("gt_error");
  if (r.has_gt) {
    const auto& g = j.at("gt_error");
    r.trans_mean_m = g.at("trans_mean_m").get<double>();
    r.trans_std_m = g.at("trans_std_m").get<double>();
    r.rot_mean_deg = g.at("rot_mean_deg").get<double>();
    r.rot_std_deg = g.at("rot_std_deg").get<double>();
    r.relations_used = g.at("relations_used").get<int>();
  }
}

}  // namespace slamtune::optim
