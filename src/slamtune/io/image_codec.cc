#include "slamtune/io/image_codec.h"

#include <fmt/format.h>
#include <png.h>

#include <cctype>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "slamtune/common/error.h"

namespace slamtune::io {
namespace {

constexpr const char* kConvertHint =
    "maps must be 8-bit greyscale with one channel (convert it first, e.g. `convert IN -colorspace Gray -depth 8 "
    "OUT.pgm`)";

[[noreturn]] void Fail(const std::string& path, const std::string& what, const std::string& suffix) {
  throw InputError(path, 0, what + suffix);
}

void CheckSize(std::uint64_t width, std::uint64_t height, const std::string& path, const std::string& suffix) {
  if (width == 0 || height == 0) {
    Fail(path, fmt::format("cannot decode the image: truncated, corrupt or empty ({} x {})", width, height), suffix);
  }
  if (width > kMaxImagePixels || height > kMaxImagePixels || width * height > kMaxImagePixels) {
    Fail(path,
         fmt::format("declares {} x {} pixels, more than the {} an image may have", width, height, kMaxImagePixels),
         suffix);
  }
}

// ---- PGM (Netpbm): "P5" or "P2", whitespace and #-comments, width, height, maxval, one space.
class PgmHeader {
 public:
  PgmHeader(std::string_view bytes, std::size_t start) : bytes_(bytes), pos_(start) {}
  // The next decimal number after whitespace and comments; false when there is none.
  bool Number(std::uint64_t* value) {
    while (pos_ < bytes_.size()) {
      const char c = bytes_[pos_];
      if (c == '#') {
        while (pos_ < bytes_.size() && bytes_[pos_] != '\n' && bytes_[pos_] != '\r') ++pos_;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        ++pos_;
      } else {
        break;
      }
    }
    std::size_t digits = 0;
    *value = 0;
    while (pos_ < bytes_.size() && std::isdigit(static_cast<unsigned char>(bytes_[pos_])) && digits < 12) {
      *value = *value * 10 + static_cast<std::uint64_t>(bytes_[pos_++] - '0');
      ++digits;
    }
    return digits > 0 && digits < 12;
  }
  std::size_t pos() const { return pos_; }
  void Skip() { ++pos_; }

 private:
  std::string_view bytes_;
  std::size_t pos_;
};

GreyImage DecodePgm(std::string_view bytes, const std::string& path, const std::string& suffix) {
  const bool binary = bytes[1] == '5';
  PgmHeader header(bytes, 2);  // after the magic number
  std::uint64_t width = 0, height = 0, maxval = 0;
  if (!header.Number(&width) || !header.Number(&height) || !header.Number(&maxval)) {
    Fail(path, "cannot decode the image: the PGM header (width, height, maxval) is truncated or not numbers", suffix);
  }
  if (maxval == 0 || maxval > 65535) Fail(path, fmt::format("not a valid PGM: maxval {}", maxval), suffix);
  if (maxval > 255) Fail(path, std::string("is a 1-channel 16-bit image; ") + kConvertHint, suffix);
  CheckSize(width, height, path, suffix);
  header.Skip();  // the single whitespace before the pixels
  GreyImage image;
  image.width = static_cast<int>(width);
  image.height = static_cast<int>(height);
  const std::uint64_t count = width * height;
  const std::string_view data = bytes.substr(std::min(header.pos(), bytes.size()));
  if (binary && data.size() < count) {
    Fail(path,
         fmt::format("truncated: the header declares {} x {} = {} pixels, the file holds {}", width, height, count,
                     data.size()),
         suffix);
  }
  // P2 holds at least one digit per pixel and one whitespace between pixels: a header promising
  // more than the text can hold is refused before the pixels are allocated.
  if (!binary && data.size() < 2 * count - 1) {
    Fail(path,
         fmt::format("truncated: the header declares {} x {} = {} pixels, the {} bytes of text hold at most {}", width,
                     height, count, data.size(), (data.size() + 1) / 2),
         suffix);
  }
  image.pixels.resize(count);
  PgmHeader text(data, 0);  // P2: numbers separated by whitespace
  for (std::uint64_t k = 0; k < count; ++k) {
    std::uint64_t v = 0;
    if (binary) {
      v = static_cast<unsigned char>(data[k]);
    } else if (!text.Number(&v)) {
      Fail(path, fmt::format("truncated: the header declares {} pixels, the file holds {}", count, k), suffix);
    }
    if (v > maxval) Fail(path, fmt::format("not a valid PGM: pixel {} is {}, above maxval {}", k, v, maxval), suffix);
    image.pixels[k] = static_cast<std::uint8_t>(maxval == 255 ? v : (v * 255 + maxval / 2) / maxval);
  }
  return image;
}

// ---- PNG: IHDR checked here, pixels decoded by libpng with silent handlers.
constexpr std::uint64_t kMaxDeflateRatio = 1032;  // most bytes one compressed byte of deflate can stand for
constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

std::uint32_t BigEndian32(std::string_view b, std::size_t at) {
  return (static_cast<std::uint32_t>(static_cast<unsigned char>(b[at])) << 24) |
         (static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 1])) << 16) |
         (static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 2])) << 8) |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 3]));
}

struct PngSource {
  const unsigned char* data;
  std::size_t size;
  std::size_t offset;
  char message[256];
};

void PngError(png_structp png, png_const_charp message) {
  auto* source = static_cast<PngSource*>(png_get_error_ptr(png));
  std::snprintf(source->message, sizeof(source->message), "%s", message);
  png_longjmp(png, 1);
}

