// PNG and base64 (png_encoding.h).
#include "slamtune/report/png_encoding.h"

#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "slamtune/common/atomic_file.h"
#include "slamtune/common/error.h"

namespace slamtune::report {

std::vector<std::uint8_t> EncodePng(const cv::Mat& image) {
  SLAMTUNE_CHECK_MSG(!image.empty() && image.depth() == CV_8U && (image.channels() == 1 || image.channels() == 3),
                     "EncodePng needs a non-empty 8-bit grey or BGR image");
  std::vector<std::uint8_t> bytes;
  // Fixed compression level: same pixels, same bytes.
  const bool ok = cv::imencode(".png", image, bytes, {cv::IMWRITE_PNG_COMPRESSION, 6});
  SLAMTUNE_CHECK_MSG(ok, "OpenCV failed to encode a PNG");
  return bytes;
}

void WriteBytes(const std::vector<std::uint8_t>& bytes, const std::string& path) {
  // Atomically (common/atomic_file.h): an interrupted run leaves the old file or the new one.
  WriteFileAtomically(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

std::string Base64Encode(std::span<const std::uint8_t> bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  // RFC 4648 §4: each 24-bit group becomes four 6-bit indices.
  for (; i + 3 <= bytes.size(); i += 3) {
    const std::uint32_t group = (std::uint32_t{bytes[i]} << 16) | (std::uint32_t{bytes[i + 1]} << 8) | bytes[i + 2];
    out += kAlphabet[(group >> 18) & 63];
    out += kAlphabet[(group >> 12) & 63];
    out += kAlphabet[(group >> 6) & 63];
    out += kAlphabet[group & 63];
  }
  // The final 1 or 2 bytes are zero-padded to whole 6-bit indices and marked with '='.
  const std::size_t rest = bytes.size() - i;
  if (rest > 0) {
    std::uint32_t group = std::uint32_t{bytes[i]} << 16;
    if (rest == 2) group |= std::uint32_t{bytes[i + 1]} << 8;
    out += kAlphabet[(group >> 18) & 63];
    out += kAlphabet[(group >> 12) & 63];
    out += rest == 2 ? kAlphabet[(group >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string PngDataUri(const std::vector<std::uint8_t>& png) { return "data:image/png;base64," + Base64Encode(png); }

}  // namespace slamtune::report
