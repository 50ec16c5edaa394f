#include "slamtune/tune/sweep_command.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "slamtune/common/error.h"
#include "slamtune/optim/search_space.h"

namespace slamtune::tune {

SweepRange ParseSweepRange(const std::string& vary) {
  const auto eq = vary.find('=');
  if (eq == std::string::npos) throw InputError("--vary must be NAME=LO:HI[:STEP], got '" + vary + "'");
  SweepRange range;
  range.name = optim::FullParamName(vary.substr(0, eq));
  std::vector<std::string> parts;
  for (std::string rest = vary.substr(eq + 1);;) {
    const auto c = rest.find(':');
    parts.push_back(rest.substr(0, c));
    if (c == std::string::npos) break;
    rest = rest.substr(c + 1);
  }
  if (parts.size() < 2 || parts.size() > 3) throw InputError("--vary must be NAME=LO:HI[:STEP], got '" + vary + "'");
  range.lo = optim::ParseFlagNumber(parts[0], "--vary LO");
  range.hi = optim::ParseFlagNumber(parts[1], "--vary HI");
  range.step = parts.size() == 3 ? optim::ParseFlagNumber(parts[2], "--vary STEP") : 1.0;
  if (!(range.lo <= range.hi)) throw InputError(fmt::format("--vary: bounds reversed ({} > {})", range.lo, range.hi));
  if (!(range.step > 0)) throw InputError(fmt::format("--vary: STEP must be > 0, got {}", range.step));
  if ((range.hi - range.lo) / range.step > 10000) {
    throw InputError("--vary: more than 10000 values; use a larger STEP");
  }
  return range;
}

std::vector<optim::Assignment> SweepBatch(const SweepRange& range, const std::vector<std::string>& fix,
                                          const optim::SlamEvaluationContext& context) {
  optim::Assignment fixed;
  for (const auto& f : fix) {
    const auto e = f.find('=');
    if (e == std::string::npos) throw InputError("--fix must be NAME=VALUE, got '" + f + "'");
    fixed[optim::FullParamName(f.substr(0, e))] = optim::ParseFlagNumber(f.substr(e + 1), "--fix " + f.substr(0, e));
  }
  std::vector<optim::Assignment> batch;
  for (int i = 0;; ++i) {
    const double v = range.lo + i * range.step;
    if (v > range.hi + 1e-9 * std::max(1.0, std::fabs(range.hi))) break;
    optim::Assignment a = fixed;
    a[range.name] = std::round(v * 1e9) / 1e9;  // 2 + 3 * 0.25 prints as 2.75, not 2.7500000000000004
    context.ParamsFor(a);                       // validates names and values before any work
    batch.push_back(a);
  }
  return batch;
}

SweepOutcome RunSweep(const SweepOptions& options, TuningProcess& process, const SweepHooks& hooks) {
  options.run.Validate();
  const SweepRange range = ParseSweepRange(options.vary);
  if (options.out.empty()) throw InputError("--out DIR is required");
  const TuningInputs inputs =
      LoadTuningInputs(options.inputs, options.run.quiet ? InputNotes::kDataLoss : InputNotes::kAll);
  auto context = MakeEvaluationContext(inputs, {}, options.run);
  const std::vector<optim::Assignment> batch = SweepBatch(range, options.fix, *context);
  CreateOutputFolder(options.out);
  process.SetupWorkers(options.inputs, {}, options.run, optim::WallDrawing::kSkip);
  if (hooks.started) {
    hooks.started(fmt::format("sweeping {} over {} values on {} with {}", range.name, batch.size(),
                              inputs.source.log_label, process.Parallelism(options.run.jobs)));
  }
  optim::BatchEvaluator evaluator(EvaluateWith(context), nullptr, options.run.jobs);
  process.ShareWith(evaluator);
  if (hooks.evaluated) {
    evaluator.SetProgressCallback([&](const optim::EvaluationRecord& r, const optim::BatchEvaluatorStats& s) {
      hooks.evaluated({range.name, r.params.at(range.name), r.loop_closures, s.evaluated, batch.size()});
    });
  }
  const std::vector<optim::EvaluationRecord> records = evaluator.Evaluate(batch);
  process.StopWorkers();
  SweepOutcome out;
  out.name = range.name;
  for (std::size_t i = 0; i < batch.size(); ++i) out.points.push_back({batch[i].at(range.name), records[i]});
  out.with_errors = !inputs.relations.empty();
  report::SweepReportOptions report_options;
  report_options.log_path = inputs.source.log_label;
  report_options.log_input = inputs.source.log_input;
  out.report = report::WriteSweepReport(range.name, out.points, options.out, report_options);
  out.evaluations = evaluator.stats();
  out.shared_work = optim::SharedWorkReport(*context);
  return out;
}

}  // namespace slamtune::tune
