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

}  // namespace
}  // namespace slamtune::report
