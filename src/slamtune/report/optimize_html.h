// report.html of `slamtune optimize`: one self-contained page (html_page.h) an engineer reads
// after the run: the verdict, why this set was recommended (with a warning for a value on a
// bound of its range) and what to do next, the run, the candidates (parameters, objectives,
// loop closures, errors), the maps with their loop closures, the population and
// parameter-space figures, how the search progressed generation by generation, every
// evaluation in a sortable table, the objectives against ground-truth error with their rank
// correlations, what the objectives can and cannot tell, and the settings. Under the
// recommendation: the parameter ranges that gave an equivalent map (how sure it is). The verdict
// section is verdict_html.h, which words the judgements of recommendation_assessment.h.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "slamtune/optim/optimize_result.h"
#include "slamtune/report/error_correlation.h"

namespace slamtune::report {

// The PNG bytes of the figures (the same bytes as the files beside report.html).
struct OptimizeFigures {
  std::vector<std::uint8_t> maps;  // empty: no candidates
  struct MapPanel {
    std::string label;  // "recommended = knee" when they are the same set
    std::string file;   // the panel's PNG beside report.html
    std::vector<std::uint8_t> png;
    std::string caption;
  };
  std::vector<MapPanel> map_panels;                                    // one per distinct candidate parameter set
  std::vector<std::pair<int, std::vector<std::uint8_t>>> populations;  // (generation, png)
  std::vector<std::uint8_t> evolution;                                 // empty: no snapshots
  std::vector<std::uint8_t> parameter_space;                           // empty: nothing varied or evaluated
  std::vector<std::uint8_t> objective_vs_error;                        // empty: no ground truth
  std::vector<std::uint8_t> front_end;                                 // empty: no base front end
  std::vector<MapPanel> slices;       // per objective (label = its symbol): it against each parameter; empty: none
  std::vector<std::uint8_t> history;  // best objectives and hypervolume per generation; empty: no history
  std::vector<std::uint8_t> front_end_map;  // the evidence on the base run's map; empty: no base front end or no map
};

// What the objectives can tell, measured with a reference Karto on real logs; shown in every
// report so that nobody reads a millimetre-level ranking into them.
extern const char* const kObjectivesCaveat;

std::string OptimizeHtml(const optim::OptimizeResult& result, const OptimizeFigures& figures,
                         const std::optional<ErrorCorrelationSummary>& correlation,
                         const std::vector<std::string>& files);

}  // namespace slamtune::report
