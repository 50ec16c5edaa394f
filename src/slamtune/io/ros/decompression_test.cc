#include "slamtune/io/ros/decompression.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <zstd.h>

#include <random>

#include "slamtune/common/error.h"
#include "slamtune/io/testing/recording_bytes.h"

namespace slamtune::io {
namespace {

using testing::Bytes;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// Compressible but not trivial: runs of a few values, from a fixed seed.
Bytes SampleData(std::size_t size) {
  std::mt19937 random(7);
  Bytes data(size);
  for (std::size_t i = 0; i < size; ++i) data[i] = static_cast<std::uint8_t>((i / 13) % 7 + (random() % 3));
  return data;
}

Bytes Compress(Codec codec, const Bytes& data) {
  switch (codec) {
    case Codec::kZstd: return testing::ZstdCompress(data);
    case Codec::kLz4Frame: return testing::Lz4FrameCompress(data);
    case Codec::kBz2: return testing::Bz2Compress(data);
  }
  return {};
}

constexpr Codec kCodecs[] = {Codec::kZstd, Codec::kLz4Frame, Codec::kBz2};

TEST(DecompressTest, RoundTripsEachCodecAtTheDeclaredSize) {
  for (const Codec codec : kCodecs) {
    for (const std::size_t size : {std::size_t{1}, std::size_t{1000}, std::size_t{3} << 20}) {
      const Bytes data = SampleData(size);
      EXPECT_EQ(DecompressExact(codec, Compress(codec, data), size), data) << CodecName(codec) << " " << size;
    }
    EXPECT_TRUE(DecompressExact(codec, {}, 0).empty());
  }
}

TEST(DecompressTest, ConcatenatedZstdAndLz4FramesDecodeInOrder) {
  const Bytes a = SampleData(5000), b = testing::ToBytes("second frame");
  for (const Codec codec : {Codec::kZstd, Codec::kLz4Frame}) {
    const Bytes joined = testing::Concat({Compress(codec, a), Compress(codec, b)});
    EXPECT_EQ(DecompressExact(codec, joined, a.size() + b.size()), testing::Concat({a, b})) << CodecName(codec);
  }
}

TEST(DecompressTest, OutputMustBeExactlyTheDeclaredSize) {
  const Bytes data = SampleData(4096);
  for (const Codec codec : kCodecs) {
    const Bytes packed = Compress(codec, data);
    EXPECT_THAT([&] { DecompressExact(codec, packed, 4000); },
                ThrowsMessage<InputError>(HasSubstr("decodes to more than 4000 bytes")));
    EXPECT_THAT([&] { DecompressExact(codec, packed, 5000); },
                ThrowsMessage<InputError>(HasSubstr("decodes to 4096 bytes, the declared size is 5000")));
  }
}

TEST(DecompressTest, ABombIsStoppedAtTheDeclaredSize) {
  const Bytes zeros(std::size_t{256} << 20, 0);  // 256 MiB of zeros: a few KiB compressed
  const Bytes bomb = testing::ZstdCompress(zeros);
  ASSERT_LT(bomb.size(), 100000u);
  EXPECT_THAT([&] { DecompressExact(Codec::kZstd, bomb, 1000); },
              ThrowsMessage<InputError>(HasSubstr("zstd: decodes to more than 1000")));
  EXPECT_THAT([&] { DecompressZstd(bomb, std::uint64_t{1} << 20); },
              ThrowsMessage<InputError>(HasSubstr("more than 1048576 bytes")));
  EXPECT_THAT([&] { DecompressExact(Codec::kLz4Frame, bomb, kMaxChunkBytes + 1); },
              ThrowsMessage<InputError>(
                  HasSubstr("lz4: declared uncompressed size 4294967297 is over the 4294967296-byte limit")));
}

TEST(DecompressTest, CorruptDataCarriesTheLibrarysText) {
  const Bytes garbage = testing::ToBytes("this is not compressed data at all");
  EXPECT_THAT([&] { DecompressExact(Codec::kZstd, garbage, 10); },
              ThrowsMessage<InputError>(HasSubstr("zstd: Unknown frame descriptor")));
  EXPECT_THAT([&] { DecompressExact(Codec::kLz4Frame, garbage, 10); },
              ThrowsMessage<InputError>(HasSubstr("lz4: ERROR_frameType_unknown")));
  EXPECT_THAT([&] { DecompressExact(Codec::kBz2, garbage, 10); },
              ThrowsMessage<InputError>(HasSubstr("bz2: BZ_DATA_ERROR_MAGIC")));
}

TEST(DecompressTest, TruncatedInputIsAnErrorForEachCodec) {
  const Bytes data = SampleData(100000);
  for (const Codec codec : kCodecs) {
    Bytes packed = Compress(codec, data);
    packed.resize(packed.size() / 2);
    EXPECT_THAT([&] { DecompressExact(codec, packed, data.size()); },
                ThrowsMessage<InputError>(HasSubstr(CodecName(codec))));
  }
}

TEST(DecompressTest, ZstdOfUnknownSizeIsStreamed) {
  const Bytes data = SampleData(1 << 20);
  // A frame written without its content size, as a streaming writer does.
  std::unique_ptr<ZSTD_CCtx, decltype(&ZSTD_freeCCtx)> context(ZSTD_createCCtx(), &ZSTD_freeCCtx);
  ZSTD_CCtx_setParameter(context.get(), ZSTD_c_contentSizeFlag, 0);
  Bytes packed(ZSTD_compressBound(data.size()));
  ZSTD_inBuffer in{data.data(), data.size(), 0};
  ZSTD_outBuffer out{packed.data(), packed.size(), 0};
  ASSERT_EQ(ZSTD_compressStream2(context.get(), &out, &in, ZSTD_e_end), 0u);
  packed.resize(out.pos);
  ASSERT_EQ(ZSTD_getFrameContentSize(packed.data(), packed.size()), ZSTD_CONTENTSIZE_UNKNOWN);
  EXPECT_EQ(DecompressZstd(packed, kMaxWholeFileBytes), data);
  EXPECT_EQ(DecompressZstd(testing::ZstdCompress(data), kMaxWholeFileBytes), data);
  EXPECT_TRUE(HasZstdMagic(packed));
  EXPECT_FALSE(HasZstdMagic(data));
}

}  // namespace
}  // namespace slamtune::io
