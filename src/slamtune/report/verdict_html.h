// The "Verdict" section of report.html (optimize_html.h): the log's scans no run maps, why the
// set was recommended and a warning for each recommended value on a bound of its search range
// (the words for a RecommendationAssessment, recommendation_assessment.h), the parameter sets
// with an equivalent map (how sure), the candidate closest to the ground truth, what to do next,
// and the changes from the base configuration with the commands that load them.
#pragma once

#include "slamtune/optim/optimize_result.h"
#include "slamtune/report/html_page.h"

namespace slamtune::report {

void VerdictSection(HtmlPage& page, const optim::OptimizeResult& result);

}  // namespace slamtune::report
