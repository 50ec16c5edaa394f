#include "slamtune/tune/map_evaluation.h"

#include <fmt/format.h>

#include <filesystem>
#include <set>

#include "slamtune/common/error.h"
#include "slamtune/io/map_image.h"
#include "slamtune/metrics/map_quality_overlay.h"

namespace slamtune::tune {
namespace {

namespace fs = std::filesystem;

// `<stem>.quality.png` in the debug folder; a repeated stem gets the map's position prepended.
std::string OverlayPath(const std::string& dir, const std::string& map, std::size_t index,
                        std::set<std::string>& used) {
  std::string name = fs::path(map).stem().string() + ".quality.png";
  if (!used.insert(name).second) {
    name = fmt::format("{}_{}", index + 1, name);
    used.insert(name);
  }
  return (fs::path(dir) / name).string();
}

}  // namespace

std::vector<MapEvaluation> EvaluateMaps(const std::vector<std::string>& maps, const metrics::MapQualityOptions& options,
                                        const std::string& overlay_dir) {
  options.Validate();  // before any file is read
  if (!overlay_dir.empty()) {
    std::error_code ec;
    fs::create_directories(overlay_dir, ec);
    if (ec || !fs::is_directory(overlay_dir)) {
      throw InputError(overlay_dir, 0, "--debug-dir: cannot create the folder" + (ec ? ": " + ec.message() : ""));
    }
  }
  std::vector<MapEvaluation> out;
  std::set<std::string> used_names;
  for (std::size_t i = 0; i < maps.size(); ++i) {
    const io::MapImage map = io::ReadMap(maps[i]);
    MapEvaluation row{maps[i], {}, {}};
    if (overlay_dir.empty()) {
      row.quality = metrics::ComputeMapQuality(map, options);
    } else {
      row.overlay = OverlayPath(overlay_dir, maps[i], i, used_names);
      row.quality = metrics::WriteMapQualityOverlay(map, options, row.overlay);
    }
    out.push_back(std::move(row));
  }
  return out;
}

nlohmann::ordered_json ToJson(const MapEvaluation& row) {
  const metrics::MapQuality& q = row.quality;
  nlohmann::ordered_json j = {
      {"map", row.map},
      {"width", q.width},
      {"height", q.height},
      {"resolution", q.resolution},
      {"occupied_cells", q.occupied_cells},
      {"free_cells", q.free_cells},
      {"unknown_cells", q.unknown_cells},
      {"occupied_ratio", q.occupied_ratio},
      {"occupied_ratio_known", q.occupied_ratio_known},
      {"max_corner_response", q.max_corner_response},
      {"corner_pixels", q.corner_pixels},
      {"corners", q.corners},
      {"enclosed_areas", q.enclosed_areas},
      {"contours", q.contours},
      {"message", q.message},
  };
  if (!row.overlay.empty()) j["overlay"] = row.overlay;
  return j;
}

}  // namespace slamtune::tune
