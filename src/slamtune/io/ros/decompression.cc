#include "slamtune/io/ros/decompression.h"

#include <bzlib.h>
#include <lz4frame.h>
#include <zstd.h>

#include <algorithm>
#include <climits>
#include <memory>
#include <string>

#include "slamtune/common/error.h"

namespace slamtune::io {
namespace {

constexpr std::uint64_t kMinInitialOutput = std::uint64_t{64} << 10;  // first output buffer, at least
constexpr std::uint64_t kInitialRatio = 16;                           // ... or 16 x the input
// A declared size up to this many times the input (plus kMinInitialOutput) sizes the first buffer
// directly; a larger one is not trusted for an allocation before the decoder proves it.
constexpr std::uint64_t kPlausibleRatio = 1024;

// The output buffer of one decompression: starts small, doubles as the decoder fills it, and
// never holds more than `limit` + 1 bytes (one byte past the limit proves the output too large).
class GrowingOutput {
 public:
  // `size_hint`: the size the data says it decodes to, 0 when unknown.
  GrowingOutput(std::size_t input_size, std::uint64_t size_hint, std::uint64_t limit, const char* codec)
      : limit_(limit), codec_(codec) {
    std::uint64_t initial = std::max<std::uint64_t>(kMinInitialOutput, std::uint64_t{input_size} * kInitialRatio);
    if (size_hint > 0 && size_hint <= kMinInitialOutput + std::uint64_t{input_size} * kPlausibleRatio) {
      initial = size_hint + 1;  // + 1: room to see that the output is not longer
    }
    bytes_.resize(static_cast<std::size_t>(std::min(initial, capacity_limit())));
  }

  // Room for the decoder at the end of the output; grows the buffer when it is full.
  std::uint8_t* room() {
    if (produced_ == bytes_.size()) Grow();
    return bytes_.data() + produced_;
  }
  std::size_t room_size() const { return bytes_.size() - produced_; }
  void Produced(std::size_t n) { produced_ += n; }
  std::size_t produced() const { return produced_; }

  std::vector<std::uint8_t> Take() {
    bytes_.resize(produced_);
    return std::move(bytes_);
  }

 private:
  std::uint64_t capacity_limit() const { return limit_ + 1; }
  void Grow() {
    if (bytes_.size() >= capacity_limit()) {
      throw InputError(std::string(codec_) + ": decodes to more than " + std::to_string(limit_) + " bytes");
    }
    bytes_.resize(
        static_cast<std::size_t>(std::min<std::uint64_t>(capacity_limit(), std::uint64_t{bytes_.size()} * 2)));
  }

