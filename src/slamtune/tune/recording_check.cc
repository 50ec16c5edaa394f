#include "slamtune/tune/recording_check.h"

#include "slamtune/report/scan_losses_json.h"

namespace slamtune::tune {

io::CheckReport CheckRecordingFile(const RecordingCheckOptions& options) {
  return io::CheckRecording(options.log, options.input.ToReadOptions(), options.check);
}

nlohmann::ordered_json ToJson(const io::CheckReport& report) {
  nlohmann::ordered_json problems = nlohmann::ordered_json::array();
  for (const io::CheckProblem& p : report.problems) {
    problems.push_back({{"kind", io::ProblemKindName(p.kind)},
                        {"what", p.what},
                        {"count", p.count},
                        {"scans", p.scans},
                        {"times_s", p.times_s}});
  }
  return {{"path", report.path},
          {"ok", report.ok()},
          {"facts", report.facts},
          {"problems", problems},
          {"scans_not_used", report::ScanLossesJson(report.scans_not_used)}};
}

}  // namespace slamtune::tune
