#include "slamtune/optim/evaluation_record.h"

#include <fmt/format.h>

#include <array>

#include "slamtune/common/error.h"

namespace slamtune::optim {
namespace {

// The share of the map's scan end points that land in cells the final map calls free or
// unknown (slam/occupancy_grid.h); no end point on the map at all: nothing backs it.
double UnbackedHits(const EvaluationRecord& r) {
  if (!(r.hits > 0.0)) return 1.0;
  return (r.hits_in_free_cells + r.hits_in_unknown_cells) / r.hits;
}

using R = EvaluationRecord;

// A measured figure that is not an objective; `always`: in every stored record.
constexpr RecordFigure Measured(const char* key, double R::*field, bool always) {
  return {key, field, nullptr, always, nullptr, nullptr, 0.0};
}
// An objective read from a measured figure.
constexpr RecordFigure MeasuredObjective(const char* key, double R::*field, bool always, const char* short_name,
                                         const char* title, double failure_score) {
  return {key, field, nullptr, always, short_name, title, failure_score};
}

const std::array<RecordFigure, 12> kFigures = {{
    MeasuredObjective("occupied_ratio", &R::occupied_ratio, true, "eta", "occupied ratio (eta)", 1.0),
    MeasuredObjective("corner_pixels", &R::corner_pixels, true, "n_c", "corner pixels (n_c)", 1e9),
    MeasuredObjective("enclosed_areas", &R::enclosed_areas, true, "n_e", "enclosed areas (n_e)", 1e9),
    Measured("occupied_ratio_known", &R::occupied_ratio_known, true),
    Measured("corners", &R::corners, true),
    Measured("contours", &R::contours, true),
    MeasuredObjective("occupied_cells", &R::occupied_cells, false, "n_o", "occupied cells (n_o)", 1e12),
    Measured("hits", &R::hits, false),
    Measured("hits_in_free_cells", &R::hits_in_free_cells, false),
    Measured("hits_in_unknown_cells", &R::hits_in_unknown_cells, false),
    // A share lies in [0, 1]; 2 is worse than any map.
    {"unbacked_hits", nullptr, &UnbackedHits, false, "u_h", "unbacked hits (u_h)", 2.0},
    MeasuredObjective("drawn_wall_cells", &R::drawn_wall_cells, false, "n_w",
                      "wall the log's scans draw along the path (n_w)", 1e12),
}};

// The measured figures of a record stored in the earlier layout: "objectives" and "second" together.
nlohmann::json EarlierLayoutFigures(const nlohmann::json& j) {
  nlohmann::json figures = j.at("objectives");
  figures.update(j.at("second"));
  return figures;
}

}  // namespace

std::span<const RecordFigure> RecordFigures() { return kFigures; }

const RecordFigure& FigureNamed(std::string_view key) {
  for (const RecordFigure& figure : kFigures)
    if (key == figure.key) return figure;
  SLAMTUNE_CHECK(false);
  return kFigures[0];
}

double FigureValue(const RecordFigure& figure, const EvaluationRecord& record) {
  if (figure.field != nullptr) return record.*figure.field;
  SLAMTUNE_CHECK(figure.derive != nullptr);
  return figure.derive(record);
}

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
                     {"figures", nlohmann::json::object()},
                     {"nodes", r.nodes},
                     {"loop_closures", r.loop_closures},
                     {"loop_scans", r.loop_scans},
                     {"wall_s", r.wall_s}};
  for (const RecordFigure& figure : kFigures) {
    if (!figure.derived()) j["figures"][figure.key] = r.*figure.field;
  }
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
  nlohmann::json earlier;  // filled only for a record in the earlier layout; the current one is read in place
  const auto found = j.find("figures");
  const nlohmann::json& figures = found != j.end() ? *found : (earlier = EarlierLayoutFigures(j));
  for (const RecordFigure& figure : kFigures) {
    if (figure.derived()) continue;
    r.*figure.field =
        figure.in_every_stored_record ? figures.at(figure.key).get<double>() : figures.value(figure.key, 0.0);
  }
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
