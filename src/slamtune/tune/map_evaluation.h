// `slamtune evaluate` as library work: the map-quality figures (metrics/map_quality.h) of saved
// maps, from this engine or any SLAM system that writes map_server PGM/YAML or PNG, with an
// overlay image per map on request (metrics/map_quality_overlay.h).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "slamtune/metrics/map_quality.h"

namespace slamtune::tune {

struct MapEvaluation {
  std::string map;  // the file as given
  metrics::MapQuality quality;
  std::string overlay;  // the overlay PNG written, or ""
};

// Each map of `maps` read and measured with `options` (validated before any file is read); with
// `overlay_dir` (created) an overlay per map there, `<stem>.quality.png` (a repeated stem gets the
// map's position prepended). InputError naming the file for an unreadable map or folder.
std::vector<MapEvaluation> EvaluateMaps(const std::vector<std::string>& maps, const metrics::MapQualityOptions& options,
                                        const std::string& overlay_dir);

// One map's figures as `evaluate --json` lists them.
nlohmann::ordered_json ToJson(const MapEvaluation& evaluation);

}  // namespace slamtune::tune
