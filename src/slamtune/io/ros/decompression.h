// Decompression of the codecs ROS recordings use, into memory:
//   * zstd (RFC 8878): MCAP chunks (mcap.dev/spec, Chunk record, compression "zstd"), rosbag2
//     file-level (`*.mcap.zstd`, `*.db3.zstd`) and message-level compression;
//   * LZ4 frame format (lz4frame.h; not raw LZ4 blocks): MCAP chunks "lz4" and ROS 1 bag chunks
//     "lz4" (roslz4 writes LZ4 frames);
//   * bzip2: ROS 1 bag chunks "bz2" (wiki.ros.org/Bags/Format/2.0, Chunk).
//
// Output grows as the decoder produces it, so a corrupt size field never makes a large
// allocation by itself, and it is bounded: a chunk whose declared size exceeds kMaxChunkBytes is
// refused (a decompression bomb or a corrupt field), and the output must come to exactly the
// declared size. Errors throw InputError without a file (the caller adds file and byte offset),
// carrying the library's own text, e.g. "zstd: Data corruption detected".
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace slamtune::io {

enum class Codec { kZstd, kLz4Frame, kBz2 };
// "zstd", "lz4", "bz2".
const char* CodecName(Codec codec);

constexpr std::uint64_t kMaxChunkBytes = std::uint64_t{4} << 30;       // 4 GiB: one chunk or one message
constexpr std::uint64_t kMaxWholeFileBytes = std::uint64_t{64} << 30;  // 64 GiB: one file-compressed split

// Decompresses `input`, which must decode to exactly `uncompressed_size` bytes (at most
// kMaxChunkBytes). Concatenated zstd or LZ4 frames are decoded one after the other.
std::vector<std::uint8_t> DecompressExact(Codec codec, std::span<const std::uint8_t> input,
                                          std::uint64_t uncompressed_size);

// Decompresses zstd frames whose decoded size is not known in advance (it may be in the frame
// header, ZSTD_getFrameContentSize, or not), refusing more than `max_size` bytes of output.
std::vector<std::uint8_t> DecompressZstd(std::span<const std::uint8_t> input, std::uint64_t max_size);

// True when `bytes` start with the zstd frame magic 28 B5 2F FD (RFC 8878 §3.1.1).
bool HasZstdMagic(std::span<const std::uint8_t> bytes);

}  // namespace slamtune::io
