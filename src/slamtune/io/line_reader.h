// Line-oriented reading of text files (CARMEN logs, relations, trajectories), plain or gzip
// (see gzip_reader.h), plus the field splitting and number parsing they share.
//
// Lines are returned as views into an internal buffer (valid until the next call), without the
// '\n' and without a trailing '\r'. A UTF-8 byte-order mark before the first line (Windows
// editors write one) is dropped, so the first record reads like the others. Numbers are parsed
// with std::from_chars: locale-free, exact (round-trip) and fast, which matters because the
// optimiser re-reads logs often.
#pragma once

#include <cstddef>
#include <fstream>
#include <istream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "slamtune/io/gzip_reader.h"

namespace slamtune::io {

class LineReader {
 public:
  // Opens `path`; throws InputError "PATH: cannot open (reason)" if it cannot be read.
  explicit LineReader(const std::string& path);
  // Reads from `in` (not owned, must outlive the reader); `name` is used in messages.
  LineReader(std::istream* in, std::string name);

  // Next line, or false at the end of the data. Throws InputError "NAME:LINE: ..." when the
  // data is corrupt (e.g. a truncated gzip stream), LINE being the line being read.
  bool Next(std::string_view* line);

  const std::string& name() const { return name_; }
  std::size_t line_number() const { return line_number_; }  // of the line last returned
  // True when the line last returned is the last one and has no '\n': a possibly cut line.
  bool unterminated() const { return unterminated_; }
  bool compressed() const { return gzip_->compressed(); }

 private:
  bool Refill();  // appends decoded bytes to the buffer; false at the end

  std::string name_;
  std::unique_ptr<std::ifstream> file_;
  std::unique_ptr<GzipReader> gzip_;
  std::vector<char> buffer_;
  std::size_t begin_ = 0;  // start of unread data in buffer_
  std::size_t end_ = 0;    // end of valid data in buffer_
  bool at_end_ = false;
  std::size_t line_number_ = 0;
  bool unterminated_ = false;
};

// Splits a line into whitespace-separated fields (spaces and tabs), reusing `fields`' storage.
void SplitFields(std::string_view line, std::vector<std::string_view>* fields);

// Parses the whole of `text` as a double (accepts an optional leading '+', "nan", "inf").
std::optional<double> ParseDouble(std::string_view text);
// Parses the whole of `text` as a non-negative integer.
std::optional<std::size_t> ParseCount(std::string_view text);

// Parses `text` (column `column`, 1-based, called `what`) of the reader's current line as a
// finite double; throws InputError "NAME:LINE: column C (what) is not a number: 'text'" or
// "... is not finite: nan".
double RequireFinite(const LineReader& reader, std::string_view text, std::size_t column, std::string_view what);

// True for lines to skip in relations/trajectory files: empty, blank or starting with '#'.
bool IsBlankOrComment(std::string_view line);

// Shortest text that reads back as exactly `value` (std::to_chars round trip).
std::string FormatExact(double value);

}  // namespace slamtune::io
