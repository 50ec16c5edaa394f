// PNG encoding of report figures, to a file and to base64 for embedding in report.html.
//
// Images are encoded once (EncodePng) and the same bytes are written to disk and embedded
// as a data URI, so the HTML shows exactly the file beside it. PNG is lossless and
// libpng's output depends only on the pixels and the fixed compression level, so a report is
// byte-identical from run to run. Base64 follows RFC 4648 §4 (standard alphabet, '='
// padding, no line breaks), as data URIs require (RFC 2397).
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <span>
#include <string>
#include <vector>

namespace slamtune::report {

// PNG bytes of an 8-bit image (1 or 3 channels, BGR order as OpenCV keeps it).
std::vector<std::uint8_t> EncodePng(const cv::Mat& image);

// Writes bytes to `path` atomically (replacing it). Throws InputError naming the path if it cannot be
// written.
void WriteBytes(const std::vector<std::uint8_t>& bytes, const std::string& path);

// RFC 4648 §4 base64 of `bytes`.
std::string Base64Encode(std::span<const std::uint8_t> bytes);

// "data:image/png;base64,..." for PNG bytes.
std::string PngDataUri(const std::vector<std::uint8_t>& png);

}  // namespace slamtune::report
