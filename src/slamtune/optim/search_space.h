// The space NSGA-III searches: which mapper parameters vary (by ROS name, with bounds and
// type) and which are held fixed. The default searches r = loop_search_maximum_distance and
// g = loop_match_minimum_chain_size around the base configuration (AroundBase); the seed
// paper's space (Han et al., Sensors 2020, §4: r in [2, 6] m, g in [6, 20] (integer),
// p = loop_match_minimum_response_coarse = 0.7 and q = loop_match_maximum_variance_coarse
// = 0.4 (ROS units) fixed) is PaperDefault.
//
// Decision vectors follow pagmo's convention: real genes first, integer genes last (nix), so
// dimensions are stored reals-then-integers whatever order the YAML lists them in.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "slamtune/slam/params/mapper_params.h"

namespace slamtune::optim {

struct Dimension {
  std::string name;  // ROS parameter name, e.g. "loop_search_maximum_distance"
  double lower = 0.0;
  double upper = 0.0;
  bool integer = false;
  // 0: any value in [lower, upper]. > 0: only lower + k step (k = 0, 1, ... up to upper), as
  // Optuna's `step`: offspring that differ by less than a step become the same parameter set,
  // served again by the run database, and values that must sit on a lattice (a search window
  // of an even number of cells) are never drawn off it.
  double step = 0.0;

  // The value `x` stands for: rounded to the step (or to a whole number) and kept in bounds.
  double ValueOf(double x) const;
};

struct SearchSpace {
  std::vector<Dimension> dimensions;         // reals first, then integers
  std::map<std::string, double> fixed;       // held constant (ROS units)
  std::map<std::string, std::size_t> lines;  // where each name is in the YAML file (messages only)

  // The seed paper's space (header comment); `--space paper`.
  static SearchSpace PaperDefault();
  // The default: r and g over the paper's ranges widened to contain the base configuration's
  // values (r in [min(2, r0), max(6, r0)] m, g in [min(6, g0), max(20, g0)]); nothing fixed, so
  // every other parameter keeps the base's value.
  static SearchSpace AroundBase(double base_r, int base_g);
  // `--space loop`, the default without a front-end break: the same ranges on steps that mean
  // something — r on a 1 cm lattice through the base's value, g by 1 — so offspring closer than a
  // step are one parameter set (served by the run database) and the recommended r reads as
  // written (e.g. 3.52, not 3.5197...). (AroundBase without steps is what folders written
  // before steps existed resume with.)
  static SearchSpace Loop(const slam::MapperParams& base);
  // `--space front-end`: what governs sequential matching and node density, plus r, g, p, q, for
  // maps that break before any loop closes (the sequential match snaps to a wrong pose and no
  // loop-closure setting can mend it). Each range contains the base's value; the search window
  // is on its lattice (steps of 2 x correlation_search_space_resolution) and bounded so one
  // run stays within ~30x the default's matching work; the ranges and costs are in
  // docs/search-spaces.md.
  static SearchSpace FrontEnd(const slam::MapperParams& base);

  // Reads a YAML search space:
  //   vary:
  //     loop_search_maximum_distance: {min: 2.0, max: 6.0}
  //     loop_match_minimum_chain_size: {min: 6, max: 20, type: int}
  //     correlation_search_space_dimension: {min: 0.3, max: 1.6, step: 0.02}
  //   fix:
  //     loop_match_minimum_response_coarse: 0.7
  // Throws InputError naming the file, the line and the problem (empty space, reversed bounds,
  // non-integer bounds for an int, unknown keys or parameter names, a parameter that is not a
  // number — booleans and strings cannot be searched —, an integer parameter declared real, a
  // name both varied and fixed). An integer parameter without `type` is searched as int.
  static SearchSpace FromYaml(const std::string& path);
  // The same from the command line: each of `vary` is NAME=MIN:MAX[:STEP] (an integer parameter
  // is searched as int, its STEP a whole number), each of `fix` NAME=VALUE; NAME is a ROS name
  // or one of the seed paper's short names r, g, p, q (FullParamName). Throws InputError naming
  // the flag, the entry and the rule; the same rules as FromYaml.
  static SearchSpace FromFlags(const std::vector<std::string>& vary, const std::vector<std::string>& fix);

  // Rejects an empty space, reversed or non-finite bounds, integer dimensions with
  // fractional bounds, duplicates. `source` prefixes the message (file name or "--space").
  void Validate(const std::string& source) const;

  std::size_t size() const { return dimensions.size(); }
  std::size_t LineOf(const std::string& name) const;
  std::size_t integer_count() const;
  // Whether the search varies what a map is drawn from or at — which scans become nodes
  // (minimum_travel_distance, minimum_travel_heading, minimum_time_interval), which beams are
  // drawn (max_laser_range, min_laser_range) or the cell size (resolution) — so that counts of
  // map cells differ between runs for reasons other than the map's consistency.
  bool VariesMapSampling() const;
  // Whether runs may differ in their sequential matching: the space varies a parameter of the
  // sequential matcher, of the node spacing or of the running buffer (the front end). Only then
  // can one run's front end break where another's holds.
  bool VariesFrontEnd() const;
  // The fixed values plus the decision vector's values, by name. Integer genes are
  // rounded (they already are, after NSGA-III's repair).
  std::map<std::string, double> Assign(const std::vector<double>& decision) const;
  // Canonical text of a full assignment, used as the cache key: "name=%.17g;..." sorted by name.
  static std::string Key(const std::map<std::string, double>& assignment);
  // A stable fingerprint of the space (names, bounds, types, fixed values) for --resume checks.
  std::string Fingerprint() const;
};

// The ROS name of a seed-paper short name (r = loop_search_maximum_distance, g =
// loop_match_minimum_chain_size, p = loop_match_minimum_response_coarse, q =
// loop_match_maximum_variance_coarse); any other name unchanged.
std::string FullParamName(const std::string& name);

// A number written on the command line: the whole of `text`, finite. InputError
// "WHAT: 'TEXT' is not a number" otherwise.
double ParseFlagNumber(const std::string& text, const std::string& what);

// Refuses, before any work, a space whose bounds or fixed values the engine would reject on top
// of `base` (e.g. g = 0, a negative distance): each bound is tried with the fixed values,
// validated as one set. InputError names `source`, the line and the rule.
void CheckSpaceAgainst(const SearchSpace& space, const slam::MapperParams& base, const std::string& source);

}  // namespace slamtune::optim
