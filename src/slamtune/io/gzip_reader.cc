#include "slamtune/io/gzip_reader.h"

#include <algorithm>
#include <cstring>
#include <limits>

#include "slamtune/common/error.h"

namespace slamtune::io {
namespace {

constexpr std::size_t kChunkBytes = std::size_t{1} << 20;        // raw bytes read per call
constexpr unsigned char kGzipMagic0 = 0x1f, kGzipMagic1 = 0x8b;  // RFC 1952 §2.3.1 ID1, ID2
constexpr int kGzipWindowBits = 15 + 16;                         // zlib: 32 KiB window, expect a gzip wrapper

}  // namespace

GzipReader::GzipReader(std::istream* in) : in_(in), raw_(kChunkBytes) {
  SLAMTUNE_CHECK(in_ != nullptr);
  in_->read(reinterpret_cast<char*>(raw_.data()), static_cast<std::streamsize>(raw_.size()));
  const auto got = static_cast<std::size_t>(in_->gcount());
  if (in_->bad()) error_ = "read error";
  compressed_ = got >= 2 && raw_[0] == kGzipMagic0 && raw_[1] == kGzipMagic1;
  zs_.next_in = raw_.data();
  zs_.avail_in = static_cast<uInt>(got);
  if (compressed_) {
    const int rc = inflateInit2(&zs_, kGzipWindowBits);
    SLAMTUNE_CHECK_MSG(rc == Z_OK, "inflateInit2 failed");
    zlib_ready_ = true;
  }
}

GzipReader::~GzipReader() {
  if (zlib_ready_) inflateEnd(&zs_);
}

bool GzipReader::FillInput() {
  in_->read(reinterpret_cast<char*>(raw_.data()), static_cast<std::streamsize>(raw_.size()));
  const auto got = static_cast<std::size_t>(in_->gcount());
  if (in_->bad()) error_ = "read error";
  zs_.next_in = raw_.data();
  zs_.avail_in = static_cast<uInt>(got);
  return got > 0;
}

std::size_t GzipReader::Read(char* dst, std::size_t n) {
  if (done_ || n == 0) return 0;
  if (compressed_) return ReadInflated(dst, n);
  // Plain: first drain the bytes read for content detection, then read straight through.
  if (zs_.avail_in > 0) {
    const std::size_t take = std::min<std::size_t>(n, zs_.avail_in);
    std::memcpy(dst, zs_.next_in, take);
    zs_.next_in += take;
    zs_.avail_in -= static_cast<uInt>(take);
    return take;
  }
  in_->read(dst, static_cast<std::streamsize>(n));
  const auto got = static_cast<std::size_t>(in_->gcount());
  if (in_->bad()) error_ = "read error";
  if (got == 0) done_ = true;
  return got;
}

std::size_t GzipReader::ReadInflated(char* dst, std::size_t n) {
  for (;;) {
    if (member_ended_) {
      // Another member may follow (RFC 1952 §2.2); anything else is not gzip data.
      if (zs_.avail_in == 0 && !FillInput()) {
        done_ = true;
        return 0;
      }
      if (zs_.next_in[0] != kGzipMagic0) {
        error_ = "unexpected data after the end of the gzip stream";
        done_ = true;
        return 0;
      }
      inflateReset(&zs_);
      member_ended_ = false;
    }
    if (zs_.avail_in == 0 && !FillInput()) {
      if (error_.empty()) error_ = "truncated gzip stream (the file ends inside the compressed data)";
      done_ = true;
      return 0;
    }
    const std::size_t out = std::min<std::size_t>(n, std::numeric_limits<uInt>::max());
    zs_.next_out = reinterpret_cast<Bytef*>(dst);
    zs_.avail_out = static_cast<uInt>(out);
    const int rc = inflate(&zs_, Z_NO_FLUSH);
    const std::size_t produced = out - zs_.avail_out;
    if (rc == Z_STREAM_END) {
      member_ended_ = true;
    } else if (rc != Z_OK && rc != Z_BUF_ERROR) {
      error_ = std::string("corrupt gzip stream (zlib: ") +
               (zs_.msg != nullptr ? zs_.msg : "error " + std::to_string(rc)) + ")";
      done_ = true;  // bytes produced before the error are still returned; the next call ends
    }
    if (produced > 0) return produced;
    if (done_) return 0;
  }
}

}  // namespace slamtune::io
