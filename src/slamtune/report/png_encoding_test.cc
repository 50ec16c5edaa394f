#include "slamtune/report/png_encoding.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/temp_dir.h"

namespace slamtune::report {
namespace {

std::vector<std::uint8_t> Bytes(const std::string& s) { return {s.begin(), s.end()}; }

TEST(Base64, Rfc4648TestVectors) {
  // RFC 4648 §10.
  EXPECT_EQ(Base64Encode(Bytes("")), "");
  EXPECT_EQ(Base64Encode(Bytes("f")), "Zg==");
  EXPECT_EQ(Base64Encode(Bytes("fo")), "Zm8=");
  EXPECT_EQ(Base64Encode(Bytes("foo")), "Zm9v");
  EXPECT_EQ(Base64Encode(Bytes("foob")), "Zm9vYg==");
  EXPECT_EQ(Base64Encode(Bytes("fooba")), "Zm9vYmE=");
  EXPECT_EQ(Base64Encode(Bytes("foobar")), "Zm9vYmFy");
  EXPECT_EQ(Base64Encode(std::vector<std::uint8_t>{0xff, 0xfe, 0x00}), "//4A");
}

TEST(EncodePng, RoundTripsPixelsAndIsDeterministic) {
  cv::Mat image(7, 11, CV_8UC3, cv::Scalar(10, 20, 30));
  image.at<cv::Vec3b>(3, 5) = {200, 100, 0};
  const auto png = EncodePng(image);
  EXPECT_EQ(png, EncodePng(image.clone()));
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png[1], 'P');
  const cv::Mat back = cv::imdecode(png, cv::IMREAD_UNCHANGED);
  ASSERT_EQ(back.size(), image.size());
  EXPECT_EQ(cv::norm(back, image, cv::NORM_INF), 0.0);
  EXPECT_EQ(PngDataUri(png).rfind("data:image/png;base64,iVBORw0KGgo", 0), 0u);
}

TEST(WriteBytes, WritesAndNamesUnwritablePaths) {
  const auto path = (slamtune::testing::UniqueTempDir("report_bytes") / "bytes.bin").string();
  WriteBytes({1, 2, 3}, path);
  EXPECT_EQ(std::filesystem::file_size(path), 3u);
  try {
    WriteBytes({1}, "/nonexistent-folder/x.png");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-folder/x.png"), std::string::npos);
  }
}

}  // namespace
}  // namespace slamtune::report
