// One evaluation of the tuning problem: a whole SLAM run of the log with the base parameters
// overridden by an assignment, the occupancy-grid map of its final poses, the three map
// objectives (metrics/map_quality.h) and, when relations are given, the Kümmerle et al.
// (2009) errors of its trajectory. Pure and thread-safe: the context is read-only.
#pragma once

#include <memory>
#include <vector>

#include "slamtune/io/laser_log.h"
#include "slamtune/io/map_image.h"
#include "slamtune/io/relations.h"
#include "slamtune/metrics/map_quality.h"
#include "slamtune/optim/batch_evaluator.h"
#include "slamtune/optim/evaluation_record.h"
#include "slamtune/slam/mapper_params.h"

namespace slamtune::optim {

struct SlamEvaluationContext {
  std::shared_ptr<const io::LaserLog> log;
  std::vector<io::Relation> relations;  // empty: no ground-truth errors
  slam::MapperParams base;              // parameters not in the assignment
  metrics::MapQualityOptions metrics;

  // The base parameters with `assignment` applied (InputError naming a bad name or value).
  slam::MapperParams ParamsFor(const Assignment& assignment) const;
};

EvaluationRecord EvaluateSlam(const SlamEvaluationContext& context, const Assignment& assignment);

// The map of the SLAM run of `assignment` (for the report's figures).
io::MapImage RenderSlamMap(const SlamEvaluationContext& context, const Assignment& assignment);

}  // namespace slamtune::optim
