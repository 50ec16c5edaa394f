#include "slamtune/io/line_reader.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "slamtune/common/error.h"
#include "slamtune/common/text_file.h"

namespace slamtune::io {
namespace {

constexpr std::size_t kInitialBufferBytes = std::size_t{1} << 20;

}  // namespace

LineReader::LineReader(const std::string& path) : name_(path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path, 0, "cannot open: is a directory");
  file_ = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!file_->is_open()) throw InputError(path, 0, std::string("cannot open: ") + std::strerror(errno));
  gzip_ = std::make_unique<GzipReader>(file_.get());
  buffer_.resize(kInitialBufferBytes);
}

LineReader::LineReader(std::istream* in, std::string name) : name_(std::move(name)) {
  gzip_ = std::make_unique<GzipReader>(in);
  buffer_.resize(kInitialBufferBytes);
}

bool LineReader::Refill() {
  if (begin_ > 0) {
    std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
  }
  if (end_ == buffer_.size()) buffer_.resize(buffer_.size() * 2);  // a line longer than the buffer
  const std::size_t got = gzip_->Read(buffer_.data() + end_, buffer_.size() - end_);
  if (got == 0) {
    if (!gzip_->error().empty()) throw InputError(name_, line_number_ + 1, gzip_->error());
    at_end_ = true;
    return false;
  }
  end_ += got;
  return true;
}

bool LineReader::Next(std::string_view* line) {
  unterminated_ = false;
  for (;;) {
    const char* start = buffer_.data() + begin_;
    const std::size_t available = end_ - begin_;
    const void* newline = available > 0 ? std::memchr(start, '\n', available) : nullptr;
    std::size_t length = 0;
    if (newline != nullptr) {
      length = static_cast<std::size_t>(static_cast<const char*>(newline) - start);
      begin_ += length + 1;
    } else if (!at_end_ && Refill()) {
      continue;  // Refill moved the data: recompute start
    } else {
      if (end_ == begin_) return false;
      start = buffer_.data() + begin_;  // the last line, without '\n'
      length = end_ - begin_;
      begin_ = end_;
      unterminated_ = true;
    }
    if (length > 0 && start[length - 1] == '\r') --length;
    ++line_number_;
    *line = std::string_view(start, length);
    if (line_number_ == 1) *line = StripUtf8Bom(*line);  // a Windows editor's byte-order mark
    return true;
  }
}

void SplitFields(std::string_view line, std::vector<std::string_view>* fields) {
  fields->clear();
  const char* p = line.data();
  const char* const end = p + line.size();
  while (p < end) {
    while (p < end && (*p == ' ' || *p == '\t')) ++p;
    const char* start = p;
    while (p < end && *p != ' ' && *p != '\t') ++p;
    if (p > start) fields->emplace_back(start, static_cast<std::size_t>(p - start));
  }
}

std::optional<double> ParseDouble(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty() || text.front() == '+' || text.front() == ' ') return std::nullopt;
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
  return value;
}

std::optional<std::size_t> ParseCount(std::string_view text) {
  std::size_t value = 0;
  if (text.empty() || text.front() == '-') return std::nullopt;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
  return value;
}

double RequireFinite(const LineReader& reader, std::string_view text, std::size_t column, std::string_view what) {
  const std::optional<double> value = ParseDouble(text);
  if (!value) {
    throw InputError(reader.name(), reader.line_number(),
                     "column " + std::to_string(column) + " (" + std::string(what) + ") is not a number: '" +
                         std::string(text) + "'");
  }
  if (!std::isfinite(*value)) {
    throw InputError(
        reader.name(), reader.line_number(),
        "column " + std::to_string(column) + " (" + std::string(what) + ") is not finite: " + std::string(text));
  }
  return *value;
}

bool IsBlankOrComment(std::string_view line) {
  const std::size_t first = line.find_first_not_of(" \t");
  return first == std::string_view::npos || line[first] == '#';
}

std::string FormatExact(double value) {
  char buffer[64];
  const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof(buffer), value);
  SLAMTUNE_CHECK(ec == std::errc());
  return std::string(buffer, ptr);
}

}  // namespace slamtune::io
