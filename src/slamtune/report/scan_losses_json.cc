#include "slamtune/report/scan_losses_json.h"

namespace slamtune::report {

nlohmann::json ScanLossesJson(const io::ScanLosses& losses) {
  nlohmann::json out = nlohmann::json::object();
  for (const io::ScanLoss& k : losses.kinds) {
    nlohmann::json entry = {
        {"count", k.count ? nlohmann::json(*k.count) : nlohmann::json(nullptr)},
        {"data_loss", io::IsDataLoss(k.kind)},
        {"what", k.why.empty() ? io::DescriptionOf(k.kind) : k.why},
    };
    if (!k.first.empty()) entry["first"] = k.first;
    if (k.kind == io::ScanLossKind::kCutOff) entry["bytes"] = k.bytes;
    if (!k.by.empty()) entry["by"] = k.by;
    out[io::NameOf(k.kind)] = entry;
  }
  return out;
}

}  // namespace slamtune::report
