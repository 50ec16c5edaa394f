#include "slamtune/io/image_codec.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/error_message.h"

namespace slamtune::io {
namespace {

using slamtune::testing::ErrorMessageOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// Error text of decoding `bytes`, and what was printed on stderr meanwhile.
std::string DecodeError(const std::string& bytes, std::string* printed = nullptr) {
  ::testing::internal::CaptureStderr();
  const std::string what = ErrorMessageOf([&] { DecodeGreyImage(bytes, "m.img", ""); });
  const std::string err = ::testing::internal::GetCapturedStderr();
  if (printed != nullptr) *printed = err;
  return what;
}

const std::uint8_t kPixels[6] = {0, 254, 205, 205, 0, 254};

TEST(ImageCodec, PgmAndPngRoundTrip) {
  for (const std::string& bytes : {EncodePgm(3, 2, kPixels), EncodeGreyPng(3, 2, kPixels)}) {
    const GreyImage image = DecodeGreyImage(bytes, "m", "");
    EXPECT_EQ(image.width, 3);
    EXPECT_EQ(image.height, 2);
    EXPECT_EQ(image.pixels, std::vector<std::uint8_t>(kPixels, kPixels + 6));
  }
  EXPECT_EQ(EncodePgm(3, 2, kPixels).substr(0, 11), "P5\n3 2\n255\n");
}

TEST(ImageCodec, PgmCommentsTextFormAndASmallerMaxvalAreRead) {
  const GreyImage text = DecodeGreyImage("P2\n# made by hand\n3 1\n# levels\n100\n0 50 100\n", "m", "");
  EXPECT_EQ(text.pixels, (std::vector<std::uint8_t>{0, 128, 255}));  // scaled to 0..255 as SDL_image does
}

TEST(ImageCodec, TruncatedOrHugePgmIsOneErrorAndNothingPrinted) {
  std::string printed;
  EXPECT_EQ(DecodeError(EncodePgm(3, 2, kPixels).substr(0, 14), &printed),
            "m.img: truncated: the header declares 3 x 2 = 6 pixels, the file holds 3");
  EXPECT_EQ(printed, "");
  EXPECT_EQ(DecodeError("P5\n100000 100000\n255\n\x01\x02", &printed),
            "m.img: declares 100000 x 100000 pixels, more than the 1073741824 an image may have");
  EXPECT_EQ(printed, "");
  EXPECT_EQ(DecodeError("P5\n3 2\n65535\n"),
            "m.img: is a 1-channel 16-bit image; maps must be 8-bit greyscale with one "
            "channel (convert it first, e.g. `convert IN -colorspace Gray -depth 8 "
            "OUT.pgm`)");
  EXPECT_EQ(DecodeError("P5\n3"),
            "m.img: cannot decode the image: the PGM header (width, height, maxval) is truncated or "
            "not numbers");
}

TEST(ImageCodec, TruncatedOrHugePngIsOneErrorAndNothingPrinted) {
  const std::string png = EncodeGreyPng(3, 2, kPixels);
  std::string printed;
  EXPECT_THAT(DecodeError(png.substr(0, png.size() - 20), &printed),
              HasSubstr("m.img: cannot decode the image: truncated or corrupt PNG ("));
  EXPECT_EQ(printed, "");
  std::string huge = png;  // IHDR width and height 0x00ffffff: 2.8e14 pixels
  huge.replace(16, 8, std::string("\x00\xff\xff\xff\x00\xff\xff\xff", 8));
  EXPECT_EQ(DecodeError(huge, &printed),
            "m.img: declares 16777215 x 16777215 pixels, more than the 1073741824 an image "
            "may have");
  EXPECT_EQ(printed, "");
  std::string corrupt = png;  // a flipped byte inside the IDAT data: CRC mismatch
  corrupt[corrupt.size() - 16] ^= 0x55;
  EXPECT_THAT(DecodeError(corrupt, &printed), HasSubstr("truncated or corrupt PNG"));
  EXPECT_EQ(printed, "");
}

TEST(ImageCodec, InterlacedPngIsRead) {
  // kPixels as an Adam7-interlaced 3 x 2 grey PNG.
  const std::string interlaced(
      "\x89\x50\x4e\x47\x0d\x0a\x1a\x0a\x00\x00\x00\x0d\x49\x48\x44\x52\x00\x00\x00\x03\x00\x00\x00\x02\x08"
      "\x00\x00\x00\x01\xcf\x18\x09\x50\x00\x00\x00\x0f\x49\x44\x41\x54\x78\x9c\x63\x60\x60\x38\xcb\xf0\x0f"
      "\x84\x01\x0e\x00\x03\x97\xa6\xfd\x4b\x13\x00\x00\x00\x00\x49\x45\x4e\x44\xae\x42\x60\x82",
      72);
  const GreyImage image = DecodeGreyImage(interlaced, "m", "");
  EXPECT_EQ(image.pixels, std::vector<std::uint8_t>(kPixels, kPixels + 6));
}

TEST(ImageCodec, SizeBeyondWhatTheFileCanHoldIsRefusedBeforeAllocating) {
  // 35 bytes declaring a 1 x 268435457 grey PNG: within the pixel limit, but deflate cannot
  // expand 35 bytes into 268 MB of rows.
  const std::string png(
      "\x89PNG\r\n\x1a\n\x00\x00\x00\x0dIHDR\x00\x00\x00\x01\x10\x00\x00\x01"
      "\x08\x00\x02\x00\x00\xd0\x00\x00M`\x86",
      35);
  std::string printed;
  EXPECT_EQ(DecodeError(png, &printed),
            "m.img: truncated: the header declares 1 x 268435457 pixels (536870914 bytes of "
            "image data), more than the file's 35 bytes can hold compressed");
  EXPECT_EQ(printed, "");
  // Bit depth 0, which would make the data bound 0 bytes per row.
  std::string depth0 = png;
  depth0[24] = 0;
  EXPECT_EQ(DecodeError(depth0), "m.img: not a valid PNG: grey bit depth 0 (the PNG spec allows 1, 2, 4, 8, 16)");
  EXPECT_EQ(DecodeError("P2\n30000 30000\n255\n0 1 2\n"),
            "m.img: truncated: the header declares 30000 x 30000 = 900000000 pixels, the 6 bytes of text hold at "
            "most 3");
  // A blank map compresses near deflate's limit and still reads.
  const std::vector<std::uint8_t> blank(2000 * 500, 205);
  EXPECT_EQ(DecodeGreyImage(EncodeGreyPng(2000, 500, blank.data()), "m", "").pixels, blank);
}

TEST(ImageCodec, OtherFormatsAreNamed) {
  EXPECT_EQ(DecodeError("hello"), "m.img: not an image: no known image format signature (PGM or PNG expected)");
  EXPECT_THAT([] { DecodeGreyImage("P6\n1 1\n255\nabc", "m.img", ""); },
              ThrowsMessage<InputError>(HasSubstr("m.img: is a 3-channel 8-bit image (PPM); maps must be")));
}

}  // namespace
}  // namespace slamtune::io
