// CSV tables and number formatting for the report.
//
// CSV follows RFC 4180 §2 except for line ends (LF, as Unix tools and pandas expect): a
// field is quoted when it contains a comma, a double quote, a line break or leading/trailing
// spaces, and quotes inside are doubled. Numbers are written with %.10g (ten significant
// digits: enough to tell apart every value the report compares, short enough to read);
// NaN and infinities as "nan", "inf", "-inf".
#pragma once

#include <string>
#include <vector>

namespace slamtune::report {

// %.10g of a double; "nan", "inf", "-inf" for the non-finite values.
std::string FormatNumber(double value);

// One CSV field, quoted and escaped when needed (RFC 4180 §2 rules 5-7).
std::string CsvField(const std::string& text);

struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  // each as wide as the header

  // Appends a row; its width must equal the header's (a broken invariant otherwise).
  void AddRow(std::vector<std::string> row);
  // The whole table: header line then rows, each line ended by '\n'.
  std::string ToString() const;
};

// Writes table.ToString() to `path`. Throws InputError naming the path if it cannot be written.
void WriteCsv(const CsvTable& table, const std::string& path);

// "mean ± std" with both rounded to the same decimal place, fixed by `std_digits` significant
// digits of the std (e.g. 0.012345, 0.004567 -> "0.0123 ± 0.0046"). A zero or non-finite std
// falls back to %.4g for the mean. `plus_minus` is the separator's symbol (UTF-8 "±" by
// default; "+-" for ASCII-only output).
std::string FormatMeanStd(double mean, double std, int std_digits = 2, const std::string& plus_minus = "\u00b1");

}  // namespace slamtune::report
