// Ground-truth-free quality of an occupancy-grid map, read off the image alone.
//
// The three figures of Han et al., "Optimization-Based Parameter Tuning of Karto SLAM without
// Ground Truth" (Sensors 2020, after Filatov et al., "2D SLAM quality evaluation methods",
// FRUCT 2017). When loop closure fails the same wall is drawn twice, walls blur and rooms
// repeat slightly rotated, so all three grow; lower is better:
//   eta  (occupied_ratio)  occupied cells / all cells;
//   n_c  (corner_pixels)   pixels whose Harris response (Harris & Stephens 1988) exceeds a
//                          fraction of the map's largest response; `corners` also counts their
//                          8-connected clusters;
//   n_e  (enclosed_areas)  regions of non-occupied cells completely surrounded by occupied
//                          cells: hole borders in Suzuki & Abe's border following (1985,
//                          OpenCV findContours with RETR_CCOMP).
// n_c uses the pixel count by default: on real logs with a reference Karto it separates runs
// whose loop closure failed from working runs while the cluster count does not (doubled walls
// merge corner responses into fewer, larger blobs); see docs/metrics.md.
//
// Everything is computed on the wall mask (occupied -> 255, free and unknown -> 0) of an
// in-memory MapImage, classified with map_server's rule and the map's own thresholds, so the
// engine's grid can be scored without a disk round trip. Outside the map counts as "not wall":
// walls on the image border still close rooms, and corners there are found like any other.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "slamtune/io/map_image.h"

namespace slamtune::metrics {

// How n_c and n_e are measured. Defaults follow Filatov et al. / Han et al. and OpenCV's
// cornerHarris tutorial; docs/metrics.md explains each choice.
struct MapQualityOptions {
  // Side of the Gaussian kernel smoothing the wall mask before Harris, pixels; odd, 1..31
  // (1 = no smoothing). 3 rounds the staircase of diagonal walls without merging close walls.
  int blur_size = 3;
  // Gaussian sigma, pixels; >= 0. 0 lets OpenCV derive it from blur_size (0.8 for 3).
  double blur_sigma = 0.0;
  // Harris neighbourhood (window of the structure tensor), pixels; 2..31 (1 never finds a corner).
  int harris_block_size = 2;
  // Sobel aperture of the image derivatives: 1, 3, 5 or 7.
  int harris_aperture = 3;
  // Harris' k in R = det(M) - k trace(M)^2; in (0, 0.25) (at 0.25 and above R <= 0 everywhere).
  double harris_k = 0.04;
  // A corner pixel has R > corner_threshold * (largest R in the map); in (0, 1].
  double corner_threshold = 0.01;

  // Throws InputError naming the field, its value and the rule.
  void Validate() const;
};

// The figures for one map (all counts in cells / pixels of the map image).
struct MapQuality {
  int width = 0;            // cells
  int height = 0;           // cells
  double resolution = 0.0;  // m per cell, as given by the map
  std::int64_t occupied_cells = 0;
  std::int64_t free_cells = 0;
  std::int64_t unknown_cells = 0;
  double occupied_ratio = 0.0;        // eta = occupied / all cells (the paper's definition)
  double occupied_ratio_known = 0.0;  // occupied / (occupied + free); 0 when nothing is known
  double max_corner_response = 0.0;   // largest Harris response R in the map (0 without walls)
  std::int64_t corner_pixels = 0;     // n_c, the objective: pixels with R over the threshold
  int corners = 0;                    // 8-connected clusters of corner pixels
  int enclosed_areas = 0;             // n_e: hole contours (contours with a parent)
  int contours = 0;                   // all contours: outer borders of wall components + holes
  std::string message;                // how the figures came about, e.g. why they are 0
};

// One line: size, eta, n_c (clusters), n_e (contours) and the message.
std::string BriefReport(const MapQuality& quality);

// The figures with the intermediate images, for the debug overlay.
struct MapQualityDetail {
  MapQuality quality;
  // Corner pixels (255) of the map region `corner_window` (map pixel coordinates); empty
  // when the map has no walls. Cells outside the window are not corners.
  cv::Rect corner_window;
  cv::Mat corner_mask;
  // Contours in map pixel coordinates (column, row) and their RETR_CCOMP hierarchy
  // [next, previous, first child, parent]; a hole has parent >= 0.
  std::vector<std::vector<cv::Point>> contours;
  std::vector<cv::Vec4i> hierarchy;
};

// Computes every figure. Throws InputError if the options are invalid or the map is
// malformed (empty, pixel count != width * height, bad thresholds). Deterministic.
MapQualityDetail AnalyseMapQuality(const io::MapImage& map, const MapQualityOptions& options = {});

// The figures only (same computation as AnalyseMapQuality).
MapQuality ComputeMapQuality(const io::MapImage& map, const MapQualityOptions& options = {});

}  // namespace slamtune::metrics
