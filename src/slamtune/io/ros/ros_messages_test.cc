#include "slamtune/io/ros/ros_messages.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/error_message.h"
#include "slamtune/common/testing/fixtures.h"

namespace slamtune::io {
namespace {

using slamtune::testing::ErrorMessageOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;
using Payload = std::vector<std::uint8_t>;

constexpr auto kCdr = MessageSerialization::kCdr;
constexpr auto kRos1 = MessageSerialization::kRos1;
constexpr double kInf = std::numeric_limits<double>::infinity();

// ---- Golden payloads ----------------------------------------------------------------------------
// tests/fixtures/ros_messages/*.bin, written by the foxglove serializers (make_golden.mjs, which
// names the package versions). The Expected* functions below mirror its scanCase / odomCase /
// tfCase formulas; golden.json there lists the same values.

Payload Golden(const std::string& name) {
  const std::string path = slamtune::testing::FixturePath("ros_messages/" + name);
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in) << "cannot open " << path;
  return Payload(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

const char* Suffix(MessageSerialization s) { return s == kCdr ? "_cdr.bin" : "_ros1.bin"; }

RosHeader ExpectedHeader(bool ros1, std::uint32_t seq, std::int64_t sec, std::int64_t nsec, std::string frame) {
  return RosHeader{ros1 ? seq : 0, sec * 1'000'000'000 + nsec, std::move(frame)};
}

// LaserScan case k: frame_id of length k; ranges[1] NaN and the last +inf when there are >= 3.
LaserScanMessage ExpectedScan(int k, MessageSerialization s) {
  LaserScanMessage m;
  m.header = ExpectedHeader(s == kRos1, 1000 + k, 1700000000 + k, 999999999 - k, std::string("abcdefgh", k));
  m.angle_min = -1.5f - 0.125f * k;
  m.angle_max = 1.5f + 0.125f * k;
  m.angle_increment = 0.0078125f;
  m.time_increment = (k + 1) / 1024.0f;
  m.scan_time = 0.125f;
  m.range_min = 0.0625f;
  m.range_max = 30.0f + k;
  const int n = (k == 0 || k == 4) ? 0 : k + 2;
  for (int i = 0; i < n; ++i) m.ranges.push_back(1.0f + k + 0.25f * i);
  if (n >= 3) {
    m.ranges[1] = std::numeric_limits<float>::quiet_NaN();
    m.ranges[n - 1] = std::numeric_limits<float>::infinity();
  }
  const int count = k % 3 == 0 ? 0 : k;
  for (int i = 0; i < count; ++i) m.intensities.push_back(100.0f + k + 2.0f * i);
  return m;
}

// Odometry case c; case 0 is "odom" / "base_link", case 3 has each serialization's extreme stamp.
OdometryMessage ExpectedOdom(int c, MessageSerialization s) {
  static const char* const kFrames[4][2] = {
      {"odom", "base_link"}, {"", ""}, {"o", "base_footprint"}, {"map_12345", "b"}};
  std::int64_t sec = 1700000100 + c, nsec = 500000000 + c;
  if (c == 3) {
    sec = s == kRos1 ? 4000000000 : -2;
    nsec = s == kRos1 ? 999999999 : 250000000;
  }
  OdometryMessage m;
  m.header = ExpectedHeader(s == kRos1, 7 + c, sec, nsec, kFrames[c][0]);
  m.child_frame_id = kFrames[c][1];
  m.position = {1.5 + c, -2.25, 0.1};
  m.orientation = {0, 0, 0.6, 0.8};
  m.linear = {0.25 + c, 0, 0};
  m.angular = {0, 0, -0.125};
  for (int i = 0; i < 36; ++i) {
    m.pose_covariance[i] = 0.5 * i + c;
    m.twist_covariance[i] = -i / 8.0;
  }
  return m;
}

TfMessage ExpectedTf(int n, MessageSerialization s) {
  static const char* const kFrames[3][2] = {{"odom", "base_footprint"}, {"map", "odom"}, {"", "a"}};
  TfMessage m;
  for (int j = 0; j < n; ++j) {
    TransformStampedMessage& t = m.transforms.emplace_back();
    t.header = ExpectedHeader(s == kRos1, 50 + j, 1700000200 + j, 1000 * j, kFrames[j][0]);
    t.child_frame_id = kFrames[j][1];
    t.translation = {j + 0.5, -1.0 * j, 0.125 * j};
    t.rotation = j == 0 ? RosQuaternion{0, 0, 0, 1} : RosQuaternion{0, 0, 0.6, 0.8};
  }
  return m;
}

// Bit-exact, except that any NaN equals any NaN.
bool Same(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

void ExpectHeaderEq(const RosHeader& a, const RosHeader& e) {
  EXPECT_EQ(a.seq, e.seq);
  EXPECT_EQ(a.stamp_ns, e.stamp_ns);
  EXPECT_EQ(a.frame_id, e.frame_id);
}

template <typename A, typename E>
void ExpectValuesEq(const A& actual, const E& expected, const char* what) {
  ASSERT_EQ(actual.size(), expected.size()) << what;
  for (std::size_t i = 0; i < actual.size(); ++i) EXPECT_TRUE(Same(actual[i], expected[i])) << what << "[" << i << "]";
}

void ExpectVectorEq(const RosVector3& a, const RosVector3& e) {
  EXPECT_EQ(a.x, e.x);
  EXPECT_EQ(a.y, e.y);
  EXPECT_EQ(a.z, e.z);
}

void ExpectQuaternionEq(const RosQuaternion& a, const RosQuaternion& e) {
  EXPECT_EQ(a.x, e.x);
  EXPECT_EQ(a.y, e.y);
  EXPECT_EQ(a.z, e.z);
  EXPECT_EQ(a.w, e.w);
}

void ExpectScanEq(const LaserScanMessage& a, const LaserScanMessage& e) {
  ExpectHeaderEq(a.header, e.header);
  EXPECT_EQ(a.angle_min, e.angle_min);
  EXPECT_EQ(a.angle_max, e.angle_max);
  EXPECT_EQ(a.angle_increment, e.angle_increment);
  EXPECT_EQ(a.time_increment, e.time_increment);
  EXPECT_EQ(a.scan_time, e.scan_time);
  EXPECT_EQ(a.range_min, e.range_min);
  EXPECT_EQ(a.range_max, e.range_max);
  ExpectValuesEq(a.ranges, e.ranges, "ranges");
  ExpectValuesEq(a.intensities, e.intensities, "intensities");
}

void ExpectOdomEq(const OdometryMessage& a, const OdometryMessage& e) {
  ExpectHeaderEq(a.header, e.header);
  EXPECT_EQ(a.child_frame_id, e.child_frame_id);
  ExpectVectorEq(a.position, e.position);
  ExpectQuaternionEq(a.orientation, e.orientation);
  ExpectValuesEq(a.pose_covariance, e.pose_covariance, "pose_covariance");
  ExpectVectorEq(a.linear, e.linear);
  ExpectVectorEq(a.angular, e.angular);
  ExpectValuesEq(a.twist_covariance, e.twist_covariance, "twist_covariance");
}

void ExpectTfEq(const TfMessage& a, const TfMessage& e) {
  ASSERT_EQ(a.transforms.size(), e.transforms.size());
  for (std::size_t j = 0; j < a.transforms.size(); ++j) {
    SCOPED_TRACE("transform " + std::to_string(j));
    ExpectHeaderEq(a.transforms[j].header, e.transforms[j].header);
    EXPECT_EQ(a.transforms[j].child_frame_id, e.transforms[j].child_frame_id);
    ExpectVectorEq(a.transforms[j].translation, e.transforms[j].translation);
    ExpectQuaternionEq(a.transforms[j].rotation, e.transforms[j].rotation);
  }
}

// Every golden payload with its serialization (the big-endian ones are CDR too).
struct GoldenFile {
  std::string name;
  MessageSerialization serialization;
  RosMessageKind kind;
};

std::vector<GoldenFile> AllGoldenFiles() {
  std::vector<GoldenFile> files;
  for (const auto s : {kCdr, kRos1}) {
    for (int k = 0; k <= 8; ++k) {
      files.push_back({"scan_frame" + std::to_string(k) + Suffix(s), s, RosMessageKind::kLaserScan});
    }
    for (int c = 0; c < 4; ++c) {
      files.push_back({"odom_" + std::to_string(c) + Suffix(s), s, RosMessageKind::kOdometry});
    }
    for (int n : {0, 1, 3}) files.push_back({"tf_" + std::to_string(n) + Suffix(s), s, RosMessageKind::kTf});
  }
  files.push_back({"scan_frame5_cdr_be.bin", kCdr, RosMessageKind::kLaserScan});
  files.push_back({"odom_0_cdr_be.bin", kCdr, RosMessageKind::kOdometry});
  files.push_back({"tf_3_cdr_be.bin", kCdr, RosMessageKind::kTf});
  return files;
}

void Decode(RosMessageKind kind, std::span<const std::uint8_t> data, MessageSerialization s) {
  switch (kind) {
    case RosMessageKind::kLaserScan: DecodeLaserScan(data, s); return;
    case RosMessageKind::kOdometry: DecodeOdometry(data, s); return;
    case RosMessageKind::kTf: DecodeTfMessage(data, s); return;
    case RosMessageKind::kOther: return;
  }
}

void PutU32(Payload& p, std::size_t at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) p[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
}

// ---- Golden decoding ----------------------------------------------------------------------------

TEST(RosMessagesGoldenTest, LaserScanWithFrameIdsOfEveryLength) {
  for (const auto s : {kCdr, kRos1}) {
    for (int k = 0; k <= 8; ++k) {
      const std::string name = "scan_frame" + std::to_string(k) + Suffix(s);
      SCOPED_TRACE(name);
      ExpectScanEq(DecodeLaserScan(Golden(name), s), ExpectedScan(k, s));
    }
  }
  // Spot checks that the cases hold what they are meant to.
  const LaserScanMessage scan = DecodeLaserScan(Golden("scan_frame5_cdr.bin"), kCdr);
  EXPECT_TRUE(std::isnan(scan.ranges[1]));
  EXPECT_EQ(scan.ranges.back(), kInf);
  EXPECT_TRUE(DecodeLaserScan(Golden("scan_frame0_cdr.bin"), kCdr).ranges.empty());
  EXPECT_TRUE(DecodeLaserScan(Golden("scan_frame3_ros1.bin"), kRos1).intensities.empty());
  EXPECT_EQ(DecodeLaserScan(Golden("scan_frame4_ros1.bin"), kRos1).intensities.size(), 4u);
}

TEST(RosMessagesGoldenTest, OdometryWithSeveralFrameIdLengths) {
  for (const auto s : {kCdr, kRos1}) {
    for (int c = 0; c < 4; ++c) {
      const std::string name = "odom_" + std::to_string(c) + Suffix(s);
      SCOPED_TRACE(name);
      ExpectOdomEq(DecodeOdometry(Golden(name), s), ExpectedOdom(c, s));
    }
  }
}

TEST(RosMessagesGoldenTest, OdometryWorkedExamplePutsPositionXAtByte40AfterTheHeader) {
  // docs/recordings.md §1.4: "odom\0" at d12-d16, child length at d20, "base_link\0" at d24-d33,
  // padding to d40 (8-aligned relative to the end of the header), position.x there.
  const Payload p = Golden("odom_0_cdr.bin");
  ASSERT_EQ(p.size(), 4u + 40 + 7 * 8 + 36 * 8 + 6 * 8 + 36 * 8);
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(&p[4 + 12]), 5), std::string("odom\0", 5));
  EXPECT_EQ(p[4 + 20], 10);
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(&p[4 + 24]), 10), std::string("base_link\0", 10));
  for (std::size_t d = 34; d < 40; ++d) EXPECT_EQ(p[4 + d], 0) << "padding d" << d;
  std::uint64_t bits = 0;
  for (int i = 0; i < 8; ++i) bits |= std::uint64_t{p[4 + 40 + i]} << (8 * i);
  EXPECT_EQ(std::bit_cast<double>(bits), 1.5);
  EXPECT_EQ(DecodeOdometry(p, kCdr).position.x, 1.5);
}

TEST(RosMessagesGoldenTest, TfMessagesWithZeroOneAndThreeTransforms) {
  for (const auto s : {kCdr, kRos1}) {
    for (int n : {0, 1, 3}) {
      const std::string name = "tf_" + std::to_string(n) + Suffix(s);
      SCOPED_TRACE(name);
      ExpectTfEq(DecodeTfMessage(Golden(name), s), ExpectedTf(n, s));
    }
  }
}

TEST(RosMessagesGoldenTest, BigEndianCdrDecodesToTheSameValues) {
  const Payload scan = Golden("scan_frame5_cdr_be.bin");
  ASSERT_GE(scan.size(), 4u);
  EXPECT_EQ(scan[1], 0x00);  // CDR_BE
  ExpectScanEq(DecodeLaserScan(scan, kCdr), ExpectedScan(5, kCdr));
  ExpectOdomEq(DecodeOdometry(Golden("odom_0_cdr_be.bin"), kCdr), ExpectedOdom(0, kCdr));
  ExpectTfEq(DecodeTfMessage(Golden("tf_3_cdr_be.bin"), kCdr), ExpectedTf(3, kCdr));
}

TEST(RosMessagesTest, HandBuiltBigEndianLaserScan) {
  // Independent of any writer: CDR_BE, stamp 3 s + 5 ns, frame_id "", the seven float32 fields,
  // one range (+inf), no intensities. d = offset after the header.
  const Payload p = {
      0x00, 0x00, 0x00, 0x00,                          // CDR_BE, options
      0x00, 0x00, 0x00, 0x03, 0x00, 0x00, 0x00, 0x05,  // d0 sec, d4 nanosec
      0x00, 0x00, 0x00, 0x01, 0x00,                    // d8 length 1, d12 NUL
      0x00, 0x00, 0x00,                                // d13 padding to d16
      0xbf, 0xc0, 0x00, 0x00,                          // d16 angle_min -1.5
      0x3f, 0xc0, 0x00, 0x00,                          // angle_max 1.5
      0x3c, 0x00, 0x00, 0x00,                          // angle_increment 2^-7
      0x00, 0x00, 0x00, 0x00,                          // time_increment 0
      0x3e, 0x00, 0x00, 0x00,                          // scan_time 0.125
      0x3d, 0x80, 0x00, 0x00,                          // range_min 0.0625
      0x41, 0xf0, 0x00, 0x00,                          // range_max 30
      0x00, 0x00, 0x00, 0x01, 0x7f, 0x80, 0x00, 0x00,  // d44 ranges {+inf}
      0x00, 0x00, 0x00, 0x00,                          // d52 intensities {}
  };
  const LaserScanMessage scan = DecodeLaserScan(p, kCdr);
  EXPECT_EQ(scan.header.stamp_ns, 3000000005);
  EXPECT_EQ(scan.header.frame_id, "");
  EXPECT_EQ(scan.angle_min, -1.5f);
  EXPECT_EQ(scan.angle_max, 1.5f);
  EXPECT_EQ(scan.angle_increment, 0.0078125f);
  EXPECT_EQ(scan.time_increment, 0.0f);
  EXPECT_EQ(scan.scan_time, 0.125f);
  EXPECT_EQ(scan.range_min, 0.0625f);
  EXPECT_EQ(scan.range_max, 30.0f);
  ASSERT_EQ(scan.ranges.size(), 1u);
  EXPECT_EQ(scan.ranges[0], kInf);
  EXPECT_TRUE(scan.intensities.empty());
}

// ---- Malformed input ----------------------------------------------------------------------------

TEST(RosMessagesTest, TrailingPaddingIsIgnored) {
  for (const GoldenFile& file : AllGoldenFiles()) {
    SCOPED_TRACE(file.name);
    const Payload p = Golden(file.name);
    for (std::size_t extra = 1; extra <= 8; ++extra) {
      for (const std::uint8_t fill : {std::uint8_t{0x00}, std::uint8_t{0xab}}) {
        Payload padded = p;
        padded.insert(padded.end(), extra, fill);
        EXPECT_NO_THROW(Decode(file.kind, padded, file.serialization)) << extra;
      }
    }
  }
  Payload scan = Golden("scan_frame3_cdr.bin");
  scan.insert(scan.end(), 3, 0);
  ExpectScanEq(DecodeLaserScan(scan, kCdr), ExpectedScan(3, kCdr));
}

TEST(RosMessagesTest, EveryTruncationThrowsInputError) {
  for (const GoldenFile& file : AllGoldenFiles()) {
    SCOPED_TRACE(file.name);
    const Payload p = Golden(file.name);
    for (std::size_t size = 0; size < p.size(); ++size) {
      const std::span<const std::uint8_t> cut(p.data(), size);
      EXPECT_THROW(Decode(file.kind, cut, file.serialization), InputError) << "truncated to " << size;
    }
  }
}

TEST(RosMessagesTest, StringLengthPastTheEnd) {
  // scan_frame5_cdr.bin: frame_id length at byte 12 (d8), its bytes from byte 16.
  Payload p = Golden("scan_frame5_cdr.bin");
  PutU32(p, 12, 1000);
  EXPECT_EQ(ErrorMessageOf([&] { DecodeLaserScan(p, kCdr); }),
            "sensor_msgs/LaserScan: header.frame_id: a string of length 1000 needs 1000 bytes at byte 16, the "
            "message has " +
                std::to_string(p.size()));
  // ROS 1: seq, sec, nsec, then the frame_id length at byte 12.
  Payload q = Golden("odom_2_ros1.bin");
  PutU32(q, 12, 0xfffffff0);
  EXPECT_THAT([&] { DecodeOdometry(q, kRos1); },
              ThrowsMessage<InputError>(HasSubstr(
                  "nav_msgs/Odometry: header.frame_id: a string of length 4294967280 needs 4294967280 bytes at "
                  "byte 16")));
}

TEST(RosMessagesTest, CdrStringWithoutNul) {
  Payload p = Golden("odom_0_cdr.bin");
  p[4 + 33] = 'x';  // the NUL after "base_link" (d24-d33)
  EXPECT_EQ(ErrorMessageOf([&] { DecodeOdometry(p, kCdr); }),
            "nav_msgs/Odometry: child_frame_id: a CDR string of length 10 does not end with a NUL at byte 28, the "
            "message has 724");
}

TEST(RosMessagesTest, SequenceCountOfAllOnes) {
  // scan_frame5_cdr.bin: "abcde\0" ends at d18, the float32 fields take d20-d47, ranges count at d48.
  Payload p = Golden("scan_frame5_cdr.bin");
  PutU32(p, 4 + 48, 0xffffffff);
  EXPECT_EQ(ErrorMessageOf([&] { DecodeLaserScan(p, kCdr); }),
            "sensor_msgs/LaserScan: ranges: 4294967295 float32 values need 17179869180 bytes at byte 56, the "
            "message has " +
                std::to_string(p.size()));
  Payload tf = Golden("tf_3_ros1.bin");
  PutU32(tf, 0, 0xffffffff);
  EXPECT_THAT(
      [&] { DecodeTfMessage(tf, kRos1); },
      ThrowsMessage<InputError>(HasSubstr("tf2_msgs/TFMessage: transforms: 4294967295 elements of at least 72 bytes")));
  EXPECT_THAT([&] { DecodeTfMessage(tf, kRos1); }, ThrowsMessage<InputError>(HasSubstr("at byte 4")));
}

TEST(RosMessagesTest, ErrorsInsideTransformsNameTheirIndex) {
  Payload p = Golden("tf_3_ros1.bin");
  p.resize(p.size() - 4);  // cut transforms[2].transform.rotation
  EXPECT_THAT([&] { DecodeTfMessage(p, kRos1); },
              ThrowsMessage<InputError>(
                  HasSubstr("tf2_msgs/TFMessage: transforms[2].transform.rotation: 4 float64 values need 32 bytes at "
                            "byte")));
}

TEST(RosMessagesTest, Xcdr2AndShortPayloadsAreRefused) {
  Payload p = Golden("scan_frame2_cdr.bin");
  p[1] = 0x07;
  EXPECT_THAT([&] { DecodeLaserScan(p, kCdr); },
              ThrowsMessage<InputError>(
                  HasSubstr("sensor_msgs/LaserScan: encapsulation header: representation 00 07 (CDR2_LE")));
  const Payload three = {0x00, 0x01, 0x00};
  EXPECT_EQ(ErrorMessageOf([&] { DecodeOdometry(three, kCdr); }),
            "nav_msgs/Odometry: encapsulation header: a CDR payload of 3 bytes cannot hold the 4-byte encapsulation "
            "header at byte 0, the message has 3");
  EXPECT_THAT([&] { DecodeTfMessage(three, kRos1); },
              ThrowsMessage<InputError>(
                  HasSubstr("tf2_msgs/TFMessage: transforms: a uint32 needs 4 bytes at byte 0, the message has 3")));
}

TEST(RosMessagesTest, RandomBytesGiveInputErrorOrAMessage) {
  const std::vector<GoldenFile> files = AllGoldenFiles();
  std::vector<Payload> golden;
  for (const GoldenFile& f : files) golden.push_back(Golden(f.name));
  std::mt19937 rng(42);
  std::uniform_int_distribution<int> byte(0, 255);
  std::size_t decoded = 0, refused = 0;
  for (int iteration = 0; iteration < 3000; ++iteration) {
    Payload p;
    switch (iteration % 3) {
      case 0:  // random bytes
        p.resize(rng() % 400);
        for (auto& b : p) b = static_cast<std::uint8_t>(byte(rng));
        break;
      case 1:  // random bytes after a valid CDR header
        p = {0x00, static_cast<std::uint8_t>(rng() % 2), 0x00, 0x00};
        p.resize(4 + rng() % 400);
        for (std::size_t i = 4; i < p.size(); ++i) p[i] = static_cast<std::uint8_t>(byte(rng));
        break;
      default: {  // a golden payload with a few bytes changed, maybe cut or extended
        p = golden[rng() % golden.size()];
        for (int n = 1 + rng() % 4; n > 0 && !p.empty(); --n) {
          p[rng() % p.size()] = static_cast<std::uint8_t>(byte(rng));
        }
        if (rng() % 4 == 0) p.resize(rng() % (p.size() + 16));
      }
    }
    for (const auto s : {kCdr, kRos1}) {
      for (const auto kind : {RosMessageKind::kLaserScan, RosMessageKind::kOdometry, RosMessageKind::kTf}) {
        try {
          Decode(kind, p, s);
          ++decoded;
        } catch (const InputError&) {
          ++refused;
        }
      }
    }
  }
  EXPECT_EQ(decoded + refused, 3000u * 6);
  EXPECT_GT(decoded, 0u);
  EXPECT_GT(refused, 0u);
}

// ---- Type names ---------------------------------------------------------------------------------

TEST(RosMessagesTest, KindOfRosTypeAcceptsBothSpellings) {
  EXPECT_EQ(KindOfRosType("sensor_msgs/msg/LaserScan"), RosMessageKind::kLaserScan);
  EXPECT_EQ(KindOfRosType("sensor_msgs/LaserScan"), RosMessageKind::kLaserScan);
  EXPECT_EQ(KindOfRosType("nav_msgs/msg/Odometry"), RosMessageKind::kOdometry);
  EXPECT_EQ(KindOfRosType("nav_msgs/Odometry"), RosMessageKind::kOdometry);
  EXPECT_EQ(KindOfRosType("tf2_msgs/msg/TFMessage"), RosMessageKind::kTf);
  EXPECT_EQ(KindOfRosType("tf2_msgs/TFMessage"), RosMessageKind::kTf);
  EXPECT_EQ(KindOfRosType("tf/tfMessage"), RosMessageKind::kTf);
  EXPECT_EQ(KindOfRosType("sensor_msgs/msg/PointCloud2"), RosMessageKind::kOther);
  EXPECT_EQ(KindOfRosType("sensor_msgs/msg/LaserScan "), RosMessageKind::kOther);
  EXPECT_EQ(KindOfRosType(""), RosMessageKind::kOther);
  EXPECT_STREQ(RosMessageKindName(RosMessageKind::kLaserScan), "sensor_msgs/LaserScan");
  EXPECT_STREQ(RosMessageKindName(RosMessageKind::kOdometry), "nav_msgs/Odometry");
  EXPECT_STREQ(RosMessageKindName(RosMessageKind::kTf), "tf2_msgs/TFMessage");
  EXPECT_STREQ(RosMessageKindName(RosMessageKind::kOther), "other");
}

}  // namespace
}  // namespace slamtune::io
