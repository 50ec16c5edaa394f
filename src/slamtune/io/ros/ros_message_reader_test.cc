#include "slamtune/io/ros/ros_message_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/error_message.h"

namespace slamtune::io {
namespace {

using slamtune::testing::ErrorMessageOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// Payload bytes written by hand, in the order given: no alignment is added, so each test spells
// out the padding it expects (docs/recordings.md §1.4 for CDR, 1.6 for ROS 1).
class PayloadWriter {
 public:
  explicit PayloadWriter(bool big_endian = false) : big_endian_(big_endian) {}
  PayloadWriter& U8(std::uint8_t v) {
    data.push_back(v);
    return *this;
  }
  PayloadWriter& Zeros(std::size_t n) {
    data.insert(data.end(), n, 0);
    return *this;
  }
  PayloadWriter& Text(const std::string& s) {
    data.insert(data.end(), s.begin(), s.end());
    return *this;
  }
  PayloadWriter& U32(std::uint32_t v) { return Word(v, 4); }
  PayloadWriter& F32(float v) { return Word(std::bit_cast<std::uint32_t>(v), 4); }
  PayloadWriter& F64(double v) { return Word(std::bit_cast<std::uint64_t>(v), 8); }
  std::vector<std::uint8_t> data;

 private:
  PayloadWriter& Word(std::uint64_t v, int size) {
    for (int i = 0; i < size; ++i) {
      const int shift = 8 * (big_endian_ ? size - 1 - i : i);
      data.push_back(static_cast<std::uint8_t>(v >> shift));
    }
    return *this;
  }
  bool big_endian_;
};

PayloadWriter CdrLe() { return std::move(PayloadWriter().U8(0x00).U8(0x01).U8(0x00).U8(0x00)); }
PayloadWriter CdrBe() { return std::move(PayloadWriter(true).U8(0x00).U8(0x00).U8(0x00).U8(0x00)); }

constexpr const char* kType = "sensor_msgs/LaserScan";

RosMessageReader Cdr(const PayloadWriter& b) { return RosMessageReader(b.data, MessageSerialization::kCdr, kType); }
RosMessageReader Ros1(const PayloadWriter& b) { return RosMessageReader(b.data, MessageSerialization::kRos1, kType); }

TEST(CdrEncapsulationTest, LittleAndBigEndianKindsWithOptionsIgnored) {
  const PayloadWriter le = std::move(PayloadWriter().U8(0x00).U8(0x01).U8(0xff).U8(0xee).U32(7));
  RosMessageReader a(le.data, MessageSerialization::kCdr, kType);
  EXPECT_EQ(a.format(), RosWireFormat::kCdrLittleEndian);
  EXPECT_EQ(a.offset(), 4u);
  EXPECT_EQ(a.ReadUint32("x"), 7u);

  const PayloadWriter be = std::move(PayloadWriter(true).U8(0x00).U8(0x00).U8(0x12).U8(0x34).U32(7));
  RosMessageReader b(be.data, MessageSerialization::kCdr, kType);
  EXPECT_EQ(b.format(), RosWireFormat::kCdrBigEndian);
  EXPECT_EQ(b.ReadUint32("x"), 7u);
  EXPECT_STREQ(RosWireFormatName(b.format()), "CDR big-endian");
}

TEST(CdrEncapsulationTest, OtherKindsAreRefusedByName) {
  const struct {
    std::uint8_t b0, b1;
    const char* name;
  } kCases[] = {{0x00, 0x07, "CDR2_LE"}, {0x00, 0x09, "D_CDR2_LE"}, {0x00, 0x0b, "PL_CDR2_LE"},
                {0x00, 0x06, "CDR2_BE"}, {0x00, 0x03, "PL_CDR_LE"}, {0x01, 0x00, "unknown"},
                {0x00, 0x11, "unknown"}};
  for (const auto& c : kCases) {
    const PayloadWriter b = std::move(PayloadWriter().U8(c.b0).U8(c.b1).Zeros(2).U32(1));
    const std::string error = ErrorMessageOf([&] { Cdr(b); });
    EXPECT_THAT(error, HasSubstr("sensor_msgs/LaserScan: encapsulation header: representation")) << error;
    EXPECT_THAT(error, HasSubstr(c.name)) << error;
    EXPECT_THAT(error, HasSubstr("at byte 0, the message has 8")) << error;
  }
  const PayloadWriter xcdr2 = std::move(PayloadWriter().U8(0x00).U8(0x07).Zeros(6));
  EXPECT_EQ(ErrorMessageOf([&] { Cdr(xcdr2); }),
            "sensor_msgs/LaserScan: encapsulation header: representation 00 07 (CDR2_LE, XCDR2 plain "
            "little-endian) is not supported, only XCDR1 plain CDR (00 01 little-endian, 00 00 big-endian) at byte "
            "0, the message has 8");
}

TEST(CdrEncapsulationTest, PayloadShorterThanTheHeaderIsRefused) {
  for (std::size_t size = 0; size < 4; ++size) {
    const std::vector<std::uint8_t> data(size, 0x01);
    const std::string error = ErrorMessageOf([&] { RosMessageReader(data, MessageSerialization::kCdr, kType); });
    EXPECT_EQ(error, "sensor_msgs/LaserScan: encapsulation header: a CDR payload of " + std::to_string(size) +
                         " bytes cannot hold the 4-byte encapsulation header at byte 0, the message has " +
                         std::to_string(size));
  }
  // ROS 1 has no header: an empty payload fails only at its first field.
  const std::vector<std::uint8_t> empty;
  RosMessageReader in(empty, MessageSerialization::kRos1, kType);
  EXPECT_EQ(ErrorMessageOf([&] { in.ReadUint32("header.seq"); }),
            "sensor_msgs/LaserScan: header.seq: a uint32 needs 4 bytes at byte 0, the message has 0");
}

TEST(RosMessageReaderTest, CdrAlignsRelativeToTheEndOfTheHeader) {
  // d = offset after the 4-byte header. "a" takes d0-d5 (length 2 with its NUL); the float64
  // goes to d8 = byte 12, not to byte 8 or 16 (multiples of 8 from the buffer start).
  const PayloadWriter b =
      std::move(CdrLe().U32(2).Text("a").U8(0).Zeros(2).F64(1.5).U32(3).Text("xy").U8(0).U8(0).F32(2.5));
  RosMessageReader in = Cdr(b);
  EXPECT_EQ(in.ReadString("s"), "a");
  EXPECT_EQ(in.offset(), 10u);
  EXPECT_EQ(in.ReadFloat64("d"), 1.5);
  EXPECT_EQ(in.offset(), 20u);
  // "xy" and its NUL take d20-d22; the float32 goes to d24 = byte 28.
  EXPECT_EQ(in.ReadString("s2"), "xy");
  EXPECT_EQ(in.ReadFloat32("f"), 2.5f);
  EXPECT_EQ(in.offset(), b.data.size());
}

TEST(RosMessageReaderTest, Ros1HasNoAlignmentAndNoNul) {
  const PayloadWriter b = std::move(PayloadWriter().U32(1).Text("a").F64(-0.25).U32(0).F32(4.0f));
  RosMessageReader in = Ros1(b);
  EXPECT_EQ(in.format(), RosWireFormat::kRos1);
  EXPECT_EQ(in.ReadString("s"), "a");
  EXPECT_EQ(in.ReadFloat64("d"), -0.25);
  EXPECT_EQ(in.ReadString("empty"), "");
  EXPECT_EQ(in.ReadFloat32("f"), 4.0f);
  EXPECT_EQ(in.offset(), b.data.size());
}

TEST(RosMessageReaderTest, BigEndianPrimitives) {
  const PayloadWriter b =
      std::move(CdrBe().U32(0xdeadbeef).U32(static_cast<std::uint32_t>(-5)).F32(-1.75f).Zeros(4).F64(1e300));
  RosMessageReader in = Cdr(b);
  EXPECT_EQ(in.ReadUint32("u"), 0xdeadbeefu);
  EXPECT_EQ(in.ReadInt32("i"), -5);
  EXPECT_EQ(in.ReadFloat32("f"), -1.75f);
  EXPECT_EQ(in.ReadFloat64("d"), 1e300);
}

TEST(RosMessageReaderTest, CdrStrings) {
  const PayloadWriter b = std::move(CdrLe().U32(1).U8(0).Zeros(3).U32(5).Text("odom").U8(0));
  RosMessageReader in = Cdr(b);
  EXPECT_EQ(in.ReadString("a"), "");
  EXPECT_EQ(in.ReadString("b"), "odom");

  const PayloadWriter no_nul = std::move(CdrLe().U32(4).Text("odom"));
  EXPECT_EQ(ErrorMessageOf([&] { Cdr(no_nul).ReadString("header.frame_id"); }),
            "sensor_msgs/LaserScan: header.frame_id: a CDR string of length 4 does not end with a NUL at byte 8, "
            "the message has 12");
  const PayloadWriter zero = std::move(CdrLe().U32(0).Zeros(4));
  EXPECT_THAT([&] { Cdr(zero).ReadString("header.frame_id"); },
              ThrowsMessage<InputError>(HasSubstr(
                  "header.frame_id: a CDR string length of 0 leaves no room for the terminating NUL at byte 8")));
  const PayloadWriter past = std::move(CdrLe().U32(100).Text("odom").U8(0));
  EXPECT_EQ(ErrorMessageOf([&] { Cdr(past).ReadString("header.frame_id"); }),
            "sensor_msgs/LaserScan: header.frame_id: a string of length 100 needs 100 bytes at byte 8, the message "
            "has 13");
  const PayloadWriter huge = std::move(CdrLe().U32(0xffffffff).Text("odom").U8(0));
  EXPECT_THAT([&] { Cdr(huge).ReadString("s"); },
              ThrowsMessage<InputError>(HasSubstr("length 4294967295 needs 4294967295 bytes")));
}

TEST(RosMessageReaderTest, Ros1StringPastTheEnd) {
  const PayloadWriter b = std::move(PayloadWriter().U32(5).Text("odom"));
  EXPECT_EQ(ErrorMessageOf([&] { Ros1(b).ReadString("child_frame_id"); }),
            "sensor_msgs/LaserScan: child_frame_id: a string of length 5 needs 5 bytes at byte 4, the message has 8");
}

TEST(RosMessageReaderTest, SequencesAlignTheirFirstElementUnlessEmpty) {
  // Empty float64 sequence at d0: the uint32 after it stays at d4 (no alignment to 8).
  const PayloadWriter empty = std::move(CdrLe().U32(0).U32(7));
  RosMessageReader a = Cdr(empty);
  EXPECT_TRUE(a.ReadFloat64Sequence("s").empty());
  EXPECT_EQ(a.ReadUint32("after"), 7u);
  // One float64: count at d0, element at d8.
  const PayloadWriter one = std::move(CdrLe().U32(1).Zeros(4).F64(-3.0).U32(2).F32(1.0f).F32(2.0f));
  RosMessageReader b = Cdr(one);
  EXPECT_EQ(b.ReadFloat64Sequence("s"), std::vector<double>{-3.0});
  EXPECT_EQ(b.ReadFloat32Sequence("t"), (std::vector<float>{1.0f, 2.0f}));
  // ROS 1: no padding anywhere.
  const PayloadWriter ros1 = std::move(PayloadWriter().U32(1).F64(-3.0).U32(1).F32(0.5f));
  RosMessageReader c = Ros1(ros1);
  EXPECT_EQ(c.ReadFloat64Sequence("s"), std::vector<double>{-3.0});
  EXPECT_EQ(c.ReadFloat32Sequence("t"), std::vector<float>{0.5f});
}

TEST(RosMessageReaderTest, ImpossibleSequenceCountsThrowBeforeAllocating) {
  const PayloadWriter b = std::move(CdrLe().U32(0xffffffff).Zeros(16));
  EXPECT_EQ(ErrorMessageOf([&] { Cdr(b).ReadFloat32Sequence("ranges"); }),
            "sensor_msgs/LaserScan: ranges: 4294967295 float32 values need 17179869180 bytes at byte 8, the message "
            "has 24");
  EXPECT_THAT(
      [&] { Cdr(b).ReadFloat64Sequence("values"); },
      ThrowsMessage<InputError>(HasSubstr("values: 4294967295 float64 values need 34359738360 bytes at byte 12")));
  RosMessageReader in = Cdr(b);
  EXPECT_EQ(ErrorMessageOf([&] { in.ReadSequenceCount("transforms", 72); }),
            "sensor_msgs/LaserScan: transforms: 4294967295 elements of at least 72 bytes need 309237645240 bytes at "
            "byte 8, the message has 24");
  // A count that fits passes.
  const PayloadWriter two = std::move(PayloadWriter().U32(2).Zeros(144));
  EXPECT_EQ(Ros1(two).ReadSequenceCount("transforms", 72), 2u);
}

TEST(RosMessageReaderTest, FixedArraysHaveNoCount) {
  const PayloadWriter b = std::move(CdrLe().U32(9).Zeros(4).F64(1).F64(2).F64(3));
  RosMessageReader in = Cdr(b);
  EXPECT_EQ(in.ReadUint32("n"), 9u);
  std::array<double, 3> v{};
  in.ReadFloat64Array("pose.pose.position", v);
  EXPECT_EQ(v, (std::array<double, 3>{1, 2, 3}));
  std::array<double, 36> covariance{};
  EXPECT_EQ(ErrorMessageOf([&] { in.ReadFloat64Array("pose.covariance", covariance); }),
            "sensor_msgs/LaserScan: pose.covariance: 36 float64 values need 288 bytes at byte 36, the message has 36");
}

TEST(RosMessageReaderTest, HeaderStampsAreExactNanoseconds) {
  const PayloadWriter cdr =
      std::move(CdrLe().U32(static_cast<std::uint32_t>(-2)).U32(250000000).U32(5).Text("odom").U8(0));
  RosMessageReader a = Cdr(cdr);
  const RosHeader h = a.ReadHeader();
  EXPECT_EQ(h.seq, 0u);
  EXPECT_EQ(h.stamp_ns, -1750000000);
  EXPECT_EQ(h.frame_id, "odom");

  // Real dates exceed 2^53 ns; ROS 1 seconds are unsigned.
  const PayloadWriter ros1 = std::move(PayloadWriter().U32(42).U32(4000000000u).U32(999999999).U32(3).Text("map"));
  const RosHeader g = Ros1(ros1).ReadHeader();
  EXPECT_EQ(g.seq, 42u);
  EXPECT_EQ(g.stamp_ns, std::int64_t{4000000000999999999});
  EXPECT_EQ(g.frame_id, "map");

  const PayloadWriter real = std::move(CdrLe().U32(1700000000).U32(999999999).U32(1).U8(0));
  EXPECT_EQ(Cdr(real).ReadHeader().stamp_ns, std::int64_t{1700000000999999999});
}

TEST(RosMessageReaderTest, ErrorsNameTypeContextFieldAndByte) {
  const PayloadWriter b = std::move(CdrLe().U32(1).U8(0).U8(0));  // a stamp cut in its second word
  RosMessageReader in(b.data, MessageSerialization::kCdr, "tf2_msgs/TFMessage");
  in.set_context("transforms[2]");
  EXPECT_EQ(ErrorMessageOf([&] { in.ReadHeader(); }),
            "tf2_msgs/TFMessage: transforms[2].header.stamp.nanosec: a uint32 needs 4 bytes at byte 8, the message "
            "has 10");
  // Alignment padding that runs past the end reports the aligned offset.
  const PayloadWriter c = std::move(CdrLe().U32(2).Text("a").U8(0));
  RosMessageReader d = Cdr(c);
  d.ReadString("s");
  EXPECT_EQ(ErrorMessageOf([&] { d.ReadFloat64("x"); }),
            "sensor_msgs/LaserScan: x: a float64 needs 8 bytes at byte 12, the message has 10");
}

}  // namespace
}  // namespace slamtune::io
