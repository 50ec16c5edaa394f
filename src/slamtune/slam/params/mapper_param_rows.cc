// The parameter table of mapper_param_rows.h, written section by section of docs/engine.md §9.
#include "slamtune/slam/params/mapper_param_rows.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <type_traits>
#include <utility>

#include "slamtune/common/error.h"

namespace slamtune::slam {
namespace {

constexpr double kNoBound = std::numeric_limits<double>::infinity();

ParamBounds AtLeast(double lo) { return {lo, false, kNoBound, false}; }
ParamBounds Above(double lo) { return {lo, true, kNoBound, false}; }
ParamBounds Closed(double lo, double hi) { return {lo, false, hi, false}; }
ParamBounds AnyValue() { return {}; }

// The names of `values`, which must be every value of their enum in order.
template <typename Enum>
std::vector<std::string> ChoiceNames(std::initializer_list<Enum> values) {
  std::vector<std::string> names;
  for (const Enum value : values) {
    SLAMTUNE_CHECK(static_cast<std::size_t>(value) == names.size());
    names.emplace_back(NameOf(value));
  }
  return names;
}

#define ST_BOOL(name, ros, meaning)                                                               \
  ParamRow {                                                                                      \
    {#name, ParamType::kBool, ros, "true or false", meaning}, &MapperParams::name, AnyValue(), {} \
  }
#define ST_NUM(type, name, ros, bounds, rule, meaning)                 \
  ParamRow {                                                           \
    {#name, type, ros, rule, meaning}, &MapperParams::name, bounds, {} \
  }
#define ST_CHOICE(name, ros, rule, meaning, ...)                                                                 \
  ParamRow {                                                                                                     \
    {#name, ParamType::kString, ros, rule, meaning}, &MapperParams::name, AnyValue(), ChoiceNames({__VA_ARGS__}) \
  }

// §9.1: the mapper's parameters.
std::vector<ParamRow> KartoMapperRows() {
  using enum ParamType;
  return {
      ST_BOOL(use_scan_matching, true, "match scans and build a graph (false: pure odometry)"),
      ST_BOOL(use_scan_barycenter, true, "measure scan distances between barycentres"),
      ST_NUM(kDouble, minimum_time_interval, true, AnyValue(), "any finite value",
             "s; a scan this much newer than the last accepted one is accepted"),
      ST_NUM(kDouble, minimum_travel_distance, true, AtLeast(0), ">= 0", "m; odometric travel that accepts a scan"),
      ST_NUM(kDouble, minimum_travel_heading, true, AtLeast(0), ">= 0", "rad; odometric turn that accepts a scan"),
      ST_NUM(kInt, scan_buffer_size, true, AtLeast(1), "an integer >= 1", "scans in the running buffer"),
      ST_NUM(kDouble, scan_buffer_maximum_scan_distance, true, AtLeast(0), ">= 0",
             "m; maximum span of the running buffer"),
      ST_NUM(kDouble, link_match_minimum_response_fine, true, Closed(0, 1), "in [0, 1]",
             "minimum response of a near-chain link"),
      ST_NUM(kDouble, link_scan_maximum_distance, true, AtLeast(0), ">= 0",
             "m; radius of near chains and chain-to-scan links"),
      ST_NUM(kDouble, loop_search_maximum_distance, true, AtLeast(0.001),
             ">= 0.001 (smaller radii make a scan its own loop candidate, spec §6.2 item 3)",
             "m; r, loop candidate radius between barycentres"),
      ST_BOOL(do_loop_closing, true, "try to close loops"),
      ST_NUM(kInt, loop_match_minimum_chain_size, true, AtLeast(1), "an integer >= 1",
             "g, minimum length of a loop candidate run and of a near chain"),
      ST_NUM(kDouble, loop_match_maximum_variance_coarse, true, AtLeast(0), ">= 0",
             "m; q, the coarse loop match variances must be < q^2"),
      ST_NUM(kDouble, loop_match_minimum_response_coarse, true, Closed(0, 1), "in [0, 1]",
             "p, the coarse loop response must be > p"),
      ST_NUM(kDouble, loop_match_minimum_response_fine, true, Closed(0, 1), "in [0, 1]",
             "the fine loop response must be >= this"),
      ST_NUM(kDouble, correlation_search_space_dimension, true, Above(0), "> 0", "m; sequential matcher search window"),
      ST_NUM(kDouble, correlation_search_space_resolution, true, Above(0), "> 0",
             "m; sequential matcher grid resolution"),
      ST_NUM(kDouble, correlation_search_space_smear_deviation, true, Above(0), "> 0",
             "m; sequential matcher smearing deviation"),
      ST_NUM(kDouble, loop_search_space_dimension, true, Above(0), "> 0", "m; loop matcher search window"),
      ST_NUM(kDouble, loop_search_space_resolution, true, Above(0), "> 0", "m; loop matcher grid resolution"),
      ST_NUM(kDouble, loop_search_space_smear_deviation, true, Above(0), "> 0", "m; loop matcher smearing deviation"),
      ST_NUM(kDouble, distance_variance_penalty, true, Above(0), "> 0", "m; squared inside; distance penalty"),
      ST_NUM(kDouble, angle_variance_penalty, true, Above(0), "> 0", "rad; squared inside; angle penalty"),
      ST_NUM(kDouble, fine_search_angle_offset, true, Above(0), "> 0", "rad; fine angular step"),
      ST_NUM(kDouble, coarse_search_angle_offset, true, Above(0), "> 0", "rad; coarse angular range (+-)"),
      ST_NUM(kDouble, coarse_angle_resolution, true, Above(0), "> 0", "rad; coarse angular step"),
      ST_NUM(kDouble, minimum_angle_penalty, true, Closed(0, 1), "in [0, 1]", "floor of the angle penalty"),
      ST_NUM(kDouble, minimum_distance_penalty, true, Closed(0, 1), "in [0, 1]", "floor of the distance penalty"),
      ST_BOOL(use_response_expansion, true, "widen the coarse angle search on a zero response"),
      ST_BOOL(robot_pose_graph, false,
              "pose graph over robot (base) poses as slam_toolbox; false: over sensor poses as slam_karto"),
  };
}

// §9.2: the laser's range limits and the map.
std::vector<ParamRow> LaserAndMapRows() {
  using enum ParamType;
  return {
      ST_CHOICE(range_threshold_rule, false, "slam_karto or slam_toolbox",
                "which node's rule sets the laser range threshold", RangeThresholdRule::kSlamKarto,
                RangeThresholdRule::kSlamToolbox),
      ST_NUM(kDouble, max_laser_range, true, AnyValue(), "any finite value (<= 0 means the laser maximum)",
             "m; slam_toolbox's range threshold"),
      ST_NUM(kDouble, min_laser_range, false, AtLeast(0), ">= 0", "m; laser minimum range"),
      ST_NUM(kDouble, laser_max_range_cap, false, Above(0), "> 0",
             "m; laser maximum range = min(this, the log's no-return value)"),
      ST_NUM(kDouble, resolution, true, Above(0), "> 0", "m; map cell size"),
      ST_NUM(kInt, min_pass_through, true, AtLeast(0), "an integer >= 0",
             "a map cell needs more passes than this to be known"),
      ST_NUM(kDouble, occupancy_threshold, true, Closed(0, 1), "in [0, 1]",
             "hit/pass ratio above which a map cell is occupied"),
  };
}

// §3.4: the node around Karto.
std::vector<ParamRow> NodeRows() {
  using enum ParamType;
  return {
      ST_CHOICE(node_mode, false, "slam_karto, slam_toolbox_async, slam_toolbox_sync or slam_toolbox_offline",
                "which node feeds Karto, and how (the synchronous node filters scans)", NodeMode::kSlamKarto,
                NodeMode::kSlamToolboxAsync, NodeMode::kSlamToolboxSync, NodeMode::kSlamToolboxOffline),
      ST_NUM(kInt, throttle_scans, true, AtLeast(1), "an integer >= 1",
             "slam_karto and the synchronous node: map every n-th scan"),
      ST_NUM(kDouble, sync_minimum_time_interval, false, AtLeast(0), ">= 0",
             "s; the synchronous node skips scans closer in time to the last one it kept"),
  };
}

// §7: the back-end; then the engine's own setting (matcher_threads).
std::vector<ParamRow> BackEndRows() {
  using enum ParamType;
  return {
      ST_CHOICE(solver, false, "spa or ceres", "pose-graph back-end (spa = slam_karto, ceres = slam_toolbox)",
                SolverKind::kSpa, SolverKind::kCeres),
      ST_CHOICE(ceres_loss_function, true, "None, HuberLoss or CauchyLoss", "robust loss of the ceres back-end",
                CeresLoss::kNone, CeresLoss::kHuber, CeresLoss::kCauchy),
      ST_CHOICE(ceres_linear_solver, true, "SPARSE_NORMAL_CHOLESKY, SPARSE_SCHUR, ITERATIVE_SCHUR or CGNR",
                "linear solver of the ceres back-end", CeresLinearSolver::kSparseNormalCholesky,
                CeresLinearSolver::kSparseSchur, CeresLinearSolver::kIterativeSchur, CeresLinearSolver::kCgnr),
      ST_CHOICE(ceres_preconditioner, true, "JACOBI, IDENTITY or SCHUR_JACOBI",
                "preconditioner of the ceres back-end's iterative solvers", CeresPreconditioner::kJacobi,
                CeresPreconditioner::kIdentity, CeresPreconditioner::kSchurJacobi),
      ST_CHOICE(ceres_trust_strategy, true, "LEVENBERG_MARQUARDT or DOGLEG",
                "trust-region strategy of the ceres back-end", CeresTrustStrategy::kLevenbergMarquardt,
                CeresTrustStrategy::kDogleg),
      ST_CHOICE(ceres_dogleg_type, true, "TRADITIONAL_DOGLEG or SUBSPACE_DOGLEG",
                "dogleg type of the ceres back-end (with DOGLEG)", CeresDoglegType::kTraditional,
                CeresDoglegType::kSubspace),
      ST_NUM(kInt, matcher_threads, false, AtLeast(1), "an integer >= 1",
             "threads of the correlative search (results do not depend on it)"),
  };
}

#undef ST_BOOL
#undef ST_NUM
#undef ST_CHOICE

}  // namespace

const std::vector<ParamRow>& ParamRows() {
  static const std::vector<ParamRow> rows = [] {
    std::vector<ParamRow> all;
    for (std::vector<ParamRow> (*group)() : {KartoMapperRows, LaserAndMapRows, NodeRows, BackEndRows}) {
      for (ParamRow& row : group()) all.push_back(std::move(row));
    }
    return all;
  }();
  return rows;
}

const ParamRow* FindParamRow(std::string_view name) {
  for (const ParamRow& row : ParamRows()) {
    if (name == row.info.name) return &row;
  }
  return nullptr;
}

bool InParamBounds(double v, const ParamBounds& b) {
  if (!std::isfinite(v)) return false;
  if (b.lo_open ? !(v > b.lo) : !(v >= b.lo)) return false;
  if (b.hi_open ? !(v < b.hi) : !(v <= b.hi)) return false;
  return true;
}

std::string ParamValueText(const ParamValue& value) {
  return std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, bool>) {
          return v ? "true" : "false";
        } else if constexpr (std::is_same_v<T, std::string>) {
          return v;
        } else {
          return fmt::format("{}", v);
        }
      },
      value);
}

std::string FormatParamValue(const ParamValue& value) {
  if (const auto* text = std::get_if<std::string>(&value)) return "'" + *text + "'";
  return ParamValueText(value);
}

ParamValue ReadParamValue(const MapperParams& params, const ParamMember& member) {
  return std::visit(
      [&](auto ptr) -> ParamValue {
        if constexpr (std::is_enum_v<std::remove_reference_t<decltype(params.*ptr)>>) {
          return std::string(NameOf(params.*ptr));
        } else {
          return params.*ptr;
        }
      },
      member);
}

void ThrowParamOutOfRange(const ParamRow& row, const std::string& value) {
  throw InputError(
      fmt::format("mapper parameter {} = {} is out of range: must be {}", row.info.name, value, row.info.rule));
}

void CheckParamRow(const MapperParams& params, const ParamRow& row) {
  const ParamValue value = ReadParamValue(params, row.member);
  if (const auto* s = std::get_if<std::string>(&value)) {
    if (std::find(row.choices.begin(), row.choices.end(), *s) == row.choices.end()) {
      ThrowParamOutOfRange(row, FormatParamValue(value));
    }
    return;
  }
  double v = 0;
  if (const auto* i = std::get_if<int>(&value)) v = *i;
  if (const auto* d = std::get_if<double>(&value)) v = *d;
  if (std::holds_alternative<bool>(value)) return;
  if (!InParamBounds(v, row.bounds)) ThrowParamOutOfRange(row, FormatParamValue(value));
}

}  // namespace slamtune::slam
