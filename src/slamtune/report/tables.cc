// CSV and number formatting (tables.h).
#include "slamtune/report/tables.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "slamtune/common/error.h"

namespace slamtune::report {

std::string FormatNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return fmt::format("{:.10g}", value);
}

std::string CsvField(const std::string& text) {
  const bool needs_quotes = text.find_first_of(",\"\r\n") != std::string::npos ||
                            (!text.empty() && (text.front() == ' ' || text.back() == ' '));
  if (!needs_quotes) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';  // RFC 4180 §2 rule 7: a quote inside is doubled
    out += c;
  }
  out += '"';
  return out;
}

void CsvTable::AddRow(std::vector<std::string> row) {
  SLAMTUNE_CHECK_MSG(row.size() == header.size(),
                     fmt::format("CSV row has {} fields, header has {}", row.size(), header.size()));
  rows.push_back(std::move(row));
}

std::string CsvTable::ToString() const {
  std::string out;
  auto line = [&out](const std::vector<std::string>& fields) {
    for (std::size_t i = 0; i < fields.size(); ++i) {
      if (i > 0) out += ',';
      out += CsvField(fields[i]);
    }
    out += '\n';
  };
  line(header);
  for (const auto& row : rows) line(row);
  return out;
}

void WriteCsv(const CsvTable& table, const std::string& path) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(path, 0, "cannot write the file (missing folder or no permission?)");
  out << table.ToString();
  out.close();
  if (!out) throw InputError(path, 0, "writing the file failed (disk full?)");
}

std::string FormatMeanStd(double mean, double std, int std_digits, const std::string& plus_minus) {
  if (!std::isfinite(std) || std == 0.0 || !std::isfinite(mean)) {
    return fmt::format("{:.4g} {} {:.4g}", mean, plus_minus, std);
  }
  // The last kept decimal of the std's `std_digits` significant digits sets both roundings.
  const int exponent = static_cast<int>(std::floor(std::log10(std::abs(std))));
  const int decimals = std::clamp(std::max(std_digits, 1) - 1 - exponent, 0, 12);
  return fmt::format("{:.{}f} {} {:.{}f}", mean, decimals, plus_minus, std, decimals);
}

}  // namespace slamtune::report