void PngWarning(png_structp, png_const_charp) {}  // a warning changes no pixel: say nothing

void PngRead(png_structp png, png_bytep out, png_size_t n) {
  auto* source = static_cast<PngSource*>(png_get_io_ptr(png));
  if (n > source->size - source->offset) png_error(png, "the file ends inside the image data");
  std::memcpy(out, source->data + source->offset, n);
  source->offset += n;
}

// libpng's decode into `pixels` (height rows of width bytes), row by row and pass by pass for an
// interlaced image, so that no array of row pointers is allocated. Only plain data in this
// frame: png_longjmp returns here past no destructor.
bool DecodePngRows(PngSource* source, png_bytep pixels, std::size_t width, std::size_t height) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, source, PngError, PngWarning);
  if (png == nullptr) return false;
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_set_read_fn(png, source, PngRead);
  png_read_info(png, info);
  if (png_get_bit_depth(png, info) < 8) png_set_expand_gray_1_2_4_to_8(png);
  const int passes = png_set_interlace_handling(png);
  png_read_update_info(png, info);
  if (png_get_rowbytes(png, info) != width) png_error(png, "unexpected row size");
  for (int pass = 0; pass < passes; ++pass) {
    for (std::size_t r = 0; r < height; ++r) png_read_row(png, pixels + r * width, nullptr);
  }
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

GreyImage DecodePng(std::string_view bytes, const std::string& path, const std::string& suffix) {
  if (bytes.size() < 33 || bytes.substr(12, 4) != "IHDR") {
    Fail(path, "cannot decode the image: truncated PNG (no complete IHDR header)", suffix);
  }
  const std::uint32_t width = BigEndian32(bytes, 16), height = BigEndian32(bytes, 20);
  const int depth = static_cast<unsigned char>(bytes[24]), colour = static_cast<unsigned char>(bytes[25]);
  const char* channels = colour == 0   ? "1-channel"
                         : colour == 4 ? "2-channel (grey + alpha)"
                         : colour == 6 ? "4-channel"
                         : colour == 3 ? "3-channel (palette)"
                                       : "3-channel";
  if (colour != 0 || depth > 8) {
    Fail(path, fmt::format("is a {} {}-bit image; {}", channels, depth > 8 ? 16 : 8, kConvertHint), suffix);
  }
  if (depth != 1 && depth != 2 && depth != 4 && depth != 8) {
    Fail(path, fmt::format("not a valid PNG: grey bit depth {} (the PNG spec allows 1, 2, 4, 8, 16)", depth), suffix);
  }
  CheckSize(width, height, path, suffix);
  // Deflate expands at most 1032-fold (zlib's technical details), so the file's bytes bound the
  // image data it can hold: every row's filter byte and its pixels' bits (interlaced or not). A
  // header promising more is refused before the pixels are allocated (a 40-byte file must not
  // cost gigabytes).
  const std::uint64_t min_data =
      height + static_cast<std::uint64_t>(width) * height * static_cast<std::uint64_t>(depth) / 8;
  const std::uint64_t max_data = static_cast<std::uint64_t>(bytes.size()) * kMaxDeflateRatio;
  if (min_data > max_data) {
    Fail(path,
         fmt::format("truncated: the header declares {} x {} pixels ({} bytes of image data), more than the "
                     "file's {} bytes can hold compressed",
                     width, height, min_data, bytes.size()),
         suffix);
  }
  GreyImage image;
  image.width = static_cast<int>(width);
  image.height = static_cast<int>(height);
  image.pixels.resize(static_cast<std::size_t>(width) * height);
  PngSource source{reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), 0, {}};
  if (!DecodePngRows(&source, image.pixels.data(), width, height)) {
    Fail(path, std::string("cannot decode the image: truncated or corrupt PNG (") + source.message + ")", suffix);
  }
  return image;
}

}  // namespace

GreyImage DecodeGreyImage(std::string_view bytes, const std::string& path, const std::string& suffix) {
  if (bytes.size() >= 8 && std::memcmp(bytes.data(), kPngSignature, 8) == 0) return DecodePng(bytes, path, suffix);
  if (bytes.size() >= 2 && bytes[0] == 'P' && (bytes[1] == '2' || bytes[1] == '5')) {
    return DecodePgm(bytes, path, suffix);
  }
  if (bytes.size() >= 2 && bytes[0] == 'P' && (bytes[1] == '3' || bytes[1] == '6')) {
    Fail(path, std::string("is a 3-channel 8-bit image (PPM); ") + kConvertHint, suffix);
  }
  if (bytes.size() >= 2 && bytes[0] == 'P' && (bytes[1] == '1' || bytes[1] == '4')) {
    Fail(path, std::string("is a 1-bit PBM bitmap; ") + kConvertHint, suffix);
  }
  Fail(path, "not an image: no known image format signature (PGM or PNG expected)", suffix);
}

std::string EncodePgm(int width, int height, const std::uint8_t* pixels) {
  std::string out = fmt::format("P5\n{} {}\n255\n", width, height);
  out.append(reinterpret_cast<const char*>(pixels), static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  return out;
}

std::string EncodeGreyPng(int width, int height, const std::uint8_t* pixels) {
  const cv::Mat view(height, width, CV_8UC1, const_cast<std::uint8_t*>(pixels));  // read only
  std::vector<std::uint8_t> png;
  SLAMTUNE_CHECK(cv::imencode(".png", view, png));
  return std::string(png.begin(), png.end());
}

}  // namespace slamtune::io
