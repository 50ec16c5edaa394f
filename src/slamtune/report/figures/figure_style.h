// What the report's figures (plot.h, parallel_coordinates.h, map_panels.h) share: colours, spacing
// and the check of their options.
#pragma once

#include <fmt/format.h>

#include <opencv2/core.hpp>
#include <string>

#include "slamtune/common/error.h"

namespace slamtune::report {

inline const cv::Scalar kWhite(255, 255, 255);  // BGR
inline const cv::Scalar kBlack(0, 0, 0);
inline const cv::Scalar kTextGrey(60, 60, 60);
inline constexpr int kMargin = 10;     // px around everything
inline constexpr int kTickLength = 5;  // px, out from an axis
inline constexpr int kGap = 6;         // px between a label and what it labels

// Throws InputError "field = value: rule" unless `ok`: the checks of the figures' options.
inline void RequireOption(bool ok, const std::string& field, double value, const std::string& rule) {
  if (!ok) throw InputError(fmt::format("{} = {}: {}", field, value, rule));
}

}  // namespace slamtune::report
