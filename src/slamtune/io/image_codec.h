// 8-bit greyscale map images to and from bytes, without a word from OpenCV or libpng.
//
// Why not cv::imread / cv::imwrite: on a bad file they print their own lines on stderr
// ("imread_(...): can't read header", "libpng error: Read Error", an OpenCV assertion for a
// huge declared size) before slamtune's one error line, and cv::imwrite reports no short write
// (a full disk left a truncated map.pgm behind). Here the PGM header is read by hand (Netpbm
// P2/P5), the PNG header (signature and IHDR, PNG spec §11.2.2) is checked before any pixel
// is decoded, PNG pixels are decoded by libpng with error and warning handlers that print
// nothing, and the declared size is checked against the data before memory is allocated.
// Files are written by map_image.cc through WriteFileAtomically, whole or not at all.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace slamtune::io {

// Width x height pixels, row-major, row 0 at the top.
struct GreyImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;
};

// Largest image accepted (pixels), OpenCV's own default limit (CV_IO_MAX_IMAGE_PIXELS).
inline constexpr std::uint64_t kMaxImagePixels = std::uint64_t{1} << 30;

// Decodes a PGM (P5 binary or P2 text; maxval below 255 scaled to 0..255) or a PNG (grey, 1 to 8
// bits) held in `bytes`. Throws InputError(path, 0, what + suffix) for anything else: no known
// signature ("not an image ..."), colour, grey+alpha or 16-bit data ("is a 3-channel 8-bit image;
// maps must be 8-bit greyscale ..."), a declared size over kMaxImagePixels or beyond the data
// ("truncated ..."), corrupt PNG data.
GreyImage DecodeGreyImage(std::string_view bytes, const std::string& path, const std::string& suffix);

// Binary PGM (P5, maxval 255) of `width` x `height` pixels.
std::string EncodePgm(int width, int height, const std::uint8_t* pixels);

// 8-bit grey PNG (lossless), as OpenCV's encoder writes it.
std::string EncodeGreyPng(int width, int height, const std::uint8_t* pixels);

}  // namespace slamtune::io
