// A self-contained HTML page for the report: inline CSS, images as base64 data URIs (RFC
// 2397), no external resources, and no script but the few inline lines that sort a sortable
// table when a header is clicked, so report.html reads the same offline, mailed or
// archived (a figure may also link to its full-size file beside the page). The layout fits a
// 1400 px window without horizontal scrolling: content is at most 1200 px wide, table cells
// wrap long values anywhere, and a table still too wide scrolls inside its own box. Every piece of text goes through
// HtmlEscape: log paths, labels and verdicts come from the user or the run and must not be able to inject markup.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace slamtune::report {

// Escapes & < > " ' (HTML Living Standard, "escaping a string", plus the apostrophe so the
// result is safe inside either kind of attribute quotes).
std::string HtmlEscape(const std::string& text);

class HtmlPage {
 public:
  explicit HtmlPage(std::string title);

  // <h1>..<h3>; level is clamped to [1, 3]; `id` (optional) makes it a link target (#id).
  void Heading(int level, const std::string& text, const std::string& id = "");
  // A paragraph; `css_class` selects a style from the page's sheet ("verdict", "note",
  // "warning", "" for plain).
  void Paragraph(const std::string& text, const std::string& css_class = "");
  // A two-column table of names and values.
  void KeyValues(const std::vector<std::pair<std::string, std::string>>& items);
  // A table with a header row; rows shorter than the header are padded with empty cells.
  void Table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows);
  // A table whose rows the reader sorts by clicking a column header (numbers as numbers, text as
  // text, empty cells last; a second click reverses). It scrolls inside its own box (at most
  // about 36 lines high, as wide as the page) with the header kept in view. Cells do not wrap,
  // except those of the last column (for long text, e.g. why a run failed); headers wrap after
  // an underscore, or anywhere when they must, so many columns of numbers fit the page. The
  // page then ends with the sorting script.
  void SortableTable(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows);
  // A bulleted list.
  void List(const std::vector<std::string>& items);
  // A figure with the PNG embedded as a data URI, its alt text and a caption.
  void Image(const std::vector<std::uint8_t>& png, const std::string& alt, const std::string& caption);

  struct Figure {
    std::vector<std::uint8_t> png;
    std::string alt;
    std::string caption;
    std::string link;  // a file beside the page opened by a click (the full-size image); empty: none
  };
  // Figures side by side, `columns` per row (1..4), each as wide as its column. `css_class`
  // adds a class to the grid (e.g. "first": images at most 58% of the window's height, so
  // that a page's first screen holds them).
  void FigureGrid(const std::vector<Figure>& figures, int columns, const std::string& css_class = "");

  // A collapsed section the reader opens with a click (<details>), closed by EndDetails.
  void BeginDetails(const std::string& summary);
  void EndDetails();

  // The complete document.
  std::string Finish() const;

 private:
  std::string title_;
  std::string body_;
  bool sortable_ = false;  // a SortableTable was added: Finish appends the sorting script
};

}  // namespace slamtune::report
