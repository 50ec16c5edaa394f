// The objectives NSGA-III minimises, read off one evaluation's record, and the named sets a
// user chooses from (`slamtune optimize --objectives NAME`).
//
//   occupied     unbacked hits, n_c, occupied cells   (default when every run draws the same scans)
//   drawn        unbacked hits, n_c, drawn wall cells (default when the search varies node spacing)
//   consistency  unbacked hits, n_c, n_e
//   paper        eta, n_c, n_e (Han et al., Sensors 2020, §3)
//
// Why the defaults replace the paper's eta: eta = occupied cells / all cells of the image, so a
// map that breaks apart spreads over a larger bounding box and its eta falls — minimising eta
// drives the search towards broken maps wherever the front end can break. The unbacked-hit
// share does not depend on the map's extent: it is the share of scan end points that land in
// cells the final map calls free or unknown (slam/occupancy_grid.h). Where one pass draws a
// wall into space another pass saw as free, those end points are overruled; in a consistent
// map almost every end point lands on a wall. docs/metrics.md gives the measurements.
//
// Why `occupied` exists: a loop that fails to close can leave a corridor as two parallel,
// disjoint copies, each clean — no end point is overruled, so u_h cannot see it, but the map
// holds more wall than the building has. The count of occupied cells sees that (mit-killian);
// it also falls when sparser nodes draw fewer walls, so it is biased wherever the search varies
// the node spacing (docs/metrics.md, "Where u_h, n_c and n_e fail").
//
// Why `drawn` exists: the count of wall cells that the same fixed scans of the log draw along each
// run's path (metrics/trajectory_map.h) sees the same doubled walls without depending on the node
// spacing, the laser range or the cell size a run uses.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "slamtune/optim/evaluation_record.h"

namespace slamtune::optim {

// One objective: a row of RecordFigures() (evaluation_record.h) that carries an objective's short
// name, title and failure score. The table is the one list of objectives; an Objective only
// points into it.
class Objective {
 public:
  // The objective read from the figure called `key`; a broken invariant (SLAMTUNE_CHECK) when the
  // table has no objective of that key.
  explicit Objective(std::string_view key);

  const RecordFigure& figure() const { return *figure_; }
  friend bool operator==(Objective a, Objective b) { return a.figure_ == b.figure_; }

 private:
  explicit Objective(const RecordFigure* figure) : figure_(figure) {}
  friend const std::vector<Objective>& AllObjectives();

  const RecordFigure* figure_;
};

// The objective's row of RecordFigures(): key, short name, title, failure score.
inline const RecordFigure& InfoOf(Objective objective) { return objective.figure(); }
// Every objective any set may use, in the table's order.
const std::vector<Objective>& AllObjectives();

// The objective's value for an ok record (no failure scoring).
double ValueOf(const EvaluationRecord& record, Objective objective);

enum class ObjectiveSetKind { kConsistency, kOccupied, kDrawn, kPaper };

// The set `optimize` uses when the user names none: 'occupied' when every run draws its map
// from the same scans at the same cell size (SearchSpace::VariesMapSampling() false: the count
// of occupied cells then compares maps), else 'drawn' (fewer nodes draw fewer wall cells, so
// the map's own count would reward sparse, worse maps; the drawn wall is counted on the same
// scans for every run). Measured in docs/metrics.md.
ObjectiveSetKind DefaultObjectiveSetKind(bool search_varies_map_sampling);

class ObjectiveSet {
 public:
  ObjectiveSet() : ObjectiveSet(ObjectiveSetKind::kConsistency) {}
  explicit ObjectiveSet(ObjectiveSetKind kind);

  // The set called `name` ("drawn", "occupied", "consistency" or "paper"); InputError naming the known sets.
  static ObjectiveSet Parse(const std::string& name);
  // "drawn", "occupied", "consistency", "paper".
  static const char* NameOf(ObjectiveSetKind kind);
  // The names a user may give, for help texts: "drawn, occupied, consistency, paper".
  static std::string KnownNames();

  ObjectiveSetKind kind() const { return kind_; }
  const char* name() const { return NameOf(kind_); }
  const std::vector<Objective>& objectives() const { return objectives_; }
  std::size_t size() const { return objectives_.size(); }
  // Whether `objective` is one of the set's (drawn_wall_cells needs the evaluation's trajectory map).
  bool Uses(Objective objective) const;

  // The vector NSGA-III minimises, in objectives() order. A failed record is scored worst on
  // every objective (each InfoOf(..).failure_score), so the optimisation goes on.
  std::vector<double> Score(const EvaluationRecord& record) const;
  // The record's values in objectives() order, without failure scoring.
  std::vector<double> Values(const EvaluationRecord& record) const;
  // True when `scores` is a failed record's Score() (every entry at its failure score), has the
  // wrong length or holds a non-finite value: left out of figures, where such points would
  // squash every real point into a corner.
  bool IsFailureScore(const std::vector<double>& scores) const;
  // "unbacked hits (u_h), corner pixels (n_c) and enclosed areas (n_e)".
  std::string Describe() const;

 private:
  ObjectiveSetKind kind_;
  std::vector<Objective> objectives_;
};

}  // namespace slamtune::optim
