// One evaluation of the tuning problem: a whole SLAM run of the log with the base parameters
// overridden by an assignment, the occupancy-grid map of its final poses, the three map
// objectives (metrics/map_quality.h) and, when relations are given, the Kümmerle et al.
// (2009) errors of its trajectory. Pure and thread-safe: the context is read-only.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <vector>

#include "slamtune/io/laser_log.h"
#include "slamtune/io/map_image.h"
#include "slamtune/io/relations.h"
#include "slamtune/metrics/gt_error.h"
#include "slamtune/metrics/map_quality.h"
#include "slamtune/metrics/trajectory_map.h"
#include "slamtune/optim/evaluation/batch_evaluator.h"
#include "slamtune/optim/evaluation/map_score_cache.h"
#include "slamtune/optim/evaluation_record.h"
#include "slamtune/optim/optimize_result.h"
#include "slamtune/slam/front_end_evidence.h"
#include "slamtune/slam/log_runner.h"
#include "slamtune/slam/params/mapper_params.h"
#include "slamtune/slam/run_trace.h"
#include "slamtune/slam/sharing/shared_work.h"

namespace slamtune::optim {

struct SlamEvaluationContext {
  std::shared_ptr<const io::LaserLog> log;
  std::vector<io::Relation> relations;  // empty: no ground-truth errors
  slam::MapperParams base;              // parameters not in the assignment
  metrics::MapQualityOptions metrics;
  // Scan matches, back-end solves and scan barycentres shared by all evaluations of this context
  // (slam/sharing/shared_work.h); null caches: no sharing. Results are identical either way; only
  // the time changes.
  slam::SharedWork shared_work;
  // Map scores of final states already scored (map_score_cache.h); null: every run builds and
  // scores its map. Results are identical either way.
  std::shared_ptr<MapScoreCache> map_scores;
  // The fixed scans every run's path draws for the drawn wall (metrics/trajectory_map.h,
  // objective n_w); null: EvaluationRecord::drawn_wall_cells stays 0 (the map is not drawn).
  std::shared_ptr<const metrics::TrajectoryMap> trajectory_map;
  // Stop a run as soon as its own sequential matches show a break (slam::BreakWatch) and record
  // it as failed, with where and why, instead of mapping the rest of the log: a broken map is
  // never the recommendation. The base configuration is always mapped to the end (every answer is
  // judged against it). Only meaningful when runs differ in their front end
  // (SearchSpace::VariesFrontEnd); it changes which runs are scored, so it is a setting.
  bool stop_broken_runs = false;
  // Evaluation slots left idle by the evaluator (BatchEvaluator::idle_slots; null: none): a run
  // gives its correlative search that many more threads while they are idle. Speed only: results
  // do not depend on the thread count.
  std::shared_ptr<const std::atomic<int>> idle_slots;

  // The base parameters with `assignment` applied (InputError naming a bad name or value).
  slam::MapperParams ParamsFor(const Assignment& assignment) const;
};

// Gives `context` every cache shared between its runs (results are identical either way): scan
// matches (budget share_mb MB), back-end solves (share_mb / 2), map scores of final states
// (share_mb / 4) and scan barycentres (share_mb / 8), each at least 1 MB. share_mb > 0.
void ShareWork(SlamEvaluationContext& context, std::size_t share_mb);
// Whether the runs of a context draw the fixed scans along their path (the drawn wall n_w).
enum class WallDrawing { kSkip, kDraw };
// kDraw when `objectives` read the drawn wall (ObjectiveSet::Uses), else kSkip.
WallDrawing WallDrawingFor(const ObjectiveSet& objectives);
// Gives `context` the trajectory map (metrics/trajectory_map.h, drawn with the context's base
// parameters) for kDraw, and takes it away for kSkip, so no run pays for a map nothing reads.
void DrawWall(SlamEvaluationContext& context, WallDrawing drawing);
// One line per cache with its counters, or that sharing is off.
std::string SharedWorkReport(const SlamEvaluationContext& context);
// The match cache in a few words for progress lines, e.g. "matches: 97.9% of 1.2 M shared,
// 25.1 k computed"; empty when sharing is off or nothing was matched yet. The computed
// matches are the cold work.
std::string SharedWorkBrief(const SlamEvaluationContext& context);

// What one SLAM run of an evaluation produced.
struct SlamRun {
  slam::RunSummary summary;
  std::vector<io::TimedPose> trajectory;                      // one pose per log scan
  io::MapImage map;                                           // occupancy grid of the final poses
  metrics::MapQuality quality;                                // the map's metrics (the record's objectives)
  metrics::GtError error;                                     // against the context's relations (none: empty)
  std::vector<slam::SequentialMatchStep> sequential_matches;  // every sequential match, in log order
  slam::FrontEndEvidence front_end;                           // where sequential matching may have lost its place
  slam::LogLasers lasers;                                     // the run's Karto lasers
  double range_threshold = 0.0;                               // m, the mapper's (scans beyond it are not mapped)
  double map_wall_s = 0.0;                                    // s, building and measuring the map
};

// What a single observed run adds to an evaluation (`slamtune run`): progress and a trace. They
// change no result.
struct RunObservers {
  std::function<void(const slam::LogRunner& runner)> after_step;  // after every log scan
  std::shared_ptr<slam::RunTrace> trace;                          // every match and solve (slam/run_trace.h)
};

// `run` (may be null) receives the SLAM run the record was computed from; `observers` watch it
// (a run with observers is mapped to the end, like the base configuration).
EvaluationRecord EvaluateSlam(const SlamEvaluationContext& context, const Assignment& assignment,
                              SlamRun* run = nullptr, const RunObservers& observers = {});

// The map of the SLAM run of `assignment` and its loop closures as edges between the final
// robot poses of the two scans each joins (for the report's figures). A loop closure that
// added no edge (linked_to = -1) is drawn from the first scan of its candidate chain. The path
// is the final robot position of every processed scan.
CandidateMap RenderSlamMap(const SlamEvaluationContext& context, const Assignment& assignment);

}  // namespace slamtune::optim
