// A picture of what the map-quality metrics counted, for `slamtune evaluate --debug-dir`
// and docs/metrics.md: the map (occupied black, free white, unknown grey), each enclosed
// area (n_e) filled in its own colour, corner pixels (n_c) in red with a red ring around
// each cluster, and the figures in a caption.
#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "slamtune/io/map_image.h"
#include "slamtune/metrics/map_quality.h"

namespace slamtune::metrics {

// Small maps are enlarged by a whole factor (nearest neighbour, so cells stay square and
// sharp) until the longer side reaches this many pixels, by at most kOverlayMaxScale.
inline constexpr int kOverlayTargetSide = 480;
inline constexpr int kOverlayMaxScale = 8;

// The overlay as a BGR image; `detail` must come from AnalyseMapQuality(map, ...).
cv::Mat RenderMapQualityOverlay(const io::MapImage& map, const MapQualityDetail& detail);

// Analyses the map, writes the overlay as PNG and returns the figures. Throws InputError for
// an invalid map or options, a path not ending in .png, or an unwritable file.
MapQuality WriteMapQualityOverlay(const io::MapImage& map, const MapQualityOptions& options,
                                  const std::string& png_path);

}  // namespace slamtune::metrics