  std::vector<std::uint8_t> bytes_;
  std::size_t produced_ = 0;
  std::uint64_t limit_;
  const char* codec_;
};

[[noreturn]] void ThrowTruncated(const char* codec) {
  throw InputError(std::string(codec) + ": truncated data (the input ends inside a compressed frame)");
}

std::vector<std::uint8_t> DecodeZstd(std::span<const std::uint8_t> input, std::uint64_t size_hint,
                                     std::uint64_t limit) {
  std::unique_ptr<ZSTD_DCtx, decltype(&ZSTD_freeDCtx)> context(ZSTD_createDCtx(), &ZSTD_freeDCtx);
  if (!context) throw InputError("zstd: cannot create a decompression context");
  GrowingOutput out(input.size(), size_hint, limit, "zstd");
  ZSTD_inBuffer in{input.data(), input.size(), 0};
  for (;;) {
    ZSTD_outBuffer chunk{out.room(), out.room_size(), 0};
    const std::size_t hint = ZSTD_decompressStream(context.get(), &chunk, &in);
    if (ZSTD_isError(hint)) throw InputError(std::string("zstd: ") + ZSTD_getErrorName(hint));
    out.Produced(chunk.pos);
    const bool input_done = in.pos == in.size;
    if (hint == 0 && input_done) break;                                // the last frame is complete
    if (input_done && chunk.pos < chunk.size) ThrowTruncated("zstd");  // wants input there is not
  }
  return out.Take();
}

std::vector<std::uint8_t> DecodeLz4Frames(std::span<const std::uint8_t> input, std::uint64_t size_hint,
                                          std::uint64_t limit) {
  LZ4F_dctx* raw_context = nullptr;
  const std::size_t created = LZ4F_createDecompressionContext(&raw_context, LZ4F_VERSION);
  if (LZ4F_isError(created)) throw InputError(std::string("lz4: ") + LZ4F_getErrorName(created));
  std::unique_ptr<LZ4F_dctx, decltype(&LZ4F_freeDecompressionContext)> context(raw_context,
                                                                               &LZ4F_freeDecompressionContext);
  GrowingOutput out(input.size(), size_hint, limit, "lz4");
  std::size_t consumed = 0;
  for (;;) {
    std::uint8_t* dst = out.room();
    const std::size_t room = out.room_size();
    std::size_t dst_size = room;
    std::size_t src_size = input.size() - consumed;
    const std::size_t hint =
        LZ4F_decompress(context.get(), dst, &dst_size, input.data() + consumed, &src_size, nullptr);
    if (LZ4F_isError(hint)) throw InputError(std::string("lz4: ") + LZ4F_getErrorName(hint));
    consumed += src_size;
    out.Produced(dst_size);
    const bool input_done = consumed == input.size();
    if (hint == 0 && input_done) break;  // the last frame is complete
    if (input_done && dst_size < room) ThrowTruncated("lz4");
  }
  return out.Take();
}

const char* Bz2ErrorName(int code) {
  switch (code) {
    case BZ_SEQUENCE_ERROR: return "BZ_SEQUENCE_ERROR";
    case BZ_PARAM_ERROR: return "BZ_PARAM_ERROR";
    case BZ_MEM_ERROR: return "BZ_MEM_ERROR (out of memory)";
    case BZ_DATA_ERROR: return "BZ_DATA_ERROR (data integrity error)";
    case BZ_DATA_ERROR_MAGIC: return "BZ_DATA_ERROR_MAGIC (not bzip2 data)";
    case BZ_UNEXPECTED_EOF: return "BZ_UNEXPECTED_EOF";
    default: return "unknown error";
  }
}

struct Bz2Stream {
  bz_stream stream{};
  bool ready = false;
  ~Bz2Stream() {
    if (ready) BZ2_bzDecompressEnd(&stream);
  }
};

std::vector<std::uint8_t> DecodeBz2(std::span<const std::uint8_t> input, std::uint64_t size_hint, std::uint64_t limit) {
  Bz2Stream bz;
  const int init = BZ2_bzDecompressInit(&bz.stream, /*verbosity=*/0, /*small=*/0);
  if (init != BZ_OK) throw InputError(std::string("bz2: ") + Bz2ErrorName(init));
  bz.ready = true;
  GrowingOutput out(input.size(), size_hint, limit, "bz2");
  std::size_t consumed = 0;  // input handed to libbz2 (its counters are 32-bit)
  for (;;) {
    if (bz.stream.avail_in == 0 && consumed < input.size()) {
      const std::size_t piece = std::min<std::size_t>(input.size() - consumed, UINT_MAX);
      bz.stream.next_in = const_cast<char*>(reinterpret_cast<const char*>(input.data() + consumed));
      bz.stream.avail_in = static_cast<unsigned int>(piece);
      consumed += piece;
    }
    std::uint8_t* dst = out.room();
    const unsigned int offered = static_cast<unsigned int>(std::min<std::size_t>(out.room_size(), UINT_MAX));
    bz.stream.next_out = reinterpret_cast<char*>(dst);
    bz.stream.avail_out = offered;
    const int rc = BZ2_bzDecompress(&bz.stream);
    const unsigned int produced = offered - bz.stream.avail_out;
    out.Produced(produced);
    if (rc == BZ_STREAM_END) {
      const std::size_t left = bz.stream.avail_in + (input.size() - consumed);
      if (left > 0) throw InputError("bz2: " + std::to_string(left) + " bytes after the end of the stream");
      break;
    }
    if (rc != BZ_OK) throw InputError(std::string("bz2: ") + Bz2ErrorName(rc));
    const bool input_done = bz.stream.avail_in == 0 && consumed == input.size();
    if (input_done && produced < offered) ThrowTruncated("bz2");
  }
  return out.Take();
}

}  // namespace

const char* CodecName(Codec codec) {
  switch (codec) {
    case Codec::kZstd: return "zstd";
    case Codec::kLz4Frame: return "lz4";
    case Codec::kBz2: return "bz2";
  }
  return "?";
}

std::vector<std::uint8_t> DecompressExact(Codec codec, std::span<const std::uint8_t> input,
                                          std::uint64_t uncompressed_size) {
  const char* name = CodecName(codec);
  if (uncompressed_size > kMaxChunkBytes) {
    throw InputError(std::string(name) + ": declared uncompressed size " + std::to_string(uncompressed_size) +
                     " is over the " + std::to_string(kMaxChunkBytes) + "-byte limit");
  }
  if (input.empty() && uncompressed_size == 0) return {};
  std::vector<std::uint8_t> out;
  switch (codec) {
    case Codec::kZstd: out = DecodeZstd(input, uncompressed_size, uncompressed_size); break;
    case Codec::kLz4Frame: out = DecodeLz4Frames(input, uncompressed_size, uncompressed_size); break;
    case Codec::kBz2: out = DecodeBz2(input, uncompressed_size, uncompressed_size); break;
  }
  if (out.size() != uncompressed_size) {
    throw InputError(std::string(name) + ": decodes to " + std::to_string(out.size()) +
                     " bytes, the declared size is " + std::to_string(uncompressed_size));
  }
  return out;
}

std::vector<std::uint8_t> DecompressZstd(std::span<const std::uint8_t> input, std::uint64_t max_size) {
  // The first frame's header may say its size (ZSTD_getFrameContentSize); a hint only.
  const unsigned long long declared = ZSTD_getFrameContentSize(input.data(), input.size());
  const bool known = declared != ZSTD_CONTENTSIZE_UNKNOWN && declared != ZSTD_CONTENTSIZE_ERROR;
  return DecodeZstd(input, known ? std::min<std::uint64_t>(declared, max_size) : 0, max_size);
}

bool HasZstdMagic(std::span<const std::uint8_t> bytes) {
  return bytes.size() >= 4 && bytes[0] == 0x28 && bytes[1] == 0xB5 && bytes[2] == 0x2F && bytes[3] == 0xFD;
}

}  // namespace slamtune::io
