// Occupancy maps as labelled figure panels, for the report's side-by-side comparison of the
// candidates' maps.
//
// A SLAM map is mostly unknown border, so each map is first cropped to its known cells (plus
// a margin) and then scaled to a common height, so maps of different extents compare at a
// glance; INTER_AREA when shrinking keeps one-cell walls visible as grey rather than dropping
// them, INTER_NEAREST when enlarging keeps cells square. The greys are map_server's
// (occupied black, free near-white, unknown grey, io/map_image.h).
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "slamtune/io/map_image.h"

namespace slamtune::report {

struct MapPanelOptions {
  int height = 480;        // px, height of the map part of every panel, in [32, 4000]
  int max_width = 1200;    // px, wider maps are shrunk to this width (keeping the aspect), >= 32
  bool crop = true;        // crop each map to its known (non-unknown) cells first
  int crop_margin = 10;    // cells of border kept around the known area, in [0, 1000]
  double font_scale = 0.6; // Hershey simplex scale of the label (caption 0.85x), in (0, 4]

  void Validate() const;
};

// True when the map has cells and width * height pixels (what WriteMapServer accepts).
bool HasMap(const io::MapImage& map);

// Bounding box (in image pixels) of the cells that are not unknown, grown by `margin` and
// kept inside the image; the whole image when every cell is unknown.
cv::Rect KnownBounds(const io::MapImage& map, int margin);

// A BGR panel: `label` on top, the map (cropped and scaled) under it, `caption` below. A map
// without cells (HasMap false) gives a grey placeholder saying so, of the same height.
cv::Mat RenderMapPanel(const io::MapImage& map, const std::string& label, const std::string& caption,
                       const MapPanelOptions& options);

}  // namespace slamtune::report
