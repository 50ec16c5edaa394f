#include "slamtune/io/byte_cursor.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/error_message.h"
#include "slamtune/io/testing/recording_bytes.h"

namespace slamtune::io {
namespace {

using slamtune::testing::ErrorMessageOf;
using testing::Bytes;
using testing::ByteWriter;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(ByteCursorTest, ReadsLittleEndianIntegersStringsAndBytes) {
  const Bytes bytes = ByteWriter()
                          .U8(0xAB)
                          .U16(0x1234)
                          .U32(0xDEADBEEF)
                          .U64(0x0102030405060708)
                          .StringU32("topic")
                          .BytesU64(Bytes{9, 8})
                          .Raw("tail")
                          .Take();
  ByteCursor cursor(bytes, "f.mcap");
  EXPECT_EQ(cursor.U8("a"), 0xAB);
  EXPECT_EQ(cursor.U16("b"), 0x1234);
  EXPECT_EQ(cursor.U32("c"), 0xDEADBEEFu);
  EXPECT_EQ(cursor.U64("d"), 0x0102030405060708u);
  EXPECT_EQ(cursor.StringU32("e"), "topic");
  const auto field = cursor.BytesU64("f");
  EXPECT_EQ(Bytes(field.begin(), field.end()), (Bytes{9, 8}));
  EXPECT_EQ(cursor.offset(), 1u + 2 + 4 + 8 + 4 + 5 + 8 + 2);
  EXPECT_EQ(cursor.remaining(), 4u);
  const auto rest = cursor.Rest();
  EXPECT_EQ(std::string(rest.begin(), rest.end()), "tail");
  EXPECT_TRUE(cursor.empty());
}

TEST(ByteCursorTest, ReadingPastTheEndNamesTheAbsoluteOffsetAndTheField) {
  const Bytes bytes = {1, 2, 3, 4, 5, 6};
  ByteCursor cursor(bytes, "f.mcap", /*first_offset=*/100, "byte 90 (chunk), uncompressed ");
  cursor.U32("Message sequence");
  EXPECT_EQ(ErrorMessageOf([&] { cursor.U64("Message log_time"); }),
            "f.mcap: byte 90 (chunk), uncompressed byte 104 (Message log_time): needs 8 bytes, 2 left");
  EXPECT_EQ(cursor.offset(), 104u);  // a failed read moves nothing
}

TEST(ByteCursorTest, ALengthPrefixRunningPastTheEndIsReportedAtThePrefix) {
  const Bytes bytes = ByteWriter().U8(0).U32(1000).Raw("abc").Take();
  ByteCursor cursor(bytes, "x.bag");
  cursor.U8("op");
  EXPECT_EQ(ErrorMessageOf([&] { cursor.StringU32("Channel topic"); }),
            "x.bag: byte 1 (Channel topic): length 1000 runs past the end (3 bytes left)");
  const Bytes huge_length = ByteWriter().U64(~std::uint64_t{0}).Take();
  ByteCursor huge(huge_length, "y");
  EXPECT_THAT([&] { huge.BytesU64("records"); },
              ThrowsMessage<InputError>(HasSubstr("byte 0 (records): length 18446744073709551615")));
}

}  // namespace
}  // namespace slamtune::io
