#include "slamtune/report/html_page.h"

#include <gtest/gtest.h>

namespace slamtune::report {
namespace {

TEST(HtmlEscape, EscapesMarkupCharacters) {
  EXPECT_EQ(HtmlEscape("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
  EXPECT_EQ(HtmlEscape("plain ± text"), "plain ± text");
}

TEST(HtmlPage, EscapesEverythingItIsGiven) {
  HtmlPage page("<title>");
  page.Heading(1, "<h>");
  page.Paragraph("<script>alert(1)</script>", "verdict");
  page.KeyValues({{"<k>", "<v>"}});
  page.Table({"<th>"}, {{"<td>", "extra"}});
  page.List({"<li>"});
  page.Image({1, 2, 3}, "\"alt\"", "<cap>");
  const std::string html = page.Finish();
  EXPECT_EQ(html.find("<script>"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
  EXPECT_NE(html.find("<title>&lt;title&gt;</title>"), std::string::npos);
  EXPECT_NE(html.find("<p class=\"verdict\">"), std::string::npos);
  EXPECT_NE(html.find("src=\"data:image/png;base64,AQID\""), std::string::npos);
  EXPECT_NE(html.find("alt=\"&quot;alt&quot;\""), std::string::npos);
  EXPECT_NE(html.find("<td>extra</td>"), std::string::npos);  // a row wider than the header keeps its cells
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<meta charset=\"utf-8\">"), std::string::npos);
}

TEST(HtmlPage, ASortableTableBringsItsScriptOnce) {
  HtmlPage plain("t");
  plain.Table({"a"}, {{"1"}});
  EXPECT_EQ(plain.Finish().find("<script"), std::string::npos);  // no sortable table: no script

  HtmlPage page("t");
  page.SortableTable({"<name>", "a_long_value"}, {{"<b>", "2.5"}, {"a"}});
  page.SortableTable({"x"}, {{"1"}});
  const std::string html = page.Finish();
  EXPECT_NE(html.find("<table class=\"sortable\">\n<thead><tr><th title=\"click to sort\">&lt;name&gt;</th>"),
            std::string::npos);
  EXPECT_NE(html.find("<th title=\"click to sort\">a_<wbr>long_<wbr>value</th>"), std::string::npos);
  EXPECT_NE(html.find("<tr><td>&lt;b&gt;</td><td>2.5</td></tr>"), std::string::npos);
  EXPECT_NE(html.find("<tr><td>a</td><td></td></tr>"), std::string::npos);  // padded to the header
  EXPECT_NE(html.find("<div class=\"table scroll\">"), std::string::npos);
  // One script, inline, at the end of the body, with no external source.
  const std::size_t script = html.find("<script>");
  ASSERT_NE(script, std::string::npos);
  EXPECT_EQ(html.find("<script", script + 1), std::string::npos);
  EXPECT_EQ(html.find("src=\"http"), std::string::npos);
  EXPECT_LT(script, html.find("</body>"));
  EXPECT_GT(script, html.find("</table>"));
}

}  // namespace
}  // namespace slamtune::report
