// Byte source that reads a stream either as-is or through zlib, chosen by content: a stream
// that starts with the gzip magic bytes 1f 8b (RFC 1952 §2.3.1) is inflated, anything else is
// passed through. File names play no part, so `intel.clf` may be compressed and `x.gz` plain.
//
// Reads in large chunks (the CARMEN reader is on the optimiser's hot path). Concatenated gzip
// members (RFC 1952 §2.2) are read one after the other. A stream that ends before a member's
// trailer, or whose deflate data or CRC is wrong, is reported through error(), never thrown, so
// the caller can say at which line of the text it happened.
#pragma once

#include <zlib.h>

#include <cstddef>
#include <istream>
#include <string>
#include <vector>

namespace slamtune::io {

class GzipReader {
 public:
  // `in` must outlive the reader; it is read in binary chunks from its current position.
  explicit GzipReader(std::istream* in);
  ~GzipReader();
  GzipReader(const GzipReader&) = delete;
  GzipReader& operator=(const GzipReader&) = delete;

  // Copies up to `n` decoded bytes into `dst`. Returns 0 at the end of the data or on an error;
  // then error() says which (empty at a clean end).
  std::size_t Read(char* dst, std::size_t n);

  bool compressed() const { return compressed_; }
  const std::string& error() const { return error_; }

 private:
  // Refills the raw input buffer; returns false when the underlying stream is exhausted.
  bool FillInput();
  std::size_t ReadInflated(char* dst, std::size_t n);

  std::istream* in_;
  std::vector<unsigned char> raw_;  // raw (compressed) bytes not yet consumed
  z_stream zs_{};
  bool compressed_ = false;
  bool zlib_ready_ = false;
  bool member_ended_ = false;  // the current gzip member reached its trailer
  bool done_ = false;
  std::string error_;
};

}  // namespace slamtune::io
