#include "slamtune/optim/objective_set.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "slamtune/common/error.h"

namespace slamtune::optim {
namespace {

constexpr std::array<ObjectiveSetKind, 4> kKinds = {ObjectiveSetKind::kDrawn, ObjectiveSetKind::kOccupied,
                                                    ObjectiveSetKind::kConsistency, ObjectiveSetKind::kPaper};

}  // namespace

ObjectiveSetKind DefaultObjectiveSetKind(bool search_varies_map_sampling) {
  return search_varies_map_sampling ? ObjectiveSetKind::kDrawn : ObjectiveSetKind::kOccupied;
}

Objective::Objective(std::string_view key) : figure_(&FigureNamed(key)) { SLAMTUNE_CHECK(figure_->is_objective()); }

const std::vector<Objective>& AllObjectives() {
  static const std::vector<Objective> all = [] {
    std::vector<Objective> out;
    for (const RecordFigure& figure : RecordFigures())
      if (figure.is_objective()) out.push_back(Objective(&figure));
    return out;
  }();
  return all;
}

double ValueOf(const EvaluationRecord& record, Objective objective) { return FigureValue(objective.figure(), record); }

ObjectiveSet::ObjectiveSet(ObjectiveSetKind kind) : kind_(kind) {
  switch (kind) {
    case ObjectiveSetKind::kConsistency:
      objectives_ = {Objective("unbacked_hits"), Objective("corner_pixels"), Objective("enclosed_areas")};
      break;
    case ObjectiveSetKind::kOccupied:
      objectives_ = {Objective("unbacked_hits"), Objective("corner_pixels"), Objective("occupied_cells")};
      break;
    case ObjectiveSetKind::kDrawn:
      objectives_ = {Objective("unbacked_hits"), Objective("corner_pixels"), Objective("drawn_wall_cells")};
      break;
    case ObjectiveSetKind::kPaper:
      objectives_ = {Objective("occupied_ratio"), Objective("corner_pixels"), Objective("enclosed_areas")};
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
