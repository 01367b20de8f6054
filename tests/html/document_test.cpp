// The HTML report library: escaping, self-containment, and the note that
// replaces a plot when gnuplot is missing.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "particles/html/document.h"

namespace particles::html {
namespace {

TEST(HtmlDocument, EscapesText) {
  EXPECT_EQ(escape("a<b & \"c\" 'd'>"), "a&lt;b &amp; &quot;c&quot; &#39;d&#39;&gt;");
  Document d("x < y");
  Table t{"cap & tion", {"<h>"}, {{"<td>"}}, {}};
  d.table(t);
  const std::string h = d.html();
  EXPECT_NE(h.find("<title>x &lt; y</title>"), std::string::npos);
  EXPECT_NE(h.find("<th>&lt;h&gt;</th>"), std::string::npos);
  EXPECT_NE(h.find("<td>&lt;td&gt;</td>"), std::string::npos);
  EXPECT_EQ(h.find("<td>"), h.find("<td>&lt;td&gt;</td>"));  // the only cell, escaped
}

// A linked cell is <a href> with its target escaped as an attribute; the
// others stay plain text.
TEST(HtmlDocument, LinksCellsThatHaveATarget) {
  Document d("links");
  Table t{"", {"name", "file"}, {{"a", "x.json"}, {"b", ""}}, {}, {{"", "dir/x.json?a=\"1\""}}};
  d.table(t);
  const std::string h = d.html();
  EXPECT_NE(h.find("<td>a</td><td><a href=\"dir/x.json?a=&quot;1&quot;\">x.json</a></td>"),
            std::string::npos)
      << h;
  EXPECT_NE(h.find("<td>b</td><td></td>"), std::string::npos) << h;
  EXPECT_EQ(h.find("<a "), h.rfind("<a "));  // one link only
}

Plot twoPointPlot() {
  Plot p;
  p.title = "slide_roll: t";
  p.logX = p.logY = true;
  p.series = {{"a", {{1e-3, 1.0}, {1e-2, 0.1}, {0.0, 5.0}}, "linespoints", 7, 0}};
  return p;
}

// With gnuplot present (CI installs gnuplot-nox only when asked: the test
// skips otherwise), the plot is inline SVG and nothing is fetched.
TEST(HtmlDocument, PlotIsInlineSvgWithNothingLoaded) {
  if (!gnuplotAvailable()) GTEST_SKIP() << "gnuplot not installed";
  Document d("plots");
  d.plot(twoPointPlot());
  const std::string h = d.html();
  EXPECT_NE(h.find("<svg"), std::string::npos);
  EXPECT_EQ(h.find("<?xml"), std::string::npos);
  EXPECT_EQ(h.find("src=\""), std::string::npos);
  EXPECT_EQ(h.find("href=\"http"), std::string::npos);
  EXPECT_EQ(h.find("<script"), std::string::npos);
  EXPECT_NE(h.find("slide_roll: t"), std::string::npos);  // plain title, not a subscript
}

// Without gnuplot on PATH the document still builds, with a note in the plot's place.
TEST(HtmlDocument, DegradesToANoteWithoutGnuplot) {
  const char* old = std::getenv("PATH");
  const std::string saved = old ? old : "";
  const std::filesystem::path empty =
      std::filesystem::temp_directory_path() / "particles-no-gnuplot";
  std::filesystem::create_directories(empty);
  ::setenv("PATH", empty.c_str(), 1);
  Document d("no plots");
  d.plot(twoPointPlot());
  d.plot(twoPointPlot());
  ::setenv("PATH", saved.c_str(), 1);
  const std::string h = d.html();
  EXPECT_EQ(h.find("<svg"), std::string::npos);
  EXPECT_NE(h.find("gnuplot is not installed"), std::string::npos);
  EXPECT_NE(h.find("not drawn (no gnuplot)"), std::string::npos);
}

TEST(HtmlDocument, WritesIndexHtml) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "particles-html-test";
  std::filesystem::create_directories(dir);
  Document d("written");
  d.paragraph("hello");
  d.write(dir);
  std::ifstream in(dir / "index.html");
  std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(all.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(all.find("<p>hello</p>"), std::string::npos);
}

}  // namespace
}  // namespace particles::html
