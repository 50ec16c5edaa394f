// A number for JSON: NaN and infinities have no JSON form, so a figure that is not finite (no
// relation matched, nothing to divide by) is written as null rather than as invalid JSON.
#pragma once

#include <cmath>
#include <nlohmann/json.hpp>

namespace slamtune::report {

// `v`, or null when it is not finite; as nlohmann::json or nlohmann::ordered_json.
template <typename Json = nlohmann::json>
Json FiniteOrNull(double v) {
  return std::isfinite(v) ? Json(v) : Json(nullptr);
}

}  // namespace slamtune::report
