// Self-contained HTML (html_page.h).
#include "slamtune/report/html_page.h"

#include <fmt/format.h>

#include <algorithm>

#include "slamtune/report/png_encoding.h"

namespace slamtune::report {
namespace {

constexpr const char* kStyle = R"(body{font-family:system-ui,-apple-system,"Segoe UI",Helvetica,Arial,sans-serif;
max-width:1200px;margin:2em auto;padding:0 1em;color:#222;line-height:1.45}
h1{font-size:1.6em;border-bottom:2px solid #0072b2;padding-bottom:.2em}
h2{font-size:1.3em;margin-top:1.8em;border-bottom:1px solid #ccc}
h3{font-size:1.1em}
.table{max-width:100%;overflow-x:auto;margin:.8em 0}
table{border-collapse:collapse;font-size:.92em}
th,td{border:1px solid #ccc;padding:.3em .6em;text-align:left;vertical-align:top;overflow-wrap:break-word}
th{background:#f2f2f2}
.kv td{overflow-wrap:anywhere}
tr:nth-child(even) td{background:#fafafa}
.verdict{background:#e8f3fa;border-left:5px solid #0072b2;padding:.7em 1em;font-weight:600}
.note{background:#fff8e6;border-left:5px solid #e69f00;padding:.7em 1em}
.warning{background:#fdecea;border-left:5px solid #d55e00;padding:.7em 1em}
.grid{display:grid;gap:1em}
.grid figure{margin:0;min-width:0}
.grid img{width:100%}
.first img{max-height:58vh;object-fit:contain}
figcaption b{color:#222}
details{margin:.8em 0}
summary{cursor:pointer;color:#0072b2}
figure{margin:1em 0}
figure img{max-width:100%;height:auto;border:1px solid #ddd}
figcaption{font-size:.9em;color:#555}
code,.mono{font-family:ui-monospace,Menlo,Consolas,monospace;font-size:.92em}
.scroll{max-height:36em;overflow:auto;border:1px solid #ddd}
.scroll table{margin:0}
table.sortable{width:100%;font-size:.85em}
table.sortable th{cursor:pointer;position:sticky;top:0;overflow-wrap:anywhere;padding:.25em .35em}
table.sortable td{white-space:nowrap;padding:.25em .35em}
table.sortable td:last-child{white-space:normal;overflow-wrap:anywhere;min-width:6em}
table.sortable th[aria-sort=ascending]::after{content:" \25B2"}
table.sortable th[aria-sort=descending]::after{content:" \25BC"})";

// Sorts a table.sortable by the column whose header is clicked (again: the other way). Cells
// compare as numbers when both are numbers, as text otherwise; empty cells stay last.
constexpr const char* kSortScript = R"(document.querySelectorAll("table.sortable").forEach(function (table) {
  var heads = table.tHead.rows[0].cells;
  Array.prototype.forEach.call(heads, function (th, column) {
    th.addEventListener("click", function () {
      var ascending = th.getAttribute("aria-sort") !== "ascending";
      Array.prototype.forEach.call(heads, function (h) { h.removeAttribute("aria-sort"); });
      th.setAttribute("aria-sort", ascending ? "ascending" : "descending");
      var body = table.tBodies[0];
      var rows = Array.prototype.slice.call(body.rows);
      var text = function (row) { var c = row.cells[column]; return c ? c.textContent.trim() : ""; };
      rows.sort(function (a, b) {
        var x = text(a), y = text(b);
        if (x === "" || y === "") return (x === "") - (y === "");
        var nx = Number(x), ny = Number(y);
        var order = !isNaN(nx) && !isNaN(ny) ? nx - ny : x.localeCompare(y);
        return ascending ? order : -order;
      });
      rows.forEach(function (row) { body.appendChild(row); });
    });
  });
});)";

}  // namespace

std::string HtmlEscape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

HtmlPage::HtmlPage(std::string title) : title_(std::move(title)) {}

void HtmlPage::Heading(int level, const std::string& text, const std::string& id) {
  const int l = std::clamp(level, 1, 3);
  const std::string anchor = id.empty() ? "" : " id=\"" + HtmlEscape(id) + "\"";
  body_ += fmt::format("<h{0}{1}>{2}</h{0}>\n", l, anchor, HtmlEscape(text));
}

void HtmlPage::Paragraph(const std::string& text, const std::string& css_class) {
  if (css_class.empty())
    body_ += "<p>" + HtmlEscape(text) + "</p>\n";
  else
    body_ += "<p class=\"" + HtmlEscape(css_class) + "\">" + HtmlEscape(text) + "</p>\n";
}

void HtmlPage::KeyValues(const std::vector<std::pair<std::string, std::string>>& items) {
  body_ += "<div class=\"table\"><table class=\"kv\">\n";
  for (const auto& [key, value] : items) {
    body_ += "<tr><th>" + HtmlEscape(key) + "</th><td>" + HtmlEscape(value) + "</td></tr>\n";
  }
  body_ += "</table></div>\n";
}

void HtmlPage::Table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  body_ += "<div class=\"table\"><table>\n<tr>";
  for (const auto& h : header) body_ += "<th>" + HtmlEscape(h) + "</th>";
  body_ += "</tr>\n";
  for (const auto& row : rows) {
    body_ += "<tr>";
    for (std::size_t i = 0; i < std::max(row.size(), header.size()); ++i) {
      body_ += "<td>" + (i < row.size() ? HtmlEscape(row[i]) : std::string()) + "</td>";
    }
    body_ += "</tr>\n";
  }
  body_ += "</table></div>\n";
}

void HtmlPage::SortableTable(const std::vector<std::string>& header,
                             const std::vector<std::vector<std::string>>& rows) {
  body_ += "<div class=\"table scroll\"><table class=\"sortable\">\n<thead><tr>";
  for (const auto& h : header) {
    // Long snake_case names wrap after an underscore rather than anywhere.
    std::string text;
    for (char c : HtmlEscape(h)) text += c == '_' ? std::string("_<wbr>") : std::string(1, c);
    body_ += "<th title=\"click to sort\">" + text + "</th>";
  }
  body_ += "</tr></thead>\n<tbody>\n";
  for (const auto& row : rows) {
    body_ += "<tr>";
    for (std::size_t i = 0; i < std::max(row.size(), header.size()); ++i) {
      body_ += "<td>" + (i < row.size() ? HtmlEscape(row[i]) : std::string()) + "</td>";
    }
    body_ += "</tr>\n";
  }
  body_ += "</tbody></table></div>\n";
  sortable_ = true;
}

void HtmlPage::List(const std::vector<std::string>& items) {
  body_ += "<ul>\n";
  for (const auto& item : items) body_ += "<li>" + HtmlEscape(item) + "</li>\n";
  body_ += "</ul>\n";
}

void HtmlPage::Image(const std::vector<std::uint8_t>& png, const std::string& alt, const std::string& caption) {
  body_ += "<figure><img src=\"" + PngDataUri(png) + "\" alt=\"" + HtmlEscape(alt) + "\">";
  if (!caption.empty()) body_ += "<figcaption>" + HtmlEscape(caption) + "</figcaption>";
  body_ += "</figure>\n";
}

void HtmlPage::FigureGrid(const std::vector<Figure>& figures, int columns, const std::string& css_class) {
  const int n = std::clamp(columns, 1, 4);
  std::string classes = "grid";
  if (!css_class.empty()) classes.append(" ").append(HtmlEscape(css_class));
  body_ += fmt::format("<div class=\"{}\" style=\"grid-template-columns:repeat({},minmax(0,1fr))\">\n", classes, n);
  for (const Figure& f : figures) {
    const std::string img = "<img src=\"" + PngDataUri(f.png) + "\" alt=\"" + HtmlEscape(f.alt) + "\">";
    body_ += "<figure>";
    body_ += f.link.empty() ? img : "<a href=\"" + HtmlEscape(f.link) + "\">" + img + "</a>";
    if (!f.caption.empty()) body_ += "<figcaption>" + HtmlEscape(f.caption) + "</figcaption>";
    body_ += "</figure>\n";
  }
  body_ += "</div>\n";
}

void HtmlPage::BeginDetails(const std::string& summary) {
  body_ += "<details><summary>" + HtmlEscape(summary) + "</summary>\n";
}

void HtmlPage::EndDetails() { body_ += "</details>\n"; }

std::string HtmlPage::Finish() const {
  return fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>{}</title>\n"
      "<style>\n{}\n</style>\n</head>\n<body>\n{}{}</body>\n</html>\n",
      HtmlEscape(title_), kStyle, body_, sortable_ ? "<script>\n" + std::string(kSortScript) + "\n</script>\n" : "");
}

}  // namespace slamtune::report
