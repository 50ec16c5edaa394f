#include "slamtune/optim/objective_set.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "slamtune/common/error.h"

namespace slamtune::optim {
namespace {

constexpr std::array<ObjectiveInfo, 6> kInfos = {{
    {Objective::kOccupiedRatio, "occupied_ratio", "eta", "occupied ratio (eta)", 1.0},
    {Objective::kCornerPixels, "corner_pixels", "n_c", "corner pixels (n_c)", 1e9},
    {Objective::kEnclosedAreas, "enclosed_areas", "n_e", "enclosed areas (n_e)", 1e9},
    // A share lies in [0, 1]; 2 is worse than any map.
    {Objective::kUnbackedHits, "unbacked_hits", "u_h", "unbacked hits (u_h)", 2.0},
    {Objective::kOccupiedCells, "occupied_cells", "n_o", "occupied cells (n_o)", 1e12},
    {Objective::kDrawnWallCells, "drawn_wall_cells", "n_w", "wall the log's scans draw along the path (n_w)", 1e12},
}};

constexpr std::array<ObjectiveSetKind, 4> kKinds = {ObjectiveSetKind::kDrawn, ObjectiveSetKind::kOccupied,
                                                    ObjectiveSetKind::kConsistency, ObjectiveSetKind::kPaper};

}  // namespace

ObjectiveSetKind DefaultObjectiveSetKind(bool search_varies_map_sampling) {
  return search_varies_map_sampling ? ObjectiveSetKind::kDrawn : ObjectiveSetKind::kOccupied;
}

const ObjectiveInfo& InfoOf(Objective objective) {
  for (const auto& info : kInfos)
    if (info.id == objective) return info;
  SLAMTUNE_CHECK(false);
  return kInfos[0];
}

const std::vector<Objective>& AllObjectives() {
  static const std::vector<Objective> all = [] {
    std::vector<Objective> out;
    for (const auto& info : kInfos) out.push_back(info.id);
    return out;
  }();
  return all;
}

double ValueOf(const EvaluationRecord& record, Objective objective) {
  return FigureValue(FigureNamed(InfoOf(objective).key), record);
}

ObjectiveSet::ObjectiveSet(ObjectiveSetKind kind) : kind_(kind) {
  switch (kind) {
    case ObjectiveSetKind::kConsistency:
      objectives_ = {Objective::kUnbackedHits, Objective::kCornerPixels, Objective::kEnclosedAreas};
      break;
    case ObjectiveSetKind::kOccupied:
      objectives_ = {Objective::kUnbackedHits, Objective::kCornerPixels, Objective::kOccupiedCells};
      break;
    case ObjectiveSetKind::kDrawn:
      objectives_ = {Objective::kUnbackedHits, Objective::kCornerPixels, Objective::kDrawnWallCells};
      break;
    case ObjectiveSetKind::kPaper:
      objectives_ = {Objective::kOccupiedRatio, Objective::kCornerPixels, Objective::kEnclosedAreas};
      break;
  }
  SLAMTUNE_CHECK(!objectives_.empty());
}

const char* ObjectiveSet::NameOf(ObjectiveSetKind kind) {
  switch (kind) {
    case ObjectiveSetKind::kConsistency: return "consistency";
    case ObjectiveSetKind::kOccupied: return "occupied";
    case ObjectiveSetKind::kDrawn: return "drawn";
    case ObjectiveSetKind::kPaper: return "paper";
  }
  return "consistency";
}

std::string ObjectiveSet::KnownNames() {
  std::string out;
  for (ObjectiveSetKind kind : kKinds) out += std::string(out.empty() ? "" : ", ") + NameOf(kind);
  return out;
}

ObjectiveSet ObjectiveSet::Parse(const std::string& name) {
  for (ObjectiveSetKind kind : kKinds)
    if (name == NameOf(kind)) return ObjectiveSet(kind);
  throw InputError(fmt::format("--objectives: unknown objective set '{}' (known: {})", name, KnownNames()));
}

std::vector<double> ObjectiveSet::Score(const EvaluationRecord& record) const {
  std::vector<double> out;
  out.reserve(objectives_.size());
  for (Objective o : objectives_) {
    out.push_back(record.status == RunStatus::kOk ? ValueOf(record, o) : InfoOf(o).failure_score);
  }
  return out;
}

std::vector<double> ObjectiveSet::Values(const EvaluationRecord& record) const {
  std::vector<double> out;
  out.reserve(objectives_.size());
  for (Objective o : objectives_) out.push_back(ValueOf(record, o));
  return out;
}

bool ObjectiveSet::IsFailureScore(const std::vector<double>& scores) const {
  if (scores.size() != objectives_.size()) return true;
  bool all_failure_scores = true;
  for (std::size_t k = 0; k < scores.size(); ++k) {
    if (!std::isfinite(scores[k])) return true;
    all_failure_scores = all_failure_scores && scores[k] >= InfoOf(objectives_[k]).failure_score;
  }
  return all_failure_scores;
}

bool ObjectiveSet::Uses(Objective objective) const {
  return std::find(objectives_.begin(), objectives_.end(), objective) != objectives_.end();
}

std::string ObjectiveSet::Describe() const {
  std::string out;
  for (std::size_t k = 0; k < objectives_.size(); ++k) {
    if (k > 0) out += k + 1 == objectives_.size() ? " and " : ", ";
    out += InfoOf(objectives_[k]).title;
  }
  return out;
}

}  // namespace slamtune::optim
